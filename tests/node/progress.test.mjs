// onProgress: computeKernelSync reports each phase once, in order, with its count, stops early on
// rejected and non-star meshes, and rethrows a callback's throw after the call without leaking.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { assertBuilt } from './lib/env.mjs';
import { box, lPrism, uPrism } from './lib/geometry.mjs';

let K;
before(async () => {
  assertBuilt();
  K = await import('../../wasm/index.js');
  await K.init();
});

// ---- onProgress ---------------------------------------------------------------------------------

test('onProgress: each phase once, in order, with its count; rejected and non-star meshes stop early', async () => {
  const L = lPrism();
  const phases = [];
  const k = await K.computeKernel(L.positions, L.indices, { onProgress: (p) => phases.push(p) });
  assert.deepEqual(
    phases.map((p) => p.phase),
    ['validating', 'planes', 'lp', 'tracing', 'assembling'],
  );
  assert.equal(phases[0].count, L.indices.length / 3, 'validating: input faces');
  assert.equal(phases[1].count, L.indices.length / 3, 'planes: faces left (none has zero area)');
  assert.equal(phases[2].count, k.stats.distinctPlanes, 'lp: distinct planes');
  assert.equal(phases[3].count, k.stats.distinctPlanes, 'tracing: distinct planes');
  assert.equal(phases[4].count, k.vertices.length / 3, 'assembling: kernel vertices');

  const open = box();
  const rejected = [];
  assert.throws(
    () =>
      K.computeKernelSync(open.positions, open.indices.subarray(0, 33), { onProgress: (p) => rejected.push(p.phase) }),
    { code: 'OPEN_MESH' },
  );
  assert.deepEqual(rejected, ['validating']);

  const U = uPrism(); // not star-shaped: the LP finds no kernel point, nothing is traced
  const notStar = [];
  const e = await K.computeKernel(U.positions, U.indices, { onProgress: (p) => notStar.push(p.phase) });
  assert.equal(e.status, 'EMPTY');
  assert.deepEqual(notStar, ['validating', 'planes', 'lp']);
});

test('onProgress: a throw is rethrown after the call, later phases are not reported, nothing leaks', async () => {
  const L = lPrism();
  const heapBefore = K.memoryStats().heapUsed;
  const seen = [];
  const boom = new Error('stop here');
  let steps = 0;
  assert.throws(
    () =>
      K.computeKernelSync(L.positions, L.indices, {
        onStep: () => void steps++,
        onProgress: (p) => {
          seen.push(p.phase);
          if (p.phase === 'lp') throw boom;
        },
      }),
    (err) => err === boom,
  );
  assert.deepEqual(seen, ['validating', 'planes', 'lp']);
  assert.ok(steps <= 1, `the trace stopped at its first step (${steps} step callbacks)`);
  assert.equal(K.memoryStats().jsHandles, 0);
  assert.equal(K.memoryStats().heapUsed, heapBefore);
  assert.throws(() => K.computeKernelSync(L.positions, L.indices, { onProgress: 1 }), { code: 'INVALID_ARGUMENT' });
});
