// The baked textures as a browser client sees them: a jersey swatch and a red and blue
// heather, built by knitc (textures are on by default), opened by three.js's GLTFLoader in
// headless Chromium (tools/browser/show.mjs) and drawn close up, then drawn again with the
// maps taken off. Checks that the loader made all three maps of each material, with the
// tangents, and that the maps show: the plies' relief adds detail to the frame, and the
// heather's red and blue fibres, which only the colour map carries, appear in its pixels.
// Usage: node textures.mjs KNITC SOURCE_DIR OUT_DIR
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

const files = [
  { name: 'jersey', pattern: 'patterns/jersey.lua', glb: join(out, 'textured_jersey.glb') },
  { name: 'heather', pattern: 'tests/yarn/heather_swatch.lua', glb: join(out, 'textured_heather.glb') },
];
for (const f of files) {
  const r = spawnSync(knitc, ['build', join(source, f.pattern), '-o', f.glb, '-q'], { encoding: 'utf8' });
  if (r.status !== 0) throw new Error(`knitc build ${f.pattern}: ${r.stderr}`);
}
const shown = spawnSync('node', [join(source, 'tools/browser/show.mjs'), '--png', out, '--zoom', '4', '--maps',
                                 ...files.map((f) => f.glb)], { encoding: 'utf8' });
if (shown.status !== 0) {
  console.log(shown.stdout, shown.stderr);
  process.exit(1);
}
const [jersey, heather] = shown.stdout.trim().split('\n').map((line) => JSON.parse(line));
for (const [f, r] of [[files[0], jersey], [files[1], heather]]) {
  for (const m of r.materials) {
    const all = [m.normal, m.occlusion, m.colour].every((size) => size && size[0] === 256 && size[1] === 256);
    check(all, `${f.name}: material ${m.name} has its normal, occlusion and colour maps, 256 x 256`);
    check(m.tangents, `${f.name}: material ${m.name}'s primitive has its tangents`);
    check(m.repeat && m.repeat[0] > 0.05 && m.repeat[0] < 1 && m.repeat[1] === 1,
          `${f.name}: the maps repeat every ${(1 / m.repeat[0]).toFixed(2)} mm of yarn and once round it`);
  }
  console.log(`${f.name}: detail ${r.detail.toFixed(2)} with the maps, ${r.detail_without_maps.toFixed(2)} without; ` +
              `${(100 * r.changed_share).toFixed(0)}% of the frame changed; middle pixel ${r.middle_pixel} against ` +
              `${r.middle_pixel_without_maps}`);
  check(r.changed_share > 0.2, `${f.name}: the maps change ${(100 * r.changed_share).toFixed(0)}% of the frame`);
}
// The plies' relief and the fibres' ridges: a plain yarn's frame has more detail with its maps.
check(jersey.detail > 1.2 * jersey.detail_without_maps, 'jersey: the normal and occlusion maps add detail to the frame');
// The heather's colours are in its colour map alone: without it the frame has no red or blue.
const [red, , blue] = heather.hues, [red0, , blue0] = heather.hues_without_maps;
console.log(`heather: ${(100 * red).toFixed(0)}% red and ${(100 * blue).toFixed(0)}% blue pixels with the maps, ` +
            `${(100 * red0).toFixed(0)}% and ${(100 * blue0).toFixed(0)}% without`);
check(red > 0.1 && blue > 0.1, 'heather: red and blue fibres show where the colour map is drawn');
check(red0 < 0.01 && blue0 < 0.01, 'heather: none show without it');
// A fibre's colour, lit or in shade: saturated (a grey's channels are near equal), and not
// black.
const [r, g, b] = heather.middle_pixel;
const top = Math.max(r, g, b);
check(top >= 30 && (top - Math.min(r, g, b)) / top > 0.5,
      `heather: the pixel at the frame's middle, ${heather.middle_pixel}, is a fibre's colour`);
process.exit(failures === 0 ? 0 : 1);
