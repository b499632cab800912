// kergen-wasm demo: load a mesh (file, drop or generated sample), compute its kernel in a worker
// (the package's KernelWorker — nothing heavy runs on this thread), and animate the kernel's growth
// from the stream of step events.

import * as THREE from 'three';
import { STLExporter } from 'three/examples/jsm/exporters/STLExporter.js';
import { KernelWorker } from 'kergen-wasm/worker';
import { Viewer } from './viewer.js';
import { SAMPLES, sampleById } from './samples.js';
import { parseMeshFile } from './loaders.js';

const $ = (id) => document.getElementById(id);
const ui = {
  fileInput: $('file-input'), samples: $('samples'), viewport: $('viewport'), overlay: $('drop-overlay'),
  busy: $('busy'), busyText: $('busy-text'), play: $('play'), jumpEnd: $('jump-end'), cancel: $('cancel'),
  scrubber: $('scrubber'), stepLabel: $('step-label'), speed: $('speed'), speedLabel: $('speed-label'),
  animV: $('anim-vertices'), animE: $('anim-edges'), animF: $('anim-faces'), status: $('status'),
  message: $('message'), exportObj: $('export-obj'), exportStl: $('export-stl'), fit: $('fit-view'),
  fitKernel: $('fit-kernel'),
};

const viewer = new Viewer(ui.viewport);

const state = {
  token: 0, // identifies the current run; results of older runs are ignored
  worker: null,
  computing: false,
  name: '',
  result: null,
  t0: 0,
  timing: {},
  cursor: 0,
  playing: true,
  stickToEnd: false,
  speed: 40,
  seen: { vertex: new Set(), edge: new Set(), face: new Set() },
};

// ------------------------------------------------------------------------------------------
// Formatting and UI helpers

const fmt = (x, digits = 6) => (Number.isFinite(x) ? Number(x.toPrecision(digits)).toString() : String(x));

function setStat(id, text, value = text) {
  const el = $(id);
  el.textContent = text;
  el.dataset.value = value === null || value === undefined ? '' : String(value);
}

function clearStats() {
  for (const id of ['stat-input-faces', 'stat-planes', 'stat-status', 'stat-vertices', 'stat-edges', 'stat-faces',
    'stat-volume', 'stat-area', 'stat-ratio', 'stat-kernel-point', 'stat-time', 'stat-wall']) setStat(id, '—', '');
}

function setStatus(stateName, text, value = '') {
  ui.status.dataset.state = stateName;
  ui.status.dataset.value = value;
  ui.status.textContent = text;
}

function showMessage(kind, title, detail = '', code = '') {
  ui.message.hidden = false;
  ui.message.dataset.kind = kind;
  ui.message.dataset.code = code;
  ui.message.replaceChildren();
  const b = document.createElement('b');
  b.textContent = title;
  ui.message.append(b);
  if (detail) ui.message.append(document.createTextNode(detail));
}

function hideMessage() {
  ui.message.hidden = true;
  ui.message.dataset.kind = '';
  ui.message.dataset.code = '';
  ui.message.replaceChildren();
}

function setBusy(text) {
  ui.busy.hidden = !text;
  if (text) ui.busyText.textContent = text;
}

const ERROR_TITLES = {
  PARSE_ERROR: 'Could not read the file',
  OPEN_MESH: 'The mesh is open',
  NON_MANIFOLD_EDGE: 'The mesh is not manifold',
  INCONSISTENT_ORIENTATION: 'Inconsistent face orientation',
  MULTIPLE_COMPONENTS: 'The mesh has several separate pieces',
  DEGENERATE_INPUT: 'The mesh encloses no volume',
  NON_FINITE_COORDINATE: 'Invalid coordinates',
  INDEX_OUT_OF_RANGE: 'A face refers to a vertex that does not exist',
  EMPTY_INPUT: 'The mesh is empty',
  FACE_TOO_SMALL: 'A face has fewer than 3 vertices',
  TOO_LARGE: 'The mesh is too large',
  COORDINATE_RANGE: 'Coordinates span too many orders of magnitude',
};
const ERROR_HINTS = {
  OPEN_MESH: ' The kernel is defined for closed (watertight) meshes: every edge must belong to exactly two faces.',
  NON_MANIFOLD_EDGE: ' Every edge must belong to exactly two faces.',
  INCONSISTENT_ORIENTATION: ' Neighbouring faces must traverse their shared edge in opposite directions.',
  MULTIPLE_COMPONENTS: ' Load one closed piece at a time.',
};

