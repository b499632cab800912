// The page's two workers: the kernel worker (kergen-wasm's KernelWorker, one per page, kept in
// state.worker so that a new run can cancel the busy one) and the drawing worker (draw-worker.js),
// whose replies are matched to requests by id. Every module that computes or draws imports them
// from here; nothing here imports the page's other modules but its state.

import { KernelWorker } from 'kergen-wasm/worker';
import { state } from './page-state.js';

export function worker() {
  state.worker ??= new KernelWorker();
  return state.worker;
}

// The drawing worker, and its replies by request id.
const draw = { worker: null, nextId: 1, waiting: new Map() };
export function drawRequest(message, transfer = []) {
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
