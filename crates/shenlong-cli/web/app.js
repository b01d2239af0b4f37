// Shenlong's editor: draws the scene with three.js and edits it through the JSON API.
//
// Every name from the scene reaches the page through `textContent` or a text node (the
// `h` helper below), never as markup: a name is data, whatever characters it holds.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/OrbitControls.js';
import { VRButton } from 'three/addons/VRButton.js';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';

const view = document.getElementById('view');
const status = document.getElementById('status');
const $ = (id) => document.getElementById(id);

const COLOURS = { floor: 0x9bb8de, resting: 0xf2b880, edited: 0x5cc46f, candidate: 0xa97fe0 };
const ANIMATION_MS = 600;
// The most candidates offered as buttons; the rest are named by typing.
const MAX_CHOICES = 24;

// An element with properties and children; strings become text nodes, never markup.
function h(tag, props = {}, ...children) {
  const element = document.createElement(tag);
  for (const [key, value] of Object.entries(props)) {
    if (key === 'class') element.className = value;
    else element[key] = value;
  }
  for (const child of children.flat(Infinity)) {
    if (child === null || child === undefined || child === false) continue;
    element.append(child instanceof Node ? child : document.createTextNode(String(child)));
  }
  return element;
}

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

const objects = new Map(); // name → { group, mesh, edges, front, data, row }
let roomLines = null;
let extent = new THREE.Box3(new THREE.Vector3(-3, 0, -3), new THREE.Vector3(3, 2, 3));
const animations = [];
const edited = new Set(); // moved by the last edit
const selected = new Set(); // clicked in the view or the list
const candidates = new Set(); // offered by the last refusal
let hovered = new Set(); // under the pointer, in the view or on anything linked to objects
let allNames = false; // the "Names" button
const ghosts = new THREE.Group(); // where the last edit's objects were
world.add(ghosts);

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

// A failed request: the API's one-line message, with the whole answer (`ambiguity`).
class ApiFailure extends Error {
  constructor(message, status, data) {
    super(message);
    this.status = status;
    this.data = data;
  }
}

async function api(path, body) {
  const response = await fetch(path, body === undefined ? {} : {
    method: 'POST', headers: { 'Content-Type': 'application/json' }, body: JSON.stringify(body),
  });
  const data = await response.json().catch(() => ({ error: `HTTP ${response.status}` }));
  if (!response.ok) throw new ApiFailure(data.error || `HTTP ${response.status}`, response.status, data);
  return data;
}

// The pose of an object: its pivot (bottom centre) at `position`, turned and scaled.
function pose(data) {
  const [x, y, z] = data.position;
  const q = data.rotation || [0, 0, 0, 1];
  const s = data.scale ?? 1;
  return { position: new THREE.Vector3(x, y, z), quaternion: new THREE.Quaternion(q[0], q[1], q[2], q[3]), scale: s };
}

