// kergen-wasm — exact kernel of a closed 3D polygon mesh (KerGen), compiled to WebAssembly.
//
// Plain typed arrays in and out: every result is copied out of the wasm heap, so there is nothing
// to delete() and nothing that dies when the heap grows. Works in browsers, Web Workers, bundlers
// (Vite, webpack) and Node >= 18 from the same files: the Emscripten glue (dist/kergen.mjs) is
// built for web+worker and finds kergen.wasm with `new URL('kergen.wasm', import.meta.url)`; in
// Node this module reads the .wasm with fs, loaded by a dynamic import that only runs in Node.
import createKergenModule from '../dist/kergen.mjs';
import { FACE_SOURCE_BOX, FACE_SOURCE_WALL } from '../dist/constants.js';
import { KergenError } from './errors.js';

export { KergenError };
// kernel.faceSources values that name no input face (kergen.h's kFaceSourceBox and
// kFaceSourceWall): dist/constants.js is written by the wasm build from the module's
// wireFormat(), so they are there before init() (and for a KernelWorker's results too).
export { FACE_SOURCE_BOX, FACE_SOURCE_WALL };

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

function requireModule(fn) {
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
    if (typeof v !== 'number' || !Number.isInteger(v))
      throw invalid(fn, `${name}[${i}] = ${String(v)} is not an integer`);
    if (v < 0 || v > 0xffffffff) {
      const code = name === 'indices' ? 'INDEX_OUT_OF_RANGE' : 'INVALID_ARGUMENT';
      throw new KergenError(code, `${fn}: ${name}[${i}] = ${v} is outside 0 .. 2^32-1`);
    }
  }
}

// A typed array whose buffer was transferred (to a worker, say) reads as empty but cannot be
// copied: caught here, before anything reaches the module. Only empty views are probed.
function checkNotDetached(fn, name, arr) {
  if (!ArrayBuffer.isView(arr) || arr.byteLength !== 0) return;
  try {
    new Uint8Array(arr.buffer);
  } catch {
    throw invalid(
      fn,
      `${name} is a detached typed array (its buffer was transferred); pass a fresh array, or { copy: true } to the worker call that transferred it`,
    );
  }
}