function showError(err) {
  const code = err?.code || 'ERROR';
  const title = ERROR_TITLES[code] ?? 'Error';
  showMessage('error', `${title} (${code})`, `${err?.message ?? err}${ERROR_HINTS[code] ?? ''}`, code);
  setStatus('error', `${title}.`, 'ERROR');
  setStat('stat-status', code, 'ERROR');
}

// ------------------------------------------------------------------------------------------
// Runs

function worker() {
  state.worker ??= new KernelWorker();
  return state.worker;
}

// Stops whatever is running and starts a new run; returns its token.
function beginRun(name) {
  state.token++;
  // KernelWorker.cancel() terminates the busy worker thread and starts a fresh one (same object).
  if (state.computing && state.worker) state.worker.cancel();
  state.computing = false;
  state.name = name;
  state.result = null;
  state.cursor = 0;
  state.playing = true;
  state.stickToEnd = false;
  state.seen = { vertex: new Set(), edge: new Set(), face: new Set() };
  state.timing = {};
  viewer.kernel.reset();
  viewer.setKernelPoint(null);
  hideMessage();
  clearStats();
  setStat('stat-name', name);
  ui.cancel.disabled = false;
  ui.exportObj.disabled = ui.exportStl.disabled = true;
  setPlayButton();
  return state.token;
}

function endRun() {
  state.computing = false;
  ui.cancel.disabled = true;
  setBusy('');
}

function pushEvent(ev) {
  const kind = ev.type;
  if (!state.seen[kind] || state.seen[kind].has(ev.id)) return;
  if (viewer.kernel.push(ev)) state.seen[kind].add(ev.id);
}

async function computeKernel(mesh, token) {
  const tView = performance.now();
  viewer.setInput(mesh.positions, mesh.indices, mesh.faceSizes);
  state.timing.view = performance.now() - tView;
  const faces = mesh.faceSizes ? mesh.faceSizes.length : mesh.indices.length / 3;
  setStat('stat-input-faces', `${faces} ${mesh.faceSizes ? 'faces' : 'triangles'} (${mesh.positions.length / 3} vertices)`, faces);
  setStatus('computing', 'Computing the kernel…', 'RUNNING');
  setBusy('Computing…');
  state.computing = true;
  const kw = worker();
  state.timing.posted = performance.now();
  let result;
  try {
    // The package may transfer (detach) the arrays: give it copies, the viewer keeps the originals.
    result = await kw.compute(mesh.positions.slice(), mesh.indices.slice(), {
      faceSizes: mesh.faceSizes?.slice(),
      onStep: (ev) => {
        if (token === state.token) pushEvent(ev);
      },
      onProgress: ({ phase, steps }) => {
        if (token === state.token) setBusy(`${phase}${steps ? ` · ${steps} steps` : ''}…`);
      },
    });
  } catch (err) {
    if (token !== state.token) return;
    endRun();
    if (err?.code === 'CANCELLED') {
      showMessage('info', 'Cancelled.', ' The computation was stopped; the steps found so far are still shown.', 'CANCELLED');
      setStatus('cancelled', 'Cancelled.', 'CANCELLED');
    } else {
      showError(err);
    }
    return;
  }
  if (token !== state.token) return;
  endRun();
  finish(result);
}

