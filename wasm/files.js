// Mesh files: the core's readers and writers (kergen/io.h) through the module.
import { KergenError } from './errors.js';
import { init, requireModule, callWasm, W } from './load.js';
import { invalid, checkMesh, checkNotDetached, throwIfError } from './checks.js';
import { OUT_OF_MEMORY, writeRequest, readResult } from './wire.js';

// readMesh / writeMesh format names at their kergen::MeshFormat codes ('' = Unknown: from the name's
// extension, else from the content); bindings.cpp checks the codes.
const FORMATS = ['', 'off', 'obj', 'stl', 'ply'];
const WRITE_FORMATS = ['obj', 'off', 'stl'];
const textEncoder = new TextEncoder();

// A Uint8Array over the caller's bytes (never copied, detached or modified here; cells.js too).
export function bytesView(fn, bytes) {
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
        `${fn}: indices[${i}] = ${indices[i]} but the mesh has ${numVertices} ${numVertices === 1 ? 'vertex' : 'vertices'}`,
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
