// Test-only: a minimal Web Worker (`new Worker(url, { type: 'module' })`) on top of Node's
// worker_threads, so that KernelWorker and kergen-worker.js run unmodified in Node tests.
// It records every message the worker posts (for batching assertions).
import { Worker as NodeWorker } from 'node:worker_threads';

const bootstrap = new URL('./worker-bootstrap.mjs', import.meta.url);

export class WebWorkerShim {
  static spawned = [];

  constructor(url, options = {}) {
    if (options.type !== 'module') throw new Error('the package must spawn a module worker');
    this.url = String(url);
    this.received = [];
    this.onmessage = null;
    this.onerror = null;
    this.terminated = false;
    this._w = new NodeWorker(bootstrap, { workerData: { url: this.url } });
    this._w.on('message', (data) => {
      this.received.push(data);
      if (this.onmessage) this.onmessage({ data });
    });
    this._w.on('error', (err) => {
      if (this.onerror) this.onerror({ message: err.message, error: err, preventDefault() {} });
    });
    WebWorkerShim.spawned.push(this);
  }

  postMessage(data, transfer) {
    this._w.postMessage(data, transfer);
  }

  terminate() {
    this.terminated = true;
    this._w.terminate();
  }
}

export function installWorkerShim() {
  globalThis.Worker = WebWorkerShim;
}
