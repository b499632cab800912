// Type declarations for `kergen-wasm/three` (needs `three` and its types, `@types/three`).
/**
 * three.js helpers: the kernel of a BufferGeometry or of a whole scene (computeKernelOfObject),
 * and the kernel as geometries to draw.
 *
 * @module kergen-wasm/three
 */
import type { BufferGeometry, Object3D } from 'three';
import type { KernelOptions, KernelResult } from './index.js';
import { KernelWorker as PlainKernelWorker, type WorkerComputeOptions } from './worker.js';

export { KergenError } from './index.js';
export type { KernelResult, KernelOptions, KergenErrorCode, StepEvent } from './index.js';
export type { ProgressEvent, WorkerComputeOptions } from './worker.js';

/**
 * Any three.js BufferGeometry, whatever its attributes: its 'position' attribute (any typed array,
 * normalized or interleaved) and its index (Uint8/16/32, or none: then every 3 vertices are a
 * triangle) are read; groups, draw range and other attributes are ignored.
 */
// `any` attributes: a geometry typed with its own attribute map (a loader's, a generator's) fits.
export type GeometryInput = BufferGeometry<any, any>;

/** Options of the geometry functions: computeKernel's, without faceSizes (triangles only). */
export type GeometryKernelOptions = Omit<KernelOptions, 'faceSizes'>;

/** Options of KernelWorker.computeGeometry: compute's, without faceSizes / transfer / copy. */
export type WorkerGeometryOptions = Omit<WorkerComputeOptions, 'faceSizes' | 'transfer' | 'copy'>;

/**
 * The triangle mesh of a geometry as fresh arrays (ready for computeKernel). The geometry is not
 * modified, and no array of it is shared with the result.
 */
export function geometryToMesh(geometry: GeometryInput): { positions: Float64Array; indices: Uint32Array };

/**
 * The kernel of a geometry, computed on the calling thread (loads the module on first use).
 * Equal positions are welded by default (three.js geometries repeat vertices along seams, per
 * face or per triangle).
 */
export function computeKernelOfGeometry(
  geometry: GeometryInput,
  options?: GeometryKernelOptions,
): Promise<KernelResult>;

/** Every triangle mesh under an object, in world coordinates, merged (see objectToMesh). */
export interface MergedMesh {
  positions: Float64Array;
  indices: Uint32Array;
  /** How many meshes were merged (an InstancedMesh counts once). */
  meshes: number;
}

/**
 * Every triangle mesh under `object` (itself included: Mesh, SkinnedMesh in its bind pose,
 * InstancedMesh once per instance; visible or not; meshes without positions skipped) with its
 * world transform applied, merged into fresh arrays. Lines and points are skipped; a mirroring
 * transform keeps the faces outward. World matrices are updated first (updateWorldMatrix). Throws
 * `EMPTY_INPUT` when no triangle mesh is found.
 */
export function objectToMesh(object: Object3D): MergedMesh;

/**
 * The kernel of every mesh under a three.js object (a glTF scene, a Group), world transforms
 * applied, merged and welded (weld on by default, so meshes meeting along seams form one closed
 * surface), computed on the calling thread.
 */
export function computeKernelOfObject(object: Object3D, options?: GeometryKernelOptions): Promise<KernelResult>;

/** The kernel as three.js geometries. */
export interface KernelGeometries {
  /** The kernel's convex faces, triangulated, with flat normals (corners repeated per face): for THREE.Mesh. Empty for a point, segment or empty kernel. */
  mesh: BufferGeometry;
  /** The kernel's vertices, with its edges as the index: for THREE.LineSegments. */
  edges: BufferGeometry;
}

/** A kernel result (computeKernel, KernelWorker) as geometries to draw; float32 coordinates. */
export function kernelToGeometry(result: KernelResult): KernelGeometries;

/** `kergen-wasm/worker`'s KernelWorker, which also takes a geometry. */
export class KernelWorker extends PlainKernelWorker {
  /**
   * The kernel of a geometry, computed in the worker (equal positions welded by default). The
   * geometry's arrays are copied: nothing of the caller's is transferred or detached.
   */
  computeGeometry(geometry: GeometryInput, options?: WorkerGeometryOptions): Promise<KernelResult>;
  /**
   * The kernel of every mesh under a three.js object (world transforms applied, merged, welded by
   * default; see computeKernelOfObject), computed in the worker. The merge runs on the calling
   * thread; only its fresh arrays are transferred.
   */
  computeObject(object: Object3D, options?: WorkerGeometryOptions): Promise<KernelResult>;
}
