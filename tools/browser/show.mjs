// Opens .glb files with three.js's GLTFLoader in Debian's headless Chromium (software GL)
// and reports, per file, what a browser client sees: load, first- and next-frame times, meshes,
// instances, triangles drawn, the scene's box, and the share of a rendered frame the fabric
// covers. Usage: node show.mjs [--png DIR] FILE.glb...  Prints one JSON object a file, a
// line each; exits 1 if a file does not load, 2 on misuse.
//   --zoom K   frame the middle 1/K of the fabric (a close-up K times nearer)
//   --maps     also report each material's texture maps, and draw the frame a second time
//              with the maps taken off, reporting both frames' detail (the mean step in
//              brightness between neighbouring fabric pixels) and how far the two differ
//
// The page and three.js are served from this folder's node_modules by a server on
// 127.0.0.1 that serves only those files and the named .glb files; nothing is fetched
// from the network.
import { createServer } from 'node:http';
import { readFile, mkdtemp, rm, writeFile } from 'node:fs/promises';
import { existsSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, dirname, basename, resolve, sep } from 'node:path';
import { fileURLToPath } from 'node:url';
import puppeteer from 'puppeteer-core';

const here = dirname(fileURLToPath(import.meta.url));
const args = process.argv.slice(2);
let pngDir = null, zoom = 1, maps = false;
for (;;) {
  if (args[0] === '--png' && args.length > 1) pngDir = args.splice(0, 2)[1];
  else if (args[0] === '--zoom' && args.length > 1) zoom = Number(args.splice(0, 2)[1]);
  else if (args[0] === '--maps') maps = Boolean(args.splice(0, 1));
  else break;
}
if (!(zoom >= 1 && zoom <= 1000)) {
  console.error('show.mjs: --zoom takes a number from 1 to 1000');
  process.exit(2);
}
if (args.length === 0 || args.some((a) => a.startsWith('-'))) {
  console.error('usage: node show.mjs [--png DIR] [--zoom K] [--maps] FILE.glb...');
  process.exit(2);
}
for (const file of args) {
  if (!existsSync(file)) {
    console.error(`show.mjs: ${file}: no such file`);
    process.exit(2);
  }
}

const three = join(here, 'node_modules', 'three');
const assets = new Map([
  ['/three.module.js', join(three, 'build', 'three.module.js')],
  ['/three.core.js', join(three, 'build', 'three.core.js')],
]);
args.forEach((file, i) => assets.set(`/file${i}.glb`, file));