function checkMesh(fn, positions, indices, faceSizes) {
  checkPositions(fn, positions);
  checkNotDetached(fn, 'positions', positions);
  checkIndexArray(fn, 'indices', indices);
  checkNotDetached(fn, 'indices', indices);
  if (faceSizes != null) checkNotDetached(fn, 'faceSizes', faceSizes);
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

// weld: true (DEFAULT_RELATIVE_WELD of the bounding box diagonal), a distance, or { relative: r }.
const DEFAULT_RELATIVE_WELD = 1e-9;
function checkWeld(fn, weld) {
  const ok = (x) => typeof x === 'number' && Number.isFinite(x) && x >= 0;
  if (weld === true) return { distance: DEFAULT_RELATIVE_WELD, relative: true };
  if (ok(weld)) return { distance: weld, relative: false };
  if (weld !== null && typeof weld === 'object' && ok(weld.relative))
    return { distance: weld.relative, relative: true };
  throw invalid(fn, 'options.weld must be true, a non-negative distance or { relative: r } with r >= 0');
}

// open: 'clip' is allowOpen: true; open: 'perpendicular' accepts open meshes by itself (the core's
// OpenBoundary, named by the module: W.openBoundaries), so allowOpen: false contradicts either.
function checkOpen(fn, open, allowOpen) {
  const code = W.openBoundaries.indexOf(open);
  if (typeof open !== 'string' || code < 0) {
    throw invalid(
      fn,
      `options.open must be ${W.openBoundaries.map((o) => `'${o}'`).join(' or ')} (got ${String(open)})`,
    );
  }
  if (allowOpen === false) throw invalid(fn, `options.open accepts open meshes; allowOpen: false contradicts it`);
  return { allowOpen: open === 'clip' ? true : allowOpen, openBoundary: code };
}

// The core's messages name options as the C++ API does (Options::field); this package names its
// own options, from the module's table (kergen::option_names, in W.optionWords).
const inJsWords = (text) => W.optionWords.reduce((t, [api, js]) => t.replaceAll(api, js), text);

function checkOptions(fn, options) {
  if (options === undefined || options === null) return {};
  if (typeof options !== 'object') throw invalid(fn, 'options must be an object');
  const out = {};
  if (options.from != null) {
    const f = options.from;
    if (
      !(Array.isArray(f) || ArrayBuffer.isView(f)) ||
      f.length !== 3 ||
      ![0, 1, 2].every((i) => typeof f[i] === 'number' && Number.isFinite(f[i]))
    ) {
      throw invalid(fn, 'options.from must be [x, y, z] with finite numbers');
    }
    out.from = [f[0], f[1], f[2]];
  }
  if (options.maxSteps != null) {
    const m = options.maxSteps;
    if (typeof m !== 'number' || !Number.isInteger(m) || m < 0)
      throw invalid(fn, 'options.maxSteps must be a non-negative integer');
    out.maxSteps = m;
  }
  for (const key of ['maxFaces', 'maxVertices', 'seed']) {
    if (options[key] != null) {
      const m = options[key];
      if (typeof m !== 'number' || !Number.isSafeInteger(m) || m < 0)
        throw invalid(fn, `options.${key} must be a non-negative integer`);
      out[key] = m;
    }
  }
  for (const key of ['allowOpen', 'deepestPoint', 'cullFaces', 'repair']) {
    if (options[key] != null) {
      if (typeof options[key] !== 'boolean') throw invalid(fn, `options.${key} must be a boolean`);
      out[key] = options[key];
    }
  }
  if (options.weld != null && options.weld !== false) out.weld = checkWeld(fn, options.weld);
  if (options.open != null) Object.assign(out, checkOpen(fn, options.open, options.allowOpen));
  if (options.onStep != null && typeof options.onStep !== 'function')
    throw invalid(fn, 'options.onStep must be a function');
  if (options.onProgress != null && typeof options.onProgress !== 'function')
    throw invalid(fn, 'options.onProgress must be a function');
  if (options.faceSizes != null && !(options.faceSizes instanceof Uint32Array || Array.isArray(options.faceSizes))) {
    throw invalid(fn, 'options.faceSizes must be a Uint32Array or an array of integers');
  }
  return out;
}

function throwIfError(raw) {
  if (raw.error !== undefined) throw new KergenError(raw.error, inJsWords(raw.message || raw.error));
}

// Calls into wasm; a trap (not a user error) leaves the instance unusable, so drop it and
// report it; the next init() loads a fresh instance.
function callWasm(fn, body) {
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

// ---- heap blocks shared with wasm/bindings.cpp (layouts documented there; keep them in sync) --
// Data crosses as one request block and one result block instead of embind values: each embind
// value costs JS<->wasm round trips, which on small meshes cost as much as the computation.

// The layout (wasm/bindings.cpp's wireFormat(), read once per instance at init()): field names
// to slot, word and byte offsets, the Stats field names and the kernel status names. Nothing here
// repeats a number of the C++ side; checkWireFormat refuses a module whose layout lacks a name
// this file uses (a wrapper and a .wasm from different builds).
let W = null;
const OUT_OF_MEMORY = 'out of memory (the wasm heap is limited to 4 GB)';
const textDecoder = new TextDecoder();

// An option slot: NaN = not given (the core's default applies), booleans as 1 / 0.
const slot = (v) => (v === undefined ? NaN : Number(v));

// Copies the mesh and the checked options into one malloc'd block; returns its address (the
// caller frees it).
function writeRequest(m, positions, indices, faceSizes, opts) {
  const numFaceSizes = faceSizes ? faceSizes.length : 0;
  const slots = W.option.slots;
  const bytes = 8 * (slots + positions.length) + 4 * (indices.length + numFaceSizes);
  // malloc takes a 32-bit size; anything larger cannot fit into the heap anyway.
  const ptr = bytes < 2 ** 32 ? m._malloc(bytes) : 0;
  if (!ptr) throw new KergenError('OUT_OF_MEMORY', OUT_OF_MEMORY);
  // Views are read after malloc: growing the heap replaces them.
  const f64 = m.HEAPF64;
  const at = ptr / 8;
  const o = W.option;
  const from = opts.from;
  f64[at + o.fromX] = from ? from[0] : NaN;
  f64[at + o.fromY] = from ? from[1] : NaN;
  f64[at + o.fromZ] = from ? from[2] : NaN;
  f64[at + o.maxSteps] = slot(opts.maxSteps);
  f64[at + o.allowOpen] = slot(opts.allowOpen);
  f64[at + o.deepestPoint] = slot(opts.deepestPoint);
  f64[at + o.maxFaces] = slot(opts.maxFaces);
  f64[at + o.maxVertices] = slot(opts.maxVertices);
  f64[at + o.cullFaces] = slot(opts.cullFaces);
  f64[at + o.seed] = slot(opts.seed);
  f64[at + o.weld] = opts.weld ? opts.weld.distance : NaN;
  f64[at + o.weldRelative] = opts.weld ? Number(opts.weld.relative) : NaN;
  f64[at + o.repair] = slot(opts.repair);
  f64[at + o.openBoundary] = slot(opts.openBoundary);
  f64.set(positions, at + slots);
  const u32 = m.HEAPU32;
  const indexAt = (at + slots + positions.length) * 2;
  u32.set(indices, indexAt);
  if (numFaceSizes) u32.set(faceSizes, indexAt + indices.length);
  return ptr;
}

// A step event from the StepOut at `address` (valid during the callback).
function readStep(m, address) {
  const u32 = m.HEAPU32;
  const st = W.step;
  const kind = W.stepKinds[u32[(address + st.kind) / 4]];
  const id = u32[(address + st.id) / 4];
  if (kind === 'vertex') {
    const f64 = m.HEAPF64;
    const d = (address + st.position) / 8;
    return { type: 'vertex', id, position: [f64[d], f64[d + 1], f64[d + 2]] };
  }
  if (kind === 'edge') return { type: 'edge', id, a: u32[(address + st.a) / 4], b: u32[(address + st.b) / 4] };
  const first = u32[(address + st.loop) / 4] / 4;
  const loop = [];
  for (let i = 0, n = u32[(address + st.loopSize) / 4]; i < n; i++) loop.push(u32[first + i]);
  return { type: 'face', id, loop };
}

// The NUL-terminated strings from byte `start` to `end`. ASCII (the core's names and messages) is
// decoded here: a TextDecoder call costs more than the short status string it would decode.
function readStrings(u8, start, end) {
  const out = [];
  let s = '';
  for (let i = start; i < end; i++) {
    const c = u8[i];
    if (c === 0) {
      out.push(s);
      s = '';
    } else if (c < 0x80) {
      s += String.fromCharCode(c);
    } else {
      return textDecoder.decode(u8.subarray(start, end)).split('\0');
    }
  }
  return out;
}

// The result block's stats: kergen::stats_fields in order, named as the layout names them (in
// camelCase). The object gets its keys in the same order every call, so V8 gives every result
// the same shape.
function readStats(f64, st) {
  const out = {};
  const names = W.statsKeys;
  for (let i = 0; i < names.length; i++) out[names[i]] = f64[st + i];
  return out;
}

const xyz = (f64, at) => [f64[at], f64[at + 1], f64[at + 2]];

// Copies a result block out of the heap into plain JS values and frees it. Returns
// { error, message } or the fields of a result (findPoint's point is in kernelPoint).
function readResult(m, ptr) {
  if (!ptr) throw new KergenError('OUT_OF_MEMORY', OUT_OF_MEMORY);
  try {
    const u32 = m.HEAPU32;
    const f64 = m.HEAPF64;
    const h = ptr / 4;
    const H = W.head;
    const S = W.scalar;
    const numWarnings = u32[h + H.numWarnings];
    const s = (ptr + 4 * H.words) / 8; // scalars
    const counts = s + S.count; // warning counts
    const v = counts + numWarnings;
    // The eight arrays lie back to back in the block (the vertices' f64 values, then the 32-bit
    // arrays): one copy into one fresh buffer, then views of it. (Each fresh typed array of more
    // than a few values costs about a microsecond in V8, most of a tiny mesh's overhead here.)
    const numVertexValues = u32[h + H.numVertexValues];
    const numEdgeValues = u32[h + H.numEdgeValues];
    const numFaceIndices = u32[h + H.numFaceIndices];
    const numFaces = u32[h + H.numFaces];
    const numTriangleValues = u32[h + H.numTriangleValues];
    const numWitnessFaces = u32[h + H.numWitnessFaces];
    const numFaceSources = u32[h + H.numFaceSources];
    const numWallEdgeValues = u32[h + H.numWitnessBoundaryEdgeValues];
    const arraysStart = v * 8;
    const u32Values =
      numEdgeValues +
      numFaceIndices +
      numFaces +
      numTriangleValues +
      numWitnessFaces +
      numFaceSources +
      numWallEdgeValues;
    const arrays = m.HEAPU8.slice(arraysStart, arraysStart + 8 * numVertexValues + 4 * u32Values).buffer;
    const vertices = new Float64Array(arrays, 0, numVertexValues);
    let at = 8 * numVertexValues;
    const edges = new Uint32Array(arrays, at, numEdgeValues);
    const faceIndices = new Uint32Array(arrays, (at += 4 * numEdgeValues), numFaceIndices);
    const faceSizes = new Uint32Array(arrays, (at += 4 * numFaceIndices), numFaces);
    const triangles = new Uint32Array(arrays, (at += 4 * numFaces), numTriangleValues);
    const witnessFaces = new Uint32Array(arrays, (at += 4 * numTriangleValues), numWitnessFaces);
    const faceSources = new Int32Array(arrays, (at += 4 * numWitnessFaces), numFaceSources);
    const witnessBoundaryEdges = new Uint32Array(arrays, (at += 4 * numFaceSources), numWallEdgeValues);
    const bytesStart = (v * 2 + 2 * numVertexValues + u32Values) * 4;
    const numBytes = u32[h + H.numBytes];
    const textStart = bytesStart + numBytes;
    const text = readStrings(m.HEAPU8, textStart, textStart + u32[h + H.textBytes]);
    if (u32[h + H.ok] === 0) return { error: text[0], message: text[1] };
    const warnings = new Array(numWarnings);
    for (let i = 0; i < numWarnings; i++) {
      warnings[i] = { kind: text[2 + 2 * i], count: f64[counts + i], message: text[3 + 2 * i] };
    }
    const st = s + S.stats;
    return {
      status: text[0],
      message: text[1],
      complete: u32[h + H.complete] !== 0,
      starShaped: u32[h + H.starShaped] !== 0,
      vertices,
      edges,
      faceIndices,
      faceSizes,
      triangles,
      witnessFaces,
      faceSources,
      witnessBoundaryEdges,
      bytes: numBytes ? m.HEAPU8.slice(bytesStart, textStart) : null,
      volume: f64[s + S.volume],
      area: f64[s + S.area],
      shapeVolume: f64[s + S.shapeVolume],
      volumeRatio: f64[s + S.volumeRatio],
      kernelPoint: u32[h + H.hasKernelPoint] ? xyz(f64, s + S.kernelPoint) : null,
      deepestPoint: u32[h + H.hasDeepestPoint] ? xyz(f64, s + S.deepestPoint) : null,
      inscribedRadius: f64[s + S.inscribedRadius],
      warnings,
      stats: readStats(f64, st),
    };
  } finally {
    m._free(ptr);
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
  if (!W.statuses.includes(raw.status)) throw new KergenError('INTERNAL_ERROR', `unknown kernel status ${raw.status}`);
  return {
    status: raw.status,
    complete: raw.complete,
    vertices: raw.vertices,
    edges: raw.edges,
    faces,
    faceIndices,
    faceSizes,
    triangles: raw.triangles,
    faceSources: raw.faceSources,
    witnessFaces: raw.witnessFaces,
    witnessBoundaryEdges: raw.witnessBoundaryEdges,
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
  let onStep = null;
  let onProgress = null;
  if (options && typeof options.onStep === 'function') {
    const userOnStep = options.onStep;
    onStep = (address) => {
      if (threw) return false;
      const event = readStep(m, address);
      try {
        return userOnStep(event) !== false;
      } catch (err) {
        threw = true;
        userError = err;
        return false;
      }
    };
  }
  if (options && typeof options.onProgress === 'function') {
    // A progress callback cannot stop the core: after a throw, later phases are not reported, the
    // trace stops at its next step (when onStep is given) and the error is rethrown at the end.
    const userOnProgress = options.onProgress;
    onProgress = (nameAddress, count) => {
      if (threw) return;
      const end = m.HEAPU8.indexOf(0, nameAddress);
      const phase = readStrings(m.HEAPU8, nameAddress, end + 1)[0];
      try {
        userOnProgress({ phase, count });
      } catch (err) {
        threw = true;
        userError = err;
      }
    };
  }
  const raw = callWasm(fn, () => {
    const request = writeRequest(m, positions, indices, faceSizes, opts);
    const block = m.compute(
      request,
      positions.length,
      indices.length,
      faceSizes ? faceSizes.length : 0,
      onStep,
      onProgress,
    );
    m._free(request);
    return readResult(m, block);
  });
  if (threw) throw userError;
  throwIfError(raw);
  return shapeResult(raw);
}

/** Computes the kernel (loads the module on first use). */
export async function computeKernel(positions, indices, options = {}) {
  await init();
  return computeKernelSync(positions, indices, options);
}

// The checked arguments written into a request, the module's `entry` (request, counts) called on
// it, its result block read; throws the call's error, if any (the entries without callbacks).
function callMeshEntry(fn, entry, positions, indices, options) {
  const m = requireModule(fn);
  const opts = checkOptions(fn, options);
  const faceSizes = options && options.faceSizes != null ? options.faceSizes : null;
  checkMesh(fn, positions, indices, faceSizes);
  const raw = callWasm(fn, () => {
    const request = writeRequest(m, positions, indices, faceSizes, opts);
    const block = m[entry](request, positions.length, indices.length, faceSizes ? faceSizes.length : 0);
    m._free(request);
    return readResult(m, block);
  });
  throwIfError(raw);
  return raw;
}

/**
 * Tests star-shapedness and returns one kernel point (a kernel vertex) without tracing the whole
 * kernel: validation + planes + one linear program, expected O(n). Synchronous variant.
 */
export function findKernelPointSync(positions, indices, options = {}) {
  const raw = callMeshEntry('findKernelPoint', 'findPoint', positions, indices, options);
  return {
    starShaped: raw.starShaped,
    point: raw.kernelPoint,
    witnessFaces: raw.witnessFaces,
    witnessBoundaryEdges: raw.witnessBoundaryEdges,
    warnings: raw.warnings,
  };
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

// ---- mesh files: the core's readers and writers (kergen/io.h) ---------------------------------

// readMesh / writeMesh format names at their kergen::MeshFormat codes ('' = Unknown: from the name's
// extension, else from the content); bindings.cpp checks the codes.
const FORMATS = ['', 'off', 'obj', 'stl', 'ply'];
const WRITE_FORMATS = ['obj', 'off', 'stl'];
const textEncoder = new TextEncoder();

// A Uint8Array over the caller's bytes (never copied, detached or modified here).
function bytesView(fn, bytes) {
  let view = null;
  try {
    if (bytes instanceof Uint8Array) view = bytes;
    else if (bytes instanceof ArrayBuffer) view = new Uint8Array(bytes);
    else if (typeof SharedArrayBuffer === 'function' && bytes instanceof SharedArrayBuffer)
      view = new Uint8Array(bytes);
    else if (ArrayBuffer.isView(bytes)) view = new Uint8Array(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  } catch {
    throw invalid(fn, 'bytes is a detached ArrayBuffer (it was transferred); pass a fresh one');
  }
  if (!view) {
    throw invalid(
      fn,
      'bytes must be a Uint8Array, an ArrayBuffer or another ArrayBufferView (encode text with TextEncoder)',
    );
  }
  checkNotDetached(fn, 'bytes', view);
  return view;
}

function checkReadOptions(fn, options) {
  if (options === undefined || options === null) return { format: '', name: '<memory>' };
  if (typeof options !== 'object') throw invalid(fn, 'options must be an object');
  const { format, name } = options;
  if (format != null && (typeof format !== 'string' || format === '' || !FORMATS.includes(format))) {
    throw invalid(
      fn,
      `options.format must be one of ${FORMATS.slice(1)
        .map((f) => `'${f}'`)
        .join(', ')} (got ${String(format)})`,
    );
  }
  if (name != null && typeof name !== 'string') throw invalid(fn, 'options.name must be a string');
  return { format: format ?? '', name: name ?? '<memory>' };
}

/**
 * Reads an OFF, OBJ, STL or PLY file with the core's readers (the native CLI's), synchronously
 * (init() must have finished). See index.d.ts.
 */
export function readMeshSync(bytes, options = {}) {
  const fn = 'readMesh';
  const m = requireModule(fn);
  const view = bytesView(fn, bytes);
  const { format, name } = checkReadOptions(fn, options);
  const nameBytes = textEncoder.encode(name);
  const raw = callWasm(fn, () => {
    const size = view.length + nameBytes.length;
    // malloc takes a 32-bit size; anything larger cannot fit into the heap anyway.
    const request = size < 2 ** 32 ? m._malloc(Math.max(size, 1)) : 0;
    if (!request) throw new KergenError('OUT_OF_MEMORY', OUT_OF_MEMORY);
    m.HEAPU8.set(view, request);
    m.HEAPU8.set(nameBytes, request + view.length);
    const block = m.readMesh(request, view.length, nameBytes.length, FORMATS.indexOf(format));
    m._free(request);
    return readResult(m, block);
  });
  throwIfError(raw);
  // Each array gets a buffer of its own, so that it can be transferred (to a KernelWorker, say)
  // without copying or detaching the others.
  return {
    positions: raw.vertices.slice(),
    indices: raw.faceIndices.slice(),
    faceSizes: raw.faceSizes.length ? raw.faceSizes.slice() : null,
  };
}

/** Async variant of readMeshSync (loads the module on first use). */
export async function readMesh(bytes, options = {}) {
  await init();
  return readMeshSync(bytes, options);
}

// What writeMesh writes: { positions, indices, faceSizes, kernelType } (kernelType -1 for a plain mesh).
function writableMesh(fn, meshOrKernel) {
  if (meshOrKernel === null || typeof meshOrKernel !== 'object') {
    throw invalid(fn, 'the first argument must be a kernel result or a mesh { positions, indices, faceSizes? }');
  }
  if (meshOrKernel.status !== undefined) {
    const kernelType = W.statuses.indexOf(meshOrKernel.status);
    if (kernelType < 0) throw invalid(fn, `unknown kernel status ${String(meshOrKernel.status)}`);
    const { vertices, faceIndices, faceSizes } = meshOrKernel;
    if (!(faceSizes instanceof Uint32Array)) throw invalid(fn, 'a kernel result needs its faceSizes (a Uint32Array)');
    return { positions: vertices, indices: faceIndices, faceSizes, kernelType };
  }
  const { positions, indices, faceSizes } = meshOrKernel;
  return { positions, indices, faceSizes: faceSizes ?? null, kernelType: -1 };
}

/**
 * A mesh file as bytes, written by the core's writers (the native CLI's `-o`): a kernel result
 * (its vertices and polygon faces; point, segment and empty kernels give files without faces) or
 * a mesh { positions, indices, faceSizes? }. Requires a finished init(). See index.d.ts.
 */
export function writeMesh(meshOrKernel, format) {
  const fn = 'writeMesh';
  const m = requireModule(fn);
  if (!WRITE_FORMATS.includes(format)) {
    throw invalid(fn, `format must be ${WRITE_FORMATS.map((f) => `'${f}'`).join(', ')} (got ${String(format)})`);
  }
  const { positions, indices, faceSizes, kernelType } = writableMesh(fn, meshOrKernel);
  checkMesh(fn, positions, indices, faceSizes);
  // A file the readers would refuse is not written: every value must be finite, every index a vertex.
  for (let i = 0; i < positions.length; i++) {
    if (!Number.isFinite(positions[i]))
      throw new KergenError('NON_FINITE_COORDINATE', `${fn}: positions[${i}] = ${positions[i]}`);
  }
  const numVertices = positions.length / 3;
  for (let i = 0; i < indices.length; i++) {
    if (indices[i] >= numVertices) {
      throw new KergenError(
        'INDEX_OUT_OF_RANGE',
        `${fn}: indices[${i}] = ${indices[i]} but the mesh has ${numVertices} vertices`,
      );
    }
  }
  const raw = callWasm(fn, () => {
    const request = writeRequest(m, positions, indices, faceSizes, {});
    const numFaceSizes = faceSizes ? faceSizes.length : 0;
    const block = m.writeMesh(
      request,
      positions.length,
      indices.length,
      numFaceSizes,
      FORMATS.indexOf(format),
      kernelType,
    );
    m._free(request);
    return readResult(m, block);
  });
  throwIfError(raw);
  return raw.bytes;
}

/**
 * The mesh the kernel is computed on: the input after `weld` and `repair` (as set in `options`),
 * for saving it (writeMesh). Synchronous (init() must have finished). See index.d.ts.
 */
export function repairMeshSync(positions, indices, options = {}) {
  const raw = callMeshEntry('repairMesh', 'repair', positions, indices, options);
  // As readMeshSync's: each array has a buffer of its own.
  return {
    positions: raw.vertices.slice(),
    indices: raw.faceIndices.slice(),
    faceSizes: raw.faceSizes.length ? raw.faceSizes.slice() : null,
    warnings: raw.warnings,
    error: raw.status === 'OK' ? null : raw.status,
    message: inJsWords(raw.message),
  };
}

/** Async variant of repairMeshSync (loads the module on first use). */
export async function repairMesh(positions, indices, options = {}) {
  await init();
  return repairMeshSync(positions, indices, options);
}