function finish(result) {
  state.result = result;
  const wall = performance.now() - state.t0;
  // Events and result use the same ids; add anything the stream did not deliver (in id order).
  const V = result.vertices.length / 3, E = result.edges.length / 2, F = result.faces.length;
  for (let i = 0; i < V; i++) {
    if (!state.seen.vertex.has(i)) {
      pushEvent({ type: 'vertex', id: i, position: [result.vertices[3 * i], result.vertices[3 * i + 1], result.vertices[3 * i + 2]] });
    }
  }
  for (let i = 0; i < E; i++) if (!state.seen.edge.has(i)) pushEvent({ type: 'edge', id: i, a: result.edges[2 * i], b: result.edges[2 * i + 1] });
  for (let i = 0; i < F; i++) if (!state.seen.face.has(i)) pushEvent({ type: 'face', id: i, loop: Array.from(result.faces[i]) });

  const s = result.stats ?? {};
  setStat('stat-input-faces', `${s.inputFaces ?? '—'}${s.droppedFaces ? ` (${s.droppedFaces} zero-area dropped)` : ''}`, s.inputFaces);
  const planesNote = [s.activePlanes != null ? `${s.activePlanes} active` : null, s.culledFaces ? `${s.culledFaces} faces culled first` : null]
    .filter(Boolean).join(', ');
  setStat('stat-planes', `${s.distinctPlanes ?? '—'}${planesNote ? ` (${planesNote})` : ''}`, s.distinctPlanes);
  setStat('stat-status', result.status + (result.complete === false ? ' (partial)' : ''), result.status);
  setStat('stat-vertices', String(V), V);
  setStat('stat-edges', String(E), E);
  setStat('stat-faces', String(F), F);
  if (result.status === 'POLYHEDRON') {
    setStat('stat-volume', fmt(result.volume, 10), result.volume);
    setStat('stat-ratio', `${fmt(100 * result.volumeRatio, 4)} %`, result.volumeRatio);
  } else if (result.status === 'POLYGON') {
    setStat('stat-volume', `0 (flat; area ${fmt(result.area)})`, result.volume);
    setStat('stat-ratio', '0 %', result.volumeRatio);
  } else {
    setStat('stat-volume', result.status === 'EMPTY' ? '— (empty)' : String(result.volume), result.volume);
    setStat('stat-ratio', result.status === 'EMPTY' ? '0 %' : '—', result.volumeRatio);
  }
  setStat('stat-area', result.status === 'POLYHEDRON' || result.status === 'POLYGON' ? fmt(result.area, 10) : '—', result.area);
  const kp = result.kernelPoint;
  setStat('stat-kernel-point', kp ? `(${kp.map((x) => fmt(x, 7)).join(', ')})` : 'none', kp ? kp.join(',') : '');
  setStat('stat-time', s.msTotal != null ? `${fmt(s.msTotal, 4)} ms (LP ${fmt(s.msLp ?? 0, 3)}, trace ${fmt(s.msTrace ?? 0, 3)})` : '—', s.msTotal);
  const tm = state.timing;
  const parts = [tm.read != null && `read ${tm.read.toFixed(0)}`, tm.parse != null && `parse ${tm.parse.toFixed(0)}`,
    `view ${tm.view.toFixed(0)}`, `worker round trip ${(performance.now() - tm.posted).toFixed(0)}`].filter(Boolean);
  setStat('stat-wall', `${fmt(wall, 4)} ms (${parts.join(', ')})`, wall);
  viewer.setKernelPoint(kp);

  const counts = `${V} vertices, ${E} edges, ${F} faces`;
  switch (result.status) {
    case 'POLYHEDRON':
      setStatus('done', `Star-shaped: the kernel is a polyhedron (${counts}).`, result.status);
      break;
    case 'EMPTY':
      setStatus('done', 'Not star-shaped: the kernel is empty.', result.status);
      showMessage('empty', 'Not star-shaped — the kernel is empty.',
        ' No point inside this shape sees all of it: the inner half-spaces of its face planes have no common point.', 'EMPTY');
      break;
    case 'POINT':
      setStatus('done', 'Star-shaped from a single point.', result.status);
      showMessage('flat', 'Flat kernel: a single point.',
        ` The shape is star-shaped, but only one point (${kp?.map((x) => fmt(x)).join(', ')}) sees all of it.`, 'POINT');
      break;
    case 'SEGMENT':
      setStatus('done', 'Star-shaped from a segment.', result.status);
      showMessage('flat', 'Flat kernel: a line segment.',
        ' The shape is star-shaped, but only from the points of one segment; the kernel has no volume.', 'SEGMENT');
      break;
    case 'POLYGON':
      setStatus('done', `Star-shaped from a flat polygon (${V} vertices).`, result.status);
      showMessage('flat', 'Flat kernel: a polygon.',
        ` The kernel is a flat convex polygon (area ${fmt(result.area)}); it has no volume.`, 'POLYGON');
      break;
    case 'UNBOUNDED':
      setStatus('done', 'The kernel is unbounded.', result.status);
      showMessage('warning', 'Unbounded kernel.', ' The face planes do not enclose a bounded region (an open mesh?).', 'UNBOUNDED');
      break;
    default:
      setStatus('done', String(result.status), result.status);
  }
  if (result.warnings?.length) {
    const text = result.warnings.map((w) => w.message || `${w.kind} (${w.count})`).join(' · ');
    if (ui.message.hidden) showMessage('info', 'Note', ` ${text}`, 'WARNINGS');
    else ui.message.append(document.createTextNode(` Note: ${text}`));
  }
  ui.exportObj.disabled = ui.exportStl.disabled = !(result.triangles?.length > 0);
}

