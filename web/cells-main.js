// The volume-mesh page (cells.html): a .vtu / .vtk file or a .node + .ele pair (chosen, dropped,
// or the sample generated here) goes to the package's KernelWorker untouched, which reads it with
// the core's reader and computes the kernel of every cell range by range (the progress bar);
// the cells are coloured by kernel ratio or ρ/h, and a clicked cell is shown with its kernel,
// witness faces and inscribed ball (its surface and kernel computed by the same worker).
import { KernelWorker } from 'kergen-wasm/worker';
import { CellsView } from './cells-view.js';
import { coloring, cellColor, emptyCode, gradientCss, cssColor, NON_STAR_COLOR, ERROR_COLOR } from './cells-colors.js';
import { sampleVolumeMesh, volumeMeshToVtu } from './cells-sample.js';

const $ = (id) => document.getElementById(id);
const view = new CellsView($('viewport'));
const kw = new KernelWorker();
// timings: ms from the drop or click to each stage of the last run (for the benchmark).
const state = { mesh: null, result: null, name: '', run: 0, busy: false, selected: -1, timings: {} };
// For the browser tests: the view and the page's state, read-only by convention.
window.kergenCells = { view, state };

const fmt = (x, digits = 4) => (Number.isFinite(x) ? Number(x.toPrecision(digits)).toString() : '—');
const count = (n) => n.toLocaleString('en-US');

function setText(id, text, value = '') {
  const el = $(id);
  el.textContent = text;
  if ('value' in el.dataset || value !== '') el.dataset.value = String(value);
}

function setStatus(stateName, text) {
  const el = $('cells-status');
  el.dataset.state = stateName;
  el.textContent = text;
  $('busy').hidden = !['reading', 'computing'].includes(stateName);
  $('busy-text').textContent = text;
}

function showMessage(code, text, kind = 'error') {
  const el = $('cells-message');
  el.hidden = !text;
  el.dataset.code = code || '';
  el.dataset.kind = kind;
  el.textContent = text || '';
}

function setProgress(done, total) {
  $('cells-progress').max = Math.max(total, 1);
  $('cells-progress').value = done;
  $('cells-progress-text').textContent = total ? `${count(done)} / ${count(total)} cells` : '';
}

// ---- opening ---------------------------------------------------------------------------------

// The input of a set of chosen or dropped files: one .vtu / .vtk, or a .node with its .ele.
async function inputOfFiles(files) {
  const byExt = (ext) => files.find((f) => f.name.toLowerCase().endsWith(ext));
  const node = byExt('.node'),
    ele = byExt('.ele');
  if (node || ele) {
    if (!node || !ele)
      throw Object.assign(
        new Error(
          `${(node ?? ele).name}: a .node file and its .ele file are read together: choose or drop both at once`,
        ),
        { code: 'INVALID_ARGUMENT' },
      );
    const [n, e] = await Promise.all([node.arrayBuffer(), ele.arrayBuffer()]);
    return {
      input: { node: new Uint8Array(n), ele: new Uint8Array(e) },
      name: node.name,
      eleName: ele.name,
      label: `${node.name} + ${ele.name}`,
    };
  }
  const file = byExt('.vtu') ?? byExt('.vtk') ?? files[0];
  return { input: new Uint8Array(await file.arrayBuffer()), name: file.name, label: file.name };
}

async function openFiles(files) {
  if (!files.length) return;
  const started = performance.now();
  try {
    await open(await inputOfFiles(files), started);
  } catch (err) {
    fail(err);
  }
}

function openSample() {
  const started = performance.now();
  const bytes = new TextEncoder().encode(volumeMeshToVtu(sampleVolumeMesh()));
  open({ input: bytes, name: 'agglomerated-grid.vtu', label: 'agglomerated box grid (sample)' }, started);
}

// The workers computing the cells: one per core (at most 4), each on its own range of cells;
// the first also reads the files, joins the parts and computes a clicked cell.
const pool = [kw];
const poolSize = Math.max(1, Math.min(4, navigator.hardwareConcurrency || 2));
const PARALLEL_FROM_CELLS = 2000; // fewer cells: one worker (the others would cost more to start)
const DEEPEST_AUTO_CELLS = 20000; // "auto": inscribed balls up to this many cells (they cost ~5x)

