// kergen-wasm — exact kernel of a closed 3D polygon mesh (KerGen), compiled to WebAssembly.
//
// Plain typed arrays in and out: every result is copied out of the wasm heap, so there is nothing
// to delete() and nothing that dies when the heap grows. Works in browsers, Web Workers, bundlers
// (Vite, webpack) and Node >= 18 from the same files: the Emscripten glue (dist/kergen.mjs) is
// built for web+worker and finds kergen.wasm with `new URL('kergen.wasm', import.meta.url)`; in
// Node this module reads the .wasm with fs, loaded by a dynamic import that only runs in Node.
import createKergenModule from '../dist/kergen.mjs';
import { KergenError } from './errors.js';

export { KergenError };

const STATUSES = ['EMPTY', 'POINT', 'SEGMENT', 'POLYGON', 'POLYHEDRON', 'UNBOUNDED'];

// Kept in variables (not literals) so that bundlers neither resolve nor emit them for the web.
const NODE_FS = 'node:fs/promises';
const NODE_URL = 'node:url';
const WASM_NEXT_TO_MODULE = '../dist/kergen.wasm';

let wasm = null; // the instantiated Emscripten module
let loading = null; // Promise while init() runs

function runningInNode() {
  return (
    typeof process === 'object' &&
    process !== null &&
    typeof process.versions === 'object' &&
    process.versions !== null &&
    typeof process.versions.node === 'string' &&
    typeof window === 'undefined' &&
    typeof importScripts !== 'function'
  );
}

async function readWasmInNode(source) {
  const fs = await import(/* webpackIgnore: true */ /* @vite-ignore */ NODE_FS);
  let target = source;
  if (typeof source === 'string' && /^[a-z][a-z0-9+.-]*:/i.test(source) && !/^[a-z]:[\\/]/i.test(source)) {
    target = new URL(source);
  }
  if (target instanceof URL && target.protocol !== 'file:') {
    const response = await fetch(target);
    if (!response.ok) throw new Error(`fetching ${target.href} failed: HTTP ${response.status}`);
    return new Uint8Array(await response.arrayBuffer());
  }
  if (target instanceof URL) {
    const { fileURLToPath } = await import(/* webpackIgnore: true */ /* @vite-ignore */ NODE_URL);
    target = fileURLToPath(target);
  }
  return new Uint8Array(await fs.readFile(target));
}

async function load(options) {
  const { wasmUrl, wasmBinary } = options;
  const moduleArg = {};
  if (wasmBinary != null) {
    if (wasmBinary instanceof ArrayBuffer) moduleArg.wasmBinary = new Uint8Array(wasmBinary);
    else if (wasmBinary instanceof Uint8Array) moduleArg.wasmBinary = wasmBinary;
    else throw new KergenError('INVALID_ARGUMENT', 'init: wasmBinary must be an ArrayBuffer or a Uint8Array');
  } else if (runningInNode()) {
    moduleArg.wasmBinary = await readWasmInNode(wasmUrl ?? new URL(WASM_NEXT_TO_MODULE, import.meta.url));
  } else if (wasmUrl != null) {
    const href = String(wasmUrl);
    moduleArg.locateFile = (path, prefix) => (path.endsWith('.wasm') ? href : prefix + path);
  }
  // Keep the glue quiet: problems surface as rejected promises / KergenError instead.
  moduleArg.print = () => {};
  moduleArg.printErr = () => {};
  return createKergenModule(moduleArg);
}

/**
 * Loads and instantiates the WebAssembly module. Idempotent: later calls return the same promise
 * (their options are ignored once loading has started). Called automatically by the async
 * functions; call it yourself before the *Sync functions, or to choose where the .wasm comes from.
 */
export function init(options = {}) {
  if (wasm) return Promise.resolve();
  if (!loading) {
    if (options === null || typeof options !== 'object') {
      return Promise.reject(new KergenError('INVALID_ARGUMENT', 'init: options must be an object'));
    }
    loading = load(options).then(
      (m) => {
        wasm = m;
        loading = null;
      },
      (err) => {
        loading = null;
        if (err instanceof KergenError) throw err;
        throw new KergenError('WASM_LOAD_FAILED', `could not load kergen.wasm: ${err && err.message ? err.message : err}`, { cause: err });
      },
    );
  }
  return loading;
}

/** True once init() has finished. */
export function isInitialized() {
  return wasm !== null;
}

