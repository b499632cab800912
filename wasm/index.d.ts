// Type declarations for `kergen-wasm` (hand-written; checked by `tsc --noEmit --strict`
// against tests/types/usage.ts).
/**
 * The kernel of a mesh (computeKernel), star-shapedness (findKernelPoint, isStarShaped), mesh
 * files (readMesh, writeMesh), repair (repairMesh).
 *
 * @module kergen-wasm
 */

/** A point or direction `[x, y, z]`. */
export type Vec3 = [number, number, number];

/**
 * Vertex coordinates, flat `x, y, z` per vertex: exactly the arrays the functions accept at run
 * time. (A three.js geometry, whose attribute arrays may be any typed array, normalized or
 * interleaved, goes through `kergen-wasm/three`.)
 */
export type PositionsInput = Float32Array | Float64Array | readonly number[];

/**
 * Vertex indices of the faces, concatenated (triangles unless `faceSizes` is given). Any of these
 * index arrays of a three.js geometry (`geometry.index.array`) is accepted as it is.
 */
export type IndicesInput = Uint32Array | Uint16Array | Uint8Array | Int32Array | readonly number[];

/** Shape of the kernel. */
export type KernelStatus = 'EMPTY' | 'POINT' | 'SEGMENT' | 'POLYGON' | 'POLYHEDRON' | 'UNBOUNDED';

/** `KergenError.code` values coming from the C++ core (`kergen::Error`). */
export type CoreErrorCode =
  | 'EMPTY_INPUT'
  | 'NON_FINITE_COORDINATE'
  | 'INDEX_OUT_OF_RANGE'
  | 'FACE_TOO_SMALL'
  | 'OPEN_MESH'
  | 'NON_MANIFOLD_EDGE'
  | 'INCONSISTENT_ORIENTATION'
  | 'MULTIPLE_COMPONENTS'
  | 'DEGENERATE_INPUT'
  | 'TOO_LARGE'
  | 'INVALID_ARGUMENT'
  /** A file could not be opened or written (the core's file functions; not produced in wasm). */
  | 'IO_ERROR'
  /** readMesh: a malformed file; the message is the CLI's, "name:line: reason" (binary: "name: byte N: reason"). */
  | 'PARSE_ERROR'
  /** Coordinates span too many orders of magnitude for exact evaluation (e.g. 1 next to 1e-60). */
  | 'COORDINATE_RANGE'
  /** The surface crosses or touches itself (a ray from inside the half-spaces' intersection crosses it more than once; or, for flat or unbounded kernels and open meshes, two faces meet away from what they share). */
  | 'SELF_INTERSECTION';

/** Every `KergenError.code` this package produces. */
export type KergenErrorCode =
  | CoreErrorCode
  /** init() could not fetch, read or compile kergen.wasm. */
  | 'WASM_LOAD_FAILED'
  /** A *Sync function was called before init() finished. */
  | 'NOT_INITIALIZED'
  /** The 4 GB wasm heap was exhausted. */
  | 'OUT_OF_MEMORY'
  /** An unexpected failure inside the module (a bug: please report it). */
  | 'INTERNAL_ERROR'
  /** KernelWorker: cancel(), dispose(), or onStep returned false. */
  | 'CANCELLED'
  /** KernelWorker: compute() after dispose(). */
  | 'DISPOSED'
  /** KernelWorker: the worker script or the module could not start, or crashed. */
  | 'WORKER_ERROR'
  /** KernelWorker: the worker runs a build of the package without the requested function. */
  | 'UNSUPPORTED';

/** The error thrown (or rejected with) by every function of this package. */
export class KergenError extends Error {
  constructor(code: KergenErrorCode, message: string, options?: { cause?: unknown });
  readonly name: 'KergenError';
  /** What went wrong, e.g. 'OPEN_MESH', 'NON_MANIFOLD_EDGE', 'INVALID_ARGUMENT' (a closed set: a typo does not compile). */
  code: KergenErrorCode;
}

export interface InitOptions {
  /** Where to load kergen.wasm from (default: next to the module, found by the bundler). */
  wasmUrl?: string | URL;
  /** The bytes of kergen.wasm (then nothing is fetched). */
  wasmBinary?: ArrayBuffer | Uint8Array;
}

