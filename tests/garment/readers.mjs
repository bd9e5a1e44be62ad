// The files knitc writes, opened by a browser client: the instanced sweater front and a
// flat swatch, each built by knitc and loaded with three.js's GLTFLoader in headless
// Chromium (tools/browser/show.mjs). Checks each scene's instances and box against what
// knitc said it wrote (--stats), and that a frame drawn of it shows fabric.
// Usage: node readers.mjs KNITC SOURCE_DIR OUT_DIR
import { spawnSync } from 'node:child_process';
import { join } from 'node:path';
import { mkdirSync } from 'node:fs';

const [knitc, source, out] = process.argv.slice(2);
mkdirSync(out, { recursive: true });
let failures = 0;
const check = (ok, what) => {
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`);
  if (!ok) failures += 1;
};

function build(pattern, glb) {
  const r = spawnSync(knitc, ['build', join(source, pattern), '-o', glb, '--stats'], { encoding: 'utf8' });
  if (r.status !== 0) throw new Error(`knitc build ${pattern}: ${r.stderr}`);
  const stats = r.stderr;
  const bounds = stats.match(/^bounds mm +\[([^\]]+)\] \.\. \[([^\]]+)\]/m);
  const placed = stats.match(/placed (\d+) times/);
  return {
    min: bounds[1].split(',').map(Number), max: bounds[2].split(',').map(Number),
    instances: placed ? Number(placed[1]) : 0, mesh: stats.match(/^mesh +(.*)$/m)[1],
  };
}

const files = [
  { name: 'sweater front', pattern: 'tests/garment/sweater_front.lua', glb: join(out, 'sweater_front.glb'), instanced: true },
  { name: 'swatch', pattern: 'patterns/jersey.lua', glb: join(out, 'jersey_swatch.glb'), instanced: false },
];
for (const f of files) {
  f.knitc = build(f.pattern, f.glb);
  console.log(`${f.name}: ${f.knitc.mesh}`);
}
const shown = spawnSync('node', [join(source, 'tools/browser/show.mjs'), '--png', out, ...files.map((f) => f.glb)], { encoding: 'utf8' });
if (shown.status !== 0) {
  console.log(shown.stdout, shown.stderr);
  process.exit(1);
}
const results = shown.stdout.trim().split('\n').map((line) => JSON.parse(line));
files.forEach((f, i) => {
  const r = results[i];
  console.log(`${f.name}: loaded in ${r.load_ms.toFixed(0)} ms, first frame in ${r.frame_ms.toFixed(0)} ms, next in ${r.next_frame_ms.toFixed(0)} ms, ` +
              `${r.triangles} triangles drawn, ${r.instances} instances (${r.webgl})`);
  check(f.instanced === f.knitc.mesh.startsWith('instanced'), `${f.name}: knitc chose ${f.instanced ? 'instanced' : 'flat'}`);
  // An instanced file's edges are one instance of their own mesh (one shader program for
  // the whole fabric): the tile's placements and that one.
  check(r.instanced_meshes === (f.instanced ? 2 : 0), `${f.name}: ${r.instanced_meshes} instanced meshes`);
  const written = f.knitc.instances + (f.instanced ? 1 : 0);
  check(r.instances === written, `${f.name}: ${r.instances} instances in the scene, ${written} written`);
  // The scene's box is the fabric's (metres in glTF, mm in knitc), to a tenth of a mm.
  const off = Math.max(...[0, 1, 2].flatMap((k) => [Math.abs(r.min[k] * 1000 - f.knitc.min[k]), Math.abs(r.max[k] * 1000 - f.knitc.max[k])]));
  check(off < 0.1, `${f.name}: the scene's box is knitc's within ${off.toFixed(4)} mm`);
  check(r.fabric_share > 0.2, `${f.name}: fabric covers ${(100 * r.fabric_share).toFixed(0)}% of the frame`);
});
process.exit(failures === 0 ? 0 : 1);