function cancelAll() {
  for (const w of pool) w.cancel();
}

// The mesh's topology (cells-geometry.js), from a worker of its own: a second or more for 100k
// cells, which the page's thread would otherwise spend in one task.
let topologyWorker = null;
let topologyJobs = 0;
function topologyOf(mesh) {
  if (!topologyWorker)
    topologyWorker = new Worker(new URL('./cells-topology-worker.js', import.meta.url), { type: 'module' });
  const id = ++topologyJobs;
  return new Promise((resolve, reject) => {
    topologyWorker.onmessage = (e) => e.data.id === id && resolve(e.data.topology);
    topologyWorker.onerror = (e) => reject(new Error(`the topology worker failed: ${e.message}`));
    topologyWorker.postMessage({ id, mesh });
  });
}

// Cells first .. first + count - 1 in `parts` consecutive ranges of nearly equal size.
function split(count, parts) {
  const out = [];
  for (let i = 0, first = 0; i < parts; i++) {
    const n = Math.floor(count / parts) + (i < count % parts ? 1 : 0);
    out.push({ firstCell: first, count: n });
    first += n;
  }
  return out;
}

async function open({ input, name, eleName, label }, started) {
  if (state.busy) cancelAll();
  const run = ++state.run;
  state.busy = true;
  state.mesh = null;
  state.result = null;
  state.name = label;
  select(-1);
  showMessage('', '');
  $('cells-legend').hidden = true;
  $('cells-cancel').disabled = false;
  setText('sum-name', label);
  for (const id of ['sum-cells', 'sum-star', 'sum-nonstar', 'sum-errors', 'sum-ratio', 'sum-rho', 'sum-time'])
    setText(id, '—', '');
  setProgress(0, 0);
  setStatus('reading', `Reading ${label}…`);
  try {
    const mark = (what) => (state.timings[what] = Math.round(performance.now() - started));
    state.timings = {};
    const mesh = await kw.readVolumeMesh(input, { name, eleName, transfer: true });
    if (run !== state.run) return;
    mark('read');
    state.mesh = mesh;
    const numCells = mesh.cellOffsets.length ? mesh.cellOffsets.length - 1 : 0;
    setText('sum-cells', count(numCells), numCells);
    const mode = $('cells-deepest').value;
    const deepestPoint = mode === 'always' || (mode === 'auto' && numCells <= DEEPEST_AUTO_CELLS);
    setStatus(
      'computing',
      `Computing the kernels of ${count(numCells)} cells${deepestPoint ? ' and their inscribed balls' : ''}…`,
    );
    const workers = numCells < PARALLEL_FROM_CELLS ? 1 : poolSize;
    while (pool.length < workers) pool.push(new KernelWorker());
    const done = new Array(workers).fill(0);
    const jobs = split(numCells, workers).map(({ firstCell, count: n }, i) =>
      pool[i].computeCellKernels(mesh, {
        firstCell,
        count: n,
        deepestPoint,
        rangeSize: 500,
        onProgress: ({ phase, count: cells }) => {
          if (run !== state.run || phase !== 'cells') return;
          done[i] = cells;
          setProgress(
            done.reduce((a, b) => a + b, 0),
            numCells,
          );
        },
      }),
    );
    // Drawn while the workers compute (the mesh was copied to them as the jobs were posted).
    mark('posted');
    const topology = await topologyOf(mesh);
    mark('topology');
    if (run === state.run) view.setMesh(mesh, topology);
    mark('drawn');
    const parts = await Promise.all(jobs);
    if (run !== state.run) return;
    mark('cells');
    const result = parts.length === 1 ? parts[0] : await kw.joinCellKernels(parts);
    if (run !== state.run) return;
    mark('joined');
    state.result = result;
    const ms = performance.now() - started;
    setText('sum-time', ms >= 1000 ? `${(ms / 1000).toFixed(2)} s` : `${ms.toFixed(0)} ms`, ms.toFixed(0));
    setText('sum-workers', `${parts.length} worker${parts.length > 1 ? 's' : ''}`, parts.length);
    showSummary(result);
    applyColors();
    mark('coloured');
    setStatus('done', `${count(result.numCells)} cells computed.`);
  } catch (err) {
    if (run === state.run) {
      cancelAll();
      fail(err);
    }
  } finally {
    if (run === state.run) {
      state.busy = false;
      $('cells-cancel').disabled = true;
    }
  }
}