/** A step of the trace, in discovery order; ids index the final result's arrays. */
export type StepEvent =
  | { type: 'vertex'; id: number; position: Vec3 }
  | { type: 'edge'; id: number; a: number; b: number }
  | { type: 'face'; id: number; loop: number[] };

/** A phase of computeKernel, in the order they run (the core's `kergen::Progress::Phase`). */
export type KernelPhase = 'validating' | 'planes' | 'lp' | 'tracing' | 'assembling';

/**
 * Passed to `onProgress` once as each phase begins. `count` is what the phase works on:
 * 'validating' input faces, 'planes' faces left after zero-area ones are dropped, 'lp' and
 * 'tracing' distinct planes, 'assembling' kernel vertices found. Phases that do not run are
 * skipped (a rejected mesh stops after 'validating', a non-star one after 'lp').
 */
export interface KernelProgress {
  phase: KernelPhase;
  count: number;
}

export interface KernelOptions {
  /** Grow the kernel from the kernel vertex extreme towards this point. */
  from?: Vec3;
  /**
   * Called once per discovered vertex / edge / face; return `false` to stop (result: complete = false).
   * KernelWorker's onStep receives the same objects, in the same order: its worker sends them in
   * batches of typed arrays (transferred), turned back into these objects on the receiving thread.
   */
  onStep?: (event: StepEvent) => void | boolean;
  /**
   * Called synchronously as each phase begins. If it throws, later phases are not reported, the
   * trace stops at its next step (when onStep is given) and the error is rethrown by computeKernel.
   */
  onProgress?: (progress: KernelProgress) => void;
  /** Stop after this many step events (0 or absent: no limit). */
  maxSteps?: number;
  /** Accept meshes with holes; the result may then be 'UNBOUNDED'. */
  allowOpen?: boolean;
  /**
   * Accept meshes with holes (a surface with a boundary: a bowl, a terrain, a scan) and say what
   * bounds their kernel. The faces keep their orientation as given; the kernel lies behind their
   * counter-clockwise fronts.
   * - `'clip'`: the same as `allowOpen: true`: the faces' half-spaces only, clipped to a box twice
   *   the size of the mesh where they leave it open ('UNBOUNDED').
   * - `'perpendicular'`: also a wall at every boundary edge (an edge of one face only): the plane
   *   through the edge perpendicular to its face, whose inner side holds the face (Asiler &
   *   Sahillioglu 2024, Sec. 6.3). The kernel is the points that see every face from its inner
   *   side and lie inside every wall: bounded where the surface and its walls close around it (a
   *   bowl, a dome), still 'UNBOUNDED' (clipped) where they leave a direction open (a flat disc or
   *   a single triangle: the prism behind it; a valley whose walls spread apart), 'EMPTY' when no
   *   point is behind every face and inside every wall. A wall holds its edge exactly and is
   *   within 2e-14 radians of the perpendicular (its third point is rounded); every predicate on
   *   it is exact.
   * `allowOpen` need not be given; `allowOpen: false` with `open` is an 'INVALID_ARGUMENT'.
   * Closed meshes are not affected.
   */
  open?: 'clip' | 'perpendicular';
  /** Also compute the centre of the largest inscribed ball (`deepestPoint`, `inscribedRadius`). */
  deepestPoint?: boolean;
  /** Refuse larger inputs with `TOO_LARGE` before any work (default 20 000 000). */
  maxFaces?: number;
  /** Refuse inputs with more vertices with `TOO_LARGE` (default 20 000 000). */
  maxVertices?: number;
  /** Drop, before planes are merged, the faces whose planes cannot touch the kernel (large
   * closed meshes; default true). The kernel is the same either way; false keeps every face
   * (`stats.distinctPlanes` then counts the planes of all faces). */
  cullFaces?: boolean;
  /** Order of the LP's constraints (a non-negative safe integer; results do not depend on it). */
  seed?: number;
  /**
   * Merge vertices closer than a tolerance before validation, so that a triangle soup (an
   * unindexed STL, a three.js geometry) or a mesh whose seams differ by rounding becomes the
   * closed surface it describes: `true` (within 1e-9 of the bounding box diagonal), a distance
   * in the input's units (0: only vertices at exactly one position), or `{ relative: r }` (r
   * times the diagonal). Groups merge transitively into their lowest-indexed vertex (its input
   * position is kept); faces left with fewer than three corners are dropped. Reported as a
   * `VERTICES_WELDED` warning. Default: off.
   */
  weld?: boolean | number | { relative: number };
  /**
   * Repair, before validation, what leaves a well-defined solid refused: weld (within `weld`, or
   * equal positions), remove faces repeating another's corners (copies; pairs of opposite
   * orientation), split T-junctions (a vertex exactly inside an edge one face uses is inserted
   * into that face). Each repair is a warning with a count (`VERTICES_WELDED`,
   * `DUPLICATE_FACES_REMOVED`, `CANCELLING_FACES_REMOVED`, `T_JUNCTIONS_SPLIT`). Default: off.
   */
  repair?: boolean;
  /**
   * Turn every face over (reverse its loop) first: for an open surface given inside out (warning
   * `FACES_POINT_INWARD`), which is never turned over by itself. A closed surface is oriented by
   * its volume either way. Default: false.
   */
  flipFaces?: boolean;
  /** Vertices per face, for polygon input (absent or null: every face is a triangle, as readMesh gives it). */
  faceSizes?: Uint32Array | readonly number[] | null;
}

