// The volume-mesh jobs of the kergen worker (kergen-worker.js runs them; worker-cells.js posts
// them): 'readVolumeMesh', 'computeCellKernels' (progress after every range of cells) and
// 'cellSurface', run with the package's functions (cells.js).
//
// Protocol (main → worker):  { type: 'readVolumeMesh', id, input, readOptions }
//                            { type: 'computeCellKernels', id, mesh | input, readOptions?, cellOptions, wantMesh }
//                            { type: 'cellSurface', id, mesh, cell }
//                            { type: 'joinCellKernels', id, parts, worst? }
// Protocol (worker → main):  { type: 'progress', id, phase, steps: 0, count?, total? }
//                            { type: 'mesh', id, mesh }   (computeCellKernels of a file with wantMesh)
//                            { type: 'result', id, result } | { type: 'error', id, code, message }
import { readVolumeMeshSync, computeCellKernelsSync, cellSurfaceSync, joinCellKernelsSync } from './cells.js';

const buffersOf = (object) => [
  ...new Set(
    Object.values(object)
      .filter((v) => ArrayBuffer.isView(v) && v.byteLength > 0)
      .map((v) => v.buffer),
  ),
];

const copyOf = (mesh) => Object.fromEntries(Object.entries(mesh).map(([k, v]) => [k, v.slice()]));

/** The handlers, by message type; `ensureInit(wasmUrl)` loads the module once. */
export function cellHandlers(ensureInit) {
  return {
    async readVolumeMesh(msg) {
      await ensureInit(msg.wasmUrl);
      const mesh = readVolumeMeshSync(msg.input, msg.readOptions);
      self.postMessage({ type: 'result', id: msg.id, result: mesh }, buffersOf(mesh));
    },

    async computeCellKernels(msg) {
      const { id } = msg;
      self.postMessage({ type: 'progress', id, phase: 'loading', steps: 0 });
      await ensureInit(msg.wasmUrl);
      let mesh = msg.mesh;
      if (!mesh) {
        self.postMessage({ type: 'progress', id, phase: 'reading', steps: 0 });
        mesh = readVolumeMeshSync(msg.input, msg.readOptions);
        if (msg.wantMesh) {
          const early = copyOf(mesh);
          self.postMessage({ type: 'mesh', id, mesh: early }, buffersOf(early));
        }
      }
      const onProgress = ({ phase, count, total }) =>
        self.postMessage({ type: 'progress', id, phase, steps: 0, count, total });
      const result = computeCellKernelsSync(mesh, { ...msg.cellOptions, onProgress });
      // A file's mesh goes back with the result unless the page has its copy already.
      if (!msg.mesh && !msg.wantMesh) result.mesh = mesh;
      self.postMessage({ type: 'progress', id, phase: 'done', steps: 0 });
      const transfer = [
        ...buffersOf(result),
        ...(result.mesh ? buffersOf(result.mesh) : []),
        ...buffersOf(result.summary),
      ];
      self.postMessage({ type: 'result', id, result }, [...new Set(transfer)]);
    },

    async joinCellKernels(msg) {
      await ensureInit(msg.wasmUrl);
      const result = joinCellKernelsSync(msg.parts, msg.worst != null ? { worst: msg.worst } : {});
      self.postMessage({ type: 'result', id: msg.id, result }, [
        ...new Set([...buffersOf(result), ...buffersOf(result.summary)]),
      ]);
    },

    async cellSurface(msg) {
      await ensureInit(msg.wasmUrl);
      const surface = cellSurfaceSync(msg.mesh, msg.cell);
      self.postMessage({ type: 'result', id: msg.id, result: surface }, buffersOf(surface));
    },
  };
}
