// Shenlong's editor: draws the scene with three.js and edits it through the JSON API.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/OrbitControls.js';
import { VRButton } from 'three/addons/VRButton.js';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';

const view = document.getElementById('view');
const status = document.getElementById('status');
const tooltip = document.getElementById('tooltip');
const $ = (id) => document.getElementById(id);

const COLOURS = { floor: 0x9bb8de, resting: 0xf2b880, edited: 0x5cc46f };
const ANIMATION_MS = 600;

const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setPixelRatio(window.devicePixelRatio);
renderer.xr.enabled = true;
view.appendChild(renderer.domElement);
// "Enter VR" only where the browser can actually start an immersive session.
if (navigator.xr) {
  navigator.xr.isSessionSupported('immersive-vr').then((supported) => {
    if (!supported) return;
    const button = VRButton.createButton(renderer);
    button.id = 'vr-button';
    view.appendChild(button);
  }).catch(() => {});
}

const world = new THREE.Scene();
world.background = new THREE.Color(0xeef1f5);
world.add(new THREE.HemisphereLight(0xffffff, 0x8890a0, 2.2));
const sun = new THREE.DirectionalLight(0xffffff, 1.4);
sun.position.set(4, 8, 6);
world.add(sun);

const perspective = new THREE.PerspectiveCamera(50, 1, 0.01, 500);
const orthographic = new THREE.OrthographicCamera(-5, 5, 5, -5, 0.01, 500);
let camera = perspective;
const controls = new OrbitControls(perspective, renderer.domElement);
controls.enableDamping = true;

const objects = new Map(); // name → { mesh, edges, data }
let roomLines = null;
let extent = new THREE.Box3(new THREE.Vector3(-3, 0, -3), new THREE.Vector3(3, 2, 3));
const animations = [];
const edited = new Set();

function resize() {
  const { clientWidth: w, clientHeight: h } = view;
  renderer.setSize(w, h);
  perspective.aspect = w / h;
  perspective.updateProjectionMatrix();
  const size = extent.getSize(new THREE.Vector3());
  const half = Math.max(size.x, size.z * (w / h)) * 0.6 + 0.5;
  orthographic.left = -half; orthographic.right = half;
  orthographic.top = half * h / w; orthographic.bottom = -half * h / w;
  orthographic.updateProjectionMatrix();
}
window.addEventListener('resize', resize);

function say(text, kind = '') {
  status.textContent = text;
  status.className = kind;
}

async function api(path, body) {
  const response = await fetch(path, body === undefined ? {} : {
    method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify(body),
  });
  const data = await response.json().catch(() => ({ error: `HTTP ${response.status}` }));
  if (!response.ok) throw new Error(data.error || `HTTP ${response.status}`);
  return data;
}

// The pose of an object: its pivot (bottom centre) at `position`, turned and scaled.
function pose(data) {
  const [x, y, z] = data.position;
  const q = data.rotation || [0, 0, 0, 1];
  const s = data.scale ?? 1;
  return { position: new THREE.Vector3(x, y, z), quaternion: new THREE.Quaternion(q[0], q[1], q[2], q[3]), scale: s };
}

function colourOf(data) {
  if (edited.has(data.name)) return COLOURS.edited;
  return data.resting_on ? COLOURS.resting : COLOURS.floor;
}

function place(entry, p) {
  const [w, h, d] = entry.data.size;
  entry.group.position.copy(p.position);
  entry.group.quaternion.copy(p.quaternion);
  entry.group.scale.setScalar(p.scale);
  entry.mesh.scale.set(w, h, d);
  entry.edges.scale.set(w, h, d);
  // The front: a tick out of the face the object faces (its `front`, local +Z unless the
  // scene says otherwise).
  const f = new THREE.Vector3(...(entry.data.front || [0, 0, 1])).normalize();
  const reach = new THREE.Vector3(f.x * w, f.y * h, f.z * d).length() / 2;
  const out = reach + Math.max(0.12, 0.35 * reach);
  entry.front.geometry.setFromPoints([
    new THREE.Vector3(f.x * reach, h / 2 + f.y * reach, f.z * reach),
    new THREE.Vector3(f.x * out, h / 2 + f.y * out, f.z * out),
  ]);
}