export interface KernelWarning {
  /**
   * 'ORIENTATION_FLIPPED' | 'DEGENERATE_FACES_DROPPED' | 'NON_PLANAR_FACES_SPLIT' | 'UNUSED_VERTICES' |
   * 'VERTICES_WELDED' | 'DUPLICATE_FACES_REMOVED' | 'CANCELLING_FACES_REMOVED' | 'T_JUNCTIONS_SPLIT' |
   * 'SEPARATE_SHELLS' | 'FACES_POINT_INWARD' (an open surface whose faces point inward: closed over
   * its holes it encloses a negative volume; see `flipFaces`) | 'CROSSINGS_UNCHECKED'
   */
  kind: string;
  count: number;
  message: string;
}

export interface KernelStats {
  inputVertices: number;
  inputFaces: number;
  /** Zero-area faces ignored. */
  droppedFaces: number;
  /**
   * Faces dropped before coplanar faces are merged (large closed meshes): their planes hold the
   * kernel of a sample of faces strictly, so they cannot touch the kernel.
   */
  culledFaces: number;
  /** Face planes after merging coplanar faces (of the faces not culled). */
  distinctPlanes: number;
  /** Planes left after culling those that cannot touch the kernel. */
  activePlanes: number;
  tracedLines: number;
  /** Predicate evaluations the floating-point filter could not decide. */
  exactFallbacks: number;
  msValidate: number;
  msPlanes: number;
  msLp: number;
  msTrace: number;
  msAssemble: number;
  msTotal: number;
}

/**
 * `KernelResult.faceSources` value of a face of the clipping box of an 'UNBOUNDED' kernel (it
 * lies on no input face's plane). The core's `kergen::kFaceSourceBox`, passed on by the build
 * (dist/constants.js, from the module's wire format); importable before init().
 */
export const FACE_SOURCE_BOX: number;
/**
 * `KernelResult.faceSources` value of a face that lies on a boundary wall of `open:
 * 'perpendicular'` (and on no input face's plane). The core's `kergen::kFaceSourceWall`.
 */
export const FACE_SOURCE_WALL: number;

/**
 * A computed kernel. Its eight typed arrays (`vertices`, `edges`, `faceIndices`, `faceSizes`,
 * `triangles`, `faceSources`, `witnessFaces`, `witnessBoundaryEdges`) are copies out of the wasm
 * heap into one fresh ArrayBuffer, which they share as views (use `.slice()` for an array with a
 * buffer of its own, e.g. before transferring only it).
 */
