// kergen-wasm demo: load a mesh (file, drop or generated sample), compute its kernel in a worker
// (the package's KernelWorker), and animate the kernel's growth from the stream of step events.
// Nothing heavy runs on this thread: a file's bytes go to the worker untouched (it parses them
// with the package's reader), the input is prepared for drawing in a second worker
// (draw-worker.js), and the replay only moves draw ranges.

import { KernelWorker } from 'kergen-wasm/worker';
import { Viewer } from './viewer.js';
import { SAMPLES, sampleById } from './samples.js';
import { prepareDrawing } from './draw-prep.js';

// Above this many faces the input is prepared in the drawing worker, and its face edges are off
// by default (a dense wireframe hides the kernel and costs every frame).
const INLINE_FACES = 20000;
const EDGE_FACES = 50000;
// Above this many triangles the view draws a simplified copy of the input (draw-prep.js simplify).
const DRAW_TRIANGLES = 10000;
// A full replay at speed 1× takes at most this long, whatever the kernel's size.
const REPLAY_SECONDS = 10;
const MIN_STEPS_PER_S = 40;
// ?stream=0: compute without step events (the replay is then built from the result); for
// measuring what streaming costs (bench/browser_bench.mjs).
const STREAM = new URLSearchParams(location.search).get('stream') !== '0';

const $ = (id) => document.getElementById(id);
const ui = {
  fileInput: $('file-input'), samples: $('samples'), viewport: $('viewport'), overlay: $('drop-overlay'),
  busy: $('busy'), busyText: $('busy-text'), play: $('play'), jumpEnd: $('jump-end'), cancel: $('cancel'),
  scrubber: $('scrubber'), stepLabel: $('step-label'), speed: $('speed'), speedLabel: $('speed-label'),
  animV: $('anim-vertices'), animE: $('anim-edges'), animF: $('anim-faces'), status: $('status'),
  message: $('message'), exportObj: $('export-obj'), exportStl: $('export-stl'), exportOff: $('export-off'),
  fit: $('fit-view'), fitKernel: $('fit-kernel'), opacity: $('opacity'), opacityLabel: $('opacity-label'),
  showEdges: $('show-edges'), edgesNote: $('edges-note'),
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
  speed: 1, // multiplier of the base replay rate (replayRate())
  seen: { vertex: new Set(), edge: new Set(), face: new Set() },
  inputShown: false, // step events wait in `pending` until the input (and its centre) is drawn
  pending: [],
  faces: 0,
  edgesReady: false,
};

// ------------------------------------------------------------------------------------------
// Formatting and UI helpers

const fmt = (x, digits = 6) => (Number.isFinite(x) ? Number(x.toPrecision(digits)).toString() : String(x));
// Durations: "850 ms", "1.3 s".
const fmtMs = (ms) => (ms < 1000 ? `${ms.toFixed(0)} ms` : `${(ms / 1000).toFixed(ms < 10000 ? 1 : 0)} s`);
const fmtBytes = (n) => (n < 1e6 ? `${(n / 1e3).toFixed(0)} kB` : `${(n / 1e6).toFixed(1)} MB`);
const fmtCount = (n) => Number(n).toLocaleString('en-US');

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

// The drawing worker, and its replies by request id.
const draw = { worker: null, nextId: 1, waiting: new Map() };
function drawRequest(message, transfer = []) {
  if (!draw.worker) {
    draw.worker = new Worker(new URL('./draw-worker.js', import.meta.url), { type: 'module' });
    draw.worker.onmessage = ({ data }) => {
      draw.waiting.get(data.id)?.(data);
      draw.waiting.delete(data.id);
    };
    // A failure (out of memory on a huge file...) answers every request with nothing to draw:
    // the kernel is still shown, around the origin.
    draw.worker.onerror = (e) => {
      e.preventDefault?.();
      for (const resolve of draw.waiting.values()) resolve({ error: e.message ?? 'the drawing worker failed' });
      draw.waiting.clear();
      draw.worker.terminate();
      draw.worker = null;
    };
  }
  const id = draw.nextId++;
  return new Promise((resolve) => {
    draw.waiting.set(id, resolve);
    draw.worker.postMessage({ ...message, id }, transfer);
  });
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
  state.inputShown = false;
  state.pending = [];
  state.timing = {};
  state.phases = [];
  ui.busy.dataset.phases = '';
  viewer.kernel.reset();
  viewer.setKernelPoint(null);
  hideMessage();
  clearStats();
  setStat('stat-name', name);
  ui.cancel.disabled = false;
  setExportEnabled(false);
  setPlayButton();
  return state.token;
}

