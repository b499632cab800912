// The weld option: a triangle soup (as an unindexed STL or a three.js geometry gives it) with
// seams that differ by rounding becomes the closed surface it describes; without it the error
// says what to try in this package's words.
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

// Every triangle with its own three corners; every other corner moved by `jitter`.
function soup(m, jitter) {
  const positions = new Float64Array(3 * m.indices.length);
  for (let i = 0; i < m.indices.length; i++) {
    for (let k = 0; k < 3; k++) positions[3 * i + k] = m.positions[3 * m.indices[i] + k] + (i % 2 ? jitter : 0);
  }
  return { positions, indices: Uint32Array.from(m.indices, (_, i) => i) };
}

const sphere = bumpySphere(40, 21);
const reference = () => K.computeKernel(sphere.positions, sphere.indices);

test("an open soup is refused with a message in the package's words", async () => {
  const s = soup(sphere, 1e-12);
  await assert.rejects(K.computeKernel(s.positions, s.indices), (e) => {
    assert.equal(e.code, 'OPEN_MESH');
    assert.match(e.message, /weld: true/);
    assert.match(e.message, /allowOpen: true/);
    assert.doesNotMatch(e.message, /Options::/);
    return true;
  });
});

test("weld: true, a distance or { relative } closes the soup: the indexed mesh's kernel", async () => {
  const ref = await reference();
  const s = soup(sphere, 1e-12);
  const before = Float64Array.from(s.positions);
  for (const weld of [true, 1e-10, { relative: 1e-9 }]) {
    const r = await K.computeKernel(s.positions, s.indices, { weld });
    assert.equal(r.status, ref.status, JSON.stringify(weld));
    assert.ok(Math.abs(r.volume - ref.volume) <= 1e-9 * ref.volume, JSON.stringify(weld));
    const w = r.warnings.find((x) => x.kind === 'VERTICES_WELDED');
    assert.ok(w, 'a VERTICES_WELDED warning');
    assert.equal(w.count, s.positions.length / 3 - sphere.positions.length / 3);
  }
  assert.deepEqual(s.positions, before, 'the input is not modified');
  // Exact equality does not merge corners 1e-12 apart.
  await assert.rejects(K.computeKernel(s.positions, s.indices, { weld: 0 }), (e) => e.code === 'OPEN_MESH');
});

test('bad weld values are INVALID_ARGUMENT', async () => {
  const s = soup(sphere, 0);
  for (const weld of [-1, NaN, 'yes', { relative: -2 }, {}]) {
    await assert.rejects(
      K.computeKernel(s.positions, s.indices, { weld }),
      (e) => e.code === 'INVALID_ARGUMENT',
      String(weld),
    );
  }
  const off = await K.computeKernel(sphere.positions, sphere.indices, { weld: false });
  assert.equal(off.warnings.length, 0);
});

test('repair: true splits T-junctions: the box whose bottom is two squares gets its kernel', async () => {
  // [0,2]x[0,1]x[0,1]; (1,0,0) and (1,1,0) lie inside the bottom edges of the front and back quads.
  const positions = new Float64Array([
    0, 0, 0, 2, 0, 0, 2, 1, 0, 0, 1, 0, 0, 0, 1, 2, 0, 1, 2, 1, 1, 0, 1, 1, 1, 0, 0, 1, 1, 0,
  ]);
  const indices = new Uint32Array([0, 3, 9, 8, 8, 9, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 2, 3, 7, 6, 1, 2, 6, 5, 3, 0, 4, 7]);
  const faceSizes = new Uint32Array([4, 4, 4, 4, 4, 4, 4]);
  await assert.rejects(
    K.computeKernel(positions, indices, { faceSizes }),
    (e) => e.code === 'OPEN_MESH' && /repair: true/.test(e.message),
  );
  const r = await K.computeKernel(positions, indices, { faceSizes, repair: true });
  assert.equal(r.status, 'POLYHEDRON');
  assert.equal(r.volume, 2);
  assert.equal(r.warnings.find((w) => w.kind === 'T_JUNCTIONS_SPLIT').count, 2);
});