function fail(err) {
  const code = err && err.code ? err.code : 'ERROR';
  if (code === 'CANCELLED') {
    setStatus('cancelled', 'Cancelled.');
    return;
  }
  setStatus('error', 'The mesh could not be computed.');
  showMessage(code, `${code}: ${err && err.message ? err.message : err}`);
}

// ---- the results -----------------------------------------------------------------------------

function showSummary(result) {
  const s = result.summary;
  const empty = s.byType.EMPTY ?? 0;
  const errors = s.cells - s.okCells;
  setText('sum-cells', count(s.cells), s.cells);
  setText('sum-star', count(s.okCells - empty), s.okCells - empty);
  setText('sum-nonstar', count(empty), empty);
  setText(
    'sum-errors',
    errors
      ? `${count(errors)} (${Object.entries(s.byError)
          .map(([k, n]) => `${k} ${n}`)
          .join(', ')})`
      : '0',
    errors,
  );
  setText(
    'sum-ratio',
    s.okCells ? `min ${fmt(s.minRatio)} · median ${fmt(s.medianRatio)} · max ${fmt(s.maxRatio)}` : '—',
  );
  setText(
    'sum-rho',
    s.hasRhoOverH
      ? `min ${fmt(s.minRhoOverH)} · median ${fmt(s.medianRhoOverH)} · max ${fmt(s.maxRhoOverH)}`
      : 'not computed',
  );
  $('cells-colour-by').querySelector('option[value="rho"]').disabled = !s.hasRhoOverH;
  if (!s.hasRhoOverH) $('cells-colour-by').value = 'ratio';
  if (result.errors.length) {
    const first = result.errors[0];
    showMessage(first.code, `${count(result.errors.length)} cell(s) without a kernel; first: ${first.message}`, 'info');
  }
}

function applyColors() {
  const result = state.result;
  if (!result) return;
  const col = coloring(result, $('cells-colour-by').value);
  const empty = emptyCode(result);
  view.setColors(
    (c) => cellColor(result, col, c, empty),
    (c) => result.status[c] === empty,
  );
  const legend = $('cells-legend');
  legend.hidden = false;
  legend.dataset.by = col.by;
  $('legend-label').textContent = col.label;
  $('legend-bar').style.background = gradientCss();
  setText('legend-min', fmt(col.min, 3));
  setText('legend-mid', fmt((col.min + col.max) / 2, 3));
  setText('legend-max', fmt(col.max, 3));
  $('legend-nonstar-swatch').style.background = cssColor(NON_STAR_COLOR);
  $('legend-error-swatch').style.background = cssColor(ERROR_COLOR);
  setText('legend-nonstar', count(result.summary.byType.EMPTY ?? 0), result.summary.byType.EMPTY ?? 0);
  setText(
    'legend-errors',
    count(result.summary.cells - result.summary.okCells),
    result.summary.cells - result.summary.okCells,
  );
}

// ---- one cell --------------------------------------------------------------------------------

