// Type-level usage example: `npx tsc -p tests/types` must pass with --strict (checks index.d.ts
// and worker.d.ts as a package consumer sees them, through the package's "exports" map).
import {
  init,
  computeKernel,
  computeKernelSync,
  findKernelPoint,
  isStarShaped,
  memoryStats,
  readMesh,
  readMeshSync,
  writeMesh,
  repairMesh,
  repairMeshSync,
  computeKernels,
  computeKernelsSync,
  KergenError,
  FACE_SOURCE_BOX,
  FACE_SOURCE_WALL,
  type RepairedMesh,
  type KernelPhase,
  type KernelProgress,
  type MeshData,
  type KernelResult,
  type StepEvent,
  type Vec3,
  type KernelMesh,
} from 'kergen-wasm';
import {
  KernelWorker,
  FACE_SOURCE_BOX as WORKER_BOX,
  FACE_SOURCE_WALL as WORKER_WALL,
  type ProgressEvent,
} from 'kergen-wasm/worker';

const positions = new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1]);
const indices = new Uint32Array([0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3]);

async function main(): Promise<void> {
  await init({ wasmUrl: new URL('https://example.invalid/kergen.wasm') });
  await init({ wasmBinary: new Uint8Array(8) });

  const seen: Vec3[] = [];
  const result: KernelResult = await computeKernel(positions, indices, {
    from: [0.1, 0.1, 0.1],
    maxSteps: 1000,
    deepestPoint: true,
    onStep(event: StepEvent) {
      switch (event.type) {
        case 'vertex':
          seen.push(event.position);
          break;
        case 'edge':
          return event.a !== event.b;
        case 'face': {
          const n: number = event.loop.length;
          return n >= 3;
        }
      }
      return undefined;
    },
  });
  const status: 'EMPTY' | 'POINT' | 'SEGMENT' | 'POLYGON' | 'POLYHEDRON' | 'UNBOUNDED' = result.status;
  const tri: Uint32Array = result.triangles;
  const verts: Float64Array = result.vertices;
  const firstFace: Uint32Array | undefined = result.faces[0];
  const p: Vec3 | null = result.deepestPoint;
  const total: number = result.stats.msTotal + result.volume + result.volumeRatio;
  const kinds: string[] = result.warnings.map((w) => `${w.kind} x${w.count}: ${w.message}`);
  void [status, tri, verts, firstFace, p, total, kinds];

  const phases: KernelPhase[] = [];
  await computeKernel(positions, indices, {
    onProgress(progress: KernelProgress) {
      phases.push(progress.phase);
      const count: number = progress.count;
      void count;
    },
  });

  // Files: bytes of any ArrayBufferView or an ArrayBuffer in, plain typed arrays out.
  const read: MeshData = await readMesh(new Uint8Array([0x4f, 0x46, 0x46]), { format: 'off', name: 'cube.off' });
  const fromBuffer = readMeshSync(new ArrayBuffer(8), { name: 'shape.ply' });
  const fromView = readMeshSync(new DataView(new ArrayBuffer(8)));
  const sizes: Uint32Array | null = fromBuffer.faceSizes;
  const again: KernelResult = await computeKernel(read.positions, read.indices, { faceSizes: read.faceSizes });
  const obj: Uint8Array = writeMesh(again, 'obj');
  const stl: Uint8Array = writeMesh(
    { positions: fromView.positions, indices: fromView.indices, faceSizes: fromView.faceSizes },
    'stl',
  );
  const off: Uint8Array = writeMesh({ positions: [0, 0, 0, 1, 0, 0, 0, 1, 0], indices: [0, 1, 2] }, 'off');
  void [sizes, obj, stl, off];

  // The repaired mesh: a MeshData with warnings and validation's verdict, ready for writeMesh.
  const repaired: RepairedMesh = await repairMesh(read.positions, read.indices, {
    faceSizes: read.faceSizes,
    repair: true,
  });
  const verdict: string | null = repaired.error;
  const saved: Uint8Array = writeMesh(repaired, 'off');
  const again2 = repairMeshSync([0, 0, 0, 1, 0, 0, 0, 1, 0], [0, 1, 2], { weld: true, open: 'perpendicular' });
  void [verdict, saved, again2.warnings, repaired.message];
  const walled: KernelResult = await computeKernel(positions, indices, { open: 'perpendicular' });
  // What bounds the kernel: per face an input face index, or a mark for the box and the walls.
  const sources: Int32Array = walled.faceSources;
  const bounded: string[] = Array.from(sources, (s: number) =>
    s === FACE_SOURCE_BOX ? 'box' : s === FACE_SOURCE_WALL ? 'wall' : `face ${s}`,
  );
  // The walls of a witness, as the boundary edges they stand on (vertex id pairs).
  const wallEdges: Uint32Array = walled.witnessBoundaryEdges;
  const firstWall: [number, number] | null = wallEdges.length ? [wallEdges[0], wallEdges[1]] : null;
  void [bounded, firstWall];

  const sync = computeKernelSync([0, 0, 0, 1, 0, 0, 0, 1, 0], [0, 1, 2], { allowOpen: true, faceSizes: [3] });
  const complete: boolean = sync.complete;
  const kp = await findKernelPoint(positions, indices, { from: [0, 0, 0] });
  if (kp.starShaped && kp.point) {
    const [x, y, z] = kp.point;
    void (x + y + z);
  }
  // Why a shape is not star-shaped: input face indices (empty unless the kernel is empty).
  const why: Uint32Array = kp.starShaped ? new Uint32Array(0) : kp.witnessFaces;
  const whyToo: Uint32Array = sync.witnessFaces;
  const walls: Uint32Array = kp.witnessBoundaryEdges;
  void walls;
  const star: boolean = await isStarShaped(positions, indices);
  const heap: number = memoryStats().heapUsed + memoryStats().heapSize;
  void [complete, why, whyToo, star, heap];

  try {
    await computeKernel([NaN], [0]);
  } catch (err) {
    if (err instanceof KergenError) {
      const code: string = err.code;
      const message: string = err.message;
      void [code, message];
    }
  }

  const worker = new KernelWorker({ wasmUrl: '/assets/kergen.wasm' });
  const fromWorker: KernelResult = await worker.compute(positions, indices, {
    copy: true,
    onStep: (e) => e.type !== 'face',
    onProgress: (pr: ProgressEvent) => {
      const phase:
        'loading' | 'reading' | 'computing' | 'validating' | 'planes' | 'lp' | 'tracing' | 'assembling' | 'done' =
        pr.phase;
      void [phase, pr.steps, pr.count, pr.bytes];
    },
  });
  void fromWorker.edges;
  const workerSources: Int32Array = fromWorker.faceSources;
  const boxFaces: number = workerSources.filter((s) => s === WORKER_BOX || s === WORKER_WALL).length;
  void boxFaces;
  const { mesh, result: fileKernel } = await worker.computeFile(new Uint8Array(8), {
    name: 'a.stl',
    onMesh: (m) => void m.faceSizes,
  });
  const positions64: Float64Array = mesh.positions;
  void [positions64, fileKernel.volume];
  const stlBytes: Uint8Array = await worker.writeMesh(fileKernel, 'stl');
  const inWorker: RepairedMesh = await worker.repairMesh(positions, indices, { repair: true, transfer: false });
  void inWorker.error;
  void stlBytes;
  const many: KernelMesh[] = [{ positions, indices }, await readMesh(new Uint8Array(8), { name: 'b.off' })];
  const entries = await computeKernels(many, {
    deepestPoint: true,
    rangeSize: 10,
    signal: new AbortController().signal,
    onProgress: ({ phase, count, total }) => void [phase === 'meshes', count, total],
  });
  for (const e of entries) {
    if (e instanceof KergenError) void e.code;
    else void e.volume;
  }
  const syncEntries: (KernelResult | KergenError)[] = computeKernelsSync(many, { open: 'clip' });
  const workerEntries = await worker.computeKernels(many, { transfer: true, onProgress: (p) => void p.total });
  void [syncEntries, workerEntries.length];
  worker.cancel();
  worker.dispose();
}

// @ts-expect-error: positions must be numbers
void computeKernel(['a'], [0]);
// @ts-expect-error: from is a 3-tuple
void computeKernel(positions, indices, { from: [1, 2] });
// @ts-expect-error: readMesh reads no other format
void readMesh(new Uint8Array(0), { format: 'gltf' });
// @ts-expect-error: writeMesh writes OBJ, OFF and STL only
void writeMesh({ positions: [], indices: [] }, 'ply');
// @ts-expect-error: phases are a closed set
const badPhase: KernelPhase = 'loading';
void badPhase;
// @ts-expect-error: the face source marks are constants
FACE_SOURCE_BOX = 0;
// @ts-expect-error: statuses are a closed set
const bad: KernelResult['status'] = 'CONCAVE';
void bad;
// @ts-expect-error: computeKernels has no onStep (one options object for all meshes)
void computeKernels([{ positions, indices }], { onStep: () => true });
// @ts-expect-error: each mesh gives its own faceSizes
void computeKernels([{ positions, indices }], { faceSizes: [3] });

void main;