function kindOf(data) {
  if (candidates.has(data.name)) return 'candidate';
  if (edited.has(data.name)) return 'edited';
  return data.resting_on ? 'resting' : 'floor';
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

// Colours, highlight and list classes of one object, from the sets above.
function look(entry) {
  const name = entry.data.name;
  const kind = kindOf(entry.data);
  entry.mesh.material.color.setHex(COLOURS[kind]);
  const hover = hovered.has(name);
  entry.mesh.material.emissive.setHex(hover ? 0x5a5a2a : selected.has(name) ? 0x1c3560 : 0x000000);
  entry.edges.material.color.setHex(hover ? 0xe0a800 : selected.has(name) ? 0x2f6db3 : kind === 'candidate' ? 0x6b3fb0 : 0x2d3a4d);
  if (entry.row) {
    entry.row.button.classList.toggle('hover', hover);
    entry.row.button.classList.toggle('selected', selected.has(name));
    entry.row.button.classList.toggle('candidate', candidates.has(name));
    entry.row.swatch.className = `swatch ${kind}`;
  }
}

// Restyles the objects named in `only` (all of them by default), what is linked to
// objects, and the labels.
function restyle(only) {
  if (only) {
    for (const name of only) if (objects.has(name)) look(objects.get(name));
  } else {
    for (const entry of objects.values()) look(entry);
  }
  for (const element of document.querySelectorAll('.linked')) {
    element.classList.toggle('hover', (element.linkedNames || []).some((n) => hovered.has(n)));
  }
  updateLabels();
}

// Highlights `names` (in the view, the list, and whatever else names them), or nothing.
function setHover(names) {
  const next = new Set(names.filter((n) => objects.has(n)));
  if (next.size === hovered.size && [...next].every((n) => hovered.has(n))) return;
  const changed = new Set([...hovered, ...next]);
  hovered = next;
  restyle(changed);
  if (next.size === 1) {
    const row = objects.get([...next][0]).row;
    if (row && !row.item.hidden && document.activeElement !== $('filter')) row.button.scrollIntoView({ block: 'nearest' });
  }
}

// Makes `element` stand for `names`: hovering it highlights them.
function link(element, names) {
  element.classList.add('linked');
  element.linkedNames = names;
  element.addEventListener('mouseenter', () => setHover(names));
  element.addEventListener('mouseleave', () => setHover([]));
  return element;
}

// Quotes a name as the grounder reads one name: the first pair whose closing quote is not
// in it.
function quote(name) {
  for (const [open, close] of [["'", "'"], ['"', '"'], ['‘', '’'], ['“', '”'], ['`', '`']]) {
    if (!name.includes(close)) return `${open}${name}${close}`;
  }
  return name;
}

// Inserts an object's quoted name at the cursor (after a space, unless one is there).
function insertName(name) {
  const box = $('instruction');
  const at = box.selectionStart ?? box.value.length;
  const text = (at > 0 && !/\s/.test(box.value[at - 1]) ? ' ' : '') + quote(name);
  box.value = box.value.slice(0, at) + text + box.value.slice(box.selectionEnd ?? at);
  box.focus();
  box.selectionStart = box.selectionEnd = at + text.length;
}

// A click selects an object — what "it" and "them" mean in the next instruction — in
// place of the selection, or (with Shift, Ctrl or Cmd) added to it or taken out; a click
// on the only selected object clears the selection.
function select(name, additive) {
  const before = [...selected];
  if (additive) {
    if (selected.has(name)) selected.delete(name); else selected.add(name);
  } else if (selected.size === 1 && selected.has(name)) {
    selected.clear();
  } else {
    selected.clear();
    selected.add(name);
  }
  showSelection();
  restyle([...before, name]);
}

// What "it" means now: the selection, or what the last edit moved.
function showSelection() {
  const names = [...selected];
  $('selection').textContent = names.length
    ? `Selected: ${names.join(', ')} — “it” means ${names.length === 1 ? 'this' : 'these'}`
    : (lastMoved.length ? `“it” means what the last edit moved: ${lastMoved.join(', ')}` : '');
}

// The conversation: each instruction and what came of it.
let lastMoved = [];
function addTurn(instruction, result, refused) {
  const item = h('li', { class: refused ? 'refused' : '' }, h('code', {}, instruction), ` — ${result}`);
  $('conversation').append(item);
  item.scrollIntoView({ block: 'nearest' });
}

// The outliner: one row per object, in scene order.
function buildList() {
  const list = $('object-list');
  list.replaceChildren();
  for (const entry of objects.values()) {
    const name = entry.data.name;
    const swatch = h('span', { class: 'swatch' });
    const button = h('button', { type: 'button', title: `Select '${name}' (Shift: add to the selection); double-click to insert its name` }, swatch, h('span', { class: 'name' }, name));
    button.addEventListener('mouseenter', () => setHover([name]));
    button.addEventListener('mouseleave', () => setHover([]));
    button.addEventListener('focus', () => setHover([name]));
    button.addEventListener('blur', () => setHover([]));
    button.addEventListener('click', (event) => select(name, event.shiftKey || event.ctrlKey || event.metaKey));
    button.addEventListener('dblclick', () => insertName(name));
    const item = h('li', {}, button);
    entry.row = { item, button, swatch, key: name.toLowerCase() };
    list.append(item);
  }
  $('object-count').textContent = `(${objects.size})`;
  filterList();
}

function filterList() {
  const words = $('filter').value.toLowerCase().split(/\s+/).filter(Boolean);
  for (const entry of objects.values()) {
    if (entry.row) entry.row.item.hidden = !words.every((w) => entry.row.key.includes(w));
  }
}
$('filter').addEventListener('input', filterList);

function build(scene, animate) {
  $('scene-name').textContent = scene.name || '';
  const seen = new Set();
  let added = false;
  for (const data of scene.objects) {
    seen.add(data.name);
    let entry = objects.get(data.name);
    const target = pose(data);
    if (!entry) {
      const geometry = new THREE.BoxGeometry(1, 1, 1).translate(0, 0.5, 0);
      const mesh = new THREE.Mesh(geometry, new THREE.MeshStandardMaterial({ color: COLOURS.floor, roughness: 0.8, transparent: true, opacity: 0.92 }));
      const edges = new THREE.LineSegments(new THREE.EdgesGeometry(geometry), new THREE.LineBasicMaterial({ color: 0x2d3a4d }));
      const front = new THREE.Line(new THREE.BufferGeometry(), new THREE.LineBasicMaterial({ color: 0xc0392b }));
      const group = new THREE.Group();
      group.add(mesh, edges, front);
      mesh.userData.name = data.name;
      world.add(group);
      entry = { group, mesh, edges, front, data, row: null };
      objects.set(data.name, entry);
      place(entry, target);
      added = true;
      continue;
    }
    const from = { position: entry.group.position.clone(), quaternion: entry.group.quaternion.clone(), scale: entry.group.scale.x };
    entry.data = data;
    if (animate) {
      animations.push({ entry, from, to: target, start: performance.now() });
    } else {
      place(entry, target);
    }
  }
  let removed = false;
  for (const [name, entry] of objects) {
    if (!seen.has(name)) { world.remove(entry.group); objects.delete(name); removed = true; }
  }
  if (added || removed) buildList();
  drawRoom(scene);
  restyle();
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

// Ghosts: each object the last edit moved, drawn where it was, with a line to where it is.
const ghostLabels = []; // { element, point }: "was here" above each ghost
function clearGhosts() {
  for (const { element } of ghostLabels.splice(0)) element.remove();
  for (const ghost of [...ghosts.children]) {
    ghost.traverse((o) => { if (o.geometry) o.geometry.dispose(); if (o.material) o.material.dispose(); });
    ghosts.remove(ghost);
  }
}

function showGhosts(moved) {
  clearGhosts();
  for (const m of moved || []) {
    const entry = objects.get(m.object);
    if (!entry) continue;
    const [w, hgt, d] = entry.data.size;
    const geometry = new THREE.BoxGeometry(1, 1, 1).translate(0, 0.5, 0);
    const box = new THREE.Mesh(geometry, new THREE.MeshBasicMaterial({ color: 0x7d8898, transparent: true, opacity: 0.22, depthWrite: false }));
    const outline = new THREE.LineSegments(new THREE.EdgesGeometry(geometry), new THREE.LineDashedMaterial({ color: 0x2d3a4d, dashSize: 0.05, gapSize: 0.035 }));
    outline.computeLineDistances();
    box.scale.set(w, hgt, d);
    outline.scale.set(w, hgt, d);
    const ghost = new THREE.Group();
    ghost.add(box, outline);
    const before = pose(m.before);
    ghost.position.copy(before.position);
    ghost.quaternion.copy(before.quaternion);
    ghost.scale.setScalar(before.scale);
    ghost.userData = { object: m.object, position: m.before.position };
    const after = pose(m.after);
    const lift = new THREE.Vector3(0, 0.02, 0);
    const trail = new THREE.Line(new THREE.BufferGeometry().setFromPoints([before.position.clone().add(lift), after.position.clone().add(lift)]),
      new THREE.LineBasicMaterial({ color: 0x2f8a43, depthTest: false, transparent: true }));
    trail.userData = { trail: true };
    ghosts.add(ghost, trail);
    const top = new THREE.Vector3(0, hgt, 0).applyMatrix4(new THREE.Matrix4().compose(before.position, before.quaternion, new THREE.Vector3().setScalar(before.scale)));
    const element = h('div', { class: 'label ghost', title: `where ${m.object} was` }, 'was here');
    $('labels').append(element);
    ghostLabels.push({ element, point: top });
  }
  placeLabels();
}

// Names in the view: for the objects hovered, selected, offered, just edited — or all.
const labels = new Map(); // name → element
const labelPoint = new THREE.Vector3();
function labelled() {
  if (allNames) return new Set(objects.keys());
  return new Set([...hovered, ...selected, ...candidates, ...edited].filter((n) => objects.has(n)));
}

function updateLabels() {
  const wanted = labelled();
  for (const [name, element] of labels) {
    if (!wanted.has(name)) { element.remove(); labels.delete(name); }
  }
  for (const name of wanted) {
    let element = labels.get(name);
    if (!element) {
      element = h('div', { class: 'label' }, name);
      labels.set(name, element);
      $('labels').append(element);
    }
    element.className = `label${edited.has(name) ? ' edited' : ''}${selected.has(name) ? ' selected' : ''}${candidates.has(name) ? ' candidate' : ''}${hovered.has(name) ? ' hover' : ''}`;
  }
  placeLabels();
}

// Screen position (CSS pixels within the view) of a point on an object: its top centre.
function screenOf(entry, height = 1) {
  return screenOfPoint(entry.group.localToWorld(new THREE.Vector3(0, entry.data.size[1] * height, 0)));
}

// Screen position of a world point.
function screenOfPoint(point) {
  labelPoint.copy(point).project(camera);
  return {
    x: (labelPoint.x + 1) / 2 * view.clientWidth,
    y: (1 - labelPoint.y) / 2 * view.clientHeight,
    visible: labelPoint.z < 1 && Math.abs(labelPoint.x) <= 1 && Math.abs(labelPoint.y) <= 1,
  };
}

function placeLabel(element, p) {
  element.hidden = !p.visible;
  element.style.transform = `translate(${p.x.toFixed(1)}px, ${(p.y - 4).toFixed(1)}px) translate(-50%, -100%)`;
}

function placeLabels() {
  for (const [name, element] of labels) {
    const entry = objects.get(name);
    if (entry) placeLabel(element, screenOf(entry));
  }
  for (const { element, point } of ghostLabels) placeLabel(element, screenOfPoint(point));
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
  placeLabels();
}
renderer.setAnimationLoop(tick);

// Hover: names and highlight in both the view and the list. Click (not a drag): select;
// double-click: insert the quoted name into the instruction.
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
  setHover(name ? [name] : []);
  renderer.domElement.style.cursor = name ? 'pointer' : '';
});
renderer.domElement.addEventListener('pointerleave', () => setHover([]));
let pressedAt = null;
renderer.domElement.addEventListener('pointerdown', (event) => { pressedAt = [event.clientX, event.clientY]; });
renderer.domElement.addEventListener('click', (event) => {
  // A drag that turned the view is not a click on what it ended over.
  if (pressedAt && Math.hypot(event.clientX - pressedAt[0], event.clientY - pressedAt[1]) > 5) return;
  const name = pick(event);
  if (name) select(name, event.shiftKey || event.ctrlKey || event.metaKey);
});
renderer.domElement.addEventListener('dblclick', (event) => {
  const name = pick(event);
  if (name) insertName(name);
});