async function select(c) {
  state.selected = c;
  const panel = $('cells-selected');
  panel.dataset.cell = c >= 0 ? String(c) : '';
  panel.dataset.shown = '';
  if (c < 0 || !state.result) {
    panel.hidden = true;
    view.clearCell();
    return;
  }
  const r = state.result;
  const i = c - r.firstCell;
  panel.hidden = false;
  panel.scrollIntoView({ block: 'nearest' }); // the numbers in sight, on a phone too
  $('sel-cell').textContent = String(c);
  const status = r.statusNames[r.status[i]];
  setText('sel-status', status, status);
  setText('sel-kernel-volume', fmt(r.kernelVolume[i], 6), r.kernelVolume[i]);
  setText('sel-cell-volume', fmt(r.cellVolume[i], 6), r.cellVolume[i]);
  setText('sel-ratio', fmt(r.kernelRatio[i]), r.kernelRatio[i]);
  setText('sel-h', fmt(r.diameter[i], 6), r.diameter[i]);
  setText('sel-rho', r.summary.hasRhoOverH ? fmt(r.inscribedRadius[i], 6) : 'not computed', r.inscribedRadius[i]);
  setText('sel-rho-h', r.summary.hasRhoOverH ? fmt(r.rhoOverH[i]) : 'not computed', r.rhoOverH[i]);
  const witness = [...r.witnessGlobalFaces.subarray(r.witnessOffsets[i], r.witnessOffsets[i + 1])];
  setText('sel-witness', witness.length ? `faces ${witness.join(', ')}` : '—', witness.join(' '));
  const error = r.errors.find((e) => e.cell === c);
  $('sel-note').textContent = error
    ? error.message
    : r.reoriented[i]
      ? 'Its faces were turned outward for the computation.'
      : '';
  try {
    const surface = await kw.cellSurface(state.mesh, c);
    const kernel = await kw.compute(surface.positions, surface.indices, {
      faceSizes: surface.faceSizes,
      deepestPoint: true,
    });
    if (state.selected !== c) return;
    view.showCell(surface, kernel);
    panel.dataset.shown = 'kernel';
    panel.dataset.kernelVolume = String(kernel.volume);
    panel.dataset.witnessFaces = String(kernel.witnessFaces.length);
  } catch (err) {
    if (state.selected !== c) return;
    panel.dataset.shown = 'error';
    $('sel-note').textContent = `${err.code ?? 'ERROR'}: ${err.message}`;
  }
}

// ---- controls --------------------------------------------------------------------------------

$('cells-open').addEventListener('click', () => $('cells-file').click());
$('cells-file').addEventListener('change', (e) => {
  openFiles([...e.target.files]);
  e.target.value = '';
});
$('cells-sample').addEventListener('click', openSample);
$('cells-cancel').addEventListener('click', () => {
  if (!state.busy) return;
  state.run++;
  state.busy = false;
  $('cells-cancel').disabled = true;
  cancelAll();
  setStatus('cancelled', 'Cancelled.');
});
$('cells-colour-by').addEventListener('change', applyColors);
const applyFilter = () => {
  $('cells-cut-label').textContent = `${Math.round(100 * Number($('cells-cut').value))} %`;
  view.setFilter({
    axis: Number($('cells-cut-axis').value),
    cut: Number($('cells-cut').value),
    onlyNonStar: $('cells-only-nonstar').checked,
  });
};
for (const id of ['cells-cut', 'cells-cut-axis', 'cells-only-nonstar']) $(id).addEventListener('input', applyFilter);
$('cells-back').addEventListener('click', () => select(-1));
window.addEventListener('keydown', (e) => {
  if (e.key === 'Escape') select(-1);
});

// A click (not a drag) on the view selects the cell under it.
const canvas = view.renderer.domElement;
let down = null;
canvas.addEventListener('pointerdown', (e) => (down = { x: e.clientX, y: e.clientY }));
canvas.addEventListener('pointerup', (e) => {
  if (!down || Math.hypot(e.clientX - down.x, e.clientY - down.y) > 4 || !state.result) return;
  const c = view.pick(e.clientX, e.clientY);
  if (c >= 0) select(c);
});

const viewport = $('viewport');
viewport.addEventListener('dragover', (e) => {
  e.preventDefault();
  $('drop-overlay').hidden = false;
});
viewport.addEventListener('dragleave', () => ($('drop-overlay').hidden = true));
viewport.addEventListener('drop', (e) => {
  e.preventDefault();
  $('drop-overlay').hidden = true;
  openFiles([...e.dataTransfer.files]);
});

if (new URLSearchParams(location.search).get('sample') !== 'none') openSample();