export interface KernelResult {
  status: KernelStatus;
  /** false when stopped early by onStep / maxSteps (the result is then the partial kernel). */
  complete: boolean;
  /** Kernel vertices, flat x, y, z. */
  vertices: Float64Array;
  /** Kernel edges, pairs of vertex ids. */
  edges: Uint32Array;
  /** Convex polygon faces (vertex id loops, counter-clockwise seen from outside the kernel). */
  faces: Uint32Array[];
  /** The same loops concatenated (`faces[i]` are views into this array). */
  faceIndices: Uint32Array;
  /** Vertices per face. */
  faceSizes: Uint32Array;
  /** The faces fan-triangulated, 3 vertex ids per triangle (three.js BufferGeometry index). */
  triangles: Uint32Array;
  /**
   * What bounds the kernel: one entry per face (in face order; a partial result: per face
   * returned), the input face whose plane the face lies on with the same inner side, the lowest
   * index among the faces of that oriented plane (indices of the faces given; with `weld` or
   * `repair` too, the plane then that of the welded, repaired face; a non-planar polygon split
   * into triangles, for its triangles' planes). FACE_SOURCE_BOX for a face of the clipping box
   * ('UNBOUNDED'), FACE_SOURCE_WALL for a face on a boundary wall (`open: 'perpendicular'`).
   * A 'POLYGON' has one face; 'EMPTY', 'POINT' and 'SEGMENT' none.
   */
  faceSources: Int32Array;
  /** Kernel volume (0 unless 'POLYHEDRON' and complete). */
  volume: number;
  /** Kernel surface area ('POLYGON': the polygon's area). */
  area: number;
  /**
   * Volume enclosed by the input mesh; for an open mesh, by the surface closed over its holes,
   * each capped by a fan from its centroid (negative when its faces point inward).
   */
  shapeVolume: number;
  /** volume / shapeVolume; 0 for an open mesh, whose kernel may reach beyond the caps of its holes. */
  volumeRatio: number;
  /**
   * Why the kernel is 'EMPTY': at most four half-spaces, of input faces and (with `open:
   * 'perpendicular'`) of boundary walls (witnessBoundaryEdges), that have no common point, so no
   * point sees all those faces from the inside and lies inside those walls (Helly's theorem:
   * four suffice in 3D). Minimal, one face per plane (the lowest-indexed one; a wall only when
   * no face lies in its plane), checked with exact arithmetic before it is returned. Here the
   * faces: indices of the faces given, in increasing order (with `weld` or `repair` too); a
   * non-planar polygon split into triangles is named for its triangles' planes. Empty when the
   * kernel is not empty, and when no set of faces and walls alone shows it (with `allowOpen`:
   * half-spaces that meet only outside the clipping box). Computed only for an empty kernel.
   */
  witnessFaces: Uint32Array;
  /**
   * The boundary walls of the witness (see witnessFaces), each named by the boundary edge it
   * stands on: vertex id pairs a, b (the edge as its face's loop runs from a to b), flat.
   */
  witnessBoundaryEdges: Uint32Array;
  /** A kernel vertex (null when 'EMPTY'). */
  kernelPoint: Vec3 | null;
  /** Centre of the largest inscribed ball (with options.deepestPoint and a full-dimensional kernel). */
  deepestPoint: Vec3 | null;
  inscribedRadius: number;
  warnings: KernelWarning[];
  stats: KernelStats;
}

export interface KernelPointResult {
  /** The kernel is non-empty. */
  starShaped: boolean;
  /** A kernel vertex, or null when not star-shaped. */
  point: Vec3 | null;
  /** When not star-shaped: why (see KernelResult.witnessFaces); empty otherwise. */
  witnessFaces: Uint32Array;
  /** Its boundary walls as edges (see KernelResult.witnessBoundaryEdges). */
  witnessBoundaryEdges: Uint32Array;
  warnings: KernelWarning[];
}

export type KernelPointOptions = Pick<
  KernelOptions,
  'from' | 'allowOpen' | 'open' | 'faceSizes' | 'maxFaces' | 'maxVertices'
>;

export interface MemoryStats {
  /** Bytes of WebAssembly memory (grows, never shrinks). */
  heapSize: number;
  /** Bytes currently allocated by the C++ side. */
  heapUsed: number;
  /** JS values currently held by the C++ side (0 between calls). */
  jsHandles: number;
}

/** Loads the module (idempotent; the async functions call it for you). */
export function init(options?: InitOptions): Promise<void>;
/** True once init() has finished. */
export function isInitialized(): boolean;

