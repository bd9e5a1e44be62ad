// knitc view, driven as a designer would in headless Chromium (Debian's, through the
// pinned puppeteer-core): the fabric drawn, an edit shown with the camera kept, a broken
// edit's message over the last fabric, a loop pointed at and named, a chart cell lighting
// its loop, foreign requests refused, and Ctrl-C leaving nothing behind.
// Usage: node view.mjs KNITC SOURCE_DIR OUT_DIR   (a screenshot goes to OUT_DIR/view.png)
import { spawn, spawnSync } from 'node:child_process';
import { mkdtemp, writeFile, readFile, readdir, rm, mkdir } from 'node:fs/promises';
import { request } from 'node:http';
import { connect } from 'node:net';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

const [knitc, source, out] = process.argv.slice(2);
const { default: puppeteer } = await import(join(source, 'tools/browser/node_modules/puppeteer-core/lib/esm/puppeteer/puppeteer-core.js'));
await mkdir(out, { recursive: true });
let failures = 0;
const check = (ok, what) => {
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`);
  if (!ok) failures += 1;
};
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

// A 12-stitch swatch: the rows of the pattern file are lines 9 to 13.
const pattern = (lastRow) => `pattern {
  name  = "view test",
  gauge = { loop_width = 4.0, loop_height = 4.2, thickness = 2.0 },
  yarns = { A = { diameter = 1.0, color = "#c0392b" } },
  knitting = "flat",
}
cast_on(12)
for _ = 1, 4 do
  row "k"
  row "p"
end
row "k"
${lastRow}
bind_off()
`;
const dir = await mkdtemp(join(tmpdir(), 'knitc-view-'));
const file = join(dir, 'pattern.lua');
await writeFile(file, pattern('row "p"'));

const server = spawn(knitc, ['view', file, '--no-open'], { stdio: ['ignore', 'pipe', 'pipe'] });
let printed = '', errors = '';
server.stderr.on('data', (d) => { errors += d; });
const address = await new Promise((resolve, reject) => {
  server.stdout.on('data', (d) => {
    printed += d;
    const m = printed.match(/at (http:\/\/127\.0\.0\.1:\d+\/)/);
    if (m) resolve(m[1]);
  });
  server.on('exit', (code) => reject(new Error(`knitc view exited ${code}: ${errors}`)));
  setTimeout(() => reject(new Error(`knitc view printed no address: ${printed} ${errors}`)), 60000);
});
const port = Number(address.match(/:(\d+)\//)[1]);
check(true, `knitc view serves at ${address}`);

// A raw request, its path and Host exactly as given (no client tidies them): the status.
function raw(path, host = `127.0.0.1:${port}`) {
  return new Promise((resolve) => {
    const socket = connect(port, '127.0.0.1', () => socket.write(`GET ${path} HTTP/1.1\r\nHost: ${host}\r\nConnection: close\r\n\r\n`));
    let text = '';
    socket.on('data', (d) => { text += d; });
    socket.on('end', () => resolve({ status: Number((text.match(/^HTTP\/1\.\d (\d+)/) || [])[1]), body: text }));
    socket.on('error', () => resolve({ status: 0, body: '' }));
  });
}

const browser = await puppeteer.launch({
  executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
  headless: true,
  args: ['--no-sandbox', '--disable-gpu', '--no-first-run', '--disable-background-networking', '--disable-component-update',
         '--disable-sync', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist'],
});
try {
  const tab = await browser.newPage();
  await tab.setViewport({ width: 1200, height: 700 });
  const problems = [];
  tab.on('console', (m) => { if (m.type() === 'error') problems.push(m.text()); });
  tab.on('pageerror', (e) => problems.push(String(e)));
  await tab.goto(address);
  await tab.waitForFunction('window.knitcView && window.knitcView.fabricVersion > 0', { timeout: 60000 });
  check(problems.length === 0, `the page loads with no error (${problems.join('; ') || 'none'})`);
  // A screenshot's pixels, read in the page: a 2D context holding it.
  await tab.evaluate(() => {
    window.decodedShot = async (png) => {
      const image = new Image();
      image.src = `data:image/png;base64,${png}`;
      await image.decode();
      const c = document.createElement('canvas');
      c.width = image.width;
      c.height = image.height;
      const g = c.getContext('2d');
      g.drawImage(image, 0, 0);
      return g;
    };
  });

  // Drawn: the fabric's middle in the yarn's red, lit; the corners the background.
  const pixels = async () => {
    const shot = await tab.screenshot({ encoding: 'base64', clip: { x: 0, y: 0, width: 840, height: 700 } });
    return tab.evaluate(async (png) => {
      const g = await window.decodedShot(png);
      const v = window.knitcView;
      const box = v.box;
      const corners = [[5, 690], [835, 690], [835, 60]].map(([x, y]) => Array.from(g.getImageData(x, y, 1, 1).data));
      // The share of yarn-red pixels (red well above green and blue) inside the fabric's middle.
      let red = 0, all = 0;
      const a = v.screenOf(v.info.loops.length >> 1, 0.25);
      for (let y = Math.round(a.y) - 40; y < a.y + 40; y += 2)
        for (let x = Math.round(a.x) - 40; x < a.x + 40; x += 2) {
          const [r, gr, b] = g.getImageData(x, y, 1, 1).data;
          all += 1;
          if (r > gr + 40 && r > b + 40) red += 1;
        }
      return { corners, red: red / all, box: box ? [box.min.x, box.max.x] : null };
    }, shot);
  };
  const seen = await pixels();
  const background = (p) => Math.abs(p[0] - 0xf4) < 6 && Math.abs(p[1] - 0xf1) < 6 && Math.abs(p[2] - 0xec) < 6;
  check(seen.red > 0.3, `the fabric is drawn in its yarn's colour (${(100 * seen.red).toFixed(0)}% of its middle)`);
  check(seen.corners.every(background), `the background elsewhere (${JSON.stringify(seen.corners)})`);

  // The designer turns the fabric; an edit then shows within 2 s, the camera kept.
  await tab.evaluate(() => { const v = window.knitcView; v.look('back'); });
  const camera = await tab.evaluate(() => window.knitcView.camera());
  const before = await tab.evaluate(() => ({ version: window.knitcView.fabricVersion, rows: window.knitcView.info.rows.length }));
  const saved = Date.now();
  await writeFile(file, pattern('row "p"\nrow "k"\nrow "p"'));
  let shown = null;
  try {
    await tab.waitForFunction((v0) => window.knitcView.fabricVersion > v0, { timeout: 10000, polling: 20 }, before.version);
    shown = (Date.now() - saved) / 1000;
  } catch { /* shown stays null */ }
  const after = await tab.evaluate(() => ({ rows: window.knitcView.info.rows.length, camera: window.knitcView.camera() }));
  check(shown !== null && shown < 2.0, `the edit shows in the page in ${shown === null ? 'never' : shown.toFixed(2) + ' s'} (under 2 s)`);
  check(after.rows === before.rows + 2, `the new fabric has the rows added (${before.rows} -> ${after.rows})`);
  check(JSON.stringify(after.camera) === JSON.stringify(camera), 'the camera stays where the designer left it');
  console.log(`     (a swatch's edit shown in ${shown === null ? '-' : shown.toFixed(2)} s; knitc: ${(errors.match(/rebuilt in [0-9.]+ s/g) || []).join(', ')})`);

  // A broken edit: its file:line in the page, the last fabric still drawn.
  const goodVersion = await tab.evaluate(() => window.knitcView.fabricVersion);
  await writeFile(file, pattern('row "p"\nrow "kk2tog"'));
  let message = '';
  try {
    await tab.waitForFunction(() => window.knitcView.error !== '', { timeout: 10000, polling: 20 });
    message = await tab.evaluate(() => document.getElementById('error').textContent);
  } catch { /* message stays empty */ }
  check(message.includes(`${file}:14:`), `a broken edit shows its file and line (${message.slice(0, 120)})`);
  const shownError = await tab.evaluate(() => getComputedStyle(document.getElementById('error')).display !== 'none');
  check(shownError, 'the message is on screen');
  await tab.evaluate(() => window.knitcView.look('face'));
  const still = await pixels();
  const fabricKept = await tab.evaluate((v) => window.knitcView.fabricVersion === v && window.knitcView.fabric !== null, goodVersion);
  check(fabricKept && still.red > 0.3, `the last good fabric stays on screen (${(100 * still.red).toFixed(0)}% red)`);

  // Fixed again; then a known loop pointed at: row 5 (line 9), its 4th stitch.
  await writeFile(file, pattern('row "p"'));
  await tab.waitForFunction(() => window.knitcView.error === '' && window.knitcView.fabricVersion > 0, { timeout: 10000 });
  await tab.waitForFunction((v) => window.knitcView.fabricVersion > v, { timeout: 10000 }, goodVersion);
  await tab.evaluate(() => window.knitcView.look('face'));
  const pointed = await tab.evaluate(() => {
    const v = window.knitcView;
    const row = v.info.rows[4];
    const loop = row.cells[3].loops[0];
    const at = v.screenOf(loop, 0.25);  // on a leg, in front of the row above's
    return { named: v.pointAt(at.x, at.y), loop, line: row.line };
  });
  const named = pointed.named || {};
  check(named.row === 5 && named.cell === 3, `pointing at row 5's 4th loop names row ${named.row}, stitch ${named.cell + 1}`);
  check((named.text || '').includes('knit (k)') && (named.text || '').includes('pattern.lua:9'),
        `it names the stitch and the script line: "${named.text}"`);
  const cellLit = await tab.evaluate(() => {
    const v = window.knitcView;
    const c = v.chartCellAt(5, 3);
    const chart = document.getElementById('chart');
    const px = chart.getContext('2d').getImageData(c.x + 3, c.y + 3, 1, 1).data;
    return Array.from(px);
  });
  check(cellLit[0] > 240 && cellLit[1] > 180 && cellLit[2] < 100, `its chart cell is lit (${cellLit})`);

  // A chart cell pointed at: its loop lit in 3D.
  const fromChart = await tab.evaluate(async () => {
    const v = window.knitcView;
    const c = v.chartCellAt(3, 6);
    const chart = document.getElementById('chart');
    const r = chart.getBoundingClientRect();
    chart.dispatchEvent(new MouseEvent('click', { clientX: r.left + c.x + 4, clientY: r.top + c.y + 4, bubbles: true }));
    const loop = v.info.rows[2].cells[6].loops[0];
    v.drawNow();
    return { picked: v.picked, loop, at: v.screenOf(loop, 0.25) };
  });
  check(fromChart.picked && fromChart.picked.loops.length === 1 && fromChart.picked.loops[0] === fromChart.loop,
        `pointing at row 3's 7th chart cell lights loop ${fromChart.loop} (${fromChart.picked && fromChart.picked.loops})`);
  const litShot = await tab.screenshot({ encoding: 'base64', clip: { x: 0, y: 0, width: 840, height: 700 } });
  const pink = await tab.evaluate(async (png, at) => {
    const g = await window.decodedShot(png);
    let n = 0;
    for (let y = Math.round(at.y) - 12; y <= at.y + 12; ++y)
      for (let x = Math.round(at.x) - 12; x <= at.x + 12; ++x) {
        const [r, gr, b] = g.getImageData(x, y, 1, 1).data;
        if (r > 200 && gr < 90 && b > 70) n += 1;  // the highlight's pink, #ff2a6d
      }
    return n;
  }, litShot, fromChart.at);
  check(pink > 3, `the loop is lit in the 3D view (${pink} highlight pixels at it)`);
  await tab.screenshot({ path: join(out, 'view.png') });

  // Only its own files, and only to its own name.
  const own = await raw('/');
  check(own.status === 200, `its page: ${own.status}`);
  for (const path of ['/../../../../etc/passwd', '/%2e%2e/%2e%2e/etc/passwd', '/etc/passwd', '//etc/passwd', '/three/../../../../etc/passwd',
                      `/${file}`, '/view/page/index.html']) {
    const r = await raw(path);
    check(r.status >= 400 && !r.body.includes('root:'), `${path} refused (${r.status})`);
  }
  const foreign = await raw('/', 'attacker.example:80');
  check(foreign.status === 403, `a foreign Host header refused (${foreign.status})`);
  const rebinding = await raw('/fabric.glb', `attacker.example:${port}`);
  check(rebinding.status === 403, `a rebound name with its port refused (${rebinding.status})`);
} finally {
  await browser.close();
}

