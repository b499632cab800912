// Type declarations for `kergen-wasm/worker`.
/**
 * KernelWorker: the same computations in a module Web Worker, with progress and cancel.
 *
 * @module kergen-wasm/worker
 */
import type {
  IndicesInput,
  KernelOptions,
  KernelResult,
  MeshData,
  MeshFormat,
  MeshInput,
  PositionsInput,
  RepairedMesh,
  RepairMeshOptions,
  VolumeMesh,
  VolumeMeshBytes,
  VolumeMeshInput,
  ReadVolumeMeshOptions,
  CellKernelOptions,
  CellKernelsResult,
  CellSurface,
  KergenError,
  KernelMesh,
  KernelsOptions,
} from './index.js';

export { KergenError, FACE_SOURCE_BOX, FACE_SOURCE_WALL } from './index.js';
export type { KernelResult, StepEvent, KernelOptions, KergenErrorCode, PositionsInput, IndicesInput } from './index.js';

export interface KernelWorkerOptions {
  /** Where the worker loads kergen.wasm from (default: next to the module, found by the bundler). */
  wasmUrl?: string | URL;
}

/**
 * Progress phases: 'loading' the module; 'reading' the file (computeFile only); 'computing'
 * (compute only, before the core's phases); the core's phases 'validating', 'planes', 'lp',
 * 'tracing', 'assembling', each announced once as it begins (with `count`), 'tracing' repeated
 * while steps stream; 'done'.
 */
export type ProgressPhase =
  'loading' | 'reading' | 'computing' | 'validating' | 'planes' | 'lp' | 'tracing' | 'assembling' | 'done';

export interface ProgressEvent {
  phase: ProgressPhase;
  /** Step events so far. */
  steps: number;
  /** The number of items the core's phase works on (faces, planes, ...), when it gives one. */
  count?: number;
  /** 'reading': the file's size in bytes. */
  bytes?: number;
  /** computeCellKernels, phase 'cells' (computeKernels, phase 'meshes'): the number of cells
   * (meshes) to compute (`count` are done). */
  total?: number;
}

/** computeCellKernels in the worker: its options, and the worker's progress and mesh events. */
export interface WorkerCellKernelOptions extends Omit<CellKernelOptions, 'onProgress' | 'signal'> {
  /** 'loading', 'reading' (a file), then 'cells' after every range (`count` of `total`), then 'done'. */
  onProgress?: (progress: {
    phase: 'loading' | 'reading' | 'cells' | 'done';
    steps: number;
    count?: number;
    total?: number;
  }) => void;
  /** Called with the mesh read from a file (its own copy) before the cells are computed. */
  onMesh?: (mesh: VolumeMesh) => void;
  /** Transfer the input's buffers instead of copying them (detached here afterwards). */
  transfer?: boolean;
}

/** computeKernels in the worker: its options, and the worker's progress. */
export interface WorkerKernelsOptions extends Omit<KernelsOptions, 'onProgress'> {
  /** 'loading', then 'meshes' after every range (`count` of `total`), then 'done'. */
  onProgress?: (progress: {
    phase: 'loading' | 'meshes' | 'done';
    steps: number;
    count?: number;
    total?: number;
  }) => void;
  /** Transfer the meshes' buffers instead of copying them (detached here afterwards). */
  transfer?: boolean;
}

export interface WorkerComputeFileOptions extends WorkerComputeOptions {
  /** Default: from the name's extension, else from the content (as readMesh). */
  format?: MeshFormat;
  /** The file's name: picks the format by extension and names the file in parse errors. */
  name?: string;
  /** Called with the parsed mesh (its own copy) before the computation starts. */
  onMesh?: (mesh: MeshData) => void;
}

