// kergen-wasm/worker: the KernelWorker helper and its module worker script, run in Node through a
// small Web Worker shim over worker_threads (the browser path is covered by the e2e tests).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { usePackageWithWorker } from './lib/package-with-worker.mjs';
import { lPrismFiles } from './lib/example-meshes.mjs';
import { WebWorkerShim } from './lib/web-worker-shim.mjs';
import { box, extrude, plusPrism } from './lib/geometry.mjs';

let K;
let W;
const { newWorker } = usePackageWithWorker((pkg) => ({ K, W } = pkg));

function starPrism(n, inner) {
  const poly = [];
  for (let i = 0; i < 2 * n; i++) {
    const r = i % 2 ? inner : 1;
    poly.push([r * Math.cos((Math.PI * i) / n), r * Math.sin((Math.PI * i) / n)]);
  }
  return extrude(poly, 0, 1);
}

test('spawns a module worker from kergen-worker.js next to worker.js', () => {
  const before = WebWorkerShim.spawned.length;
  newWorker();
  const spawned = WebWorkerShim.spawned.slice(before);
  assert.equal(spawned.length, 1);
  assert.match(spawned[0].url, /\/wasm\/kergen-worker\.js$/);
});

test('compute in the worker equals computeKernelSync; step events replay in order; progress ends with done', async () => {
  const m = starPrism(9, 0.5);
  const syncEvents = [];
  const expected = K.computeKernelSync(m.positions, m.indices, { onStep: (e) => void syncEvents.push(e) });
  const events = [];
  const progress = [];
  const kw = newWorker();
  const r = await kw.compute(m.positions, m.indices, {
    copy: true,
    onStep: (e) => void events.push(e),
    onProgress: (p) => progress.push(p),
  });
  assert.equal(r.status, expected.status);
  assert.equal(r.volume, expected.volume);
  assert.deepEqual(Array.from(r.vertices), Array.from(expected.vertices));
  assert.deepEqual(
    r.faces.map((f) => Array.from(f)),
    expected.faces.map((f) => Array.from(f)),
  );
  assert.deepEqual(Array.from(r.triangles), Array.from(expected.triangles));
  assert.deepEqual(r.stats.inputFaces, expected.stats.inputFaces);
  assert.deepEqual(events, syncEvents);
  assert.ok(progress.length >= 2);
  assert.deepEqual(progress[0], { phase: 'loading', steps: 0 });
  assert.deepEqual(progress.at(-1), { phase: 'done', steps: syncEvents.length });
  for (let i = 1; i < progress.length; i++)
    assert.ok(progress[i].steps >= progress[i - 1].steps, 'steps never decrease');
});

test('input arrays are copied by default (never detached); transfer: true detaches them; copy is an accepted no-op', async () => {
  const kw = newWorker();
  const m = plusPrism(0.3, 1);
  const positions = Float32Array.from(m.positions);
  const indices = Uint16Array.from(m.indices);
  const bytesBefore = [Buffer.from(positions.buffer).toString('hex'), Buffer.from(indices.buffer).toString('hex')];
  const buffers = [positions.buffer, indices.buffer];
  const r1 = await kw.compute(positions, indices);
  assert.equal(r1.status, 'POLYHEDRON');
  assert.equal(positions.length, m.positions.length, 'positions kept');
  assert.equal(indices.length, m.indices.length, 'indices kept');
  assert.ok(positions.buffer === buffers[0] && indices.buffer === buffers[1], 'same buffers');
  assert.deepEqual(
    [Buffer.from(positions.buffer).toString('hex'), Buffer.from(indices.buffer).toString('hex')],
    bytesBefore,
    'same bytes',
  );

  const r2 = await kw.compute(positions, indices, { copy: true });
  assert.equal(positions.length, m.positions.length, 'kept with copy: true');
  assert.equal(r2.volume, r1.volume);

  const p3 = Float32Array.from(m.positions);
  const i3 = Uint32Array.from(m.indices);
  const r3 = await kw.compute(p3, i3, { transfer: true });
  assert.equal(r3.volume, r1.volume);
  assert.equal(p3.byteLength, 0, 'positions detached with transfer: true');
  assert.equal(i3.byteLength, 0, 'indices detached with transfer: true');
  await assert.rejects(
    kw.compute(positions, indices, { copy: true, transfer: true }),
    (err) => err.code === 'INVALID_ARGUMENT' && /contradict/.test(err.message),
  );
  await assert.rejects(
    kw.compute(positions, indices, { transfer: 'yes' }),
    (err) => err.code === 'INVALID_ARGUMENT' && /transfer must be a boolean/.test(err.message),
  );

  const big = new Float64Array(m.positions.length + 6);
  big.set(m.positions, 3);
  const view = big.subarray(3, 3 + m.positions.length);
  const r4 = await kw.compute(view, Array.from(m.indices), { transfer: true });
  assert.equal(
    big.byteLength,
    (m.positions.length + 6) * 8,
    'a partial view never detaches its buffer, even with transfer: true',
  );
  assert.equal(r4.volume, K.computeKernelSync(view, m.indices).volume);
});

