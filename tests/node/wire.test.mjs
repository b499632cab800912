// The C++/JS wire format is declared once (wasm/bindings.cpp, wireFormat()): index.js reads it at
// init() and refuses a module whose layout lacks a name it uses. Also the options that only cross
// through it (cullFaces, seed).
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { assertBuilt } from './lib/env.mjs';
import { bumpySphere } from '../../scripts/gen-big-mesh.mjs';

let K;
before(async () => {
  assertBuilt();
  K = await import('../../wasm/index.js');
  await K.init();
});

const box = {
  positions: new Float64Array([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1]),
  indices: new Uint32Array([
    0, 2, 1, 0, 3, 2, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4, 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7,
  ]),
};

test('a layout missing a name the wrapper uses is refused, naming it', () => {
  assert.throws(
    () => K.checkWireFormat({ option: {}, head: {}, scalar: {}, step: {}, stats: [], statuses: [], stepKinds: [] }),
    (e) =>
      e instanceof K.KergenError &&
      e.code === 'WASM_LOAD_FAILED' &&
      /option\.fromX/.test(e.message) &&
      /head\.numBytes/.test(e.message),
  );
  assert.throws(
    () => K.checkWireFormat(undefined),
    (e) => e.code === 'WASM_LOAD_FAILED' && /stats/.test(e.message),
  );
});

test("stats carry the core's fields, in camelCase, with values that fit them", async () => {
  const r = await K.computeKernel(box.positions, box.indices);
  assert.deepEqual(Object.keys(r.stats), [
    'inputVertices',
    'inputFaces',
    'droppedFaces',
    'culledFaces',
    'distinctPlanes',
    'activePlanes',
    'tracedLines',
    'exactFallbacks',
    'msValidate',
    'msPlanes',
    'msLp',
    'msTrace',
    'msAssemble',
    'msTotal',
  ]);
  assert.equal(r.stats.inputVertices, 8);
  assert.equal(r.stats.inputFaces, 12);
  assert.equal(r.stats.distinctPlanes, 6);
  assert.equal(r.status, 'POLYHEDRON');
  assert.ok(Math.abs(r.volume - 1) < 1e-12);
  assert.deepEqual(
    r.kernelPoint.map((c) => c === 0 || c === 1),
    [true, true, true],
  );
});

test('cullFaces: false keeps every face and gives the same kernel; seed changes nothing', async () => {
  const m = bumpySphere(60, 40); // 4680 faces: above the face culling threshold, a small kernel
  const culled = await K.computeKernel(m.positions, m.indices);
  const kept = await K.computeKernel(m.positions, m.indices, { cullFaces: false });
  assert.ok(culled.stats.culledFaces > 0, 'the default culls faces here');
  assert.equal(kept.stats.culledFaces, 0);
  assert.ok(kept.stats.distinctPlanes > culled.stats.distinctPlanes);
  assert.equal(kept.status, culled.status);
  assert.ok(Math.abs(kept.volume - culled.volume) <= 1e-12 * culled.volume);
  const seeded = await K.computeKernel(m.positions, m.indices, { seed: 12345 });
  assert.ok(Math.abs(seeded.volume - culled.volume) <= 1e-12 * culled.volume);
  assert.deepEqual(seeded.kernelPoint, culled.kernelPoint);
  for (const bad of [{ cullFaces: 1 }, { seed: -1 }, { seed: 2 ** 60 }, { seed: 1.5 }]) {
    await assert.rejects(K.computeKernel(box.positions, box.indices, bad), (e) => e.code === 'INVALID_ARGUMENT');
  }
});
