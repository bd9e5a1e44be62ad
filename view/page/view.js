// knitc view's page: the fabric in 3D (three.js), its chart, and what links them. It
// polls the server for a new build, loads the fabric when there is one (keeping the
// camera), and shows a failed build's message over the last fabric that worked.
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { MeshoptDecoder } from 'three/addons/libs/meshopt_decoder.module.js';

const holder = document.getElementById('fabric');
const errorBox = document.getElementById('error');
const pickedBox = document.getElementById('picked');
const figuresBox = document.getElementById('figures');
const chart = document.getElementById('chart');

const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio);
holder.prepend(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0xf4f1ec);
const camera = new THREE.PerspectiveCamera(35, 1, 0.1, 100000);
camera.up.set(0, 1, 0);
const controls = new OrbitControls(camera, renderer.domElement);
controls.enableDamping = false;
controls.addEventListener('change', () => draw());
// A soft sky and a raking key light, low across the fabric, so the loops' relief shows.
scene.add(new THREE.HemisphereLight(0xffffff, 0x8a8278, 1.4));
const key = new THREE.DirectionalLight(0xffffff, 2.2);
scene.add(key);
scene.add(key.target);

const loader = new GLTFLoader();
loader.setMeshoptDecoder(MeshoptDecoder);

// The page's state, also read by the tests.
const view = {
  version: 0,          // the server's last build
  fabricVersion: 0,    // the build whose fabric is on screen
  error: '',
  info: null,          // the fabric's loops, chart and figures (/fabric.json)
  fabric: null,        // the scene's group
  box: null,
  picked: null,        // {loops: [...], row, cell}
};
window.knitcView = view;

function resize() {
  const w = holder.clientWidth, h = holder.clientHeight;
  renderer.setSize(w, h, false);
  camera.aspect = w / Math.max(h, 1);
  camera.updateProjectionMatrix();
  draw();
}
window.addEventListener('resize', resize);

// At most one frame is drawn per display frame. Software GL (SwiftShader) takes a good
// part of a second to draw a swatch with its maps, so a frame already asked for by rAF is
// dropped when one is drawn now: otherwise an edit would be drawn twice.
let pending = 0;  // the requestAnimationFrame id of the frame asked for, or 0
function draw() {
  if (pending) return;
  pending = requestAnimationFrame(() => {
    pending = 0;
    renderer.render(scene, camera);
  });
}
view.drawNow = () => {
  if (pending) cancelAnimationFrame(pending);
  pending = 0;
  renderer.render(scene, camera);
};
view.camera = () => ({ position: camera.position.toArray(), target: controls.target.toArray() });

// The three standard views: the face (+z), the back (-z), edge-on (along x, a little above).
function look(which) {
  if (!view.box) return;
  const centre = view.box.getCenter(new THREE.Vector3());
  const size = view.box.getSize(new THREE.Vector3());
  const reach = Math.max(size.x, size.y) / (2 * Math.tan(THREE.MathUtils.degToRad(camera.fov) / 2)) * 1.15 + size.z;
  const way = which === 'back' ? new THREE.Vector3(0, 0, -1) : which === 'edge' ? new THREE.Vector3(1, 0.15, 0.02) : new THREE.Vector3(0, 0, 1);
  camera.position.copy(centre).addScaledVector(way.normalize(), reach);
  controls.target.copy(centre);
  controls.update();
  key.position.copy(centre).add(new THREE.Vector3(-reach, reach * 0.6, way.z >= 0 ? reach * 0.35 : -reach * 0.35));
  key.target.position.copy(centre);
  draw();
}
for (const b of document.querySelectorAll('#views button')) b.addEventListener('click', () => look(b.dataset.view));
view.look = look;

async function loadFabric(version) {
  const [gltf, info] = await Promise.all([
    loader.loadAsync(`/fabric.glb?v=${version}`),
    fetch(`/fabric.json?v=${version}`).then((r) => r.json()),
  ]);
  show(gltf, info, version);
}

function show(gltf, info, version) {
  const first = view.fabric === null;
  const old = view.fabric;
  if (old) scene.remove(old);
  // glTF is in metres; the page works in the fabric's millimetres, as its loops are given.
  view.fabric = new THREE.Group();
  view.fabric.scale.setScalar(1000);
  view.fabric.add(gltf.scene);
  scene.add(view.fabric);
  view.fabric.updateMatrixWorld(true);
  view.box = new THREE.Box3().setFromObject(view.fabric);
  triangles = 0;
  view.fabric.traverse((o) => {
    if (o.isMesh && o.geometry.index) triangles += (o.geometry.index.count / 3) * (o.isInstancedMesh ? o.count : 1);
  });
  view.info = info;
  showFigures(info);
  drawChart(info);
  highlight(null);
  if (first) look('face');  // later builds keep the camera where the designer left it
  camera.updateMatrixWorld();
  view.drawNow();
  // The old fabric's geometry, materials and maps leave the GPU only now: the new materials
  // have taken the same shader programs first, so they are not compiled again.
  if (old) {
    old.traverse((o) => {
      if (o.geometry) o.geometry.dispose();
      if (o.material) {
        for (const map of ['map', 'normalMap', 'aoMap']) if (o.material[map]) o.material[map].dispose();
        o.material.dispose();
      }
    });
  }
  view.fabricVersion = version;
}