async function loadFile(file, t0 = performance.now()) {
  selectSample(null);
  const token = beginRun(file.name);
  state.t0 = t0;
  viewer.clearInput(); // nothing stale to render while the file is read
  setStatus('reading', `Reading ${file.name}…`, 'READING');
  setBusy('Reading…');
  let mesh;
  try {
    const buffer = await file.arrayBuffer();
    if (token !== state.token) return;
    const tParse = performance.now();
    state.timing.read = tParse - t0;
    mesh = parseMeshFile(file.name, buffer);
    state.timing.parse = performance.now() - tParse;
  } catch (err) {
    if (token !== state.token) return;
    endRun();
    viewer.clearInput();
    showError(err.code ? err : Object.assign(err, { code: 'PARSE_ERROR' }));
    return;
  }
  setStat('stat-name', `${file.name} (${mesh.format})`);
  await computeKernel(mesh, token);
}

function loadSample(id) {
  const sample = sampleById(id);
  if (!sample) return;
  selectSample(id);
  const t0 = performance.now();
  const token = beginRun(sample.name);
  state.t0 = t0;
  const url = new URL(location.href);
  url.searchParams.set('sample', id);
  history.replaceState(null, '', url);
  computeKernel(sample.build(), token);
}

function selectSample(id) {
  for (const b of ui.samples.querySelectorAll('button')) b.classList.toggle('active', b.dataset.sample === id);
  if (!id && location.search) history.replaceState(null, '', location.pathname);
}

ui.cancel.addEventListener('click', () => {
  if (state.computing && state.worker) {
    state.worker.cancel(); // compute() rejects with CANCELLED → message shown by computeKernel
  } else if (!ui.cancel.disabled) {
    state.token++; // still reading the file: drop the run
    endRun();
    showMessage('info', 'Cancelled.', '', 'CANCELLED');
    setStatus('cancelled', 'Cancelled.', 'CANCELLED');
  }
});

// ------------------------------------------------------------------------------------------
// Playback

function setPlayButton() {
  ui.play.textContent = state.playing ? 'Pause' : 'Play';
  ui.play.setAttribute('aria-pressed', String(state.playing));
}

function speedFromSlider() {
  state.speed = Math.round(2 ** Number(ui.speed.value));
  ui.speedLabel.textContent = `${state.speed} steps/s`;
}
ui.speed.addEventListener('input', speedFromSlider);
speedFromSlider();

ui.play.addEventListener('click', () => {
  const total = viewer.kernel.length;
  if (!state.playing && state.result && Math.floor(state.cursor) >= total) state.cursor = 0; // replay
  state.playing = !state.playing;
  state.stickToEnd = false;
  setPlayButton();
});
ui.jumpEnd.addEventListener('click', () => {
  state.stickToEnd = true;
  state.playing = false;
  state.cursor = viewer.kernel.length;
  setPlayButton();
});
ui.scrubber.addEventListener('input', () => {
  state.playing = false;
  state.stickToEnd = false;
  state.cursor = Number(ui.scrubber.value);
  setPlayButton();
});

