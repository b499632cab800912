// The module worker spawned by KernelWorker (worker.js). It loads the wasm module once, runs one
// computation per 'compute' message, forwards step events in batches (every ~16 ms or 256 events,
// so a huge kernel does not flood the main thread) and transfers the result's buffers back.
//
// Protocol (main → worker):  { type: 'init', wasmUrl? }
//                            { type: 'compute', id, wasmUrl?, positions, indices, faceSizes?, options, wantSteps }
// Protocol (worker → main):  { type: 'steps', id, events, steps }
//                            { type: 'progress', id, phase, steps }
//                            { type: 'result', id, result }  |  { type: 'error', id, code, message }
import { init, computeKernelSync, KergenError } from './index.js';

const BATCH_EVENTS = 256;
const BATCH_MS = 16;

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

const now = typeof performance !== 'undefined' ? () => performance.now() : () => Date.now();

function transferables(result) {
  const list = [result.vertices.buffer, result.edges.buffer, result.triangles.buffer, result.faceIndices.buffer, result.faceSizes.buffer];
  return [...new Set(list)].filter((b) => b.byteLength > 0);
}

async function handleCompute(msg) {
  const { id } = msg;
  self.postMessage({ type: 'progress', id, phase: 'loading', steps: 0 });
  await ensureInit(msg.wasmUrl);
  self.postMessage({ type: 'progress', id, phase: 'computing', steps: 0 });

  let steps = 0;
  let batch = [];
  let lastFlush = now();
  const flush = () => {
    if (msg.wantSteps && batch.length > 0) {
      self.postMessage({ type: 'steps', id, events: batch, steps });
      batch = [];
    }
    self.postMessage({ type: 'progress', id, phase: 'tracing', steps });
    lastFlush = now();
  };
  const onStep = (event) => {
    steps++;
    if (msg.wantSteps) batch.push(event);
    if (batch.length >= BATCH_EVENTS || now() - lastFlush >= BATCH_MS) flush();
  };

  const options = { ...msg.options, onStep };
  if (msg.faceSizes != null) options.faceSizes = msg.faceSizes;
  const result = computeKernelSync(msg.positions, msg.indices, options);
  if (steps > 0) flush();
  self.postMessage({ type: 'progress', id, phase: 'done', steps });
  self.postMessage({ type: 'result', id, result }, transferables(result));
}

self.onmessage = (e) => {
  const msg = e.data;
  if (!msg || typeof msg !== 'object') return;
  if (msg.type === 'init') {
    // Warm up; a failure is reported by the next 'compute'.
    ensureInit(msg.wasmUrl).catch(() => {});
    return;
  }
  if (msg.type === 'compute') {
    handleCompute(msg).catch((err) => {
      const code = err instanceof KergenError ? err.code : 'INTERNAL_ERROR';
      const message = err && err.message ? err.message : String(err);
      self.postMessage({ type: 'error', id: msg.id, code, message });
    });
  }
};