// A byte range of UTF-8 text as a string (the API's spans are bytes).
const encoder = new TextEncoder();
const decoder = new TextDecoder();

// The instruction as it was understood: each grounded phrase marked, with its variable,
// and linked to its objects.
function showUnderstood(r) {
  const line = $('understood');
  const bytes = encoder.encode(r.instruction);
  const parts = ['Understood: '];
  let at = 0;
  for (const g of [...(r.grounding || [])].sort((a, b) => a.span[0] - b.span[0])) {
    const [start, end] = g.span;
    if (start < at || end > bytes.length || start >= end) continue;
    parts.push(decoder.decode(bytes.slice(at, start)));
    const mark = link(h('mark', { title: `“${g.phrase}” → ${g.objects.join(', ')}` }, decoder.decode(bytes.slice(start, end))), g.objects);
    parts.push(mark, h('sub', {}, g.variables.join(',')));
    at = end;
  }
  parts.push(decoder.decode(bytes.slice(at)));
  line.replaceChildren(...parts);
  line.hidden = false;
}

function showReport(r, note) {
  showUnderstood(r);
  const fmt = (v) => v.map((x) => Number(x).toFixed(3)).join(', ');
  const grounding = (r.grounding || []).map((g) => link(h('dd', { class: 'grounding' },
    `“${g.phrase}” → `, h('b', {}, g.variables.join(', ')), ` ${g.objects.join(', ')}`, h('br'),
    h('span', { class: 'why' }, g.reasons.map((why) => `${why.kind}: ${why.detail}`).join(' · '))), g.objects));
  const changes = r.objects.map((o) => link(h('dd', {},
    h('b', {}, o.variable), ` ${o.object}: `,
    o.expressions.map((e, i) => [i ? ' then ' : '', h('code', {}, e)]),
    h('br'), `move [${fmt(o.translation)}] · turn ${o.rotation_degrees.toFixed(1)}° · scale ${o.scale.toFixed(3)}`), [o.object]));
  const collisions = r.collisions_resolved.length
    ? r.collisions_resolved.map((c) => link(h('dd', {}, `${c.object} moved [${fmt(c.displacement)}] to clear ${c.collided_with.join(', ')}`), [c.object]))
    : [h('dd', {}, 'none')];
  $('report').replaceChildren(h('dl', {},
    note ? h('dd', { class: 'why' }, note) : null,
    h('dt', {}, 'Grounding'), grounding.length ? grounding : h('dd', {}, 'none'),
    h('dt', {}, 'Query'), h('dd', {}, h('code', {}, r.query)),
    h('dt', {}, 'Objects'), changes,
    r.carried.length ? [h('dt', {}, 'Carried'), link(h('dd', {}, r.carried.join(', ')), r.carried)] : null,
    h('dt', {}, 'Collisions resolved'), collisions,
    h('dt', {}, 'Model'), h('dd', {},
      `${r.model} · answered by ${r.answered_by || r.model} · ${r.system} (${r.prompt_version}) · ${r.retries} retries${r.cache_hit ? ' · cached' : ''}`,
      r.offline_refusal ? [h('br'), h('span', { class: 'why' }, `offline: ${r.offline_refusal}`)] : null),
    h('dt', {}, 'Timings'), h('dd', {}, `translate ${r.timings_ms.translate.toFixed(2)} ms · total ${r.timings_ms.total.toFixed(2)} ms`)));
}