const page = `<!doctype html><html><head><meta charset="utf-8">
<script type="importmap">{"imports": {"three": "/three.module.js"}}</script>
</head><body style="margin:0;background:#fff"><canvas id="c" width="640" height="480"></canvas>
<script type="module">
import * as THREE from 'three';
import { GLTFLoader } from '/jsm/loaders/GLTFLoader.js';
import { MeshoptDecoder } from '/jsm/libs/meshopt_decoder.module.js';
// The fabric's pixels (not the white background) and their mean brightness step to the
// right-hand neighbour.
function measure(pixels, width, height) {
  let fabric = 0, steps = 0, step = 0;
  const isFabric = (i) => pixels[i] < 245 || pixels[i + 1] < 245 || pixels[i + 2] < 245;
  const light = (i) => 0.2126 * pixels[i] + 0.7152 * pixels[i + 1] + 0.0722 * pixels[i + 2];
  for (let y = 0; y < height; ++y)
    for (let x = 0; x < width; ++x) {
      const i = 4 * (y * width + x);
      if (!isFabric(i)) continue;
      fabric += 1;
      if (x + 1 < width && isFabric(i + 4)) { step += Math.abs(light(i + 4) - light(i)); steps += 1; }
    }
  return { fabric, detail: steps ? step / steps : 0 };
}
window.show = async (url, zoom, maps) => {
  const t0 = performance.now();
  const loader = new GLTFLoader().setMeshoptDecoder(MeshoptDecoder);
  const gltf = await loader.loadAsync(url);
  const loaded = performance.now() - t0;
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(1, 1, 1);
  scene.add(gltf.scene);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x444444, 2.0));
  const sun = new THREE.DirectionalLight(0xffffff, 2.0);
  sun.position.set(1, 2, 3);
  scene.add(sun);
  let meshes = 0, instanced = 0, instances = 0, triangles = 0;
  gltf.scene.updateMatrixWorld(true);
  gltf.scene.traverse((o) => {
    if (!o.isMesh) return;
    meshes += 1;
    const n = o.isInstancedMesh ? o.count : 1;
    if (o.isInstancedMesh) { instanced += 1; instances += n; o.computeBoundingBox(); o.computeBoundingSphere(); }
    const index = o.geometry.index;
    triangles += n * (index ? index.count : o.geometry.attributes.position.count) / 3;
  });
  const box = new THREE.Box3().setFromObject(gltf.scene);
  const size = box.getSize(new THREE.Vector3()), centre = box.getCenter(new THREE.Vector3());
  const canvas = document.getElementById('c');
  const renderer = new THREE.WebGLRenderer({ canvas, antialias: false, preserveDrawingBuffer: true });
  const camera = new THREE.PerspectiveCamera(30, canvas.width / canvas.height, 1e-4, 100);
  const reach = Math.max(size.x, size.y / (canvas.height / canvas.width)) / 2 / Math.tan(THREE.MathUtils.degToRad(15) * canvas.width / canvas.height);
  camera.position.set(centre.x, centre.y, centre.z + 1.2 * Math.max(reach, size.y / 2 / Math.tan(THREE.MathUtils.degToRad(15))) / zoom);
  camera.lookAt(centre);
  const gl = renderer.getContext();
  const t1 = performance.now();
  renderer.render(scene, camera);
  const pixels = new Uint8Array(4 * canvas.width * canvas.height);
  gl.readPixels(0, 0, canvas.width, canvas.height, gl.RGBA, gl.UNSIGNED_BYTE, pixels);  // waits for the frame
  const drawn = performance.now() - t1;
  // The same frame again: what each frame of a turning view costs, the first frame's
  // one-time work (compiling the shaders, uploading the buffers) done.
  const t2 = performance.now();
  renderer.render(scene, camera);
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
  const redrawn = performance.now() - t2;
  // The fabric's share of the frame: pixels that are not the white background.
  const seen = measure(pixels, canvas.width, canvas.height);
  const image = canvas.toDataURL('image/png');
  const report = { load_ms: loaded, frame_ms: drawn, next_frame_ms: redrawn, meshes, instanced_meshes: instanced, instances, triangles,
                   min: box.min.toArray(), max: box.max.toArray(), fabric_share: seen.fabric / (canvas.width * canvas.height),
                   webgl: gl.getParameter(gl.VERSION), image };
  if (maps) {
    // What the loader made of each material's maps, then the same frame without them.
    const materials = new Map();
    gltf.scene.traverse((o) => { if (o.isMesh) materials.set(o.material.uuid, o.material); });
    const size = (t) => (t && t.image ? [t.image.width, t.image.height] : null);
    report.materials = [...materials.values()].map((m) => ({
      name: m.name, normal: size(m.normalMap), occlusion: size(m.aoMap), colour: size(m.map),
      repeat: m.normalMap ? m.normalMap.repeat.toArray() : null, tangents: false }));
    gltf.scene.traverse((o) => { if (o.isMesh) report.materials.forEach((r) => { if (r.name === o.material.name) r.tangents = Boolean(o.geometry.attributes.tangent); }); });
    report.detail = seen.detail;
    // The frame's colours: the share of fabric pixels clearly red, green or blue.
    const hue = (px) => {
      const share = [0, 0, 0];
      let n = 0;
      for (let i = 0; i < px.length; i += 4) {
        if (!(px[i] < 245 || px[i + 1] < 245 || px[i + 2] < 245)) continue;
        n += 1;
        for (let c = 0; c < 3; ++c) if (px[i + c] > px[i + (c + 1) % 3] + 40 && px[i + c] > px[i + (c + 2) % 3] + 40) share[c] += 1;
      }
      return share.map((k) => k / Math.max(1, n));
    };
    report.hues = hue(pixels);
    for (const m of materials.values()) { m.normalMap = null; m.aoMap = null; m.map = null; m.needsUpdate = true; }
    renderer.render(scene, camera);
    const bare = new Uint8Array(pixels.length);
    gl.readPixels(0, 0, canvas.width, canvas.height, gl.RGBA, gl.UNSIGNED_BYTE, bare);
    report.detail_without_maps = measure(bare, canvas.width, canvas.height).detail;
    report.hues_without_maps = hue(bare);
    let changed = 0;
    for (let i = 0; i < pixels.length; i += 4)
      if (Math.abs(pixels[i] - bare[i]) + Math.abs(pixels[i + 1] - bare[i + 1]) + Math.abs(pixels[i + 2] - bare[i + 2]) > 24) changed += 1;
    report.changed_share = changed / (canvas.width * canvas.height);
    // The pixel at the middle of the frame, with and without the maps.
    const mid = 4 * ((canvas.height >> 1) * canvas.width + (canvas.width >> 1));
    report.middle_pixel = [...pixels.slice(mid, mid + 3)];
    report.middle_pixel_without_maps = [...bare.slice(mid, mid + 3)];
  }
  renderer.dispose();
  return report;
};
window.ready = true;
</script></body></html>`;