function build(scene, animate) {
  $('scene-name').textContent = scene.name || '';
  const seen = new Set();
  for (const data of scene.objects) {
    seen.add(data.name);
    let entry = objects.get(data.name);
    const target = pose(data);
    if (!entry) {
      const geometry = new THREE.BoxGeometry(1, 1, 1).translate(0, 0.5, 0);
      const mesh = new THREE.Mesh(geometry, new THREE.MeshStandardMaterial({ color: colourOf(data), roughness: 0.8, transparent: true, opacity: 0.92 }));
      const edges = new THREE.LineSegments(new THREE.EdgesGeometry(geometry), new THREE.LineBasicMaterial({ color: 0x2d3a4d }));
      const front = new THREE.Line(new THREE.BufferGeometry(), new THREE.LineBasicMaterial({ color: 0xc0392b }));
      const group = new THREE.Group();
      group.add(mesh, edges, front);
      mesh.userData.name = data.name;
      world.add(group);
      entry = { group, mesh, edges, front, data };
      objects.set(data.name, entry);
      place(entry, target);
      continue;
    }
    const from = { position: entry.group.position.clone(), quaternion: entry.group.quaternion.clone(), scale: entry.group.scale.x };
    entry.data = data;
    entry.mesh.material.color.setHex(colourOf(data));
    if (animate) {
      animations.push({ entry, from, to: target, start: performance.now() });
    } else {
      place(entry, target);
    }
  }
  for (const [name, entry] of objects) {
    if (!seen.has(name)) { world.remove(entry.group); objects.delete(name); }
  }
  drawRoom(scene);
}

function drawRoom(scene) {
  if (roomLines) world.remove(roomLines);
  const box = new THREE.Box3();
  if (scene.bounds) {
    box.set(new THREE.Vector3(...scene.bounds.min), new THREE.Vector3(...scene.bounds.max));
  } else {
    for (const { group } of objects.values()) box.expandByObject(group);
    if (box.isEmpty()) box.set(new THREE.Vector3(-1, 0, -1), new THREE.Vector3(1, 1, 1));
  }
  extent = box.clone();
  roomLines = new THREE.Group();
  if (scene.bounds) {
    const outline = new THREE.Box3Helper(box, 0x55606e);
    roomLines.add(outline);
  }
  const size = box.getSize(new THREE.Vector3());
  const grid = new THREE.GridHelper(Math.ceil(Math.max(size.x, size.z)) + 2, Math.ceil(Math.max(size.x, size.z)) + 2, 0xb0b8c4, 0xd0d6de);
  grid.position.set(box.getCenter(new THREE.Vector3()).x, box.min.y + 0.001, box.getCenter(new THREE.Vector3()).z);
  roomLines.add(grid);
  world.add(roomLines);
}

function frameCamera() {
  const centre = extent.getCenter(new THREE.Vector3());
  const size = extent.getSize(new THREE.Vector3());
  const r = Math.max(size.x, size.z, 2);
  perspective.position.set(centre.x + r * 0.55, centre.y + r * 0.75, centre.z + r * 0.95);
  controls.target.copy(centre);
  orthographic.position.set(centre.x, centre.y + r * 3, centre.z);
  orthographic.up.set(0, 0, -1);
  orthographic.lookAt(centre);
  resize();
}

function tick(now) {
  for (let i = animations.length - 1; i >= 0; i--) {
    const a = animations[i];
    const t = Math.min(1, (now - a.start) / ANIMATION_MS);
    const k = t * t * (3 - 2 * t);
    place(a.entry, {
      position: a.from.position.clone().lerp(a.to.position, k),
      quaternion: a.from.quaternion.clone().slerp(a.to.quaternion, k),
      scale: a.from.scale + (a.to.scale - a.from.scale) * k,
    });
    if (t >= 1) animations.splice(i, 1);
  }
  controls.update();
  renderer.render(world, camera);
}
renderer.setAnimationLoop(tick);

// Hover: names. Click: insert the quoted name into the instruction.
const raycaster = new THREE.Raycaster();
const pointer = new THREE.Vector2();
function pick(event) {
  const rect = renderer.domElement.getBoundingClientRect();
  pointer.set(((event.clientX - rect.left) / rect.width) * 2 - 1, -((event.clientY - rect.top) / rect.height) * 2 + 1);
  raycaster.setFromCamera(pointer, camera);
  const hit = raycaster.intersectObjects([...objects.values()].map((e) => e.mesh))[0];
  return hit ? hit.object.userData.name : null;
}
renderer.domElement.addEventListener('pointermove', (event) => {
  const name = pick(event);
  tooltip.hidden = !name;
  if (name) {
    tooltip.textContent = name;
    tooltip.style.left = `${event.clientX + 12}px`;
    tooltip.style.top = `${event.clientY + 12}px`;
  }
});
renderer.domElement.addEventListener('click', (event) => {
  const name = pick(event);
  if (!name) return;
  const box = $('instruction');
  const text = `'${name}'`;
  const at = box.selectionStart ?? box.value.length;
  box.value = box.value.slice(0, at) + text + box.value.slice(box.selectionEnd ?? at);
  box.focus();
  box.selectionStart = box.selectionEnd = at + text.length;
});

