// kergen-wasm demo: load a mesh (file, drop, link or generated sample), compute its kernel in a
// worker (the package's KernelWorker), and animate the kernel's growth from the stream of step
// events. Nothing heavy runs on this thread: a file's bytes go to the worker untouched (it parses
// them with the package's reader; GLB/glTF, a scene format, is read by three.js's loader), the
// input is prepared for drawing in a second worker (draw-worker.js), and the replay only moves
// draw ranges.

import { KernelWorker } from 'kergen-wasm/worker';
import { Viewer } from './viewer.js';
import { SAMPLES, sampleById } from './samples.js';
import { prepareDrawing, openEdgeLines, faceHighlight } from './draw-prep.js';
import { boxFacets } from './unbounded.js';
import { readGltf, isGltfName } from './gltf.js';
import { viewFromParams, shareUrl } from './share.js';
import { ROWS, REPAIRABLE, describeError, describeResult, sentence } from './outcome.js';

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
const PARAMS = new URLSearchParams(location.search);
const STREAM = PARAMS.get('stream') !== '0';

const $ = (id) => document.getElementById(id);
const ui = {
  fileInput: $('file-input'),
  samples: $('samples'),
  viewport: $('viewport'),
  overlay: $('drop-overlay'),
  busy: $('busy'),
  busyText: $('busy-text'),
  play: $('play'),
  jumpEnd: $('jump-end'),
  cancel: $('cancel'),
  scrubber: $('scrubber'),
  stepLabel: $('step-label'),
  speed: $('speed'),
  speedLabel: $('speed-label'),
  animV: $('anim-vertices'),
  animE: $('anim-edges'),
  animF: $('anim-faces'),
  status: $('status'),
  message: $('message'),
  exportObj: $('export-obj'),
  exportStl: $('export-stl'),
  exportOff: $('export-off'),
  fit: $('fit-view'),
  fitKernel: $('fit-kernel'),
  opacity: $('opacity'),
  opacityLabel: $('opacity-label'),
  showEdges: $('show-edges'),
  edgesNote: $('edges-note'),
  openFile: $('open-file'),
  showInput: $('show-input'),
  showBall: $('show-ball'),
  sectionOn: $('section-on'),
  sectionAxis: $('section-axis'),
  sectionKernel: $('section-kernel'),
  sectionPos: $('section-pos'),
  sectionLabel: $('section-label'),
  shareUrl: $('share-url'),
  copyLink: $('copy-link'),
  shareNote: $('share-note'),
  actions: $('actions'),
  retryOpen: $('retry-open'),
  retryWalls: $('retry-walls'),
  retryRepair: $('retry-repair'),
  playbar: $('playbar'),
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
  // What is open, kept so that it can be computed again with other options (see open()).
  source: null,
  runOptions: {
    allowOpen: PARAMS.get('allowOpen') === '1',
    repair: PARAMS.get('repair') === '1',
    walls: PARAMS.get('open') === 'perpendicular',
  },
  view: viewFromParams(PARAMS),
  mesh: null, // the parsed input when it is drawn on this thread (small); else the drawing worker has it
  drawing: null, // { center, maxAbs } of the drawn input
  openEdges: 0,
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
  for (const id of [
    'stat-input-faces',
    'stat-open-edges',
    'stat-planes',
    'stat-status',
    'stat-vertices',
    'stat-edges',
    'stat-faces',
    'stat-volume',
    'stat-area',
    'stat-ratio',
    'stat-kernel-point',
    'stat-deepest',
    'stat-time',
    'stat-wall',
  ])
    setStat(id, '—', '');
}

// Shows the rows of the stats table that apply (the others are hidden, not shown as 0).
function showRows(rows) {
  for (const id of ROWS) $(`row-${id}`).hidden = !rows.includes(id);
}

// `stateName`: idle, reading, computing, cancelled, error, done; `outcome` (done only): star,
// empty, flat, open. The canvas's label says the same in words.
function setStatus(stateName, text, value = '', outcome = '') {
  ui.status.dataset.state = stateName;
  ui.status.dataset.value = value;
  ui.status.dataset.outcome = outcome;
  ui.status.textContent = text;
  viewer.renderer.domElement.setAttribute('aria-label', `3D view${state.name ? ` of ${state.name}` : ''}: ${text}`);
}

