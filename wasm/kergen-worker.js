// The module worker spawned by KernelWorker (worker.js). It loads the wasm module once and runs
// one job per message: a computation on arrays ('compute'), a file read + computation
// ('computeFile': the bytes are parsed here, so a big file never costs the page's thread), or a
// mesh written to file bytes ('writeMesh'), or the mesh after weld and repair ('repairMesh').
// Step events are forwarded in batches of typed arrays (step-batch.js; every ~50 ms or 4096
// events: a kernel of a million steps is a few hundred messages of transferred buffers, which the
// page receives without cloning an object per event), and result buffers are transferred back.
//
// Protocol (main → worker):  { type: 'init', wasmUrl? }
//                            { type: 'compute', id, wasmUrl?, positions, indices, faceSizes?, options, wantSteps }
//                            { type: 'computeFile', id, wasmUrl?, bytes, format?, name?, options, wantSteps, wantMesh }
//                            { type: 'writeMesh', id, wasmUrl?, mesh, format }
//                            { type: 'repairMesh', id, wasmUrl?, positions, indices, faceSizes?, options }
// Protocol (worker → main):  { type: 'steps', id, batch, steps }     (batch: step-batch.js)
//                            { type: 'progress', id, phase, steps, count?, bytes? }
//                            { type: 'mesh', id, mesh }                  (computeFile with wantMesh, before computing)
//                            { type: 'result', id, result, mesh? }  |  { type: 'error', id, code, message }
import * as kergen from './index.js';
import { StepBatchWriter, batchBuffers } from './step-batch.js';
import { cellHandlers } from './kergen-worker-cells.js';

const { init, computeKernelSync, KergenError } = kergen;

const BATCH_EVENTS = 4096;
const BATCH_MS = 50;

let ready = null;
function ensureInit(wasmUrl) {
  if (!ready) {
    ready = init(wasmUrl ? { wasmUrl } : {}).catch((err) => {
      ready = null;
      throw err;
    });
  }
  return ready;
}

// readMeshSync / writeMesh come from the package's file layer; looked up at call time so this
// worker still loads (and computes on arrays) with a package build that lacks them.
function packageFunction(name) {
  const fn = kergen[name];
  if (typeof fn !== 'function') throw new KergenError('UNSUPPORTED', `this build of kergen-wasm has no ${name}()`);
  return fn;
}

const now = typeof performance !== 'undefined' ? () => performance.now() : () => Date.now();

function resultTransferables(result) {
  const list = [
    result.vertices.buffer,
    result.edges.buffer,
    result.triangles.buffer,
    result.faceIndices.buffer,
    result.faceSizes.buffer,
    result.witnessFaces.buffer,
    result.faceSources.buffer,
    result.witnessBoundaryEdges.buffer,
  ];
  return list.filter((b) => b.byteLength > 0); // may repeat a buffer: see unique()
}

// The result's arrays can share one buffer, and a transfer list must not repeat one.
const unique = (buffers) => [...new Set(buffers)];

function meshTransferables(mesh) {
  return [mesh.positions.buffer, mesh.indices.buffer, mesh.faceSizes && mesh.faceSizes.buffer].filter(
    (b) => b && b.byteLength > 0,
  );
}

const copyMesh = (mesh) => ({
  positions: mesh.positions.slice(),
  indices: mesh.indices.slice(),
  faceSizes: mesh.faceSizes ? mesh.faceSizes.slice() : null,
});

// Runs computeKernelSync with batched step events and phase progress posted for job `id`.
function computeWithEvents(id, positions, indices, faceSizes, msg) {
  let steps = 0;
  const batch = msg.wantSteps ? new StepBatchWriter(BATCH_EVENTS) : null;
  let lastFlush = now();
  const flush = () => {
    if (batch && batch.count > 0) {
      const events = batch.take();
      self.postMessage({ type: 'steps', id, batch: events, steps }, batchBuffers(events));
    }
    self.postMessage({ type: 'progress', id, phase: 'tracing', steps });
    lastFlush = now();
  };
  // The clock is read every 64 steps: a step costs far less than reading it.
  const onStep = (event) => {
    steps++;
    if (batch) batch.push(event);
    if ((batch && batch.count >= BATCH_EVENTS) || ((steps & 63) === 0 && now() - lastFlush >= BATCH_MS)) flush();
  };
  // The core announces each phase once as it begins, with the number of items it works on.
  const onProgress = ({ phase, count }) => {
    self.postMessage({ type: 'progress', id, phase, steps, count });
  };
  const options = { ...msg.options, onStep, onProgress };
  if (faceSizes != null) options.faceSizes = faceSizes;
  const result = computeKernelSync(positions, indices, options);
  if (steps > 0) flush();
  self.postMessage({ type: 'progress', id, phase: 'done', steps });
  return result;
}

