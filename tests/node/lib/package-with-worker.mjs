// The package and its worker helper in one test file: registers the node:test hooks that install
// the Web Worker shim, import wasm/index.js and wasm/worker.js and init() the module before the
// file's tests (then hand both modules to `onReady`), and dispose every worker made by
// newWorker() after them.
import { before, after } from 'node:test';
import { assertBuilt } from './env.mjs';
import { installWorkerShim } from './web-worker-shim.mjs';

export function usePackageWithWorker(onReady) {
  const workers = [];
  let W;
  before(async () => {
    assertBuilt();
    installWorkerShim();
    const K = await import('../../../wasm/index.js');
    W = await import('../../../wasm/worker.js');
    await K.init();
    onReady({ K, W });
  });
  after(() => {
    for (const w of workers) w.dispose();
  });
  return {
    /** A KernelWorker disposed after the file's tests. */
    newWorker(options) {
      const w = new W.KernelWorker(options);
      workers.push(w);
      return w;
    },
  };
}