test('step events arrive in batches of at most 4096, as transferred typed arrays', async () => {
  const kw = newWorker();
  const m = starPrism(1500, 0.9);
  let count = 0;
  const r = await kw.compute(m.positions, m.indices, { onStep: () => void count++ });
  const total = r.vertices.length / 3 + r.edges.length / 2 + r.faces.length;
  assert.equal(count, total, 'every event delivered');
  assert.ok(total > 2 * 4096, `a large kernel (${total} events)`);
  const shim = WebWorkerShim.spawned.find((s) =>
    s.received.some((msg) => msg.type === 'result' && msg.result.vertices.length === r.vertices.length),
  );
  const batches = shim.received.filter((msg) => msg.type === 'steps');
  assert.ok(batches.length >= Math.ceil(total / 4096), `${batches.length} batches`);
  assert.ok(
    batches.length < total / 64,
    `${batches.length} batches for ${total} events: batched, not one message per event`,
  );
  assert.equal(
    batches.reduce((n, b) => n + b.batch.count, 0),
    total,
  );
  for (const { batch } of batches) {
    assert.ok(batch.count <= 4096);
    assert.ok(batch.kinds instanceof Uint8Array && batch.kinds.length === batch.count);
    assert.ok(batch.ids instanceof Uint32Array && batch.positions instanceof Float64Array);
    assert.ok(batch.ends instanceof Uint32Array && batch.loopStarts instanceof Uint32Array);
  }
});

// computeFile / writeMesh need the package's file layer (readMeshSync, writeMesh).
const fileLayer = () => typeof K.readMeshSync === 'function' && typeof K.writeMesh === 'function';

// An L prism with non-convex hexagon caps as OFF bytes: its kernel is the unit cube.
const lPrismOff = () => new TextEncoder().encode(lPrismFiles().off);

test('computeFile parses in the worker: mesh and kernel, bytes kept (transferred only with transfer: true), onMesh before the result, progress by phase', async (t) => {
  if (!fileLayer()) return t.skip('this package build has no readMeshSync / writeMesh');
  const kw = newWorker();
  const bytes = lPrismOff();
  const size = bytes.byteLength;
  const order = [];
  const progress = [];
  const { mesh, result } = await kw.computeFile(bytes, {
    name: 'l-prism.off',
    onMesh: (m) => order.push(['mesh', m.faceSizes.length]),
    onProgress: (p) => progress.push(p),
    onStep: () => void order.push('step'),
  });
  assert.equal(bytes.byteLength, size, 'the bytes are copied by default');
  assert.equal(result.status, 'POLYHEDRON');
  const moved = lPrismOff();
  assert.equal((await kw.computeFile(moved, { name: 'l.off', transfer: true })).result.volume, 1);
  assert.equal(moved.byteLength, 0, 'transfer: true moves the bytes');
  assert.equal(result.volume, 1);
  assert.ok(mesh.positions instanceof Float64Array && mesh.positions.length === 36);
  assert.deepEqual(Array.from(mesh.faceSizes), [6, 6, 4, 4, 4, 4, 4, 4]);
  assert.deepEqual(order[0], ['mesh', 8], 'onMesh comes before the first step');
  assert.equal(order.filter((x) => x === 'step').length, 8 + 12 + 6);
  const phases = progress.map((p) => p.phase);
  assert.deepEqual(
    progress.find((p) => p.phase === 'reading'),
    { phase: 'reading', steps: 0, bytes: size },
  );
  for (const phase of ['validating', 'planes', 'lp', 'tracing', 'assembling'])
    assert.ok(phases.includes(phase), `phase ${phase} in ${phases}`);
  assert.ok(
    phases.indexOf('reading') < phases.indexOf('validating') &&
      phases.indexOf('validating') < phases.indexOf('assembling'),
  );
  assert.equal(progress.find((p) => p.phase === 'validating').count, 8, 'validating counts the 8 input faces');
  assert.equal(phases.at(-1), 'done');
});