/** Computes the kernel of a closed mesh. */
export function computeKernel(
  positions: PositionsInput,
  indices: IndicesInput,
  options?: KernelOptions,
): Promise<KernelResult>;
/** Synchronous computeKernel; requires a finished init(). */
export function computeKernelSync(
  positions: PositionsInput,
  indices: IndicesInput,
  options?: KernelOptions,
): KernelResult;

/** Star-shapedness and one kernel point, without tracing the kernel (expected O(n)). */
export function findKernelPoint(
  positions: PositionsInput,
  indices: IndicesInput,
  options?: KernelPointOptions,
): Promise<KernelPointResult>;
/** Synchronous findKernelPoint; requires a finished init(). */
export function findKernelPointSync(
  positions: PositionsInput,
  indices: IndicesInput,
  options?: KernelPointOptions,
): KernelPointResult;

/** True when the kernel is non-empty. */
export function isStarShaped(
  positions: PositionsInput,
  indices: IndicesInput,
  options?: KernelPointOptions,
): Promise<boolean>;

/** Mesh file formats readMesh reads. */
export type MeshFormat = 'off' | 'obj' | 'stl' | 'ply';

export interface ReadMeshOptions {
  /**
   * The file's format. Absent: from `name`'s extension (case-insensitive), else from the content
   * (binary STL by its size, 'solid', 'ply', an OFF header, a first OBJ record).
   */
  format?: MeshFormat;
  /** The file name used in error messages (default '<memory>'), and for the format when absent. */
  name?: string;
}

/**
 * A mesh as the readers give it, ready for `computeKernel(positions, indices, { faceSizes })`.
 * Each array has an ArrayBuffer of its own (transferable without touching the others).
 */
export interface MeshData {
  /** Vertex coordinates, flat x, y, z, as in the file (STL: corners welded by exact equality). */
  positions: Float64Array;
  /** Vertex indices of the faces, concatenated, 0-based. */
  indices: Uint32Array;
  /** Vertices per face; null when every face is a triangle. */
  faceSizes: Uint32Array | null;
}

/** The bytes of a mesh file: the caller's array is never detached or modified. */
export type MeshBytes = ArrayBuffer | ArrayBufferView;

/** A mesh to write: positions + concatenated face loops (faceSizes absent/null = triangles). */
export interface MeshInput {
  positions: PositionsInput;
  indices: IndicesInput;
  faceSizes?: Uint32Array | readonly number[] | null;
}

/**
 * Reads an OFF, OBJ, STL or PLY file with the core's readers, exactly as the native CLI reads it
 * (same mesh, same errors: 'PARSE_ERROR' with "name:line: reason", 'EMPTY_INPUT', 'TOO_LARGE').
 */
export function readMesh(bytes: MeshBytes, options?: ReadMeshOptions): Promise<MeshData>;
/** Synchronous readMesh; requires a finished init(). */
export function readMeshSync(bytes: MeshBytes, options?: ReadMeshOptions): MeshData;

/**
 * A mesh file's bytes, written by the core's writers (the same bytes as the CLI's `-o`): a kernel
 * result (its vertices and polygon faces; point, segment and empty kernels give files without
 * faces) or a mesh. OBJ and OFF keep every coordinate bit; STL is binary, fan-triangulated,
 * float. Requires a finished init(). A mesh with a non-finite coordinate or an index past its
 * vertices is refused ('NON_FINITE_COORDINATE', 'INDEX_OUT_OF_RANGE').
 */
export function writeMesh(meshOrKernel: KernelResult | MeshInput, format: 'obj' | 'off' | 'stl'): Uint8Array;

/** What repairMesh accepts: the options that change the mesh the kernel is computed on. */
export type RepairMeshOptions = Pick<
  KernelOptions,
  'weld' | 'repair' | 'flipFaces' | 'allowOpen' | 'open' | 'faceSizes' | 'maxFaces' | 'maxVertices'
>;

/**
 * The mesh computeKernel computes the kernel on, as repairMesh returns it. Faces keep their
 * orientation as given and their corners (polygons are not split); vertices no face uses (merged
 * by the weld, or unused in the input) are left out, the others keep their order and coordinates.
 */