// The worker reports its own progress (below), not computeKernel's phases.
export interface WorkerComputeOptions extends Omit<KernelOptions, 'onProgress'> {
  /**
   * Called on the main thread for every step, in order, with the same event objects as
   * computeKernel's onStep. The worker sends them in batches of typed arrays (every ~50 ms or
   * 4096 events, transferred, not cloned object by object), decoded here. Returning `false`
   * cancels the computation: the promise rejects with 'CANCELLED'; after `cancel()` (from onStep,
   * say) no further event is delivered.
   */
  onStep?: KernelOptions['onStep'];
  /** Called on the main thread once per phase, and while tracing at most every ~50 ms. */
  onProgress?: (progress: ProgressEvent) => void;
  /**
   * Transfer the input typed arrays (those that own their whole buffer) to the worker instead of
   * copying them: no copy is made, and they are detached (length 0) in the caller afterwards.
   * Default false: the caller's arrays are copied and stay usable (e.g. a three.js geometry's).
   */
  transfer?: boolean;
  /** Copy the inputs: the default (accepted for older code; contradicts `transfer: true`). */
  copy?: boolean;
}

export class KernelWorker {
  constructor(options?: KernelWorkerOptions);
  /** Computes the kernel in the worker; calls queue up and run one after another. */
  compute(positions: PositionsInput, indices: IndicesInput, options?: WorkerComputeOptions): Promise<KernelResult>;
  /**
   * Reads a mesh file and computes its kernel, both in the worker; `bytes` is copied, or
   * transferred (detached here) with `transfer: true`. Parse errors reject with 'PARSE_ERROR' ("name:line: reason").
   */
  computeFile(
    bytes: ArrayBuffer | Uint8Array,
    options?: WorkerComputeFileOptions,
  ): Promise<{ mesh: MeshData; result: KernelResult }>;
  /**
   * The mesh after weld and repair (repairMesh), in the worker; the inputs are copied, or
   * transferred with `transfer: true`.
   */
  repairMesh(
    positions: PositionsInput,
    indices: IndicesInput,
    options?: RepairMeshOptions & { transfer?: boolean },
  ): Promise<RepairedMesh>;
  /** Reads a volume mesh (readVolumeMesh) in the worker; the bytes are copied, or transferred with `transfer: true`. */
  readVolumeMesh(input: VolumeMeshBytes, options?: ReadVolumeMeshOptions & { transfer?: boolean }): Promise<VolumeMesh>;
  /**
   * The kernel of every cell (computeCellKernels) in the worker, with progress after every range;
   * cancel() stops it. A file's mesh comes back in `result.mesh` unless onMesh received it.
   */
  computeCellKernels(
    meshOrBytes: VolumeMeshInput | VolumeMeshBytes,
    options?: WorkerCellKernelOptions,
  ): Promise<CellKernelsResult>;
  /** Results of consecutive cell ranges joined into one (joinCellKernels), in the worker (the parts are copied). */
  joinCellKernels(parts: readonly CellKernelsResult[], options?: { worst?: number }): Promise<CellKernelsResult>;
  /** One cell of a volume mesh as a surface (cellSurface), in the worker (the mesh is copied). */
  cellSurface(mesh: VolumeMeshInput, cell: number): Promise<CellSurface>;
  /**
   * The kernels of many meshes (computeKernels) in the worker: each entry a KernelResult or that
   * mesh's KergenError; progress after every range; cancel() or aborting `signal` stops it
   * (rejects with 'CANCELLED', restarting the worker as cancel() does).
   */
  computeKernels(
    meshes: readonly KernelMesh[],
    options?: WorkerKernelsOptions,
  ): Promise<Array<KernelResult | KergenError>>;
  /** Writes a mesh or kernel result as file bytes in the worker (arrays are copied). */
  writeMesh(meshOrKernel: KernelResult | MeshInput, format: 'obj' | 'off' | 'stl'): Promise<Uint8Array>;
  /**
   * Terminates the running computation and starts a fresh worker; pending promises reject with
   * 'CANCELLED'. (A worker that fails to start or crashes rejects the pending calls with
   * 'WORKER_ERROR' and is started again only by the next call.)
   */
  cancel(): void;
  /** Terminates the worker for good; pending promises reject with 'CANCELLED'. */
  dispose(): void;
}