// The edit the page shows: its report, its objects in green, and the ghosts of where they
// were (while it is the latest change).
function showEdit(outcome, current) {
  edited.clear();
  if (current) {
    for (const m of outcome.moved || []) edited.add(m.object);
    showGhosts(outcome.moved);
  } else {
    clearGhosts();
  }
  if (outcome.report) {
    showReport(outcome.report, current ? null : 'Undone or followed by other changes.');
  } else {
    // A follow-up ("a bit more", "put it back") moves without a translation to report.
    $('understood').hidden = true;
    $('report').textContent = (outcome.moved || []).map((m) => `${m.object} ${m.how}`).join(', ') || 'Nothing moved.';
  }
  window.shenlong.lastReport = outcome.report;
  restyle();
}

// A refusal that leaves a choice: the candidates as buttons, highlighted in the view.
function showChoice(ambiguity) {
  candidates.clear();
  for (const name of ambiguity.objects) if (objects.has(name)) candidates.add(name);
  const choices = ambiguity.choices || ambiguity.objects.map((object) => ({ object, instruction: null }));
  const shown = choices.slice(0, MAX_CHOICES);
  // The server lists a few choices and says how many there are (`total`).
  const total = ambiguity.total || ambiguity.objects.length;
  $('choice-text').replaceChildren(h('span', {}, `“${ambiguity.phrase}” could mean ${total} objects. Which one?`,
    total > shown.length ? h('span', { class: 'why' }, ` (the first ${shown.length}; name another by typing)`) : null));
  $('choices').replaceChildren(...shown.map((choice) => {
    const button = link(h('button', { type: 'button', title: choice.instruction || `Insert '${choice.object}'` }, choice.object), [choice.object]);
    button.addEventListener('click', () => {
      if (choice.instruction) {
        $('instruction').value = choice.instruction;
        run(choice.instruction);
      } else {
        insertName(choice.object);
      }
    });
    return button;
  }));
  $('choice').hidden = false;
  restyle();
}