function showFigures(info) {
  const f = info.figures;
  document.getElementById('title').textContent = info.pattern;
  const yarns = f.yarns.map((y) => `<span style="color:${y.color}">■</span> ${y.id}: ${y.metres.toFixed(1)} m, ${y.grams.toFixed(1)} g`).join(', ');
  figuresBox.innerHTML = `${f.width_cm.toFixed(1)} × ${f.height_cm.toFixed(1)} cm · ` +
    `${f.stitches_per_10cm.toFixed(1)} sts and ${f.rows_per_10cm.toFixed(1)} rows per 10 cm · ${f.loops} loops<br>${yarns}`;
  figuresBox.classList.remove('muted');
}

// The chart: row 1 at the bottom, as knitc chart prints it; each stitch a cell as wide as
// it works, its symbol in it.
const cellPx = 16;
const numberPx = 3 * cellPx;  // room for a row's number on either side
let chartCells = [];  // {x, y, w, row, cell}
let rowRight = [];    // per row: where its last cell ends
function drawChart(info) {
  const rows = info.rows;
  const widest = Math.max(1, ...rows.map((r) => r.cells.reduce((n, c) => n + c.width, 0)));
  chart.width = widest * cellPx + 2 * numberPx;
  chart.height = rows.length * cellPx + 4;
  chartCells = [];
  rowRight = [];
  rows.forEach((r, i) => {
    const y = (rows.length - 1 - i) * cellPx + 2;
    let x = 0;
    r.cells.forEach((c, k) => {
      chartCells.push({ x: numberPx + x * cellPx, y, w: c.width * cellPx, row: i, cell: k });
      x += c.width;
    });
    rowRight.push(numberPx + x * cellPx);
  });
  paintChart();
}
function paintChart() {
  const g = chart.getContext('2d');
  const rows = view.info ? view.info.rows : [];
  g.clearRect(0, 0, chart.width, chart.height);
  g.font = `${cellPx - 5}px ui-monospace, monospace`;
  g.textAlign = 'center';
  g.textBaseline = 'middle';
  for (const c of chartCells) {
    const cell = rows[c.row].cells[c.cell];
    const on = view.picked && view.picked.row === c.row + 1 && view.picked.cell === c.cell;
    g.fillStyle = on ? '#ffcf33' : '#fff';
    g.fillRect(c.x, c.y, c.w, cellPx);
    g.strokeStyle = '#ccc';
    g.strokeRect(c.x + 0.5, c.y + 0.5, c.w - 1, cellPx - 1);
    g.fillStyle = '#222';
    g.fillText(cell.symbol.replace(/-+$/, ''), c.x + c.w / 2, c.y + cellPx / 2 + 1);
  }
  // Each row's number on the side it is read from, as knitc chart prints it: right-side
  // rows on the right, wrong-side rows on the left.
  g.fillStyle = '#888';
  rows.forEach((r, i) => {
    const y = (rows.length - 1 - i) * cellPx + 2 + cellPx / 2 + 1;
    const wrong = r.side === 'wrong';
    g.textAlign = wrong ? 'right' : 'left';
    g.fillText(String(r.row), wrong ? numberPx - 4 : rowRight[i] + 4, y);
  });
}
view.chartCellAt = (row, cell) => chartCells.find((c) => c.row === row - 1 && c.cell === cell);

// What a loop is, in the knitter's words: its row and stitch, the stitch's name, the yarn
// and the script line that made it.
function describe(loopIndex) {
  const loop = view.info.loops[loopIndex];
  if (!loop || loop.length < 2) return null;
  const [course, cellIndex] = loop;
  if (course === 0) return { row: 0, cell: cellIndex, text: 'the cast-on', loops: [loopIndex] };
  const row = view.info.rows[course - 1];
  if (!row || cellIndex < 0) return { row: course, cell: -1, text: `row ${course}`, loops: [loopIndex] };
  const cell = row.cells[cellIndex];
  const file = row.file.split('/').pop();
  return {
    row: course, cell: cellIndex, loops: cell.loops.length ? cell.loops : [loopIndex],
    text: `row ${course}, stitch ${cellIndex + 1}: ${cell.name} (${cell.abbreviation}), yarn ${cell.yarn} · ${file}:${row.line}`,
    line: row.line, file: row.file,
  };
}

// The loops lit in 3D: their centrelines drawn over the fabric.
let lit = null;
function highlight(picked) {
  view.picked = picked;
  if (lit) {
    scene.remove(lit);
    lit.traverse((o) => { if (o.geometry) o.geometry.dispose(); });
    lit = null;
  }
  pickedBox.textContent = picked ? picked.text : 'Point at a loop, or at a chart cell.';
  pickedBox.classList.toggle('muted', !picked);
  if (picked && view.info) {
    // A thin tube along each loop's centreline, drawn over the yarns that hide it.
    lit = new THREE.Group();
    const material = new THREE.MeshBasicMaterial({ color: 0xff2a6d, depthTest: false });
    for (const l of picked.loops) {
      const loop = view.info.loops[l];
      const points = [];
      for (let k = 2; k + 2 < loop.length; k += 3) points.push(new THREE.Vector3(loop[k], loop[k + 1], loop[k + 2]));
      if (points.length < 2) continue;
      const tube = new THREE.Mesh(new THREE.TubeGeometry(new THREE.CatmullRomCurve3(points), 8 * points.length, 0.18, 6), material);
      tube.renderOrder = 10;
      lit.add(tube);
    }
    scene.add(lit);
  }
  if (view.info) paintChart();
  draw();
}
view.highlight = highlight;

