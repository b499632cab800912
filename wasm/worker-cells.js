// KernelWorker's volume-mesh methods (installed on its prototype by worker.js): reading a volume
// mesh, the kernel of every cell with progress events, and one cell as a surface, each run by
// the worker (kergen-worker-cells.js) with the package's functions (cells.js).
import { KergenError } from './errors.js';

const FORMATS = ['vtu', 'vtk', 'node-ele'];

// The message fields of a file input: one file's bytes, or { node, ele } (copied by default).
function fileInput(fn, input, options, transfer, toTransferable, wantsTransfer) {
  const move = wantsTransfer(fn, options);
  const view = (name, b) => {
    const v = b instanceof ArrayBuffer ? new Uint8Array(b) : b;
    if (!(v instanceof Uint8Array))
      throw new KergenError('INVALID_ARGUMENT', `${fn}: ${name} must be an ArrayBuffer or a Uint8Array`);
    return toTransferable(fn, name, v, move, transfer);
  };
  const pair = input !== null && typeof input === 'object' && !ArrayBuffer.isView(input) && 'node' in input;
  const message = pair
    ? { input: { node: view('node', input.node), ele: view('ele', input.ele) } }
    : { input: view('bytes', input) };
  const { format, name, eleName } = options;
  if (format != null && !FORMATS.includes(format))
    throw new KergenError('INVALID_ARGUMENT', `${fn}: options.format must be one of ${FORMATS.join(', ')}`);
  message.readOptions = { format, name, eleName };
  return message;
}

const isMesh = (x) =>
  x !== null && typeof x === 'object' && !ArrayBuffer.isView(x) && !(x instanceof ArrayBuffer) && 'cellOffsets' in x;

// A volume mesh's arrays as posted: copies (the caller keeps its mesh), or moved with `transfer`.
function meshInput(fn, mesh, options, transfer, toTransferable, wantsTransfer) {
  const move = wantsTransfer(fn, options);
  const out = {};
  for (const key of ['positions', 'faceIndices', 'faceOffsets', 'cellFaces', 'cellOffsets'])
    out[key] = toTransferable(fn, `mesh.${key}`, mesh[key], move, transfer);
  return out;
}

/**
 * Adds readVolumeMesh, computeCellKernels and cellSurface to KernelWorker. `tools` are worker.js's
 * own helpers (toTransferable, wantsTransfer), so that inputs are posted as compute()'s are.
 */
export function installCellMethods(KernelWorker, { toTransferable, wantsTransfer }) {
  const proto = KernelWorker.prototype;

  /** Reads a .vtu / .vtk file or { node, ele } in the worker (the package's readVolumeMesh). */
  proto.readVolumeMesh = function readVolumeMesh(input, options = {}) {
    options = options || {};
    return this._submit(
      'readVolumeMesh',
      'readVolumeMesh',
      {},
      (transfer) => fileInput('readVolumeMesh', input, options, transfer, toTransferable, wantsTransfer),
      { rawResult: true },
    );
  };

  /**
   * The kernel of every cell in the worker (the package's computeCellKernels): `meshOrBytes` is a
   * mesh from readVolumeMesh, a file's bytes or { node, ele }. Options as computeCellKernels'
   * (deepestPoint, firstCell, count, rangeSize, worst; name, format, eleName for files), plus
   * onProgress({ phase, count, total }) ('reading', then 'cells' after every range, then 'done'),
   * onMesh(mesh) with the mesh read from a file before its cells are computed, and transfer.
   * cancel() stops it (the promise rejects with 'CANCELLED').
   */
  proto.computeCellKernels = function computeCellKernels(meshOrBytes, options = {}) {
    const fn = 'computeCellKernels';
    options = options || {};
    const { onMesh, deepestPoint, firstCell, count, rangeSize, worst } = options;
    if (onMesh != null && typeof onMesh !== 'function')
      return Promise.reject(new KergenError('INVALID_ARGUMENT', `${fn}: options.onMesh must be a function`));
    return this._submit(
      fn,
      'computeCellKernels',
      { onProgress: options.onProgress },
      (transfer) => ({
        ...(isMesh(meshOrBytes)
          ? { mesh: meshInput(fn, meshOrBytes, options, transfer, toTransferable, wantsTransfer) }
          : fileInput(fn, meshOrBytes, options, transfer, toTransferable, wantsTransfer)),
        cellOptions: { deepestPoint, firstCell, count, rangeSize, worst },
        wantMesh: typeof onMesh === 'function',
      }),
      { onMesh, rawResult: true },
    );
  };

  /**
   * Results of consecutive cell ranges (computed by several workers, say) joined into one, with
   * the summary of all the cells (the package's joinCellKernels), in the worker; the parts are copied.
   */
  proto.joinCellKernels = function joinCellKernels(parts, options = {}) {
    const worst = options && options.worst;
    // Only the arrays and numbers the join reads (a part's mesh is not sent).
    const plain = Array.isArray(parts) ? parts.map(({ mesh: _mesh, ...rest }) => rest) : parts;
    return this._submit('joinCellKernels', 'joinCellKernels', {}, () => ({ parts: plain, worst }), { rawResult: true });
  };

  /** One cell of a volume mesh as a surface (the package's cellSurface), in the worker. */
  proto.cellSurface = function cellSurface(mesh, cell) {
    const fn = 'cellSurface';
    if (!isMesh(mesh))
      return Promise.reject(new KergenError('INVALID_ARGUMENT', `${fn}: the first argument must be a volume mesh`));
    return this._submit(
      fn,
      'cellSurface',
      {},
      (transfer) => ({ mesh: meshInput(fn, mesh, {}, transfer, toTransferable, wantsTransfer), cell }),
      {
        rawResult: true,
      },
    );
  };
}
