// 1000 repeated calls leave the wasm heap where it started: results are copied out, inputs are
// freed, and errors / early stops / throwing callbacks free everything too.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { assertBuilt } from './lib/env.mjs';
import { box, plusPrism } from './lib/geometry.mjs';

let K;
before(async () => {
  assertBuilt();
  K = await import('../../wasm/index.js');
  await K.init();
});

test('heapUsed rises during a call and returns to its level after it', async () => {
  const m = plusPrism(0.2, 1);
  const before = K.memoryStats().heapUsed;
  let during = -1;
  const r = await K.computeKernel(m.positions, m.indices, {
    onStep() {
      during = Math.max(during, K.memoryStats().heapUsed);
    },
  });
  assert.equal(r.status, 'POLYHEDRON');
  assert.ok(during > before, `the call allocates (${during} > ${before}): the probe measures something`);
  assert.equal(K.memoryStats().heapUsed, before);
  assert.equal(K.memoryStats().jsHandles, 0);
});

test('1000 mixed calls leave heapUsed and heapSize unchanged', async () => {
  const good = plusPrism(0.25, 1.5);
  const open = box();
  const openIdx = open.indices.subarray(0, 33);
  const nan = box();
  nan.positions[0] = NaN;
  // Warm up once per path (lazy one-time allocations are not leaks).
  const runOne = (i) => {
    switch (i % 5) {
      case 0:
        return K.computeKernelSync(good.positions, good.indices, { deepestPoint: true, onStep: () => undefined });
      case 1:
        return K.computeKernelSync(good.positions, good.indices, { onStep: (e) => e.id < 3 });
      case 2:
        try {
          K.computeKernelSync(open.positions, openIdx);
        } catch (err) {
          assert.equal(err.code, 'OPEN_MESH');
        }
        return null;
      case 3:
        try {
          K.computeKernelSync(nan.positions, nan.indices, {
            onStep() {
              throw new Error('unreachable');
            },
          });
        } catch (err) {
          assert.equal(err.code, 'NON_FINITE_COORDINATE');
        }
        return null;
      default:
        try {
          K.computeKernelSync(good.positions, good.indices, {
            onStep() {
              throw new Error('user abort');
            },
          });
        } catch (err) {
          assert.equal(err.message, 'user abort');
        }
        return K.findKernelPointSync(good.positions, good.indices);
    }
  };
  for (let i = 0; i < 5; i++) runOne(i);
  const start = K.memoryStats();
  for (let i = 0; i < 1000; i++) runOne(i);
  const end = K.memoryStats();
  assert.equal(end.heapUsed, start.heapUsed, `heapUsed ${start.heapUsed} → ${end.heapUsed}`);
  assert.equal(end.heapSize, start.heapSize, `heapSize ${start.heapSize} → ${end.heapSize}`);
  assert.equal(end.jsHandles, 0, 'no JS value is left held by the C++ side');
});