async function handleCompute(msg) {
  const { id } = msg;
  self.postMessage({ type: 'progress', id, phase: 'loading', steps: 0 });
  await ensureInit(msg.wasmUrl);
  self.postMessage({ type: 'progress', id, phase: 'computing', steps: 0 });
  const result = computeWithEvents(id, msg.positions, msg.indices, msg.faceSizes, msg);
  self.postMessage({ type: 'result', id, result }, unique(resultTransferables(result)));
}

async function handleComputeFile(msg) {
  const { id } = msg;
  self.postMessage({ type: 'progress', id, phase: 'loading', steps: 0 });
  await ensureInit(msg.wasmUrl);
  const bytes = msg.bytes instanceof ArrayBuffer ? new Uint8Array(msg.bytes) : msg.bytes;
  self.postMessage({ type: 'progress', id, phase: 'reading', steps: 0, bytes: bytes.byteLength });
  const readOptions = {};
  if (msg.format != null) readOptions.format = msg.format;
  if (msg.name != null) readOptions.name = msg.name;
  const mesh = packageFunction('readMeshSync')(bytes, readOptions);
  // The page can draw the input while the kernel is computed: send it a copy now, and the
  // original (which the computation only reads) with the result.
  if (msg.wantMesh) {
    const early = copyMesh(mesh);
    self.postMessage({ type: 'mesh', id, mesh: early }, unique(meshTransferables(early)));
  }
  const result = computeWithEvents(id, mesh.positions, mesh.indices, mesh.faceSizes, msg);
  self.postMessage(
    { type: 'result', id, result, mesh },
    unique([...resultTransferables(result), ...meshTransferables(mesh)]),
  );
}

async function handleWriteMesh(msg) {
  await ensureInit(msg.wasmUrl);
  const bytes = packageFunction('writeMesh')(msg.mesh, msg.format);
  self.postMessage({ type: 'result', id: msg.id, result: bytes }, [bytes.buffer]);
}

async function handleRepairMesh(msg) {
  await ensureInit(msg.wasmUrl);
  const options = { ...msg.options };
  if (msg.faceSizes != null) options.faceSizes = msg.faceSizes;
  const repaired = packageFunction('repairMeshSync')(msg.positions, msg.indices, options);
  self.postMessage({ type: 'result', id: msg.id, result: repaired }, unique(meshTransferables(repaired)));
}

// Many meshes (the package's computeKernelsSync): progress after every range; each entry a
// result (its arrays transferred) or a mesh's error as { code, message }.
async function handleComputeKernels(msg) {
  const { id } = msg;
  self.postMessage({ type: 'progress', id, phase: 'loading', steps: 0 });
  await ensureInit(msg.wasmUrl);
  const onProgress = ({ phase, count, total }) =>
    self.postMessage({ type: 'progress', id, phase, steps: 0, count, total });
  const options = { ...msg.options, ...msg.batchOptions, onProgress };
  const results = packageFunction('computeKernelsSync')(msg.meshes, options);
  self.postMessage({ type: 'progress', id, phase: 'done', steps: 0 });
  const transfer = [];
  const entries = results.map((r) => {
    if (r instanceof KergenError) return { code: r.code, message: r.message };
    transfer.push(...resultTransferables(r));
    const { faces: _faces, ...plain } = r; // rebuilt on the page from faceIndices
    return plain;
  });
  self.postMessage({ type: 'result', id, result: entries }, unique(transfer));
}

const HANDLERS = {
  compute: handleCompute,
  computeFile: handleComputeFile,
  writeMesh: handleWriteMesh,
  repairMesh: handleRepairMesh,
  computeKernels: handleComputeKernels,
  ...cellHandlers(ensureInit), // volume meshes: kergen-worker-cells.js
};

self.onmessage = (e) => {
  const msg = e.data;
  if (!msg || typeof msg !== 'object') return;
  if (msg.type === 'init') {
    // Warm up; a failure is reported by the next job.
    ensureInit(msg.wasmUrl).catch(() => {});
    return;
  }
  const handler = HANDLERS[msg.type];
  if (!handler) return;
  handler(msg).catch((err) => {
    const code = err instanceof KergenError ? err.code : 'INTERNAL_ERROR';
    const message = err && err.message ? err.message : String(err);
    self.postMessage({ type: 'error', id: msg.id, code, message });
  });
};