test('computeFile: parse errors reject with PARSE_ERROR naming the file and line', async (t) => {
  if (!fileLayer()) return t.skip('this package build has no readMeshSync / writeMesh');
  const kw = newWorker();
  const text = new TextEncoder().encode('OFF\n3 1 0\n0 0 0\n1 0 zero\n0 1 0\n3 0 1 2\n');
  await assert.rejects(
    kw.computeFile(text, { name: 'garbage.off' }),
    (err) => err.code === 'PARSE_ERROR' && /^garbage\.off:4: invalid number 'zero'/.test(err.message),
  );
  const r = await kw.computeFile(lPrismOff(), { format: 'off' });
  assert.equal(r.result.volume, 1, 'the worker keeps working after a parse error');
});

test('writeMesh in the worker: OFF, OBJ and STL bytes of a kernel read back to the same kernel', async (t) => {
  if (!fileLayer()) return t.skip('this package build has no readMeshSync / writeMesh');
  const kw = newWorker();
  const { result } = await kw.computeFile(lPrismOff(), { name: 'l.off' });
  for (const format of ['off', 'obj', 'stl']) {
    const bytes = await kw.writeMesh(result, format);
    assert.ok(bytes instanceof Uint8Array && bytes.length > 0, format);
    const again = await kw.computeFile(bytes, { name: `kernel.${format}` });
    assert.equal(again.result.status, 'POLYHEDRON', format);
    assert.ok(Math.abs(again.result.volume - 1) < 1e-12, `${format}: volume ${again.result.volume}`);
  }
  assert.equal(result.vertices.length, 24, 'the caller keeps its result');
});

test('errors cross as KergenError with the core code', async () => {
  const kw = newWorker();
  const m = box();
  await assert.rejects(
    kw.compute(m.positions, m.indices.subarray(0, 33), { transfer: true }),
    (err) => err instanceof W.KergenError && err.code === 'OPEN_MESH' && err.message.length > 3,
  );
  assert.equal(m.positions.byteLength, 0, 'transferred');
  // Reusing a transferred (detached) array is reported, not silently lost.
  await assert.rejects(
    kw.compute(m.positions, box().indices),
    (err) => err.code === 'INVALID_ARGUMENT' && /detached/.test(err.message),
  );
  await assert.rejects(
    kw.compute(m.positions, box().indices, { copy: true }),
    (err) => err.code === 'INVALID_ARGUMENT' && /detached/.test(err.message),
  );
  const fresh = box();
  await assert.rejects(
    kw.compute(fresh.positions, fresh.indices, { copy: true, maxSteps: -3 }),
    (err) => err.code === 'INVALID_ARGUMENT',
  );
  await assert.rejects(kw.compute(new Float64Array(0), new Uint32Array(0)), (err) => err.code === 'EMPTY_INPUT');
  const r = await kw.compute(fresh.positions, fresh.indices);
  assert.equal(r.status, 'POLYHEDRON', 'the worker keeps working after errors');
});

test('cancel() rejects running and queued computations with CANCELLED and respawns the worker', async () => {
  const kw = newWorker();
  const m = starPrism(2000, 0.9);
  const running = kw.compute(m.positions, m.indices, { copy: true });
  const queued = kw.compute(m.positions, m.indices, { copy: true });
  const spawnedBefore = WebWorkerShim.spawned.length;
  kw.cancel();
  await assert.rejects(running, (err) => err instanceof W.KergenError && err.code === 'CANCELLED');
  await assert.rejects(queued, (err) => err.code === 'CANCELLED');
  assert.equal(WebWorkerShim.spawned.length, spawnedBefore + 1, 'a fresh worker was started');
  assert.ok(WebWorkerShim.spawned[spawnedBefore - 1].terminated, 'the busy worker was terminated');
  const small = box();
  const r = await kw.compute(small.positions, small.indices);
  assert.equal(r.volume, 1);
});

test('onStep returning false cancels the worker computation', async () => {
  const kw = newWorker();
  const m = starPrism(40, 0.6);
  let n = 0;
  await assert.rejects(
    kw.compute(m.positions, m.indices, { onStep: () => ++n < 10 }),
    (err) => err.code === 'CANCELLED',
  );
  assert.equal(n, 10, 'no events delivered after false');
  const small = box();
  assert.equal((await kw.compute(small.positions, small.indices)).volume, 1);
});