const server = createServer(async (req, res) => {
  const path = new URL(req.url, 'http://127.0.0.1').pathname;
  try {
    if (path === '/') {
      res.writeHead(200, { 'content-type': 'text/html' }).end(page);
    } else if (path.startsWith('/jsm/') && path.endsWith('.js')) {
      // three.js's addons (the loader and what it imports), from their folder only.
      const root = join(three, 'examples', 'jsm');
      const file = resolve(root, '.' + decodeURIComponent(path.slice(4)));
      if (!file.startsWith(root + sep)) throw new Error('outside');
      const body = await readFile(file);  // read first: a missing file is a 404, not a second header
      res.writeHead(200, { 'content-type': 'text/javascript' }).end(body);
    } else if (assets.has(path)) {
      const type = path.endsWith('.js') ? 'text/javascript' : 'model/gltf-binary';
      const body = await readFile(assets.get(path));
      res.writeHead(200, { 'content-type': type }).end(body);
    } else {
      res.writeHead(404).end();
    }
  } catch {
    res.writeHead(404).end();
  }
});
await new Promise((ok) => server.listen(0, '127.0.0.1', ok));
const origin = `http://127.0.0.1:${server.address().port}`;
const profile = await mkdtemp(join(tmpdir(), 'knitc-chromium-'));
const browser = await puppeteer.launch({
  executablePath: process.env.CHROMIUM || '/usr/bin/chromium',
  headless: true,
  userDataDir: profile,
  args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
         '--disable-component-update', '--disable-sync', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
         '--ignore-gpu-blocklist'],
});
let failed = false;
try {
  const tab = await browser.newPage();
  tab.setDefaultTimeout(600000);
  const problems = [];
  tab.on('console', (m) => { if (m.type() === 'error') problems.push(m.text()); });
  tab.on('pageerror', (e) => problems.push(String(e)));
  await tab.goto(origin + '/');
  await tab.waitForFunction('window.ready === true', { timeout: 30000 }).catch((e) => {
    throw new Error(`the page did not start: ${problems.join('; ') || e}`);
  });
  for (let i = 0; i < args.length; ++i) {
    try {
      const r = await tab.evaluate((url, z, m) => window.show(url, z, m), `/file${i}.glb`, zoom, maps);
      if (pngDir) await writeFile(join(pngDir, basename(args[i]).replace(/\.glb$/, '') + '.browser.png'), Buffer.from(r.image.split(',')[1], 'base64'));
      delete r.image;
      console.log(JSON.stringify({ file: args[i], ...r }));
    } catch (e) {
      failed = true;
      console.log(JSON.stringify({ file: args[i], error: String(e) }));
    }
  }
} finally {
  await browser.close();
  server.close();
  await rm(profile, { recursive: true, force: true });
}
process.exit(failed ? 1 : 0);