function endRun() {
  state.computing = false;
  ui.cancel.disabled = true;
  setBusy('');
}

function pushEvent(ev) {
  if (!state.inputShown) {
    state.pending.push(ev);
    return;
  }
  const kind = ev.type;
  if (!state.seen[kind] || state.seen[kind].has(ev.id)) return;
  if (viewer.kernel.push(ev)) state.seen[kind].add(ev.id);
}

// Draws the input (prepared by prepareDrawing) and replays the events that came before it.
function showDrawing(d) {
  const t = performance.now();
  state.faces = d.faces;
  state.edgesReady = !!d.edges;
  ui.showEdges.checked = d.faces <= EDGE_FACES;
  ui.edgesNote.textContent = d.faces > EDGE_FACES ? `(${fmtCount(d.faces)} faces: off by default)` : '';
  if (d.simplified) ui.edgesNote.textContent += ` The view draws a simplified copy of the shape (${fmtCount(d.triangles.length / 3)} triangles); the kernel is computed on the real one.`;
  viewer.edgesVisible = ui.showEdges.checked;
  viewer.setInputDrawing(d);
  state.inputShown = true;
  for (const ev of state.pending) pushEvent(ev);
  state.pending = [];
  state.timing.view = (state.timing.view ?? 0) + performance.now() - t;
}

// Prepares a parsed mesh for drawing: here when small, in the drawing worker when big.
async function showMesh(mesh, token) {
  const faces = mesh.faceSizes ? mesh.faceSizes.length : mesh.indices.length / 3;
  setStat('stat-input-faces', `${fmtCount(faces)} ${mesh.faceSizes ? 'faces' : 'triangles'} (${fmtCount(mesh.positions.length / 3)} vertices)`, faces);
  const edges = faces <= EDGE_FACES;
  if (faces <= INLINE_FACES) {
    const t = performance.now();
    const d = prepareDrawing(mesh, { edges });
    state.timing.view = performance.now() - t;
    showDrawing(d);
    return;
  }
  const buffers = [...new Set([mesh.positions.buffer, mesh.indices.buffer, mesh.faceSizes?.buffer].filter(Boolean))];
  const { drawing } = await drawRequest({ type: 'prepare', mesh, edges, maxTriangles: DRAW_TRIANGLES }, buffers);
  if (token === state.token && drawing) showDrawing(drawing);
}

const PHASE_TEXT = {
  loading: () => 'Loading the kernel module…',
  reading: (p) => `Reading ${state.name} (${fmtBytes(p.bytes ?? 0)})…`,
  computing: () => 'Computing…',
  validating: (p) => `Validating ${fmtCount(p.count ?? 0)} faces…`,
  planes: (p) => `Merging planes of ${fmtCount(p.count ?? 0)} faces…`,
  lp: (p) => `Finding a kernel point (LP over ${fmtCount(p.count ?? 0)} planes)…`,
  tracing: (p) => `Tracing the kernel · ${fmtCount(p.steps)} steps…`,
  assembling: (p) => `Assembling the kernel (${fmtCount(p.count ?? 0)})…`,
  done: () => 'Drawing…',
};

function onProgress(p) {
  if (!state.phases.includes(p.phase)) {
    state.phases.push(p.phase);
    ui.busy.dataset.phases = state.phases.join(',');
  }
  setBusy((PHASE_TEXT[p.phase] ?? (() => `${p.phase}…`))(p));
}

