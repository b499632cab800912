// kergen-wasm — exact kernel of a closed 3D polygon mesh (KerGen), compiled to WebAssembly.
//
// Plain typed arrays in and out: every result is copied out of the wasm heap, so there is nothing
// to delete() and nothing that dies when the heap grows. Works in browsers, Web Workers, bundlers
// (Vite, webpack) and Node >= 18 from the same files: the Emscripten glue (dist/kergen.mjs) is
// built for web+worker and finds kergen.wasm with `new URL('kergen.wasm', import.meta.url)`; in
// Node this module reads the .wasm with fs, loaded by a dynamic import that only runs in Node.
//
// This file holds the public functions; load.js loads the module and checks its wire format,
// checks.js the arguments, wire.js the heap blocks shared with bindings.cpp, files.js the mesh
// readers and writers.
import { FACE_SOURCE_BOX, FACE_SOURCE_WALL } from '../dist/constants.js';
import { KergenError } from './errors.js';
import { init, requireModule, callWasm } from './load.js';
import { checkMesh, checkOptions, throwIfError, inJsWords } from './checks.js';
import { writeRequest, readStep, readStrings, readResult, shapeResult } from './wire.js';

export { KergenError };
// kernel.faceSources values that name no input face (kergen.h's kFaceSourceBox and
// kFaceSourceWall): dist/constants.js is written by the wasm build from the module's
// wireFormat(), so they are there before init() (and for a KernelWorker's results too).
export { FACE_SOURCE_BOX, FACE_SOURCE_WALL };
export { init, isInitialized, checkWireFormat } from './load.js';
export { readMeshSync, readMesh, writeMesh } from './files.js';
export {
  readVolumeMeshSync,
  readVolumeMesh,
  cellSurfaceSync,
  cellSurface,
  computeCellKernelsSync,
  computeCellKernels,
  joinCellKernelsSync,
  joinCellKernels,
} from './cells.js';
export { computeKernels, computeKernelsSync } from './batch.js';

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