function requireModule(fn) {
  if (!wasm) {
    throw new KergenError('NOT_INITIALIZED', `${fn}: the WebAssembly module is not loaded; await init() first (or use the async function)`);
  }
  return wasm;
}

// ---- argument checks (the C++ side receives only well-formed arrays) -----------------------

function invalid(fn, what) {
  return new KergenError('INVALID_ARGUMENT', `${fn}: ${what}`);
}

function checkPositions(fn, positions) {
  if (!(positions instanceof Float32Array || positions instanceof Float64Array || Array.isArray(positions))) {
    throw invalid(fn, 'positions must be a Float32Array, a Float64Array or an array of numbers');
  }
  if (positions.length % 3 !== 0) {
    throw invalid(fn, `positions has ${positions.length} values, not a multiple of 3 (flat x, y, z)`);
  }
  if (Array.isArray(positions)) {
    for (let i = 0; i < positions.length; i++) {
      if (typeof positions[i] !== 'number') throw invalid(fn, `positions[${i}] is not a number`);
    }
  }
}

function checkIndexArray(fn, name, arr) {
  if (arr instanceof Uint32Array || arr instanceof Uint16Array || arr instanceof Uint8Array) return;
  if (!(arr instanceof Int32Array || Array.isArray(arr))) {
    throw invalid(fn, `${name} must be a Uint32Array or an array of non-negative integers`);
  }
  for (let i = 0; i < arr.length; i++) {
    const v = arr[i];
    if (typeof v !== 'number' || !Number.isInteger(v)) throw invalid(fn, `${name}[${i}] = ${String(v)} is not an integer`);
    if (v < 0 || v > 0xffffffff) {
      const code = name === 'indices' ? 'INDEX_OUT_OF_RANGE' : 'INVALID_ARGUMENT';
      throw new KergenError(code, `${fn}: ${name}[${i}] = ${v} is outside 0 .. 2^32-1`);
    }
  }
}

function checkMesh(fn, positions, indices, faceSizes) {
  checkPositions(fn, positions);
  checkIndexArray(fn, 'indices', indices);
  if (faceSizes != null) {
    checkIndexArray(fn, 'faceSizes', faceSizes);
    let sum = 0;
    for (let i = 0; i < faceSizes.length; i++) sum += faceSizes[i];
    if (sum !== indices.length) {
      throw invalid(fn, `faceSizes add up to ${sum} but indices has ${indices.length} entries`);
    }
  } else if (indices.length % 3 !== 0) {
    throw invalid(fn, `indices has ${indices.length} entries, not a multiple of 3 (pass faceSizes for polygons)`);
  }
}

function checkOptions(fn, options) {
  if (options === undefined || options === null) return {};
  if (typeof options !== 'object') throw invalid(fn, 'options must be an object');
  const out = {};
  if (options.from != null) {
    const f = options.from;
    if (!(Array.isArray(f) || ArrayBuffer.isView(f)) || f.length !== 3 || ![0, 1, 2].every((i) => typeof f[i] === 'number' && Number.isFinite(f[i]))) {
      throw invalid(fn, 'options.from must be [x, y, z] with finite numbers');
    }
    out.from = [f[0], f[1], f[2]];
  }
  if (options.maxSteps != null) {
    const m = options.maxSteps;
    if (typeof m !== 'number' || !Number.isInteger(m) || m < 0) throw invalid(fn, 'options.maxSteps must be a non-negative integer');
    out.maxSteps = m;
  }
  for (const key of ['maxFaces', 'maxVertices']) {
    if (options[key] != null) {
      const m = options[key];
      if (typeof m !== 'number' || !Number.isInteger(m) || m < 0) throw invalid(fn, `options.${key} must be a non-negative integer`);
      out[key] = m;
    }
  }
  for (const key of ['allowOpen', 'deepestPoint']) {
    if (options[key] != null) {
      if (typeof options[key] !== 'boolean') throw invalid(fn, `options.${key} must be a boolean`);
      out[key] = options[key];
    }
  }
  if (options.onStep != null && typeof options.onStep !== 'function') throw invalid(fn, 'options.onStep must be a function');
  if (options.faceSizes != null && !(options.faceSizes instanceof Uint32Array || Array.isArray(options.faceSizes))) {
    throw invalid(fn, 'options.faceSizes must be a Uint32Array or an array of integers');
  }
  return out;
}

function throwIfError(raw) {
  if (raw.error !== undefined) throw new KergenError(raw.error, raw.message || raw.error);
}