export interface RepairedMesh extends MeshData {
  /** What weld and repair did (`VERTICES_WELDED`, `T_JUNCTIONS_SPLIT`, ...), then validation's warnings. */
  warnings: KernelWarning[];
  /**
   * Validation's verdict on the repaired mesh, as computeKernel would throw it ('OPEN_MESH' when
   * repair left it open, ...), or null when computeKernel accepts it. The mesh is returned either way.
   */
  error: string | null;
  /** The verdict's message ('' when error is null). */
  message: string;
}

/**
 * The input after `weld` and `repair` (as set in options): what computeKernel with the same
 * options computes the kernel on, for saving it (`writeMesh(repaired, 'obj')`). Throws a
 * KergenError only for malformed input (indices out of range, non-finite coordinates, faces of
 * fewer than three corners), which leaves no mesh to return.
 */
export function repairMesh(
  positions: PositionsInput,
  indices: IndicesInput,
  options?: RepairMeshOptions,
): Promise<RepairedMesh>;
/** Synchronous repairMesh; requires a finished init(). */
export function repairMeshSync(
  positions: PositionsInput,
  indices: IndicesInput,
  options?: RepairMeshOptions,
): RepairedMesh;

/** Wasm heap figures (requires a finished init()). */
export function memoryStats(): MemoryStats;

// ---- polyhedral volume meshes ------------------------------------------------------------------

/**
 * A polyhedral volume mesh (the core's `kergen::VolumeMesh`), CSR style: face `f`'s loop is
 * `faceIndices[faceOffsets[f] .. faceOffsets[f + 1])`, cell `c`'s faces are
 * `cellFaces[cellOffsets[c] .. cellOffsets[c + 1])`. Faces are kept as the file lists them (a
 * `.vtu` polyhedron lists its own faces, so a face shared by two cells is there twice), each
 * orientation as written: every cell is turned outward for the computation.
 */
export interface VolumeMesh {
  positions: Float64Array;
  faceIndices: Uint32Array;
  faceOffsets: Uint32Array;
  cellFaces: Uint32Array;
  cellOffsets: Uint32Array;
}

/** What computeCellKernels and cellSurface accept as a mesh: readVolumeMesh's, or the caller's arrays. */
export interface VolumeMeshInput {
  positions: Float64Array | Float32Array | readonly number[];
  faceIndices: Uint32Array | readonly number[];
  faceOffsets: Uint32Array | readonly number[];
  cellFaces: Uint32Array | readonly number[];
  cellOffsets: Uint32Array | readonly number[];
}

/** Volume mesh formats: VTK XML `.vtu`, legacy VTK `.vtk`, the `.node` + `.ele` pair. */
export type VolumeMeshFormat = 'vtu' | 'vtk' | 'node-ele';

/** One volume-mesh file's bytes, or the `.node` and `.ele` files of the pair. */
export type VolumeMeshBytes = MeshBytes | { node: MeshBytes; ele: MeshBytes };

export interface ReadVolumeMeshOptions {
  /** Default: from the content (`.vtu`, `.vtk`); the pair is recognised by `{ node, ele }`. */
  format?: VolumeMeshFormat;
  /** The file's name in messages (the `.node` file's for the pair). Default `'<memory>'`. */
  name?: string;
  /** The `.ele` file's name in messages. */
  eleName?: string;
}

/**
 * Reads a volume mesh with the core's readers (the CLI's `--cells`): `.vtu` (VTK_POLYHEDRON and
 * linear cells; ascii, base64 or raw appended data), legacy `.vtk`, or `{ node, ele }`.
 * Malformed files reject with 'PARSE_ERROR' naming the file and the line or byte offset.
 */
export function readVolumeMesh(input: VolumeMeshBytes, options?: ReadVolumeMeshOptions): Promise<VolumeMesh>;
/** Synchronous readVolumeMesh; requires a finished init(). */
export function readVolumeMeshSync(input: VolumeMeshBytes, options?: ReadVolumeMeshOptions): VolumeMesh;

/** One cell as a surface mesh (the core's `cell_surface`), ready for computeKernel. */
export interface CellSurface {
  /** The cell's vertices only, in increasing global id. */
  positions: Float64Array;
  /** The cell's faces in the cell's order, turned outward (counter-clockwise seen from outside). */
  indices: Uint32Array;
  faceSizes: Uint32Array;
  /** `globalVertices[i]`: the mesh's id of local vertex `i`. */
  globalVertices: Uint32Array;
  /** Whether any face was reversed to turn the cell outward. */
  reoriented: boolean;
}

