// Step events in typed-array batches (wasm/step-batch.js): what KernelWorker's onStep receives
// after the trip through the worker must be the events computeKernelSync gives, event for event,
// in order — on whole kernels, on a partial kernel (maxSteps), and when the stream is stopped
// midway (onStep returning false, cancel()).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { usePackageWithWorker } from './lib/package-with-worker.mjs';
import { box, extrude, lPrism, plusPrism } from './lib/geometry.mjs';
import { StepBatchWriter, batchBuffers, forEachStep } from '../../wasm/step-batch.js';

let K;
const { newWorker } = usePackageWithWorker((pkg) => (K = pkg.K));

function starPrism(n, inner) {
  const poly = [];
  for (let i = 0; i < 2 * n; i++) {
    const r = i % 2 ? inner : 1;
    poly.push([r * Math.cos((Math.PI * i) / n), r * Math.sin((Math.PI * i) / n)]);
  }
  return extrude(poly, 0, 1);
}

// Meshes with vertex, edge and face events of several sizes: quads, polygon caps, many faces.
const MESHES = {
  'box (quads)': () => box([0, 0, 0], [1, 1, 1], { quads: true }),
  'L prism': () => lPrism(),
  'plus prism': () => plusPrism(0.3, 1),
  'star prism 300': () => starPrism(300, 0.8),
};

function syncEvents(mesh, options = {}) {
  const events = [];
  const result = K.computeKernelSync(mesh.positions, mesh.indices, {
    ...options,
    faceSizes: mesh.faceSizes ?? undefined,
    onStep: (e) => void events.push(e),
  });
  return { events, result };
}

test('a batch decodes to the events written into it, across batches and array growth', () => {
  for (const [name, make] of Object.entries(MESHES)) {
    const { events } = syncEvents(make());
    // A capacity of 5 makes the writer grow its arrays, and batches of 7 split the stream.
    const writer = new StepBatchWriter(5);
    const decoded = [];
    for (let i = 0; i < events.length; i++) {
      writer.push(events[i]);
      if (writer.count === 7 || i === events.length - 1) {
        const batch = structuredClone(writer.take(), { transfer: [] });
        assert.ok(forEachStep(batch, (e) => void decoded.push(e)));
      }
    }
    assert.equal(writer.count, 0, `${name}: take() empties the writer`);
    assert.deepEqual(decoded, events, `${name}: ${events.length} events`);
    assert.ok(
      events.some((e) => e.type === 'face' && e.loop.length > 3) || name === 'star prism 300',
      `${name}: has polygon faces`,
    );
  }
});

test('batch buffers are distinct and transferable; forEachStep stops at the first false', () => {
  const { events } = syncEvents(lPrism());
  const writer = new StepBatchWriter();
  for (const e of events) writer.push(e);
  const batch = writer.take();
  const buffers = batchBuffers(batch);
  assert.equal(new Set(buffers).size, buffers.length);
  const moved = structuredClone(batch, { transfer: buffers });
  assert.equal(batch.kinds.byteLength, 0, 'transferred');
  let seen = 0;
  assert.equal(
    forEachStep(moved, () => ++seen < 3),
    false,
  );
  assert.equal(seen, 3);
});

test('KernelWorker: onStep receives the events of computeKernelSync, event for event, on several meshes', async () => {
  const kw = newWorker();
  for (const [name, make] of Object.entries(MESHES)) {
    const mesh = make();
    const expected = syncEvents(mesh);
    const events = [];
    const r = await kw.compute(mesh.positions, mesh.indices, {
      faceSizes: mesh.faceSizes ?? undefined,
      onStep: (e) => void events.push(e),
    });
    assert.deepEqual(events, expected.events, name);
    assert.equal(r.vertices.length, expected.result.vertices.length, name);
  }
});

test('KernelWorker: a partial kernel (maxSteps) streams the same prefix as computeKernelSync', async () => {
  const kw = newWorker();
  const mesh = starPrism(1500, 0.9);
  for (const maxSteps of [1, 100, 4097, 9000]) {
    const expected = syncEvents(mesh, { maxSteps });
    const events = [];
    const r = await kw.compute(mesh.positions, mesh.indices, { maxSteps, onStep: (e) => void events.push(e) });
    assert.equal(r.complete, false, `maxSteps ${maxSteps}: partial`);
    assert.equal(events.length, maxSteps);
    assert.deepEqual(events, expected.events, `maxSteps ${maxSteps}`);
  }
});

test('KernelWorker: stopped mid-stream (onStep false, cancel()), the events received are a prefix of the whole stream', async () => {
  const kw = newWorker();
  const mesh = starPrism(1500, 0.9);
  const all = syncEvents(mesh).events;
  assert.ok(all.length > 3 * 4096, `${all.length} events: several batches`);
  // onStep returning false in the middle of the second batch.
  const stopAt = 4096 + 1000;
  const got = [];
  await assert.rejects(
    kw.compute(mesh.positions, mesh.indices, { onStep: (e) => got.push(e) < stopAt }),
    (err) => err.code === 'CANCELLED',
  );
  assert.equal(got.length, stopAt, 'no event after false');
  assert.deepEqual(got, all.slice(0, stopAt));
  // cancel() once some events have arrived: what came is a prefix, and nothing comes after.
  const before = [];
  let cancelledAt = -1;
  const run = kw.compute(mesh.positions, mesh.indices, {
    onStep: (e) => {
      before.push(e);
      if (before.length === 5000) {
        kw.cancel();
        cancelledAt = before.length;
      }
    },
  });
  await assert.rejects(run, (err) => err.code === 'CANCELLED');
  assert.ok(cancelledAt > 0, 'cancelled mid-stream');
  assert.equal(before.length, cancelledAt, 'no event after cancel()');
  assert.deepEqual(before, all.slice(0, before.length));
  const after = box();
  assert.equal((await kw.compute(after.positions, after.indices)).volume, 1, 'usable after cancel');
});