// The library's site: knitc gallery on a folder of two patterns, two pages opened from disk.
{
  const library = await mkdtemp(join(tmpdir(), 'knitc-library-'));
  await writeFile(join(library, 'swatch.lua'), pattern('row "p"'));
  await writeFile(join(library, 'jersey.lua'), await readFile(join(source, 'patterns/jersey.lua')));
  const site = join(out, 'site');
  await rm(site, { recursive: true, force: true });
  const made = spawnSync(knitc, ['gallery', library, '-o', site, '-q'], { encoding: 'utf8' });
  check(made.status === 0, `knitc gallery writes the site (exit ${made.status}${made.stderr ? ': ' + made.stderr.trim() : ''})`);
  const browser2 = await puppeteer.launch({
    executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
    headless: true,
    args: ['--no-sandbox', '--disable-gpu', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist'],
  });
  try {
    const tab = await browser2.newPage();
    await tab.setViewport({ width: 1200, height: 700 });
    await tab.goto(`file://${join(site, 'index.html')}`);
    const cards = await tab.evaluate(() => Array.from(document.querySelectorAll('a.card')).map((a) => a.getAttribute('href')));
    check(JSON.stringify(cards) === JSON.stringify(['jersey.html', 'swatch.html']), `the index links each pattern's page (${cards})`);
    for (const page of cards) {
      const problems = [];
      tab.removeAllListeners('pageerror');
      tab.on('pageerror', (e) => problems.push(String(e)));
      await tab.goto(`file://${join(site, page)}`);
      let loaded = true;
      await tab.waitForFunction('window.knitcView && window.knitcView.fabricVersion > 0', { timeout: 60000 }).catch(() => { loaded = false; });
      const fabric = loaded ? await tab.evaluate(() => {
        const v = window.knitcView;
        v.drawNow();
        const a = v.screenOf(v.info.loops.length >> 1, 0.25);
        const canvas = document.querySelector('#fabric canvas');
        const g = document.createElement('canvas').getContext('2d');
        g.canvas.width = canvas.width;
        g.canvas.height = canvas.height;
        g.drawImage(canvas, 0, 0);
        const r = canvas.getBoundingClientRect();
        const scale = canvas.width / r.width;
        let yarn = 0, all = 0;
        for (let y = a.y - 30; y < a.y + 30; y += 3)
          for (let x = a.x - 30; x < a.x + 30; x += 3) {
            const [red, green, blue] = g.getImageData(Math.round((x - r.left) * scale), Math.round((y - r.top) * scale), 1, 1).data;
            all += 1;
            if (Math.abs(red - 0xf4) + Math.abs(green - 0xf1) + Math.abs(blue - 0xec) > 40) yarn += 1;
          }
        return yarn / all;
      }) : 0;
      check(loaded && fabric > 0.3, `${page} opened from disk shows its fabric (${(100 * fabric).toFixed(0)}% of its middle${problems.length ? '; ' + problems.join('; ') : ''})`);
    }
  } finally {
    await browser2.close();
    await rm(library, { recursive: true, force: true });
  }
}

// Ctrl-C: stops at once, exit 0, nothing left beside the pattern.
const stopped = new Promise((resolve) => server.on('exit', (code, signal) => resolve({ code, signal })));
const t0 = Date.now();
server.kill('SIGINT');
const end = await Promise.race([stopped, sleep(5000).then(() => null)]);
check(end !== null && end.code === 0, `Ctrl-C stops it in ${((Date.now() - t0) / 1000).toFixed(2)} s, exit ${end && end.code}`);
const left = await readdir(dir);
check(left.length === 1 && left[0] === 'pattern.lua', `nothing left behind (${left.join(', ')})`);
await rm(dir, { recursive: true, force: true });
if (end === null) server.kill('SIGKILL');
console.log(failures === 0 ? 'all passed' : `${failures} failed`);
process.exit(failures === 0 ? 0 : 1);