function clearChoice() {
  candidates.clear();
  $('choice').hidden = true;
  $('choices').replaceChildren();
  restyle();
}

async function refreshHistory() {
  const data = await api('/api/history');
  $('history').replaceChildren(...data.history.map((item) => h('li', { class: item.undone ? 'undone' : '' },
    h('code', {}, item.text), ` — ${item.objects.join(', ') || 'nothing moved'}`)));
  return data;
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
  if (data.example) $('instruction').placeholder = data.example;
  if (data.model) await loadModel(data.model);
  return data;
}

let running = false;
async function run(instruction) {
  if (running) return;
  if (!instruction) { say('Type an instruction first.', 'error'); return; }
  running = true;
  $('run').disabled = true;
  clearChoice();
  say('Editing…', 'busy');
  try {
    const outcome = await api('/api/edit', {
      instruction, llm: $('llm').value.trim() || undefined, system: $('system').value, report: true,
      selected: selected.size ? [...selected] : undefined,
    });
    selected.clear();
    lastMoved = outcome.moved.filter((m) => m.how === 'moved').map((m) => m.object);
    addTurn(instruction, outcome.moved.length
      ? outcome.moved.map((m) => m.how === 'moved' ? m.object : `${m.object} (${m.how})`).join(', ')
      : 'nothing moved', false);
    showSelection();
    await load(true);
    showEdit(outcome, true);
    await refreshHistory();
    if (outcome.warnings.length) say(`Done, but ${outcome.warnings.join('; ')}`, 'error');
    else say(`Done: ${outcome.moved.map((m) => m.object).join(', ') || 'nothing moved'}`);
  } catch (error) {
    say(error.message, 'error');
    addTurn(instruction, error.message, true);
    if (error.data && error.data.ambiguity) showChoice(error.data.ambiguity);
  } finally {
    running = false;
    $('run').disabled = false;
  }
}