// Runs one computation (`start(callbacks)` calls the worker) and shows its outcome.
async function runKernel(token, start) {
  setStatus('computing', 'Computing the kernel…', 'RUNNING');
  setBusy('Computing…');
  state.computing = true;
  state.timing.posted = performance.now();
  let result;
  try {
    const onStep = (ev) => {
      if (token === state.token) pushEvent(ev);
    };
    result = await start({
      ...(STREAM ? { onStep } : {}),
      onProgress: (p) => {
        if (token === state.token) onProgress(p);
      },
    });
  } catch (err) {
    if (token !== state.token) return;
    endRun();
    if (err?.code === 'CANCELLED') {
      showMessage('info', 'Cancelled.', ' The computation was stopped; the steps found so far are still shown.', 'CANCELLED');
      setStatus('cancelled', 'Cancelled.', 'CANCELLED');
    } else {
      if (!state.inputShown) viewer.clearInput();
      showError(err);
    }
    return;
  }
  if (token !== state.token) return;
  state.timing.worker = performance.now() - state.timing.posted;
  // The drawn input must be there before the kernel is finished on top of it.
  if (!state.inputShown && state.inputPromise) {
    await state.inputPromise.catch(() => {});
    if (token !== state.token) return;
  }
  if (!state.inputShown) {
    state.inputShown = true; // no drawing came: draw the kernel around the origin
    for (const ev of state.pending.splice(0)) pushEvent(ev);
  }
  endRun();
  await finish(result, token);
}

async function finish(result, token) {
  state.result = result;
  const wall = performance.now() - state.t0;
  // Events and result use the same ids; add anything the stream did not deliver (in id order).
  const V = result.vertices.length / 3, E = result.edges.length / 2, F = result.faces.length;
  if (state.seen.vertex.size !== V || state.seen.edge.size !== E || state.seen.face.size !== F) {
    if (!(await addMissingEvents(result, V, E, F, token))) return;
  }
  showStats(result, wall, V, E, F);
  showOutcome(result, V, E, F);
}

// Without a stream (?stream=0) a kernel's million events are added here: in slices, one task
// each, so the page keeps drawing frames. False when a newer run took over meanwhile.
async function addMissingEvents(result, V, E, F, token) {
  const SLICE = 20000;
  const kinds = [
    [V, 'vertex', (i) => ({ type: 'vertex', id: i, position: [result.vertices[3 * i], result.vertices[3 * i + 1], result.vertices[3 * i + 2]] })],
    [E, 'edge', (i) => ({ type: 'edge', id: i, a: result.edges[2 * i], b: result.edges[2 * i + 1] })],
    [F, 'face', (i) => ({ type: 'face', id: i, loop: Array.from(result.faces[i]) })],
  ];
  for (const [n, kind, event] of kinds) {
    for (let i = 0; i < n; i++) {
      if (!state.seen[kind].has(i)) pushEvent(event(i));
      if (i % SLICE === SLICE - 1) {
        await new Promise((resolve) => setTimeout(resolve, 0));
        if (token !== state.token) return false;
      }
    }
  }
  return true;
}

function showStats(result, wall, V, E, F) {
  const s = result.stats ?? {};
  setStat('stat-input-faces', `${s.inputFaces != null ? fmtCount(s.inputFaces) : '—'}${s.droppedFaces ? ` (${s.droppedFaces} zero-area dropped)` : ''}`, s.inputFaces);
  const planesNote = [s.activePlanes != null ? `${s.activePlanes} active` : null, s.culledFaces ? `${s.culledFaces} faces culled first` : null]
    .filter(Boolean).join(', ');
  setStat('stat-planes', `${s.distinctPlanes != null ? fmtCount(s.distinctPlanes) : '—'}${planesNote ? ` (${planesNote})` : ''}`, s.distinctPlanes);
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
  setStat('stat-time', s.msTotal != null ? `${fmtMs(s.msTotal)} (LP ${fmtMs(s.msLp ?? 0)}, trace ${fmtMs(s.msTrace ?? 0)})` : '—', s.msTotal);
  const tm = state.timing;
  const parts = [tm.read != null && `read ${fmtMs(tm.read)}`, `worker round trip ${fmtMs(tm.worker)}`,
    tm.view != null && `view ${fmtMs(tm.view)}`].filter(Boolean);
  setStat('stat-wall', `${fmtMs(wall)} (${parts.join(', ')})`, wall);
  viewer.setKernelPoint(kp);
}

function showOutcome(result, V, E, F) {
  const kp = result.kernelPoint;
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
  setExportEnabled(result.triangles?.length > 0);
}

function setExportEnabled(on) {
  ui.exportObj.disabled = ui.exportStl.disabled = ui.exportOff.disabled = !on;
}