test('dispose() terminates for good', async () => {
  const kw = newWorker();
  const m = box();
  const pending = kw.compute(m.positions, m.indices, { copy: true });
  kw.dispose();
  await assert.rejects(pending, (err) => err.code === 'CANCELLED');
  await assert.rejects(kw.compute(m.positions, m.indices), (err) => err.code === 'DISPOSED');
});

// A Worker that never starts (as a dev server serving an HTML page for the worker script does):
// it reports an error event shortly after construction.
class NeverStartingWorker {
  static spawned = 0;
  constructor() {
    NeverStartingWorker.spawned++;
    this.onmessage = null;
    this.onerror = null;
    setTimeout(() => this.onerror && this.onerror({ preventDefault() {} }), 5);
  }
  postMessage() {}
  terminate() {}
}

test('a worker that cannot start rejects the pending calls once and is not restarted until the next call', async () => {
  const RealWorker = globalThis.Worker;
  globalThis.Worker = NeverStartingWorker;
  try {
    const kw = new W.KernelWorker();
    const m = box();
    const pending = kw.compute(m.positions, m.indices);
    const queued = kw.compute(m.positions, m.indices);
    await assert.rejects(pending, (err) => err.code === 'WORKER_ERROR' && /failed to start/.test(err.message));
    await assert.rejects(queued, (err) => err.code === 'WORKER_ERROR');
    await new Promise((r) => setTimeout(r, 200));
    assert.equal(NeverStartingWorker.spawned, 1, 'no restart while nothing is asked');
    await assert.rejects(kw.compute(m.positions, m.indices), (err) => err.code === 'WORKER_ERROR');
    await new Promise((r) => setTimeout(r, 200));
    assert.equal(NeverStartingWorker.spawned, 2, 'one new worker for the one new call');
    kw.dispose();
  } finally {
    globalThis.Worker = RealWorker;
  }
  const kw = newWorker();
  const m = box();
  assert.equal((await kw.compute(m.positions, m.indices)).volume, 1, 'a working Worker works as before');
});

test('the worker forwards open and repair', async () => {
  const b = box();
  const openCube = b.indices.slice(0, b.indices.length - 6); // without the x = 1 side: a hole
  const kw = newWorker();
  const walled = await kw.compute(b.positions, openCube, { copy: true, open: 'perpendicular' });
  const expected = K.computeKernelSync(b.positions, openCube, { open: 'perpendicular' });
  assert.equal(walled.status, expected.status);
  assert.equal(walled.volume, expected.volume);
  // The bad-input table's T-junction box: open as given, the box with repair.
  const t = {
    positions: Float64Array.from([
      0, 0, 0, 2, 0, 0, 2, 1, 0, 0, 1, 0, 0, 0, 1, 2, 0, 1, 2, 1, 1, 0, 1, 1, 1, 0, 0, 1, 1, 0,
    ]),
    indices: Uint32Array.from([0, 3, 9, 8, 8, 9, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 2, 3, 7, 6, 1, 2, 6, 5, 3, 0, 4, 7]),
    faceSizes: Uint32Array.from([4, 4, 4, 4, 4, 4, 4]),
  };
  const repaired = await kw.compute(t.positions, t.indices, { copy: true, faceSizes: t.faceSizes, repair: true });
  assert.equal(repaired.volume, 2);
});

test('repairMesh in the worker equals repairMeshSync', async () => {
  const t = {
    positions: Float64Array.from([
      0, 0, 0, 2, 0, 0, 2, 1, 0, 0, 1, 0, 0, 0, 1, 2, 0, 1, 2, 1, 1, 0, 1, 1, 1, 0, 0, 1, 1, 0,
    ]),
    indices: Uint32Array.from([0, 3, 9, 8, 8, 9, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 2, 3, 7, 6, 1, 2, 6, 5, 3, 0, 4, 7]),
    faceSizes: Uint32Array.from([4, 4, 4, 4, 4, 4, 4]),
  };
  const expected = K.repairMeshSync(t.positions, t.indices, { faceSizes: t.faceSizes, repair: true });
  const kw = newWorker();
  const r = await kw.repairMesh(t.positions, t.indices, { faceSizes: t.faceSizes, repair: true });
  assert.deepEqual(r, expected);
  assert.equal(r.error, null);
  await assert.rejects(
    kw.repairMesh(t.positions, Uint32Array.from([0, 1, 99]), {}),
    (e) => e.code === 'INDEX_OUT_OF_RANGE',
  );
});