// The loop nearest a point on the fabric (mm): the one with a centreline point closest.
function nearestLoop(p) {
  let best = -1, bestD = Infinity;
  view.info.loops.forEach((loop, i) => {
    for (let k = 2; k + 2 < loop.length; k += 3) {
      const d = (loop[k] - p.x) ** 2 + (loop[k + 1] - p.y) ** 2 + (loop[k + 2] - p.z) ** 2;
      if (d < bestD) { bestD = d; best = i; }
    }
  });
  return best;
}

const raycaster = new THREE.Raycaster();
// Points at the fabric at client pixel (x, y) of its canvas: names and lights the loop
// there. Returns what it named, or null.
view.pointAt = (x, y) => {
  if (!view.fabric || !view.info) return null;
  camera.updateMatrixWorld();
  const r = renderer.domElement.getBoundingClientRect();
  const ndc = new THREE.Vector2(((x - r.left) / r.width) * 2 - 1, -((y - r.top) / r.height) * 2 + 1);
  raycaster.setFromCamera(ndc, camera);
  const hit = raycaster.intersectObject(view.fabric, true)[0];
  if (!hit) { highlight(null); return null; }
  const picked = describe(nearestLoop(hit.point));
  highlight(picked);
  return picked;
};
// The pixel where a point `along` (0 to 1) a loop's centreline shows: for the tests.
view.screenOf = (loopIndex, along = 0.5) => {
  const loop = view.info.loops[loopIndex];
  const k = 2 + 3 * Math.round(along * ((loop.length - 2) / 3 - 1));
  camera.updateMatrixWorld();
  const p = new THREE.Vector3(loop[k], loop[k + 1], loop[k + 2]).project(camera);
  const r = renderer.domElement.getBoundingClientRect();
  return { x: r.left + (p.x + 1) / 2 * r.width, y: r.top + (1 - p.y) / 2 * r.height };
};
// A swatch answers the pointer as it moves; a garment (millions of triangles to cast a ray
// through) when it is clicked, so orbiting stays smooth.
let triangles = 0, pressedAt = null;
renderer.domElement.addEventListener('pointermove', (e) => {
  if (e.buttons === 0 && triangles < 400000) view.pointAt(e.clientX, e.clientY);
});
renderer.domElement.addEventListener('pointerdown', (e) => { pressedAt = [e.clientX, e.clientY]; });
renderer.domElement.addEventListener('pointerup', (e) => {
  if (pressedAt && Math.hypot(e.clientX - pressedAt[0], e.clientY - pressedAt[1]) < 4) view.pointAt(e.clientX, e.clientY);
  pressedAt = null;
});

chart.addEventListener('click', (e) => {
  const r = chart.getBoundingClientRect();
  const x = e.clientX - r.left, y = e.clientY - r.top;
  const c = chartCells.find((c) => x >= c.x && x < c.x + c.w && y >= c.y && y < c.y + cellPx);
  if (!c) return;
  const cell = view.info.rows[c.row].cells[c.cell];
  const picked = cell.loops.length ? describe(cell.loops[0]) : null;
  highlight(picked || { row: c.row + 1, cell: c.cell, loops: [], text: `row ${c.row + 1}, stitch ${c.cell + 1}: ${cell.name} (${cell.abbreviation}): no loop of its own` });
});

// Polls the server: a new fabric is loaded; a failed build's message is shown over the
// last fabric that worked.
async function poll() {
  try {
    const s = await (await fetch('/state', { cache: 'no-store' })).json();
    if (s.version !== view.version) {
      view.version = s.version;
      view.error = s.error;
      errorBox.textContent = s.error;
      errorBox.style.display = s.error ? 'block' : 'none';
    }
    if (s.fabric !== view.fabricVersion && s.fabric > 0) await loadFabric(s.fabric);
  } catch (e) {
    errorBox.textContent = `knitc view: ${e.message || e} (is knitc view still running?)`;
    errorBox.style.display = 'block';
  }
  setTimeout(poll, 100);
}
resize();
if (window.knitcStatic) {
  // A gallery page: its fabric came with it (base64), nothing to poll.
  const bytes = Uint8Array.from(atob(window.knitcStatic.glb), (c) => c.charCodeAt(0));
  loader.parseAsync(bytes.buffer, '').then((gltf) => show(gltf, window.knitcStatic.info, 1), (e) => {
    errorBox.textContent = `knitc gallery: ${e.message || e}`;
    errorBox.style.display = 'block';
  });
} else {
  poll();
}