// A file: its bytes go to the worker as they are (transferred), which parses, validates and
// computes there and sends the parsed mesh back early to be drawn meanwhile.
async function loadFile(file, t0 = performance.now()) {
  selectSample(null);
  const token = beginRun(file.name);
  state.t0 = t0;
  viewer.clearInput(); // nothing stale to render while the file is read
  setStatus('reading', `Reading ${file.name}…`, 'READING');
  setBusy(`Reading ${file.name} (${fmtBytes(file.size)})…`);
  const bytes = await file.arrayBuffer();
  if (token !== state.token) return;
  state.timing.read = performance.now() - t0;
  state.inputPromise = null;
  // The page keeps no use for the file's bytes: move them to the worker instead of copying.
  await runKernel(token, (callbacks) => worker().computeFile(bytes, {
    name: file.name,
    transfer: true,
    // STL stores each triangle's corners on their own: welded, as the CLI does.
    weld: /\.stl$/i.test(file.name) ? true : undefined,
    ...callbacks,
    onMesh: (mesh) => {
      if (token === state.token) state.inputPromise = showMesh(mesh, token);
    },
  }).then(({ result }) => result));
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
  const mesh = sample.build();
  state.inputPromise = null;
  showMesh(mesh, token); // samples are small: drawn right here
  // The worker copies the arrays: the drawn input keeps its own.
  runKernel(token, (callbacks) => worker().compute(mesh.positions, mesh.indices, {
    faceSizes: mesh.faceSizes, ...callbacks,
  }));
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

// Steps per second at speed 1×: a full replay takes at most REPLAY_SECONDS whatever the
// kernel's size (a million-step kernel moves tens of thousands of steps per frame; a frame's work
// does not depend on it: show(k) only sets draw ranges).
const replayRate = () => Math.max(MIN_STEPS_PER_S, viewer.kernel.length / REPLAY_SECONDS);

function speedFromSlider() {
  state.speed = 2 ** Number(ui.speed.value);
  updateSpeedLabel();
}

let speedLabel = '';
function updateSpeedLabel() {
  const mult = state.speed >= 1 ? `${fmt(state.speed, 3)}×` : `1/${fmt(1 / state.speed, 3)}×`;
  const text = `${mult} (${fmtCount(Math.round(state.speed * replayRate()))} steps/s)`;
  if (text !== speedLabel) ui.speedLabel.textContent = speedLabel = text;
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
    state.cursor = Math.min(total, state.cursor + state.speed * replayRate() * dt);
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
    updateSpeedLabel();
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

// The kernel's file is written by the package (the same writer as the CLI's -o), in the worker.
async function exportKernel(format, mime) {
  const r = state.result;
  if (!r) return;
  try {
    const bytes = await worker().writeMesh(r, format);
    download(new Blob([bytes], { type: mime }), `${baseName()}-kernel.${format}`);
  } catch (err) {
    showError(err);
  }
}
ui.exportObj.addEventListener('click', () => exportKernel('obj', 'text/plain'));
ui.exportStl.addEventListener('click', () => exportKernel('stl', 'model/stl'));
ui.exportOff.addEventListener('click', () => exportKernel('off', 'text/plain'));

// ------------------------------------------------------------------------------------------
// View controls

function opacityFromSlider() {
  const x = Number(ui.opacity.value);
  viewer.setOpacity(x);
  ui.opacityLabel.textContent = `${Math.round(100 * x)} %`;
}
ui.opacity.addEventListener('input', opacityFromSlider);
opacityFromSlider();

ui.showEdges.addEventListener('change', async () => {
  const on = ui.showEdges.checked;
  viewer.setEdgesVisible(on);
  if (on && !state.edgesReady && state.inputShown) {
    // A big file's edges were not computed up front: the drawing worker still has the mesh.
    state.edgesReady = true;
    const token = state.token;
    const { edges } = await drawRequest({ type: 'edges' });
    if (token === state.token && edges) viewer.setInputEdges(edges);
  }
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

// Start the drawing worker now, not when the first big file arrives.
drawRequest({ type: 'noop' });

const initial = new URLSearchParams(location.search).get('sample') ?? 'star-prism';
if (initial !== 'none') loadSample(initial);