/**
 * Cell `cell` of a volume mesh as a surface: `computeKernel(s.positions, s.indices,
 * { faceSizes: s.faceSizes })` gives exactly that cell's computeCellKernels record.
 * Rejects with 'INDEX_OUT_OF_RANGE' when the cell names a face or vertex that does not exist,
 * 'INVALID_ARGUMENT' when the cell is out of range or the offsets are malformed.
 */
export function cellSurface(mesh: VolumeMeshInput, cell: number): Promise<CellSurface>;
/** Synchronous cellSurface; requires a finished init(). */
export function cellSurfaceSync(mesh: VolumeMeshInput, cell: number): CellSurface;

/** Progress of computeCellKernels: after every range of cells. */
export interface CellProgress {
  phase: 'cells';
  /** Cells done so far. */
  count: number;
  /** Cells to compute. */
  total: number;
}

export interface CellKernelOptions extends ReadVolumeMeshOptions {
  /** Also the inscribed ball of each kernel (its radius ρ and ρ / h). Several times slower. */
  deepestPoint?: boolean;
  /** The first cell to compute (default 0). */
  firstCell?: number;
  /** How many cells (default: all from firstCell on; clipped to the mesh). */
  count?: number;
  /** Cells per range: onProgress is called, and the async variant yields, after each (default 1000). */
  rangeSize?: number;
  /** How many cells `summary.worstCells` lists (default 10). */
  worst?: number;
  onProgress?: (progress: CellProgress) => void;
  /** computeCellKernels (async) only: cancels between ranges (rejects with 'CANCELLED'). */
  signal?: AbortSignal;
}

/** What a run says about the cells as a whole (the core's `summarize_cells`). */
export interface CellSummary {
  cells: number;
  /** Cells with a kernel (no error). */
  okCells: number;
  /** Cells with a kernel, by its status ('EMPTY' = not star-shaped). */
  byType: Record<KernelStatus, number>;
  /** Cells without a kernel, by error code. */
  byError: Partial<Record<CoreErrorCode, number>>;
  reorientedCells: number;
  /** Over the cells with a kernel; the median of an even count is the lower middle value. */
  minRatio: number;
  medianRatio: number;
  maxRatio: number;
  /** True when deepest points were computed (then the ρ / h figures are numbers). */
  hasRhoOverH: boolean;
  minRhoOverH: number | null;
  medianRhoOverH: number | null;
  maxRhoOverH: number | null;
  /** The cells with the smallest ρ / h (the smallest ratio without deepest points), worst first. */
  worstCells: Uint32Array;
}

/**
 * The kernel of every computed cell; arrays hold one value per cell (cell `firstCell + i` at `i`),
 * each exactly what computeKernel gives for that cell's surface (cellSurface).
 */
export interface CellKernelsResult {
  firstCell: number;
  numCells: number;
  /** The kernel status's value (0 EMPTY ... 5 UNBOUNDED), or minus the error's value; names in `statusNames`. */
  status: Int32Array;
  /** The name of every status code: `statusNames[status[i]]` is 'POLYHEDRON', 'EMPTY', 'OPEN_MESH', ... */
  statusNames: Record<number, string>;
  kernelVolume: Float64Array;
  cellVolume: Float64Array;
  /** kernelVolume / cellVolume (1 for a convex cell). */
  kernelRatio: Float64Array;
  /** h: the largest distance between two of the cell's vertices. */
  diameter: Float64Array;
  /** ρ: the radius of the largest ball in the kernel (deepestPoint; 0 without a full-dimensional kernel). */
  inscribedRadius: Float64Array;
  /** ρ / h. */
  rhoOverH: Float64Array;
  /** The ball's centre, 3 values per cell (NaN without one). */
  deepestPoints: Float64Array;
  /** 1 where the cell's faces were turned outward. */
  reoriented: Uint8Array;
  /** Cell i's witness faces (an EMPTY kernel's) are witnessFaces[witnessOffsets[i] .. witnessOffsets[i + 1]). */
  witnessOffsets: Uint32Array;
  /** Indices into the cell's faces (cellSurface's order). */
  witnessFaces: Uint32Array;
  /** The same faces as face ids of the mesh. */
  witnessGlobalFaces: Uint32Array;
  /** The cells without a kernel: their error code and message ("cell N: ..."). */
  errors: { cell: number; code: string; message: string }[];
  /** ORIENTATION_FLIPPED with the number of cells turned outward, when there are any. */
  warnings: KernelWarning[];
  summary: CellSummary;
  /** The mesh read, when a file's bytes were given. */
  mesh?: VolumeMesh;
}

