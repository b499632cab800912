// Sources: a sample, a file (picked or dropped), a link (?url=), each kept in state.source so
// that it can be computed again with other options (the retry buttons); the file picker, drag &
// drop and the sample buttons.

import { updateShareUrl } from './controls.js';
import { isGltfName, readGltf } from './gltf.js';
import { INLINE_FACES, state, ui, viewer } from './page-state.js';
import { fmtBytes, setBusy, setStatus, showCancelled, showError } from './page-text.js';
import { beginRun, endRun, runKernel, showMesh, stopPlayback } from './runs.js';
import { worker } from './workers.js';
import { SAMPLES, sampleById } from './samples.js';
import { ALTERNATIVES, kernelOptions as optionsFor } from './alternatives.js';

const kernelOptions = () => optionsFor(state.runOptions);

// Meshes up to this many faces are kept on this thread after a refusal's run, so that what the
// refusal proposes can be tried in the worker before it is offered (trials.js).
const TRY_FACES = 200000;
const faceCount = (mesh) => (mesh.faceSizes ? mesh.faceSizes.length : mesh.indices.length / 3);

/**
 * Opens `source` ({ kind: 'sample', id } | { kind: 'file', file } | { kind: 'url', url, file })
 * and computes its kernel with `options` ({ allowOpen, repair, walls }: walls is open: 'perpendicular').
 */
export async function openSource(
  source,
  options = { allowOpen: false, repair: false, walls: false, weld: false, flipFaces: false },
  t0 = performance.now(),
) {
  // What was tried after a refusal stays known while the same input is computed again.
  if (state.trials?.source !== source) state.trials = null;
  state.input = null;
  state.source = source;
  state.runOptions = options;
  selectSample(source.kind === 'sample' ? source.id : null);
  const token = beginRun(sourceName(source));
  state.t0 = t0;
  updateShareUrl();
  state.inputPromise = null;
  if (source.kind === 'sample') {
    const mesh = sampleById(source.id).build();
    showMesh(mesh, token); // samples are small: drawn right here
    state.input = { mesh, options: {} };
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
          if (token !== state.token) return;
          // A big mesh's arrays move to the drawing worker (showMesh): the trials keep a copy.
          const faces = faceCount(mesh);
          const copy = (a) => (faces > INLINE_FACES ? a?.slice() : a);
          if (faces <= TRY_FACES)
            state.input = {
              mesh: { positions: copy(mesh.positions), indices: copy(mesh.indices), faceSizes: copy(mesh.faceSizes) },
              options: /\.stl$/i.test(name) ? { weld: true } : {},
            };
          state.inputPromise = showMesh(mesh, token);
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
  if (faceCount(mesh) <= TRY_FACES) state.input = { mesh, options: { weld: true } };
  // A big mesh's arrays are moved to the drawing worker: it gets copies, the kernel worker these.
  state.inputPromise = showMesh({ positions: mesh.positions.slice(), indices: mesh.indices.slice() }, token);
  await runKernel(token, (callbacks) =>
    worker().compute(mesh.positions, mesh.indices, { weld: true, ...kernelOptions(), ...callbacks }),
  );
}

// ?url=: fetched here (the server must allow this page's origin: CORS), then opened as a file.
export async function openUrl(text, options) {
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
  // A server that answers every path with its site (a relative link to a file it does not have)
  // sends a web page: said as such, not as a mesh file's parse error.
  if (await isWebPage(response, blob))
    return fail(`this URL returned a web page, not a mesh: ${url.href} (is the address of the file right?)`);
  await openSource({ kind: 'url', url: url.href, file: new File([blob], name) }, options, t0);
}

// An HTML answer: it starts with a tag (no mesh format does), and says text/html or looks like a
// page. A mesh file served with a wrong Content-Type is still read.
async function isWebPage(response, blob) {
  const head = new TextDecoder().decode(await blob.slice(0, 512).arrayBuffer()).replace(/^\uFEFF/, '');
  if (!/^\s*</.test(head)) return false;
  return (
    /^\s*text\/html/i.test(response.headers.get('content-type') ?? '') || /<!doctype html|<html|<head|<body/i.test(head)
  );
}

const sourceName = (source) => (source.kind === 'sample' ? sampleById(source.id).name : source.file.name);

// The same input again with the options of alternative `alt` (the retry buttons). When the trials
// computed it, its result is shown as it came (its steps replayed from it), not computed again.
function reopen(alt) {
  const source = state.source;
  if (!source) return;
  const options = { ...state.runOptions, ...ALTERNATIVES[alt].options };
  const result = state.trials?.source === source && state.input ? state.trials.results?.[alt] : null;
  if (!result) return openSource(source, options);
  delete state.trials.results[alt]; // its arrays go to the view (and the drawing worker) once
  showTried(source, options, result);
}

async function showTried(source, options, result) {
  state.runOptions = options;
  const token = beginRun(sourceName(source));
  state.t0 = performance.now();
  state.timing.tried = true;
  updateShareUrl();
  // The kept input is drawn again; a big one's arrays move to the drawing worker: it gets copies.
  const { mesh } = state.input;
  const copy = (a) => (faceCount(mesh) > INLINE_FACES ? a?.slice() : a);
  state.inputPromise = showMesh(
    { positions: copy(mesh.positions), indices: copy(mesh.indices), faceSizes: copy(mesh.faceSizes) },
    token,
  );
  await runKernel(token, () => Promise.resolve(result));
}
// Each button runs the alternative it was offered for (trials.js sets data-alt).
for (const [id, fallback] of [
  ['retryOpen', 'allowOpen'],
  ['retryWalls', 'walls'],
  ['retryRepair', 'repair'],
  ['retryWeld', 'weld'],
  ['retryFlip', 'flipWalls'],
])
  ui[id].addEventListener('click', () => reopen(ui[id].dataset.alt || fallback));

function selectSample(id) {
  for (const b of ui.samples.querySelectorAll('button')) {
    b.classList.toggle('active', b.dataset.sample === id);
    b.setAttribute('aria-pressed', String(b.dataset.sample === id));
  }
}

ui.cancel.addEventListener('click', () => {
  if ((state.computing || state.trying) && state.worker) {
    // compute() rejects with CANCELLED → message shown by failRun (a run) or trials.js (trials)
    state.worker.cancel();
  } else if (!ui.cancel.disabled) {
    state.token++; // still reading the file: drop the run
    endRun();
    stopPlayback();
    showCancelled();
  }
});

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
