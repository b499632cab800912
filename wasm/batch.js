// The kernels of many meshes in one call (kergen/batch.h, through wasm/batch_bindings.cpp): one
// KernelBatch kept in the heap for the whole run, the meshes copied in and computed range by range
// (so progress is reported, and the async variant yields and can be cancelled, between ranges),
// each result copied out as computeKernel's is. A mesh's error is its own entry (a KergenError in
// its place); the others are still computed.
import { KergenError } from './errors.js';
import { init, requireModule, callWasm, W } from './load.js';
import { checkMesh, checkOptions, invalid, inJsWords } from './checks.js';
import { OUT_OF_MEMORY, writeOptionSlots, readResult, shapeResult } from './wire.js';
import { runThrough, runYielding } from './cells.js';

const DEFAULT_RANGE = 100;
// A range also ends once its meshes' arrays reach this many bytes (one mesh at least): the heap
// holds one range's input at a time.
const RANGE_BYTES = 2 ** 25;

const layouts = new WeakMap();
const ROW = ['positions', 'numValues', 'indices', 'numIndices', 'faceSizes', 'numFaceSizes', 'result', 'words'];

// The mesh table's row layout (batch_bindings.cpp batchWireFormat()), read once per instance.
function layout(m) {
  let L = layouts.get(m);
  if (L) return L;
  L = typeof m.batchWireFormat === 'function' ? m.batchWireFormat() : null;
  const missing = L ? ROW.filter((n) => typeof L[n] !== 'number') : ['batchWireFormat'];
  if (missing.length)
    throw new KergenError(
      'WASM_LOAD_FAILED',
      `kergen.wasm does not match this batch.js (rebuild both): it lacks ${missing.join(', ')}`,
    );
  layouts.set(m, L);
  return L;
}

function checkBatchOptions(fn, options) {
  if (options != null && typeof options !== 'object') throw invalid(fn, 'options must be an object');
  const { rangeSize, onProgress, onStep, faceSizes, signal: _signal, ...compute } = options ?? {};
  if (onStep != null) throw invalid(fn, 'options.onStep is not available for many meshes (use computeKernel)');
  if (faceSizes != null) throw invalid(fn, 'options.faceSizes: each mesh gives its own faceSizes');
  if (onProgress != null && typeof onProgress !== 'function')
    throw invalid(fn, 'options.onProgress must be a function');
  if (rangeSize != null && (!Number.isSafeInteger(rangeSize) || rangeSize < 1))
    throw invalid(fn, 'options.rangeSize must be an integer >= 1');
  return { opts: checkOptions(fn, compute), rangeSize: rangeSize ?? DEFAULT_RANGE, onProgress };
}

// The mesh's arrays after the argument checks computeKernel makes; throws its KergenError.
function checkedMesh(fn, mesh) {
  if (mesh === null || typeof mesh !== 'object')
    throw invalid(fn, 'must be { positions, indices, faceSizes? } (as readMesh returns)');
  const faceSizes = mesh.faceSizes ?? null;
  if (faceSizes != null && !(faceSizes instanceof Uint32Array || Array.isArray(faceSizes)))
    throw invalid(fn, 'faceSizes must be a Uint32Array or an array of integers');
  checkMesh(fn, mesh.positions, mesh.indices, faceSizes);
  return { positions: mesh.positions, indices: mesh.indices, faceSizes };
}

const padded = (bytes) => Math.ceil(bytes / 8) * 8;
const meshBytes = (x) => 8 * x.positions.length + padded(4 * (x.indices.length + (x.faceSizes?.length ?? 0)));

// One request block: option slots, the mesh table, the meshes' arrays. Returns its address.
function writeRange(m, L, opts, list) {
  const slots = 8 * W.option.slots;
  const table = padded(4 * L.words * list.length);
  let bytes = slots + table;
  for (const { mesh } of list) bytes += meshBytes(mesh);
  const ptr = bytes < 2 ** 32 ? m._malloc(bytes) : 0;
  if (!ptr) throw new KergenError('OUT_OF_MEMORY', OUT_OF_MEMORY);
  const f64 = m.HEAPF64;
  const u32 = m.HEAPU32;
  writeOptionSlots(f64, ptr / 8, opts);
  let at = ptr + slots + table;
  list.forEach(({ mesh }, i) => {
    const row = (ptr + slots) / 4 + i * L.words;
    const { positions, indices, faceSizes } = mesh;
    const n = faceSizes ? faceSizes.length : 0;
    u32[row + L.positions] = at;
    u32[row + L.numValues] = positions.length;
    u32[row + L.indices] = at + 8 * positions.length;
    u32[row + L.numIndices] = indices.length;
    u32[row + L.faceSizes] = at + 8 * positions.length + 4 * indices.length;
    u32[row + L.numFaceSizes] = n;
    f64.set(positions, at / 8);
    u32.set(indices, u32[row + L.indices] / 4);
    if (n) u32.set(faceSizes, u32[row + L.faceSizes] / 4);
    at += meshBytes(mesh);
  });
  return ptr;
}