let lastFrame = performance.now();
let lastUi = '';
function frame(now) {
  const dt = Math.min(0.25, (now - lastFrame) / 1000);
  lastFrame = now;
  const total = viewer.kernel.length;
  if (state.stickToEnd) state.cursor = total;
  else if (state.playing) {
    state.cursor = Math.min(total, state.cursor + state.speed * dt);
    if (state.result && state.cursor >= total) {
      state.playing = false;
      setPlayButton();
    }
  }
  const k = Math.floor(state.cursor);
  const c = viewer.kernel.show(k);
  const key = `${k}/${total}/${c.vertices}/${c.edges}/${c.faces}/${state.computing}`;
  if (key !== lastUi) {
    lastUi = key;
    ui.scrubber.max = String(total);
    ui.scrubber.value = String(k);
    ui.stepLabel.textContent = `${k} / ${total}${state.computing ? '+' : ''}`;
    for (const [el, v] of [[ui.animV, c.vertices], [ui.animE, c.edges], [ui.animF, c.faces]]) {
      el.textContent = String(v);
      el.dataset.value = String(v);
    }
  }
  viewer.render(state.computing);
  requestAnimationFrame(frame);
}
requestAnimationFrame(frame);

// ------------------------------------------------------------------------------------------
// Export

function download(blob, filename) {
  const a = document.createElement('a');
  a.href = URL.createObjectURL(blob);
  a.download = filename;
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 10000);
}

const baseName = () => (state.name || 'mesh').replace(/\.[a-z0-9]+$/i, '').replace(/[^\w.-]+/g, '_');

ui.exportObj.addEventListener('click', () => {
  const r = state.result;
  if (!r) return;
  // Convex polygon faces, full double precision (three.js's OBJExporter writes triangles only).
  const lines = [`# kernel of ${state.name}: ${r.status}, volume ${r.volume} (kergen-wasm)`];
  for (let i = 0; i < r.vertices.length; i += 3) lines.push(`v ${r.vertices[i]} ${r.vertices[i + 1]} ${r.vertices[i + 2]}`);
  for (const loop of r.faces) lines.push(`f ${Array.from(loop, (v) => v + 1).join(' ')}`);
  download(new Blob([lines.join('\n') + '\n'], { type: 'text/plain' }), `${baseName()}-kernel.obj`);
});

ui.exportStl.addEventListener('click', () => {
  const r = state.result;
  if (!r) return;
  const geo = new THREE.BufferGeometry();
  geo.setAttribute('position', new THREE.BufferAttribute(new Float32Array(r.vertices), 3));
  geo.setIndex(new THREE.BufferAttribute(new Uint32Array(r.triangles), 1));
  const data = new STLExporter().parse(new THREE.Mesh(geo), { binary: true });
  download(new Blob([data], { type: 'model/stl' }), `${baseName()}-kernel.stl`);
});

ui.fit.addEventListener('click', () => viewer.fit());
ui.fitKernel.addEventListener('click', () => viewer.fit(true));
window.addEventListener('keydown', (e) => {
  if (e.target instanceof HTMLInputElement || e.target instanceof HTMLButtonElement) return;
  if (e.key === 'f' || e.key === 'F') viewer.fit();
  if (e.key === 'k' || e.key === 'K') viewer.fit(true);
  if (e.key === ' ') {
    e.preventDefault();
    ui.play.click();
  }
});

// ------------------------------------------------------------------------------------------
// Input: file picker, drag & drop, samples

ui.fileInput.addEventListener('change', () => {
  const t0 = performance.now();
  const file = ui.fileInput.files?.[0];
  if (file) loadFile(file, t0);
  ui.fileInput.value = '';
});

let dragDepth = 0;
window.addEventListener('dragenter', (e) => {
  e.preventDefault();
  dragDepth++;
  ui.overlay.hidden = false;
});
window.addEventListener('dragover', (e) => e.preventDefault());
window.addEventListener('dragleave', () => {
  dragDepth = Math.max(0, dragDepth - 1);
  if (!dragDepth) ui.overlay.hidden = true;
});
window.addEventListener('drop', (e) => {
  e.preventDefault();
  const t0 = performance.now();
  dragDepth = 0;
  ui.overlay.hidden = true;
  const file = e.dataTransfer?.files?.[0];
  if (file) loadFile(file, t0);
});

for (const s of SAMPLES) {
  const b = document.createElement('button');
  b.type = 'button';
  b.textContent = s.name;
  b.title = s.description;
  b.dataset.sample = s.id;
  b.dataset.testid = `sample-${s.id}`;
  b.addEventListener('click', () => loadSample(s.id));
  ui.samples.append(b);
}

const initial = new URLSearchParams(location.search).get('sample') ?? 'star-prism';
if (initial !== 'none') loadSample(initial);