function escape(text) {
  return String(text).replace(/[&<>"']/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&#39;' }[c]));
}

function showReport(r) {
  const fmt = (v) => v.map((x) => Number(x).toFixed(3)).join(', ');
  const objectsHtml = r.objects.map((o) => `<dd><b>${escape(o.variable)}</b> ${escape(o.object)}: ${o.expressions.map((e) => `<code>${escape(e)}</code>`).join(' then ')}<br>
    move [${fmt(o.translation)}] · turn ${o.rotation_degrees.toFixed(1)}° · scale ${o.scale.toFixed(3)}</dd>`).join('');
  const collisions = r.collisions_resolved.length
    ? r.collisions_resolved.map((c) => `<dd>${escape(c.object)} moved [${fmt(c.displacement)}] to clear ${escape(c.collided_with.join(', '))}</dd>`).join('')
    : '<dd>none</dd>';
  const grounding = (r.grounding || []).map((g) => `<dd class="grounding">“${escape(g.phrase)}” → <b>${escape(g.variables.join(', '))}</b> ${escape(g.objects.join(', '))}<br>
    <span class="why">${g.reasons.map((why) => `${escape(why.kind)}: ${escape(why.detail)}`).join(' · ')}</span></dd>`).join('') || '<dd>none</dd>';
  $('report').innerHTML = `<dl>
    <dt>Grounding</dt>${grounding}
    <dt>Query</dt><dd><code>${escape(r.query)}</code></dd>
    <dt>Objects</dt>${objectsHtml}
    <dt>Collisions resolved</dt>${collisions}
    <dt>Model</dt><dd>${escape(r.model)} · answered by ${escape(r.answered_by || r.model)} · ${escape(r.system)} (${escape(r.prompt_version)}) · ${r.retries} retries${r.cache_hit ? ' · cached' : ''}${r.offline_refusal ? `<br><span class="why">offline: ${escape(r.offline_refusal)}</span>` : ''}</dd>
    <dt>Timings</dt><dd>translate ${r.timings_ms.translate.toFixed(2)} ms · total ${r.timings_ms.total.toFixed(2)} ms</dd>
  </dl>`;
}

async function refreshHistory() {
  const { history } = await api('/api/history');
  $('history').innerHTML = history.map((h) => `<li class="${h.undone ? 'undone' : ''}"><code>${escape(h.text)}</code> — ${escape(h.objects.join(', ') || 'nothing moved')}</li>`).join('');
}

function setUndoRedo(data) {
  $('undo').disabled = !data.can_undo;
  $('redo').disabled = !data.can_redo;
}

// A glTF scene is drawn with its own meshes; the boxes stay as outlines to pick by.
let model = null;
async function loadModel(url) {
  const response = await fetch(url);
  if (!response.ok) return;
  const gltf = await new GLTFLoader().parseAsync(await response.arrayBuffer(), '');
  if (model) world.remove(model);
  model = gltf.scene;
  world.add(model);
  for (const { mesh, edges } of objects.values()) {
    mesh.material.visible = false;
    edges.material.opacity = 0.35;
    edges.material.transparent = true;
  }
}

async function load(animate) {
  const data = await api('/api/scene');
  build(data.scene, animate);
  setUndoRedo(data);
  if (data.model) await loadModel(data.model);
  return data;
}

$('form').addEventListener('submit', async (event) => {
  event.preventDefault();
  const instruction = $('instruction').value.trim();
  if (!instruction) { say('Type an instruction first.', 'error'); return; }
  $('run').disabled = true;
  say('Editing…', 'busy');
  try {
    const report = await api('/api/edit', { instruction, llm: $('llm').value.trim() || undefined, system: $('system').value });
    edited.clear();
    for (const o of report.objects) edited.add(o.object);
    for (const name of report.carried) edited.add(name);
    showReport(report);
    window.shenlong.lastReport = report;
    await load(true);
    await refreshHistory();
    if (report.warning) say(`Done, but ${report.warning}`, 'error');
    else say(`Done: ${report.objects.map((o) => o.object).join(', ')}`);
  } catch (error) {
    say(error.message, 'error');
  } finally {
    $('run').disabled = false;
  }
});

for (const [id, path, verb] of [['undo', '/api/undo', 'Undone'], ['redo', '/api/redo', 'Redone']]) {
  $(id).addEventListener('click', async () => {
    try {
      const data = await api(path, {});
      build(data.scene, true);
      setUndoRedo(data);
      await refreshHistory();
      say(verb);
    } catch (error) {
      say(error.message, 'error');
    }
  });
}

$('topdown').addEventListener('click', () => {
  const top = camera === perspective;
  camera = top ? orthographic : perspective;
  controls.enabled = !top;
  $('topdown').setAttribute('aria-pressed', String(top));
});

window.shenlong = {
  ready: false,
  lastReport: null,
  // How many meshes are drawn (for tests): boxes, or a glTF model's meshes as well.
  meshes: () => { let n = 0; world.traverse((o) => { if (o.isMesh) n += 1; }); return n; },
};
try {
  await load(false);
  frameCamera();
  await refreshHistory();
  window.shenlong.ready = true;
} catch (error) {
  say(`Cannot load the scene: ${error.message}`, 'error');
}
