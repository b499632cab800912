// Argument checks of the public functions: the C++ side receives only well-formed arrays and
// options, and a caller's mistake is a KergenError naming the argument.
import { KergenError } from './errors.js';
import { W } from './load.js';
import { BOOLEAN_OPTIONS, COUNT_OPTIONS } from './option-names.js';

export function invalid(fn, what) {
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
export function checkNotDetached(fn, name, arr) {
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

export function checkMesh(fn, positions, indices, faceSizes) {
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
export const inJsWords = (text) => W.optionWords.reduce((t, [api, js]) => t.replaceAll(api, js), text);

export function checkOptions(fn, options) {
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
  for (const key of COUNT_OPTIONS) {
    if (options[key] != null) {
      const m = options[key];
      if (typeof m !== 'number' || !Number.isSafeInteger(m) || m < 0)
        throw invalid(fn, `options.${key} must be a non-negative integer`);
      out[key] = m;
    }
  }
  for (const key of BOOLEAN_OPTIONS) {
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

export function throwIfError(raw) {
  if (raw.error !== undefined) throw new KergenError(raw.error, inJsWords(raw.message || raw.error));
}
