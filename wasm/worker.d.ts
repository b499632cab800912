// Type declarations for `kergen-wasm/worker`.
import type { IndicesInput, KernelOptions, KernelResult, PositionsInput } from './index.js';

export { KergenError } from './index.js';
export type { KernelResult, StepEvent, KernelOptions, KergenErrorCode } from './index.js';

export interface KernelWorkerOptions {
  /** Where the worker loads kergen.wasm from (default: next to the module, found by the bundler). */
  wasmUrl?: string | URL;
}

/** Progress phases: 'loading' the module, 'computing' (validation, planes, LP), 'tracing', 'done'. */
export type ProgressPhase = 'loading' | 'computing' | 'tracing' | 'done';

export interface ProgressEvent {
  phase: ProgressPhase;
  /** Step events so far. */
  steps: number;
}

// The worker reports its own progress (below), not computeKernel's phases.
export interface WorkerComputeOptions extends Omit<KernelOptions, 'onProgress'> {
  /**
   * Called on the main thread for every step, in order (delivered in batches of up to ~16 ms or
   * 256 events). Returning `false` cancels the computation: the promise rejects with 'CANCELLED'.
   */
  onStep?: KernelOptions['onStep'];
  /** Called on the main thread at most every ~16 ms. */
  onProgress?: (progress: ProgressEvent) => void;
  /**
   * Copy the input arrays instead of transferring them. By default typed arrays that own their
   * whole buffer are transferred: they are detached (length 0) in the caller after compute().
   */
  copy?: boolean;
}

export class KernelWorker {
  constructor(options?: KernelWorkerOptions);
  /** Computes the kernel in the worker; calls queue up and run one after another. */
  compute(positions: PositionsInput, indices: IndicesInput, options?: WorkerComputeOptions): Promise<KernelResult>;
  /** Terminates the running computation and starts a fresh worker; pending promises reject with 'CANCELLED'. */
  cancel(): void;
  /** Terminates the worker for good; pending promises reject with 'CANCELLED'. */
  dispose(): void;
}