// The message box: a title and paragraphs, each its own sentence(s).
function showMessage(kind, title, paragraphs = [], code = '') {
  ui.message.hidden = false;
  ui.message.dataset.kind = kind;
  ui.message.dataset.code = code;
  ui.message.replaceChildren();
  const b = document.createElement('b');
  b.textContent = title;
  ui.message.append(b);
  for (const text of [paragraphs].flat().filter(Boolean)) addParagraph(text);
}

function addParagraph(text) {
  const p = document.createElement('p');
  p.textContent = text;
  ui.message.append(p);
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

// The error state; offers what can get an answer from the same mesh (repair, allowOpen).
function showError(err) {
  const d = describeError(err, { openEdges: state.openEdges });
  showMessage('error', d.title, d.paragraphs, d.code);
  setStatus('error', d.status, 'ERROR');
  setStat('stat-status', d.code, 'ERROR');
  showRows(d.rows);
  const reopenable = !!state.source && state.inputShown;
  const open = reopenable && d.code === 'OPEN_MESH';
  ui.retryOpen.hidden = !(open && !state.runOptions.allowOpen);
  ui.retryWalls.hidden = !(open && !state.runOptions.walls);
  ui.retryRepair.hidden = !(reopenable && REPAIRABLE.has(d.code) && !state.runOptions.repair);
  ui.actions.hidden = ui.retryOpen.hidden && ui.retryWalls.hidden && ui.retryRepair.hidden;
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
  state.mesh = null;
  state.openEdges = 0;
  ui.busy.dataset.phases = '';
  viewer.kernel.reset();
  viewer.setKernelPoint(null);
  viewer.setBall(null);
  viewer.setBoxFacets(null);
  viewer.setWitnessFaces(null);
  viewer.setOpenEdges(null);
  viewer.setKernelClosed(false);
  hideMessage();
  ui.actions.hidden = ui.retryOpen.hidden = ui.retryWalls.hidden = ui.retryRepair.hidden = true;
  clearStats();
  setStat('stat-name', name);
  showRows(['name', 'input-faces']);
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

// A run that ends without a kernel (error or cancel): nothing to play.
function stopPlayback() {
  state.playing = false;
  state.stickToEnd = false;
  setPlayButton();
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
  state.drawing = { center: d.center, maxAbs: d.maxAbs };
  ui.showEdges.checked = state.view.edges ?? d.faces <= EDGE_FACES;
  ui.edgesNote.textContent = d.faces > EDGE_FACES ? `(${fmtCount(d.faces)} faces: off by default)` : '';
  if (d.simplified)
    ui.edgesNote.textContent += ` The view draws a simplified copy of the shape (${fmtCount(d.triangles.length / 3)} triangles); the kernel is computed on the real one.`;
  viewer.edgesVisible = ui.showEdges.checked;
  viewer.setInputDrawing(d);
  applySection();
  if (ui.showEdges.checked && !d.edges) ui.showEdges.dispatchEvent(new Event('change'));
  state.inputShown = true;
  for (const ev of state.pending) pushEvent(ev);
  state.pending = [];
  state.timing.view = (state.timing.view ?? 0) + performance.now() - t;
}

// Prepares a parsed mesh for drawing: here when small (and kept here, for the open edges and
// witness faces), in the drawing worker when big (which keeps it).
async function showMesh(mesh, token) {
  const faces = mesh.faceSizes ? mesh.faceSizes.length : mesh.indices.length / 3;
  setStat(
    'stat-input-faces',
    `${fmtCount(faces)} ${mesh.faceSizes ? 'faces' : 'triangles'} (${fmtCount(mesh.positions.length / 3)} vertices)`,
    faces,
  );
  const edges = (state.view.edges ?? faces <= EDGE_FACES) && faces <= EDGE_FACES;
  if (faces <= INLINE_FACES) {
    const t = performance.now();
    const d = prepareDrawing(mesh, { edges });
    state.mesh = mesh;
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
    if (token === state.token) await failRun(err, token);
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

// A run that ended without a kernel: cancelled (by the button) or refused.
async function failRun(err, token) {
  endRun();
  stopPlayback();
  if (err?.code === 'CANCELLED') {
    showCancelled();
    return;
  }
  if (err?.code === 'OPEN_MESH' && state.inputPromise) await state.inputPromise.catch(() => {});
  if (token !== state.token) return;
  if (!state.inputShown) viewer.clearInput();
  if (err?.code === 'OPEN_MESH' && state.inputShown) await showOpenEdges(token);
  if (token === state.token) showError(err);
}

function showCancelled() {
  const steps = viewer.kernel.length;
  showMessage(
    'info',
    'Cancelled.',
    steps > 0
      ? `The computation was stopped; the ${fmtCount(steps)} steps that had arrived (part of the kernel's boundary) are still shown.`
      : 'The computation was stopped before any part of the kernel had arrived; nothing of it is shown.',
    'CANCELLED',
  );
  setStatus('cancelled', 'Cancelled.', 'CANCELLED');
  showRows(['name', 'input-faces']);
}

// The input's open edges, drawn in red and counted (from the indices: edges used by one face).
async function showOpenEdges(token) {
  const center = state.drawing?.center ?? [0, 0, 0];
  const open = state.mesh ? openEdgeLines(state.mesh, center) : await drawRequest({ type: 'open-edges' });
  if (token !== state.token || !open?.lines) return;
  state.openEdges = open.count;
  viewer.setOpenEdges(open.lines);
  setStat('stat-open-edges', `${fmtCount(open.count)} (red)`, open.count);
}

async function finish(result, token) {
  state.result = result;
  const wall = performance.now() - state.t0;
  // Events and result use the same ids; add anything the stream did not deliver (in id order).
  const V = result.vertices.length / 3,
    E = result.edges.length / 2,
    F = result.faces.length;
  if (state.seen.vertex.size !== V || state.seen.edge.size !== E || state.seen.face.size !== F) {
    if (!(await addMissingEvents(result, V, E, F, token))) return;
  }
  const extra = {};
  if (result.status === 'UNBOUNDED') {
    await showOpenEdges(token);
    if (token !== state.token) return;
    const ids = boxFacets(result, state.drawing?.maxAbs ?? 0);
    viewer.setBoxFacets(result, ids);
    Object.assign(extra, { boxFacets: ids.length, openEdges: state.openEdges });
    // The clipped kernel reaches the box, far beyond the mesh: show all of it, box facets included.
    viewer.fit(true);
  }
  const witness = result.status === 'EMPTY' ? result.witnessFaces : null;
  if (witness?.length) {
    await showWitnessFaces(witness, token);
    if (token !== state.token) return;
    extra.witness = witness.length;
  }
  showStats(result, wall, V, E, F);
  showOutcome(result, V, E, F, extra);
}

// The faces of an empty kernel's certificate (input indices), highlighted.
async function showWitnessFaces(ids, token) {
  const center = state.drawing?.center ?? [0, 0, 0];
  const faces = state.mesh
    ? faceHighlight(state.mesh, ids, center)
    : await drawRequest({ type: 'faces', faces: Array.from(ids) });
  if (token === state.token && faces?.triangles) viewer.setWitnessFaces(faces);
}

// Without a stream (?stream=0) a kernel's million events are added here: in slices, one task
// each, so the page keeps drawing frames. False when a newer run took over meanwhile.
async function addMissingEvents(result, V, E, F, token) {
  const SLICE = 20000;
  const kinds = [
    [
      V,
      'vertex',
      (i) => ({
        type: 'vertex',
        id: i,
        position: [result.vertices[3 * i], result.vertices[3 * i + 1], result.vertices[3 * i + 2]],
      }),
    ],
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
  setStat(
    'stat-input-faces',
    `${s.inputFaces != null ? fmtCount(s.inputFaces) : '—'}${s.droppedFaces ? ` (${s.droppedFaces} zero-area dropped)` : ''}`,
    s.inputFaces,
  );
  const planesNote = [
    s.activePlanes != null ? `${s.activePlanes} active` : null,
    s.culledFaces ? `${s.culledFaces} faces culled first` : null,
  ]
    .filter(Boolean)
    .join(', ');
  setStat(
    'stat-planes',
    `${s.distinctPlanes != null ? fmtCount(s.distinctPlanes) : '—'}${planesNote ? ` (${planesNote})` : ''}`,
    s.distinctPlanes,
  );
  setStat('stat-status', result.status + (result.complete === false ? ' (partial)' : ''), result.status);
  setStat('stat-vertices', String(V), V);
  setStat('stat-edges', String(E), E);
  setStat('stat-faces', String(F), F);
  setStat('stat-volume', fmt(result.volume, 10), result.volume);
  setStat('stat-ratio', `${fmt(100 * result.volumeRatio, 4)} %`, result.volumeRatio);
  setStat('stat-area', fmt(result.area, 10), result.area);
  const kp = result.kernelPoint;
  setStat('stat-kernel-point', kp ? `(${kp.map((x) => fmt(x, 7)).join(', ')})` : 'none', kp ? kp.join(',') : '');
  const dp = result.deepestPoint;
  setStat(
    'stat-deepest',
    dp ? `(${dp.map((x) => fmt(x, 7)).join(', ')}), inscribed ball radius ${fmt(result.inscribedRadius, 6)}` : '—',
    dp ? [...dp, result.inscribedRadius].join(',') : '',
  );
  setStat(
    'stat-time',
    s.msTotal != null ? `${fmtMs(s.msTotal)} (LP ${fmtMs(s.msLp ?? 0)}, trace ${fmtMs(s.msTrace ?? 0)})` : '—',
    s.msTotal,
  );
  const tm = state.timing;
  const parts = [
    tm.read != null && `read ${fmtMs(tm.read)}`,
    `worker round trip ${fmtMs(tm.worker)}`,
    tm.view != null && `view ${fmtMs(tm.view)}`,
  ].filter(Boolean);
  setStat('stat-wall', `${fmtMs(wall)} (${parts.join(', ')})`, wall);
  viewer.setKernelPoint(kp);
  viewer.setBall(dp, result.inscribedRadius);
  viewer.setKernelClosed(result.status === 'POLYHEDRON' || result.status === 'UNBOUNDED');
}

function showOutcome(result, V, E, F, extra) {
  const d = describeResult(result, V, E, F, extra);
  setStatus('done', d.status, result.status, d.outcome);
  showRows(d.rows);
  if (d.kind) showMessage(d.kind, d.title, d.paragraphs, result.status);
  if (result.warnings?.length) {
    const text = result.warnings.map((w) => sentence(w.message || `${w.kind} (${w.count})`)).join(' ');
    if (ui.message.hidden) showMessage('info', 'Note', [text], 'WARNINGS');
    else addParagraph(`Note: ${text}`);
  }
  setExportEnabled(result.triangles?.length > 0);
}

function setExportEnabled(on) {
  ui.exportObj.disabled = ui.exportStl.disabled = ui.exportOff.disabled = !on;
}

// ------------------------------------------------------------------------------------------
// Sources: a sample, a file (picked or dropped), a link (?url=), each kept in state.source so
// that it can be computed again with other options.

const kernelOptions = () => ({
  // The inscribed ball costs little next to the kernel (docs/demo.md has the numbers): always on.
  deepestPoint: true,
  // Walls at the boundary edges (the package's open: 'perpendicular') bound an open surface's
  // kernel where allowOpen clips it to a box; walls win when both were asked for.
  ...(state.runOptions.walls ? { open: 'perpendicular' } : state.runOptions.allowOpen ? { allowOpen: true } : {}),
  ...(state.runOptions.repair ? { repair: true } : {}),
});

/**
 * Opens `source` ({ kind: 'sample', id } | { kind: 'file', file } | { kind: 'url', url, file })
 * and computes its kernel with `options` ({ allowOpen, repair, walls }: walls is open: 'perpendicular').
 */
async function openSource(source, options = { allowOpen: false, repair: false, walls: false }, t0 = performance.now()) {
  state.source = source;
  state.runOptions = options;
  selectSample(source.kind === 'sample' ? source.id : null);
  const name = source.kind === 'sample' ? sampleById(source.id).name : source.file.name;
  const token = beginRun(name);
  state.t0 = t0;
  updateShareUrl();
  state.inputPromise = null;
  if (source.kind === 'sample') {
    const mesh = sampleById(source.id).build();
    showMesh(mesh, token); // samples are small: drawn right here
    // The worker copies the arrays: the drawn input keeps its own.
    await runKernel(token, (callbacks) =>
      worker().compute(mesh.positions, mesh.indices, { faceSizes: mesh.faceSizes, ...kernelOptions(), ...callbacks }),
    );
    return;
  }
  const file = source.file;
  viewer.clearInput(); // nothing stale to render while the file is read
  setStatus('reading', `Reading ${file.name}…`, 'READING');
  setBusy(`Reading ${file.name} (${fmtBytes(file.size)})…`);
  const bytes = await file.arrayBuffer();
  if (token !== state.token) return;
  state.timing.read = performance.now() - t0;
  if (isGltfName(file.name)) await computeGltf(bytes, file.name, token);
  else await computeFileBytes(bytes, file.name, token);
}

// A mesh file: its bytes go to the worker as they are (transferred), which parses, validates and
// computes there and sends the parsed mesh back early to be drawn meanwhile.
function computeFileBytes(bytes, name, token) {
  return runKernel(token, (callbacks) =>
    worker()
      .computeFile(bytes, {
        name,
        transfer: true,
        // STL stores each triangle's corners on their own: welded, as the CLI does.
        ...(/\.stl$/i.test(name) ? { weld: true } : {}),
        ...kernelOptions(),
        ...callbacks,
        onMesh: (mesh) => {
          if (token === state.token) state.inputPromise = showMesh(mesh, token);
        },
      })
      .then(({ result }) => result),
  );
}

// GLB / glTF: read here by three.js's loader (all meshes merged in world space), then welded by
// the package, as an STL is.
async function computeGltf(bytes, name, token) {
  setBusy(`Reading ${name} (glTF)…`);
  let mesh;
  try {
    mesh = await readGltf(bytes, name);
  } catch (err) {
    if (token !== state.token) return;
    endRun();
    stopPlayback();
    showError({ code: 'PARSE_ERROR', message: err.message });
    return;
  }
  if (token !== state.token) return;
  // A big mesh's arrays are moved to the drawing worker: it gets copies, the kernel worker these.
  state.inputPromise = showMesh({ positions: mesh.positions.slice(), indices: mesh.indices.slice() }, token);
  await runKernel(token, (callbacks) =>
    worker().compute(mesh.positions, mesh.indices, { weld: true, ...kernelOptions(), ...callbacks }),
  );
}

// ?url=: fetched here (the server must allow this page's origin: CORS), then opened as a file.
async function openUrl(text, options) {
  let url = null;
  try {
    url = new URL(text, location.href);
  } catch {
    // reported below
  }
  const name = url ? decodeURIComponent(url.pathname.split('/').pop() || 'mesh') : String(text);
  const fail = (message) => {
    state.source = { kind: 'url', url: url?.href ?? String(text) };
    beginRun(name);
    endRun();
    stopPlayback();
    showError({ code: 'URL_ERROR', message });
  };
  if (!url || !/^https?:$/.test(url.protocol)) return fail(`?url= must be an http or https address; got "${text}"`);
  const t0 = performance.now();
  const token = beginRun(name);
  setStatus('reading', `Fetching ${url.href}…`, 'READING');
  setBusy(`Fetching ${name}…`);
  let response;
  try {
    response = await fetch(url.href, { mode: 'cors' });
  } catch {
    if (token === state.token)
      fail(
        `could not fetch ${url.href}: the server did not answer, or it does not allow this page to read it (no CORS header Access-Control-Allow-Origin)`,
      );
    return;
  }
  if (token !== state.token) return;
  if (!response.ok) return fail(`could not fetch ${url.href}: HTTP ${response.status} ${response.statusText}`.trim());
  const blob = await response.blob();
  if (token !== state.token) return;
  await openSource({ kind: 'url', url: url.href, file: new File([blob], name) }, options, t0);
}

// The same input again with other options (the retry buttons).
function reopen(options) {
  const source = state.source;
  if (!source) return;
  openSource(source, { ...state.runOptions, ...options });
}
ui.retryOpen.addEventListener('click', () => reopen({ allowOpen: true, walls: false }));
ui.retryWalls.addEventListener('click', () => reopen({ walls: true, allowOpen: false }));
ui.retryRepair.addEventListener('click', () => reopen({ repair: true }));

function selectSample(id) {
  for (const b of ui.samples.querySelectorAll('button')) {
    b.classList.toggle('active', b.dataset.sample === id);
    b.setAttribute('aria-pressed', String(b.dataset.sample === id));
  }
}

ui.cancel.addEventListener('click', () => {
  if (state.computing && state.worker) {
    state.worker.cancel(); // compute() rejects with CANCELLED → message shown by failRun
  } else if (!ui.cancel.disabled) {
    state.token++; // still reading the file: drop the run
    endRun();
    stopPlayback();
    showCancelled();
  }
});

// ------------------------------------------------------------------------------------------
// Playback

// "Pause" only while something plays: not at step 0 of nothing (computing, error, cancel).
function setPlayButton() {
  const playing = state.playing && viewer.kernel.length > 0;
  ui.play.textContent = playing ? 'Pause' : 'Play';
  ui.play.setAttribute('aria-pressed', String(playing));
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
    // Nothing to play (before the first step, after an error, an empty kernel): no controls that do nothing.
    ui.play.disabled = ui.jumpEnd.disabled = ui.scrubber.disabled = total === 0;
    setPlayButton();
    ui.scrubber.max = String(total);
    ui.scrubber.value = String(k);
    ui.stepLabel.textContent = `${k} / ${total}${state.computing ? '+' : ''}`;
    updateSpeedLabel();
    for (const [el, v] of [
      [ui.animV, c.vertices],
      [ui.animE, c.edges],
      [ui.animF, c.faces],
    ]) {
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
// View controls. Each writes state.view, which the shareable URL carries.

function opacityFromSlider() {
  const x = Number(ui.opacity.value);
  state.view.opacity = x;
  viewer.setOpacity(x);
  ui.opacityLabel.textContent = `${Math.round(100 * x)} %`;
}
ui.opacity.addEventListener('input', () => {
  opacityFromSlider();
  updateShareUrl();
});

ui.showInput.addEventListener('change', () => {
  state.view.shape = ui.showInput.checked;
  viewer.setInputVisible(ui.showInput.checked);
  updateShareUrl();
});

ui.showBall.addEventListener('change', () => {
  state.view.ball = ui.showBall.checked;
  viewer.setBallVisible(ui.showBall.checked);
  updateShareUrl();
});

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
ui.showEdges.addEventListener('input', () => {
  state.view.edges = ui.showEdges.checked;
  updateShareUrl();
});

function applySection() {
  const v = state.view;
  viewer.setSection({ on: v.section, axis: 'xyz'.indexOf(v.axis), at: v.pos, clipKernel: v.clipKernel });
  ui.sectionLabel.textContent = `${Math.round(100 * v.pos)} %`;
  for (const el of [ui.sectionAxis, ui.sectionPos, ui.sectionKernel]) el.disabled = !v.section;
}
function sectionFromControls() {
  Object.assign(state.view, {
    section: ui.sectionOn.checked,
    axis: ui.sectionAxis.value,
    pos: Number(ui.sectionPos.value),
    clipKernel: ui.sectionKernel.checked,
  });
  applySection();
  updateShareUrl();
}
for (const el of [ui.sectionOn, ui.sectionAxis, ui.sectionKernel]) el.addEventListener('change', sectionFromControls);
ui.sectionPos.addEventListener('input', sectionFromControls);

// The controls as state.view says (from the URL at start).
function viewToControls() {
  const v = state.view;
  ui.opacity.value = String(v.opacity);
  ui.showInput.checked = v.shape;
  ui.showBall.checked = v.ball;
  ui.sectionOn.checked = v.section;
  ui.sectionAxis.value = v.axis;
  ui.sectionPos.value = String(v.pos);
  ui.sectionKernel.checked = v.clipKernel;
  opacityFromSlider();
  viewer.setInputVisible(v.shape);
  viewer.setBallVisible(v.ball);
  applySection();
}

// The page's URL always reopens what is shown (a sample or a link, with the view options); a
// file from this computer cannot be reopened by a link.
function updateShareUrl() {
  const url = shareUrl(location.href, state.source, state.runOptions, state.view);
  if (url) history.replaceState(null, '', url);
  else if (location.search) history.replaceState(null, '', location.pathname);
  ui.shareUrl.value = url ?? '';
  ui.copyLink.disabled = !url;
  ui.shareNote.textContent = url
    ? ''
    : 'A file opened from this computer cannot be reopened by a link; samples and meshes opened with ?url= can.';
}

ui.copyLink.addEventListener('click', async () => {
  try {
    await navigator.clipboard.writeText(ui.shareUrl.value);
    ui.shareNote.textContent = 'Link copied.';
  } catch {
    // No clipboard permission: select the link for the user to copy.
    ui.shareUrl.focus();
    ui.shareUrl.select();
    ui.shareNote.textContent = 'The clipboard is not available here: the link is selected, copy it with Ctrl+C.';
  }
});

// The play bar covers the bottom of the view: fitting uses the area above it.
new ResizeObserver(() => {
  const view = ui.viewport.getBoundingClientRect(),
    bar = ui.playbar.getBoundingClientRect();
  viewer.setInsetBottom(Math.max(0, view.bottom - bar.top));
}).observe(ui.playbar);

ui.fit.addEventListener('click', () => viewer.fit());
ui.fitKernel.addEventListener('click', () => viewer.fit(true));

// Shortcuts work wherever the focus is, except where a key types text or picks an option.
const typesText = (el) =>
  el instanceof HTMLTextAreaElement ||
  el instanceof HTMLSelectElement ||
  el?.isContentEditable ||
  (el instanceof HTMLInputElement &&
    !['checkbox', 'radio', 'range', 'button', 'submit', 'reset', 'file', 'color'].includes(el.type));
const SHORTCUTS = {
  f: () => viewer.fit(),
  k: () => viewer.fit(true),
  h: () => ui.showInput.click(),
  s: () => ui.sectionOn.click(),
  ' ': () => ui.play.click(),
};
window.addEventListener('keydown', (e) => {
  if (e.ctrlKey || e.metaKey || e.altKey || typesText(e.target)) return;
  const action = SHORTCUTS[e.key.toLowerCase()];
  if (!action) return;
  // Space would also press the focused button or tick the focused box: play/pause instead.
  e.preventDefault();
  if (!e.repeat) action();
});
window.addEventListener('keyup', (e) => {
  if (e.key === ' ' && !typesText(e.target)) e.preventDefault();
});

// ------------------------------------------------------------------------------------------
// Input: file picker, drag & drop, samples, ?sample= / ?url=

// A new input from the user: the face-edge toggle goes back to its default for the mesh's size.
function openFile(file, t0) {
  state.view.edges = null;
  openSource({ kind: 'file', file }, { allowOpen: false, repair: false, walls: false }, t0);
}

ui.openFile.addEventListener('click', () => ui.fileInput.click());
ui.fileInput.addEventListener('change', () => {
  const t0 = performance.now();
  const file = ui.fileInput.files?.[0];
  if (file) openFile(file, t0);
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
  if (file) openFile(file, t0);
});

for (const s of SAMPLES) {
  const b = document.createElement('button');
  b.type = 'button';
  b.textContent = s.name;
  b.title = s.description;
  b.dataset.sample = s.id;
  b.dataset.testid = `sample-${s.id}`;
  b.setAttribute('aria-pressed', 'false');
  b.addEventListener('click', () => {
    state.view.edges = null;
    openSource({ kind: 'sample', id: s.id });
  });
  ui.samples.append(b);
}

// For the browser tests: the view (camera, scene) and the page's state, read-only by convention.
window.kergenDemo = { viewer, state };

const canvas = viewer.renderer.domElement;
canvas.setAttribute('role', 'img');
canvas.tabIndex = 0; // focusable: the view's label is read, and the keys work from there too
setStatus('idle', 'No mesh loaded.');
showRows(['name']);
viewToControls();

// Start the drawing worker now, not when the first big file arrives.
drawRequest({ type: 'noop' });

if (PARAMS.has('url')) openUrl(PARAMS.get('url'), state.runOptions);
else {
  const initial = PARAMS.get('sample') ?? 'star-prism';
  if (sampleById(initial)) openSource({ kind: 'sample', id: initial }, state.runOptions);
  else updateShareUrl();
}
