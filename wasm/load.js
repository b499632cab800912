// Loading the WebAssembly module (browsers, workers, Node) and the wire format it declares:
// the module instance and its layout (W) live here, read by the other files of the wrapper.
import createKergenModule from '../dist/kergen.mjs';
import { FACE_SOURCE_BOX, FACE_SOURCE_WALL } from '../dist/constants.js';
import { KergenError } from './errors.js';

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
  if (target instanceof URL && target.protocol !== 'file:') return fetchWasm(target.href);
  if (target instanceof URL) {
    const { fileURLToPath } = await import(/* webpackIgnore: true */ /* @vite-ignore */ NODE_URL);
    target = fileURLToPath(target);
  }
  return new Uint8Array(await fs.readFile(target));
}

// The bytes of the .wasm at `href`, checked before anything compiles them: a 404 page or a dev
// server's HTML fallback is reported with the URL and the HTTP status, not as a CompileError
// ("expected magic word").
async function fetchWasm(href) {
  const fail = (what, cause) =>
    new KergenError('WASM_LOAD_FAILED', `could not load kergen.wasm from ${href}: ${what}`, { cause });
  let response;
  try {
    response = await fetch(href, { credentials: 'same-origin' });
  } catch (err) {
    throw fail(err && err.message ? err.message : String(err), err);
  }
  const status = `HTTP ${response.status}${response.statusText ? ` ${response.statusText}` : ''}`;
  if (!response.ok) throw fail(status);
  const bytes = new Uint8Array(await response.arrayBuffer());
  if (bytes[0] !== 0 || bytes[1] !== 0x61 || bytes[2] !== 0x73 || bytes[3] !== 0x6d) {
    const type = response.headers.get('content-type') || 'none';
    const start = JSON.stringify(new TextDecoder().decode(bytes.subarray(0, 24)));
    throw fail(`${status} but not a WebAssembly module (content-type ${type}, starts with ${start})`);
  }
  return bytes;
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
    moduleArg.wasmBinary = await fetchWasm(String(wasmUrl));
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
        loading = null;
        W = checkWireFormat(m.wireFormat());
        wasm = m;
      },
      (err) => {
        loading = null;
        if (err instanceof KergenError) throw err;
        throw new KergenError(
          'WASM_LOAD_FAILED',
          `could not load kergen.wasm: ${err && err.message ? err.message : err}`,
          { cause: err },
        );
      },
    );
  }
  return loading;
}

/** True once init() has finished. */
export function isInitialized() {
  return wasm !== null;
}

export function requireModule(fn) {
  if (!wasm) {
    throw new KergenError(
      'NOT_INITIALIZED',
      `${fn}: the WebAssembly module is not loaded; await init() first (or use the async function)`,
    );
  }
  return wasm;
}

// The layout names this file uses (see W); a module without one of them is from another build.
const WIRE_NAMES = {
  option: [
    'fromX',
    'fromY',
    'fromZ',
    'maxSteps',
    'allowOpen',
    'deepestPoint',
    'maxFaces',
    'maxVertices',
    'cullFaces',
    'seed',
    'weld',
    'weldRelative',
    'repair',
    'openBoundary',
    'slots',
  ],
  head: [
    'ok',
    'complete',
    'hasKernelPoint',
    'hasDeepestPoint',
    'starShaped',
    'numWarnings',
    'textBytes',
    'numVertexValues',
    'numEdgeValues',
    'numFaceIndices',
    'numFaces',
    'numTriangleValues',
    'numWitnessFaces',
    'numFaceSources',
    'numWitnessBoundaryEdgeValues',
    'numBytes',
    'words',
  ],
  scalar: [
    'volume',
    'area',
    'shapeVolume',
    'volumeRatio',
    'kernelPoint',
    'deepestPoint',
    'inscribedRadius',
    'stats',
    'count',
  ],
  step: ['kind', 'id', 'a', 'b', 'loop', 'loopSize', 'position'],
  faceSource: ['box', 'wall'],
};
const camelCase = (name) => name.replace(/_([a-z])/g, (_, c) => c.toUpperCase());

/**
 * Checks the module's wire format (bindings.cpp wireFormat()) against the names this wrapper
 * uses and returns it with the Stats keys in camelCase. Throws WASM_LOAD_FAILED naming what is
 * missing: the wrapper and the .wasm come from different builds. (Internal; exported for tests.)
 */
export function checkWireFormat(w) {
  const missing = [];
  for (const [group, names] of Object.entries(WIRE_NAMES)) {
    for (const n of names) if (typeof w?.[group]?.[n] !== 'number') missing.push(`${group}.${n}`);
  }
  for (const list of ['stats', 'statuses', 'stepKinds', 'optionWords', 'openBoundaries'])
    if (!Array.isArray(w?.[list])) missing.push(list);
  if (missing.length === 0 && !['vertex', 'edge', 'face'].every((k) => w.stepKinds.includes(k)))
    missing.push('stepKinds');
  if (missing.length === 0 && (w.faceSource.box !== FACE_SOURCE_BOX || w.faceSource.wall !== FACE_SOURCE_WALL))
    missing.push(`faceSource as dist/constants.js gives it (${FACE_SOURCE_BOX}, ${FACE_SOURCE_WALL})`);
  if (missing.length) {
    throw new KergenError(
      'WASM_LOAD_FAILED',
      `kergen.wasm does not match this index.js (rebuild both): its wire format lacks ${missing.join(', ')}`,
    );
  }
  return { ...w, statsKeys: w.stats.map(camelCase) };
}

// The layout (wasm/bindings.cpp's wireFormat(), read once per instance at init()): field names
// to slot, word and byte offsets, the Stats field names and the kernel status names. Nothing here
// repeats a number of the C++ side; checkWireFormat refuses a module whose layout lacks a name
// this file uses (a wrapper and a .wasm from different builds).
export let W = null;

// Calls into wasm; a trap (not a user error) leaves the instance unusable, so drop it and
// report it; the next init() loads a fresh instance.
export function callWasm(fn, body) {
  try {
    return body();
  } catch (err) {
    if (err instanceof KergenError) throw err;
    wasm = null;
    throw new KergenError(
      'INTERNAL_ERROR',
      `${fn}: the WebAssembly module failed: ${err && err.message ? err.message : err}`,
      { cause: err },
    );
  }
}