$('form').addEventListener('submit', (event) => {
  event.preventDefault();
  run($('instruction').value.trim());
});

// Enter runs; Shift+Enter is a new line.
$('instruction').addEventListener('keydown', (event) => {
  if (event.key === 'Enter' && !event.shiftKey && !event.isComposing) {
    event.preventDefault();
    $('form').requestSubmit();
  }
});

async function step(undo) {
  try {
    const outcome = await api(undo ? '/api/undo' : '/api/redo', {});
    await load(true);
    edited.clear();
    clearGhosts();
    clearChoice();
    await refreshHistory();
    say(outcome.warnings.length ? `${undo ? 'Undone' : 'Redone'}, but ${outcome.warnings.join('; ')}` : (undo ? 'Undone' : 'Redone'),
      outcome.warnings.length ? 'error' : undefined);
  } catch (error) {
    say(error.message, 'error');
  }
}
$('undo').addEventListener('click', () => step(true));
$('redo').addEventListener('click', () => step(false));

// Ctrl+Z / Ctrl+Shift+Z (and Ctrl+Y) undo and redo, except in a text field, where they
// are the field's own. Esc clears the selection and the choice.
document.addEventListener('keydown', (event) => {
  const target = event.target;
  const typing = target instanceof HTMLTextAreaElement || target instanceof HTMLSelectElement
    || (target instanceof HTMLInputElement && target.type !== 'button' && target.type !== 'checkbox');
  if (event.key === 'Escape') {
    if (target === $('filter') && $('filter').value) return;
    const before = [...selected];
    selected.clear();
    showSelection();
    restyle(before);
    clearChoice();
    return;
  }
  if (typing || !(event.ctrlKey || event.metaKey) || event.altKey) return;
  const key = event.key.toLowerCase();
  if (key === 'z' || key === 'y') {
    event.preventDefault();
    step(key === 'z' && !event.shiftKey);
  }
});

$('topdown').addEventListener('click', () => {
  const top = camera === perspective;
  camera = top ? orthographic : perspective;
  controls.enabled = !top;
  $('topdown').setAttribute('aria-pressed', String(top));
  updateLabels();
});

$('names').addEventListener('click', () => {
  allNames = !allNames;
  $('names').setAttribute('aria-pressed', String(allNames));
  updateLabels();
});

window.shenlong = {
  ready: false,
  lastReport: null,
  // How many meshes are drawn (for tests): boxes, or a glTF model's meshes as well.
  meshes: () => { let n = 0; world.traverse((o) => { if (o.isMesh) n += 1; }); return n; },
  // The ghosts shown: each object and where it was.
  ghosts: () => ghosts.children.filter((g) => g.userData.object).map((g) => ({ object: g.userData.object, position: g.userData.position })),
  // The objects highlighted in the view (under the pointer or linked).
  highlighted: () => [...hovered],
  // The names shown in the view.
  labels: () => [...labels.entries()].filter(([, e]) => !e.hidden).map(([name]) => name),
  // Where a point of an object is on the page (by default its middle), for tests that
  // point at it.
  pointAt: (name, height = 0.5) => {
    const entry = objects.get(name);
    if (!entry) return null;
    const p = screenOf(entry, height);
    const rect = view.getBoundingClientRect();
    return { x: rect.left + p.x, y: rect.top + p.y };
  },
};
try {
  await load(false);
  frameCamera();
  // The last edit and the history, even when the edit was made before the page opened.
  const history = await refreshHistory();
  const last = history.last_edit;
  if (last) {
    const latest = history.history[history.history.length - 1];
    const current = latest !== undefined && latest.id === last.history_id && !latest.undone;
    showEdit(last, current);
  }
  window.shenlong.ready = true;
} catch (error) {
  say(`Cannot load the scene: ${error.message}`, 'error');
}
