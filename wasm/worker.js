// kergen-wasm/worker — run kernel computations off the main thread.
//
//   import { KernelWorker } from 'kergen-wasm/worker';
//   const kw = new KernelWorker();
//   const result = await kw.compute(positions, indices, { onStep, onProgress });
//   const { mesh, result } = await kw.computeFile(await file.arrayBuffer(), { name: file.name, onProgress });
//   const stl = await kw.writeMesh(result, 'stl');   // Uint8Array: the file's bytes
//   kw.cancel();   // stop the running computation (its promise rejects with code 'CANCELLED')
//   kw.dispose();  // terminate for good
//
// The input arrays are *copied* to the worker: the caller's arrays (a three.js geometry's
// attribute arrays, say) stay usable. `{ transfer: true }` transfers whole-buffer typed arrays
// instead (no copy; they are detached in the caller); so for computeFile's bytes. Step events
// arrive in batches of typed arrays (every ~50 ms or 4096 events; step-batch.js) and are replayed
// in order through onStep on the main thread, as event objects.
import { KergenError } from './errors.js';
import { forEachStep } from './step-batch.js';
import { OPTION_NAMES } from './option-names.js';
import { installCellMethods } from './worker-cells.js';

// The marks of result.faceSources (as the package's main entry exports them), for pages that use
// only the worker.
export { FACE_SOURCE_BOX, FACE_SOURCE_WALL } from '../dist/constants.js';

function isDetached(buffer) {
  if (buffer.byteLength !== 0) return false;
  try {
    new Uint8Array(buffer); // throws on a detached buffer
    return false;
  } catch {
    return true;
  }
}

// What is posted for one input array. By default a copy of its own (a view into a larger buffer
// would otherwise be cloned with its whole buffer), whose buffer is then transferred. With
// `transfer`, a typed array that owns its whole buffer is transferred as it is (detached here).
function toTransferable(fn, name, arr, wantTransfer, transfer) {
  if (arr == null) return arr;
  if (!ArrayBuffer.isView(arr)) return arr; // plain arrays are structured-cloned
  if (isDetached(arr.buffer)) {
    throw new KergenError(
      'INVALID_ARGUMENT',
      `${fn}: ${name} is detached: its buffer was transferred to the worker by an earlier call with { transfer: true }`,
    );
  }
  if (arr.byteLength === 0) return arr;
  const whole = arr.byteOffset === 0 && arr.byteLength === arr.buffer.byteLength;
  const shared = typeof SharedArrayBuffer !== 'undefined' && arr.buffer instanceof SharedArrayBuffer;
  const own = wantTransfer && whole && !shared ? arr : arr.slice(); // never detach a buffer we do not fully own
  transfer.push(own.buffer);
  return own;
}

// `transfer: true` moves the caller's buffers; `copy` is the default and still accepted (it was
// the opt-out when transferring was the default).
function wantsTransfer(fn, options) {
  const { copy, transfer } = options;
  if (transfer != null && typeof transfer !== 'boolean')
    throw new KergenError('INVALID_ARGUMENT', `${fn}: options.transfer must be a boolean`);
  if (copy != null && typeof copy !== 'boolean')
    throw new KergenError('INVALID_ARGUMENT', `${fn}: options.copy must be a boolean`);
  if (transfer && copy)
    throw new KergenError(
      'INVALID_ARGUMENT',
      `${fn}: options.copy and options.transfer contradict each other (copying is the default)`,
    );
  return transfer === true;
}

function resolveUrl(url) {
  if (url == null) return undefined;
  const base = typeof location !== 'undefined' && location ? location.href : undefined;
  try {
    return new URL(String(url), base).href;
  } catch {
    return String(url);
  }
}

function rebuildResult(r) {
  const faces = new Array(r.faceSizes.length);
  for (let f = 0, at = 0; f < r.faceSizes.length; f++) {
    faces[f] = r.faceIndices.subarray(at, at + r.faceSizes[f]);
    at += r.faceSizes[f];
  }
  return { ...r, faces };
}

export class KernelWorker {
  /** @param {{ wasmUrl?: string | URL }} [options] */
  constructor(options = {}) {
    this._wasmUrl = resolveUrl(options && options.wasmUrl);
    this._jobs = new Map();
    this._nextId = 1;
    this._disposed = false;
    this._spawn();
  }

