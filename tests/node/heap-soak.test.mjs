// 10,000 repeated wasm calls leave the heap where it started (heapUsed and heapSize), for
// successful kernels, user errors and early stops alike. (tests/node/leak.test.mjs does 1,000
// mixed calls; this is the longer soak with a polygon mesh and the cheaper entry point.)
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

test('10,000 calls: heapUsed and heapSize unchanged', () => {
  const good = plusPrism(0.3, 1);
  const quads = box([0, 0, 0], [1, 1, 1], { quads: true });
  const dup = box();
  const dupIdx = Uint32Array.from([...dup.indices, ...dup.indices.subarray(0, 3)]);
  const calls = [
    () => assert.equal(K.computeKernelSync(good.positions, good.indices).status, 'POLYHEDRON'),
    () =>
      assert.equal(
        K.computeKernelSync(quads.positions, quads.indices, { faceSizes: quads.faceSizes }).status,
        'POLYHEDRON',
      ),
    () => assert.equal(K.findKernelPointSync(good.positions, good.indices).starShaped, true),
    () => assert.equal(K.computeKernelSync(good.positions, good.indices, { maxSteps: 3 }).complete, false),
    () =>
      assert.throws(
        () => K.computeKernelSync(dup.positions, dupIdx),
        (e) => e.code === 'NON_MANIFOLD_EDGE',
      ),
  ];
  for (const c of calls) c(); // warm-up: one-time allocations are not leaks
  const start = K.memoryStats();
  for (let i = 0; i < 10000; i++) calls[i % calls.length]();
  const end = K.memoryStats();
  assert.equal(end.heapUsed, start.heapUsed, `heapUsed ${start.heapUsed} → ${end.heapUsed}`);
  assert.equal(end.heapSize, start.heapSize, `heapSize ${start.heapSize} → ${end.heapSize}`);
});