// The kernels of `list`'s meshes ({ index, mesh }) into results[index].
function computeRange(fn, m, L, batch, opts, list, results) {
  if (!list.length) return;
  let ptr;
  try {
    ptr = callWasm(fn, () => writeRange(m, L, opts, list));
  } catch (err) {
    // No room for the range's copy: its meshes one by one, so that only a mesh that does not fit
    // alone gets OUT_OF_MEMORY as its entry.
    if (!(err instanceof KergenError) || err.code !== 'OUT_OF_MEMORY') throw err;
    if (list.length === 1) results[list[0].index] = err;
    else for (const one of list) computeRange(fn, m, L, batch, opts, [one], results);
    return;
  }
  callWasm(fn, () => {
    const rows = (ptr + 8 * W.option.slots) / 4;
    try {
      m.batchCompute(batch, ptr, rows * 4, list.length);
      list.forEach(({ index }, i) => {
        // Every row's block is read (and freed) even when one of them fails.
        try {
          const raw = readResult(m, m.HEAPU32[rows + i * L.words + L.result]);
          results[index] =
            raw.error !== undefined
              ? new KergenError(raw.error, inJsWords(raw.message || raw.error))
              : shapeResult(raw);
        } catch (err) {
          if (!(err instanceof KergenError)) throw err;
          results[index] = err;
        }
      });
    } finally {
      m._free(ptr);
    }
  });
}

// The computation as a generator: it yields after every range (the sync variant runs it through,
// the async one awaits between ranges) and returns the results.
function* kernelsRun(fn, meshes, options) {
  const m = requireModule(fn);
  const L = layout(m);
  if (!Array.isArray(meshes)) throw invalid(fn, 'meshes must be an array of { positions, indices, faceSizes? }');
  const { opts, rangeSize, onProgress } = checkBatchOptions(fn, options);
  const total = meshes.length;
  const results = new Array(total);
  const report = (count) => onProgress && onProgress({ phase: 'meshes', count, total });
  report(0);
  const batch = callWasm(fn, () => m.batchOpen());
  if (!batch) throw new KergenError('OUT_OF_MEMORY', OUT_OF_MEMORY);
  try {
    for (let done = 0; done < total;) {
      const list = [];
      let bytes = 0;
      let end = done;
      for (; end < total && end - done < rangeSize && (end === done || bytes < RANGE_BYTES); end++) {
        try {
          const mesh = checkedMesh(`${fn}: meshes[${end}]`, meshes[end]);
          list.push({ index: end, mesh });
          bytes += meshBytes(mesh);
        } catch (err) {
          if (!(err instanceof KergenError)) throw err;
          results[end] = err;
        }
      }
      computeRange(fn, m, L, batch, opts, list, results);
      done = end;
      report(done);
      if (done < total) yield;
    }
  } finally {
    try {
      m.batchClose(batch);
    } catch {
      // the module failed meanwhile (callWasm dropped it): its heap is gone with it
    }
  }
  return results;
}

/**
 * The kernels of many meshes ({ positions, indices, faceSizes? } each) with one options object,
 * synchronously (init() must have finished): results[i] is what computeKernelSync gives for
 * meshes[i], or the KergenError it throws. See index.d.ts.
 */
export function computeKernelsSync(meshes, options = {}) {
  return runThrough(kernelsRun('computeKernels', meshes, options));
}

/**
 * Async variant of computeKernelsSync (loads the module on first use): yields to the event loop
 * between ranges; options.signal (an AbortSignal) cancels between ranges (code 'CANCELLED').
 */
export async function computeKernels(meshes, options = {}) {
  await init();
  return runYielding('computeKernels', options, () => kernelsRun('computeKernels', meshes, options));
}