  _spawn() {
    if (typeof Worker !== 'function') {
      throw new KergenError(
        'WORKER_ERROR',
        'KernelWorker needs Web Workers (a browser, a worker or Deno); in Node call computeKernel() directly',
      );
    }
    const worker = new Worker(new URL('./kergen-worker.js', import.meta.url), { type: 'module' });
    worker.onmessage = (e) => this._onMessage(e.data);
    worker.onerror = (e) => {
      if (e && typeof e.preventDefault === 'function') e.preventDefault();
      const message =
        e && e.message
          ? `the kergen worker failed: ${e.message}`
          : 'the kergen worker failed to start or crashed (under a dev server, exclude kergen-wasm from dependency pre-bundling, e.g. Vite optimizeDeps.exclude)';
      // No restart here: a worker that cannot start (a dev server serving the wrong file, say)
      // would fail again at once, forever. Its calls are rejected once; the next call starts a
      // new worker.
      this._failAll(new KergenError('WORKER_ERROR', message));
      if (this._worker === worker) this._worker = null;
      worker.terminate();
    };
    worker.postMessage({ type: 'init', wasmUrl: this._wasmUrl });
    this._worker = worker;
  }

  _restart() {
    if (this._worker) this._worker.terminate();
    this._worker = null;
    if (!this._disposed) this._spawn();
  }

  _failAll(error) {
    const jobs = [...this._jobs.values()];
    this._jobs.clear();
    for (const job of jobs) job.reject(error);
  }

  _onMessage(msg) {
    const job = this._jobs.get(msg && msg.id);
    if (!job) return; // a message from a job that was cancelled
    switch (msg.type) {
      case 'steps':
        this._deliverSteps(job, msg.batch);
        break;
      case 'progress':
        if (job.onProgress) {
          const progress = { phase: msg.phase, steps: msg.steps };
          if (msg.count !== undefined) progress.count = msg.count;
          if (msg.bytes !== undefined) progress.bytes = msg.bytes;
          if (msg.total !== undefined) progress.total = msg.total;
          this._callBack(job, job.onProgress, progress);
        }
        break;
      case 'mesh':
        if (job.onMesh) this._callBack(job, job.onMesh, msg.mesh);
        break;
      case 'result':
        this._jobs.delete(job.id);
        if (job.kind === 'writeMesh' || job.kind === 'repairMesh' || job.rawResult) job.resolve(msg.result);
        else if (job.kind === 'computeKernels')
          job.resolve(
            msg.result.map((e) => (e.code !== undefined ? new KergenError(e.code, e.message) : rebuildResult(e))),
          );
        else if (job.kind === 'computeFile') job.resolve({ mesh: msg.mesh, result: rebuildResult(msg.result) });
        else job.resolve(rebuildResult(msg.result));
        break;
      case 'error':
        this._jobs.delete(job.id);
        job.reject(new KergenError(msg.code, msg.message));
        break;
      default:
        break;
    }
  }

  // One batch of step events, decoded into event objects for onStep, in order. An onStep that
  // throws or returns false stops the job; after cancel() or dispose() (from onStep, say) no
  // further event of the batch is delivered.
  _deliverSteps(job, batch) {
    if (!job.onStep) return;
    const onStep = job.onStep;
    let live = true;
    let finished;
    try {
      finished = forEachStep(batch, (event) => {
        if (onStep(event) === false) return false;
        live = this._jobs.get(job.id) === job;
        return live;
      });
    } catch (err) {
      this._abort(job, err);
      return;
    }
    if (!finished && live) this._abort(job, new KergenError('CANCELLED', 'stopped by onStep returning false'));
  }

  // A throwing callback stops its job, as onStep's does.
  _callBack(job, fn, value) {
    try {
      fn(value);
    } catch (err) {
      this._abort(job, err);
    }
  }

  // The worker is busy inside a synchronous wasm call and cannot be interrupted: terminate it,
  // reject this job and every queued one, and start a fresh worker.
  _abort(job, error) {
    this._jobs.delete(job.id);
    job.reject(error);
    this._failAll(new KergenError('CANCELLED', 'cancelled together with a running computation'));
    this._restart();
  }