// Calls into wasm; a trap (not a user error) leaves the instance unusable, so drop it and
// report it; the next init() loads a fresh instance.
function callWasm(fn, body) {
  try {
    return body();
  } catch (err) {
    if (err instanceof KergenError) throw err;
    wasm = null;
    throw new KergenError('INTERNAL_ERROR', `${fn}: the WebAssembly module failed: ${err && err.message ? err.message : err}`, { cause: err });
  }
}

function shapeResult(raw) {
  const faceIndices = raw.faceIndices;
  const faceSizes = raw.faceSizes;
  const faces = new Array(faceSizes.length);
  for (let f = 0, at = 0; f < faceSizes.length; f++) {
    faces[f] = faceIndices.subarray(at, at + faceSizes[f]);
    at += faceSizes[f];
  }
  if (!STATUSES.includes(raw.status)) throw new KergenError('INTERNAL_ERROR', `unknown kernel status ${raw.status}`);
  return {
    status: raw.status,
    complete: raw.complete,
    vertices: raw.vertices,
    edges: raw.edges,
    faces,
    faceIndices,
    faceSizes,
    triangles: raw.triangles,
    volume: raw.volume,
    area: raw.area,
    shapeVolume: raw.shapeVolume,
    volumeRatio: raw.volumeRatio,
    kernelPoint: raw.kernelPoint,
    deepestPoint: raw.deepestPoint,
    inscribedRadius: raw.inscribedRadius,
    warnings: raw.warnings,
    stats: raw.stats,
  };
}

// ---- public API -----------------------------------------------------------------------------

/**
 * Computes the kernel synchronously (init() must have finished). See index.d.ts for the result.
 * `options.onStep` is called once per discovered vertex / edge / face; returning `false` stops
 * the trace and the result holds the partial kernel (`complete: false`). If onStep throws, the
 * trace stops and the error is rethrown from here.
 */
export function computeKernelSync(positions, indices, options = {}) {
  const fn = 'computeKernel';
  const m = requireModule(fn);
  const opts = checkOptions(fn, options);
  const faceSizes = options && options.faceSizes != null ? options.faceSizes : null;
  checkMesh(fn, positions, indices, faceSizes);
  let userError = null;
  let threw = false;
  if (options && typeof options.onStep === 'function') {
    const onStep = options.onStep;
    opts.onStep = (event) => {
      if (threw) return false;
      try {
        return onStep(event) !== false;
      } catch (err) {
        threw = true;
        userError = err;
        return false;
      }
    };
  }
  const raw = callWasm(fn, () => m.compute(positions, indices, faceSizes, opts));
  if (threw) throw userError;
  throwIfError(raw);
  return shapeResult(raw);
}

/** Computes the kernel (loads the module on first use). */
export async function computeKernel(positions, indices, options = {}) {
  await init();
  return computeKernelSync(positions, indices, options);
}

/**
 * Tests star-shapedness and returns one kernel point (a kernel vertex) without tracing the whole
 * kernel: validation + planes + one linear program, expected O(n). Synchronous variant.
 */
export function findKernelPointSync(positions, indices, options = {}) {
  const fn = 'findKernelPoint';
  const m = requireModule(fn);
  const opts = checkOptions(fn, options);
  delete opts.onStep;
  const faceSizes = options && options.faceSizes != null ? options.faceSizes : null;
  checkMesh(fn, positions, indices, faceSizes);
  const raw = callWasm(fn, () => m.findPoint(positions, indices, faceSizes, opts));
  throwIfError(raw);
  return { starShaped: raw.starShaped, point: raw.point, warnings: raw.warnings };
}

/** Async variant of findKernelPointSync (loads the module on first use). */
export async function findKernelPoint(positions, indices, options = {}) {
  await init();
  return findKernelPointSync(positions, indices, options);
}

/** True when the mesh's kernel is non-empty. Throws KergenError for invalid meshes. */
export async function isStarShaped(positions, indices, options = {}) {
  return (await findKernelPoint(positions, indices, options)).starShaped;
}

/**
 * Wasm heap figures: `heapSize` = bytes of WebAssembly memory (only grows), `heapUsed` = bytes
 * currently allocated by the C++ side (returns to its level after every call: nothing leaks),
 * `jsHandles` = JS values currently held by the C++ side (0 between calls).
 */
export function memoryStats() {
  const m = requireModule('memoryStats');
  const stats = m.memoryStats();
  return { heapSize: stats.heapSize, heapUsed: stats.heapUsed, jsHandles: m.count_emval_handles() };
}