/**
 * The kernel of every cell of a volume mesh (or of a range of cells), computed range by range:
 * `meshOrBytes` is a mesh (readVolumeMesh's or the caller's arrays), a file's bytes or
 * `{ node, ele }`. One bad cell never stops the others: it gets its error in `status` and
 * `errors`. Yields to the event loop between ranges; `signal` cancels.
 */
export function computeCellKernels(
  meshOrBytes: VolumeMeshInput | VolumeMeshBytes,
  options?: CellKernelOptions,
): Promise<CellKernelsResult>;
/** Synchronous computeCellKernels (onProgress still runs between ranges); requires a finished init(). */
export function computeCellKernelsSync(
  meshOrBytes: VolumeMeshInput | VolumeMeshBytes,
  options?: Omit<CellKernelOptions, 'signal'>,
): CellKernelsResult;

/**
 * One result of results computed in parts (consecutive cell ranges, e.g. by several
 * KernelWorkers, each on its own `firstCell` / `count`): the arrays concatenated in cell order,
 * the witness offsets shifted, and the summary of all the cells computed again by the core.
 * Rejects with 'INVALID_ARGUMENT' when the parts are not consecutive.
 */
export function joinCellKernels(
  parts: readonly CellKernelsResult[],
  options?: { worst?: number },
): Promise<CellKernelsResult>;
/** Synchronous joinCellKernels; requires a finished init(). */
export function joinCellKernelsSync(
  parts: readonly CellKernelsResult[],
  options?: { worst?: number },
): CellKernelsResult;

/** One mesh of computeKernels: what computeKernel takes (readMesh's and cellSurface's results fit). */
export interface KernelMesh {
  positions: PositionsInput;
  indices: IndicesInput;
  /** Vertices per face (absent or null: every face is a triangle). */
  faceSizes?: Uint32Array | readonly number[] | null;
}

/** Progress of computeKernels: after every range of meshes. */
export interface KernelsProgress {
  phase: 'meshes';
  /** Meshes done so far. */
  count: number;
  /** Meshes to compute. */
  total: number;
}

/**
 * computeKernels' options: computeKernel's, the same for every mesh (without onStep, and without
 * faceSizes, which each mesh gives), plus the ranges' progress and cancellation.
 */
export interface KernelsOptions extends Omit<KernelOptions, 'onStep' | 'onProgress' | 'faceSizes'> {
  /** Meshes per range: onProgress is called, and the async variant yields, after each (default 100;
   * a range also ends once its meshes' arrays reach 32 MiB). */
  rangeSize?: number;
  onProgress?: (progress: KernelsProgress) => void;
  /** computeKernels (async) only: cancels between ranges (rejects with 'CANCELLED'). */
  signal?: AbortSignal;
}

/**
 * The kernels of many meshes with one options object, in one run of the module's KernelBatch:
 * `results[i]` is exactly what computeKernel gives for `meshes[i]` (the same arrays, values and
 * warnings; only `stats`' times differ), or the KergenError it would throw (check with
 * `instanceof KergenError`; its `.code` and message are computeKernel's): one bad mesh never stops
 * the others. Malformed options reject the whole call. Yields to the event loop between ranges;
 * `signal` cancels.
 */
export function computeKernels(
  meshes: readonly KernelMesh[],
  options?: KernelsOptions,
): Promise<Array<KernelResult | KergenError>>;
/** Synchronous computeKernels (onProgress still runs between ranges); requires a finished init(). */
export function computeKernelsSync(
  meshes: readonly KernelMesh[],
  options?: Omit<KernelsOptions, 'signal'>,
): Array<KernelResult | KergenError>;