  /**
   * Computes the kernel in the worker. Options as computeKernel, plus onProgress({ phase, steps })
   * and transfer (move the input arrays' buffers instead of copying them: they are detached here).
   * onStep's return value `false` cancels the computation (the promise rejects with 'CANCELLED').
   */
  compute(positions, indices, options = {}) {
    const fn = 'compute';
    options = options || {};
    const { faceSizes } = options;
    return this._submit(fn, 'compute', options, (transfer) => {
      const move = wantsTransfer(fn, options);
      return {
        positions: toTransferable(fn, 'positions', positions, move, transfer),
        indices: toTransferable(fn, 'indices', indices, move, transfer),
        faceSizes: toTransferable(fn, 'faceSizes', faceSizes, move, transfer),
      };
    });
  }

  /**
   * The mesh after weld and repair (the package's repairMesh), in the worker. Options: weld,
   * repair, allowOpen, open, faceSizes, maxFaces, maxVertices, and transfer (as compute's).
   * Resolves to { positions, indices, faceSizes, warnings, error, message }.
   */
  repairMesh(positions, indices, options = {}) {
    const fn = 'repairMesh';
    options = options || {};
    const { faceSizes } = options;
    return this._submit(fn, 'repairMesh', options, (transfer) => {
      const move = wantsTransfer(fn, options);
      return {
        positions: toTransferable(fn, 'positions', positions, move, transfer),
        indices: toTransferable(fn, 'indices', indices, move, transfer),
        faceSizes: toTransferable(fn, 'faceSizes', faceSizes, move, transfer),
      };
    });
  }

  /**
   * Reads a mesh file (OFF, OBJ, STL, PLY: the package's readMesh) and computes its kernel, both
   * in the worker. `bytes` (ArrayBuffer or Uint8Array, e.g. from `file.arrayBuffer()`) is
   * copied, or transferred with `transfer: true`. Options: format / name (as readMesh: the format
   * is taken from the name's extension or the content; the name appears in parse errors), the
   * compute options,
   * onProgress (phases 'loading', 'reading' with `bytes`, then the core's 'validating', 'planes',
   * 'lp', 'tracing', 'assembling' with `count`, and 'done'), onStep, and onMesh(mesh), called with
   * the parsed mesh before the computation starts (so the input can be drawn meanwhile).
   * Resolves to { mesh, result }: the parsed mesh and the kernel.
   */
  computeFile(bytes, options = {}) {
    options = options || {};
    const { format, name, onMesh } = options;
    if (onMesh != null && typeof onMesh !== 'function')
      return Promise.reject(new KergenError('INVALID_ARGUMENT', 'computeFile: options.onMesh must be a function'));
    return this._submit(
      'computeFile',
      'computeFile',
      options,
      (transfer) => {
        const view = bytes instanceof ArrayBuffer ? new Uint8Array(bytes) : bytes;
        if (!(view instanceof Uint8Array))
          throw new KergenError('INVALID_ARGUMENT', 'computeFile: bytes must be an ArrayBuffer or a Uint8Array');
        const move = wantsTransfer('computeFile', options);
        const message = {
          bytes: toTransferable('computeFile', 'bytes', view, move, transfer),
          wantMesh: typeof onMesh === 'function',
        };
        if (format != null) message.format = String(format);
        if (name != null) message.name = String(name);
        return message;
      },
      { onMesh },
    );
  }

  /**
   * The kernels of many meshes in the worker (the package's computeKernels: one options object for
   * all; results[i] is meshes[i]'s KernelResult or its KergenError). The meshes' arrays are copied,
   * or transferred with `transfer: true`. onProgress: 'loading', then 'meshes' after every range
   * of `rangeSize` meshes (`count` of `total`), then 'done'. cancel() or aborting `signal` stops it
   * (as cancel() does: the worker is restarted), rejecting with 'CANCELLED'.
   */
  computeKernels(meshes, options = {}) {
    const fn = 'computeKernels';
    options = options || {};
    const { signal, rangeSize, onStep, faceSizes } = options;
    if (!Array.isArray(meshes))
      return Promise.reject(
        new KergenError('INVALID_ARGUMENT', `${fn}: meshes must be an array of { positions, indices, faceSizes? }`),
      );
    if (signal != null && typeof signal.aborted !== 'boolean')
      return Promise.reject(new KergenError('INVALID_ARGUMENT', `${fn}: options.signal must be an AbortSignal`));
    if (signal && signal.aborted)
      return Promise.reject(new KergenError('CANCELLED', `${fn}: cancelled by options.signal`));
    const id = this._nextId; // the job's id, if _submit posts one
    const promise = this._submit(fn, 'computeKernels', { ...options, onStep: undefined }, (transfer) => {
      const move = wantsTransfer(fn, options);
      const post = (i, name, arr) => toTransferable(`${fn}: meshes[${i}]`, name, arr, move, transfer);
      return {
        meshes: meshes.map((mesh, i) =>
          mesh === null || typeof mesh !== 'object'
            ? mesh
            : {
                positions: post(i, 'positions', mesh.positions),
                indices: post(i, 'indices', mesh.indices),
                faceSizes: post(i, 'faceSizes', mesh.faceSizes),
              },
        ),
        // Checked by the worker's computeKernelsSync (onStep and faceSizes are refused there).
        batchOptions: { rangeSize, faceSizes, onStep: onStep == null ? undefined : true },
      };
    });
    if (signal && this._nextId > id) {
      const onAbort = () => {
        const job = this._jobs.get(id);
        if (job) this._abort(job, new KergenError('CANCELLED', `${fn}: cancelled by options.signal`));
      };
      signal.addEventListener('abort', onAbort, { once: true });
      promise.then(
        () => signal.removeEventListener('abort', onAbort),
        () => signal.removeEventListener('abort', onAbort),
      );
    }
    return promise;
  }

