// Sources: a sample, a file (picked or dropped), a link (?url=), each kept in state.source so
// that it can be computed again with other options (the retry buttons); the file picker, drag &
// drop and the sample buttons.

import { updateShareUrl } from './controls.js';
import { isGltfName, readGltf } from './gltf.js';
import { state, ui, viewer } from './page-state.js';
import { fmtBytes, setBusy, setStatus, showCancelled, showError } from './page-text.js';
import { beginRun, endRun, runKernel, showMesh, stopPlayback, worker } from './runs.js';
import { SAMPLES, sampleById } from './samples.js';

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
export async function openSource(
  source,
  options = { allowOpen: false, repair: false, walls: false },
  t0 = performance.now(),
) {
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
