// KernelWorker's volume-mesh methods (worker-cells.js, kergen-worker-cells.js), run in Node through
// the Web Worker shim: the worker's results equal the package's own, progress arrives after every
// range, the mesh read from a file arrives before the result, and cancel() stops a run.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { usePackageWithWorker } from './lib/package-with-worker.mjs';
import { agglomeratedGrid, volumeMeshToVtu } from '../../web/cells-sample.js';

let K;
let W;
const { newWorker } = usePackageWithWorker((pkg) => ({ K, W } = pkg));
const vtu = (...grid) => new TextEncoder().encode(volumeMeshToVtu(agglomeratedGrid(...grid)));

test('computeCellKernels in the worker equals computeCellKernelsSync; progress per range; onMesh first', async () => {
  const bytes = vtu(9, 6, 2);
  const expected = K.computeCellKernelsSync(bytes, { deepestPoint: true });
  const kw = newWorker();
  const events = [];
  let mesh = null;
  const r = await kw.computeCellKernels(bytes, {
    name: 'grid.vtu',
    deepestPoint: true,
    rangeSize: 10,
    onMesh: (m) => {
      mesh = m;
      events.push('mesh');
    },
    onProgress: (p) => events.push(p),
  });
  assert.equal(bytes.length > 0, true, 'the bytes were copied, not transferred');
  assert.deepEqual([...r.status], [...expected.status]);
  assert.deepEqual([...r.kernelVolume], [...expected.kernelVolume]);
  assert.deepEqual([...r.rhoOverH], [...expected.rhoOverH]);
  assert.deepEqual([...r.witnessGlobalFaces], [...expected.witnessGlobalFaces]);
  assert.deepEqual(r.summary.byType, expected.summary.byType);
  assert.ok(mesh && !r.mesh, 'the mesh came through onMesh only');
  assert.deepEqual([...mesh.cellOffsets], [...expected.mesh.cellOffsets]);
  const cells = events.filter((e) => e.phase === 'cells').map((e) => e.count);
  const total = expected.numCells;
  assert.deepEqual(
    cells,
    [...Array(Math.ceil(total / 10) + 1).keys()].map((i) => Math.min(10 * i, total)),
  );
  assert.ok(events.indexOf('mesh') < events.findIndex((e) => e.phase === 'cells'), 'the mesh before the cells');
  assert.equal(events.at(-1).phase, 'done');
  // One cell through the worker: its surface, then its kernel.
  const s = await kw.cellSurface(mesh, 0);
  const k = await kw.compute(s.positions, s.indices, { faceSizes: s.faceSizes });
  assert.equal(k.volume, expected.kernelVolume[0]);
  const read = await kw.readVolumeMesh(bytes);
  assert.deepEqual([...read.faceIndices], [...mesh.faceIndices]);
});

test('computeCellKernels in the worker: errors with their code, and cancel()', async () => {
  const kw = newWorker();
  await assert.rejects(kw.computeCellKernels(new TextEncoder().encode('<VTKFile'), { name: 'bad.vtu' }), (err) => {
    assert.ok(err instanceof W.KergenError);
    assert.equal(err.code, 'PARSE_ERROR');
    assert.match(err.message, /bad\.vtu/);
    return true;
  });
  const running = kw.computeCellKernels(vtu(30, 30, 6), { deepestPoint: true, rangeSize: 50 });
  setTimeout(() => kw.cancel(), 50);
  await assert.rejects(running, (err) => err.code === 'CANCELLED');
  const small = await kw.computeCellKernels(vtu(3, 2, 1));
  assert.equal(small.numCells, small.summary.cells);
});