  /**
   * Writes a mesh or a kernel result as file bytes ('obj', 'off' or 'stl': the package's
   * writeMesh) in the worker. The arrays are copied, the caller keeps them. Resolves to a Uint8Array.
   */
  writeMesh(meshOrKernel, format) {
    const m = meshOrKernel || {};
    // Only the arrays the writer reads; `faces` (views of faceIndices) would be cloned one by one.
    const { faces: _faces, ...plain } = m;
    return this._submit('writeMesh', 'writeMesh', {}, () => ({ mesh: plain, format }));
  }

  // Posts one job: `build(transfer)` makes the message body and lists the buffers to transfer.
  _submit(fn, kind, options, build, callbacks = {}) {
    if (this._disposed) return Promise.reject(new KergenError('DISPOSED', 'this KernelWorker was disposed'));
    const { onStep, onProgress, ...rest } = options;
    if (onStep != null && typeof onStep !== 'function')
      return Promise.reject(new KergenError('INVALID_ARGUMENT', `${fn}: options.onStep must be a function`));
    if (onProgress != null && typeof onProgress !== 'function')
      return Promise.reject(new KergenError('INVALID_ARGUMENT', `${fn}: options.onProgress must be a function`));
    const plain = {};
    for (const key of OPTION_NAMES) if (rest[key] !== undefined) plain[key] = rest[key];
    if (plain.from && ArrayBuffer.isView(plain.from)) plain.from = Array.from(plain.from);

    const transfer = [];
    let message;
    try {
      message = {
        type: kind,
        id: this._nextId++,
        wasmUrl: this._wasmUrl,
        ...build(transfer),
        options: plain,
        wantSteps: typeof onStep === 'function',
      };
    } catch (err) {
      return Promise.reject(
        err instanceof KergenError ? err : new KergenError('INVALID_ARGUMENT', `${fn}: ${err.message}`),
      );
    }
    // The worker is started again only here, by a call, after it failed to start or crashed.
    if (!this._worker) {
      try {
        this._spawn();
      } catch (err) {
        return Promise.reject(err);
      }
    }
    return new Promise((resolve, reject) => {
      const job = { id: message.id, kind, resolve, reject, onStep, onProgress, ...callbacks };
      this._jobs.set(job.id, job);
      try {
        this._worker.postMessage(message, [...new Set(transfer)]);
      } catch (err) {
        this._jobs.delete(job.id);
        reject(new KergenError('INVALID_ARGUMENT', `${fn}: the input could not be sent to the worker: ${err.message}`));
      }
    });
  }

  /** Cancels every running or queued computation (they reject with code 'CANCELLED'). */
  cancel() {
    if (this._disposed) return;
    const hadJobs = this._jobs.size > 0;
    this._failAll(new KergenError('CANCELLED', 'cancelled'));
    if (hadJobs) this._restart();
  }

  /** Terminates the worker; pending computations reject with code 'CANCELLED'. */
  dispose() {
    if (this._disposed) return;
    this._disposed = true;
    this._failAll(new KergenError('CANCELLED', 'the KernelWorker was disposed'));
    if (this._worker) this._worker.terminate();
    this._worker = null;
  }
}

// Volume meshes: readVolumeMesh, computeCellKernels, cellSurface (worker-cells.js).
installCellMethods(KernelWorker, { toTransferable, wantsTransfer });

export { KergenError };
