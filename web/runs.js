// One computation (in the workers of workers.js): the run's lifecycle (begin, step
// events, finish or fail) and what a finished run draws (open edges, witness faces, box facets).

import { applySection } from './controls.js';
import { faceHighlight, openEdgeLines, prepareDrawing } from './draw-prep.js';
import {
  DRAW_TRIANGLES,
  EDGE_FACES,
  INLINE_FACES,
  KERNEL_DRAW_TRIANGLES,
  KERNEL_SIMPLIFY_TRIANGLES,
  STREAM,
  state,
  ui,
  viewer,
} from './page-state.js';
import {
  clearStats,
  fmtCount,
  hideMessage,
  onProgress,
  setBusy,
  setExportEnabled,
  setStat,
  setStatus,
  showCancelled,
  showError,
  showOutcome,
  showRows,
  showStats,
} from './page-text.js';
import { setPlayButton } from './playback.js';
import { boxFaceIds, edgeLines } from './face-sources.js';
import { clearFaceInfo } from './face-info.js';
import { hideAlternatives, offerAlternatives } from './trials.js';
import { drawRequest } from './workers.js';

// Stops whatever is running and starts a new run; returns its token.
export function beginRun(name) {
  state.token++;
  // KernelWorker.cancel() terminates the busy worker thread and starts a fresh one (same object).
  // So are the trials of a refusal's alternatives (trials.js).
  if ((state.computing || state.trying) && state.worker) state.worker.cancel();
  state.trying = false;
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
  viewer.setWitnessEdges(null);
  viewer.setOpenEdges(null);
  viewer.setKernelClosed(false);
  hideMessage();
  hideAlternatives();
  clearFaceInfo();
  ui.faceHint.hidden = true;
  clearStats();
  setStat('stat-name', name);
  showRows(['name', 'input-faces']);
  ui.cancel.disabled = false;
  setExportEnabled(false);
  setPlayButton();
  return state.token;
}

export function endRun() {
  state.computing = false;
  ui.cancel.disabled = true;
  setBusy('');
}

// A run that ends without a kernel (error or cancel): nothing to play.
export function stopPlayback() {
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
export async function showMesh(mesh, token) {
  const faces = mesh.faceSizes ? mesh.faceSizes.length : mesh.indices.length / 3;
  setStat(
    'stat-input-faces',
    `${fmtCount(faces)} ${mesh.faceSizes ? 'face' : 'triangle'}${faces === 1 ? '' : 's'} (${fmtCount(mesh.positions.length / 3)} ${mesh.positions.length === 3 ? 'vertex' : 'vertices'})`,
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

// Runs one computation (`start(callbacks)` calls the worker) and shows its outcome.
export async function runKernel(token, start) {
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
  // The drawn input first: the open edges are drawn on it, and the alternatives reopen it.
  if (state.inputPromise) await state.inputPromise.catch(() => {});
  if (token !== state.token) return;
  if (!state.inputShown) viewer.clearInput();
  if (err?.code === 'OPEN_MESH' && state.inputShown) await showOpenEdges(token);
  if (token !== state.token) return;
  showError(err);
  await offerAlternatives(err?.code, token);
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
  const simplified = simplifiedKernel(result);
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
    const ids = boxFaceIds(result, state.drawing?.maxAbs ?? 0);
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
  if (result.status === 'EMPTY' && state.runOptions.walls) {
    // Empty with walls: the open edges (where the walls stand) in red, the walls' boundary edges
    // in the witness in magenta, and the kernel without walls when it was tried (the walls may be
    // what empties it).
    await showOpenEdges(token);
    if (token !== state.token) return;
    const pairs = result.witnessBoundaryEdges;
    const positions = state.input?.mesh.positions ?? state.mesh?.positions;
    if (pairs?.length && positions) {
      const { lines, mids } = edgeLines(positions, pairs, state.drawing?.center ?? [0, 0, 0]);
      viewer.setWitnessEdges(lines, mids);
    }
    Object.assign(extra, {
      walls: true,
      openEdges: state.openEdges,
      witnessEdges: pairs ? pairs.length / 2 : 0,
      openSurface: state.trials?.trials.allowOpen,
    });
  }
  const simple = await simplified;
  if (token !== state.token) return;
  if (simple?.positions) {
    viewer.kernel.setSimplified(simple.positions, simple.triangles);
    ui.edgesNote.textContent +=
      ` The whole kernel (${fmtCount(result.triangles.length / 3)} triangles) is drawn from a simplified copy` +
      ` (${fmtCount(simple.triangles.length / 3)} triangles); its numbers and exports are exact.`;
  }
  showStats(result, wall, V, E, F);
  showOutcome(result, V, E, F, extra);
}

// A big kernel's display copy, made in the drawing worker (null for a small one).
function simplifiedKernel(result) {
  if (!(result.triangles?.length / 3 > KERNEL_SIMPLIFY_TRIANGLES)) return null;
  const vertices = result.vertices.slice(),
    triangles = result.triangles.slice();
  return drawRequest(
    {
      type: 'simplify',
      vertices,
      triangles,
      center: viewer.kernel.offset.toArray(),
      maxTriangles: KERNEL_DRAW_TRIANGLES,
    },
    [vertices.buffer, triangles.buffer],
  );
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
