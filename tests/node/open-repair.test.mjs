// The package's `open` option (walls at the boundary of an open surface) and repairMesh (the mesh
// the kernel is computed on, after weld and repair): the core's results, in the package's words.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { assertBuilt } from './lib/env.mjs';

let K;
before(async () => {
  assertBuilt();
  K = await import('../../wasm/index.js');
  await K.init();
});

// The unit cube without its top face (triangles).
const cube = {
  positions: Float64Array.from([0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1]),
  quads: [
    [0, 2, 3, 1],
    [0, 1, 5, 4],
    [2, 6, 7, 3],
    [0, 4, 6, 2],
    [1, 3, 7, 5],
  ],
};
const openCube = Uint32Array.from(cube.quads.flatMap(([a, b, c, d]) => [a, b, c, a, c, d]));

// A bowl with a vertical lip (tests/core/open_surfaces.h): its walls are exactly z = 0, so its
// kernel is that of the bowl closed by a lid. Returns { positions, indices, lid } (lid: the rim loop).
function lippedBowl(nu, nv, lip) {
  const p = [0, 0, -1 - lip];
  for (let i = 1; i <= nv; i++) {
    for (let j = 0; j < nu; j++) {
      const th = ((Math.PI / 2) * i) / nv - Math.PI / 2,
        ph = (2 * Math.PI * j) / nu;
      p.push(Math.cos(th) * Math.cos(ph), Math.cos(th) * Math.sin(ph), Math.sin(th) - lip);
    }
  }
  const top = 3 * (1 + (nv - 1) * nu);
  for (let j = 0; j < nu; j++) p.push(p[top + 3 * j], p[top + 3 * j + 1], 0);
  const id = (i, j) => 1 + (i - 1) * nu + (j % nu);
  const t = [];
  for (let j = 0; j < nu; j++) t.push(0, id(1, j + 1), id(1, j));
  for (let i = 1; i <= nv; i++) {
    for (let j = 0; j < nu; j++)
      t.push(id(i, j), id(i, j + 1), id(i + 1, j + 1), id(i, j), id(i + 1, j + 1), id(i + 1, j));
  }
  const lid = Array.from({ length: nu }, (_, j) => id(nv + 1, j));
  return { positions: Float64Array.from(p), indices: Uint32Array.from(t), lid };
}

test("open: 'perpendicular' walls an open cube into the cube; 'clip' is allowOpen", async () => {
  const walled = await K.computeKernel(cube.positions, openCube, { open: 'perpendicular' });
  assert.equal(walled.status, 'POLYHEDRON');
  assert.ok(Math.abs(walled.volume - 1) < 1e-14, String(walled.volume));
  const clipped = await K.computeKernel(cube.positions, openCube, { open: 'clip' });
  const allowed = await K.computeKernel(cube.positions, openCube, { allowOpen: true });
  assert.equal(clipped.status, 'UNBOUNDED');
  assert.deepEqual(clipped.vertices, allowed.vertices);
  const point = await K.findKernelPoint(cube.positions, openCube, { open: 'perpendicular' });
  assert.equal(point.starShaped, true);
});

test('a lipped bowl with walls has the kernel of the bowl with a lid', async () => {
  const b = lippedBowl(24, 8, 0.25);
  const open = await K.computeKernel(b.positions, b.indices, { open: 'perpendicular' });
  const faceSizes = Uint32Array.from([...new Array(b.indices.length / 3).fill(3), b.lid.length]);
  const closed = await K.computeKernel(b.positions, Uint32Array.from([...b.indices, ...b.lid]), { faceSizes });
  assert.equal(open.status, 'POLYHEDRON');
  assert.equal(closed.status, 'POLYHEDRON');
  assert.equal(open.vertices.length, closed.vertices.length);
  assert.ok(Math.abs(open.volume - closed.volume) <= 1e-14 * closed.volume, `${open.volume} vs ${closed.volume}`);
});

test('open: bad values and contradictions are INVALID_ARGUMENT; OPEN_MESH names the option', async () => {
  for (const options of [{ open: 'sideways' }, { open: true }, { open: 'perpendicular', allowOpen: false }]) {
    await assert.rejects(
      K.computeKernel(cube.positions, openCube, options),
      (e) => e.code === 'INVALID_ARGUMENT',
      JSON.stringify(options),
    );
  }
  await assert.rejects(K.computeKernel(cube.positions, openCube), (e) => {
    assert.equal(e.code, 'OPEN_MESH');
    assert.match(e.message, /open: 'perpendicular'/);
    assert.doesNotMatch(e.message, /Options::/);
    return true;
  });
});

// The bad-input table's mesh_t_junction: a box [0,2]x[0,1]x[0,1] whose bottom is two squares.
const tBox = {
  positions: Float64Array.from([
    0, 0, 0, 2, 0, 0, 2, 1, 0, 0, 1, 0, 0, 0, 1, 2, 0, 1, 2, 1, 1, 0, 1, 1, 1, 0, 0, 1, 1, 0,
  ]),
  indices: Uint32Array.from([0, 3, 9, 8, 8, 9, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 2, 3, 7, 6, 1, 2, 6, 5, 3, 0, 4, 7]),
  faceSizes: Uint32Array.from([4, 4, 4, 4, 4, 4, 4]),
};

test('repairMesh: the repaired T-junction solid is closed and has the kernel computed with repair', async () => {
  const r = await K.repairMesh(tBox.positions, tBox.indices, { faceSizes: tBox.faceSizes, repair: true });
  assert.equal(r.error, null);
  assert.equal(r.message, '');
  assert.ok(
    r.positions instanceof Float64Array && r.indices instanceof Uint32Array && r.faceSizes instanceof Uint32Array,
  );
  assert.deepEqual(
    r.warnings.map((w) => [w.kind, w.count]),
    [['T_JUNCTIONS_SPLIT', 2]],
  );
  const plain = await K.computeKernel(r.positions, r.indices, { faceSizes: r.faceSizes });
  const repaired = await K.computeKernel(tBox.positions, tBox.indices, { faceSizes: tBox.faceSizes, repair: true });
  assert.equal(plain.volume, 2);
  assert.equal(repaired.volume, 2);
  // Saved and read back: the same mesh.
  const back = await K.readMesh(K.writeMesh(r, 'obj'), { format: 'obj' });
  assert.deepEqual(back.positions, r.positions);
  assert.deepEqual(back.indices, r.indices);
  assert.deepEqual(back.faceSizes, r.faceSizes);
});

test('repairMesh without repair returns the input with the verdict; malformed input throws', async () => {
  const r = K.repairMeshSync(tBox.positions, tBox.indices, { faceSizes: tBox.faceSizes });
  assert.equal(r.error, 'OPEN_MESH');
  assert.match(r.message, /repair: true/);
  assert.doesNotMatch(r.message, /Options::/);
  assert.deepEqual(r.indices, tBox.indices);
  const bad = Uint32Array.from(openCube);
  bad[4] = 99;
  assert.throws(
    () => K.repairMeshSync(cube.positions, bad),
    (e) => e.code === 'INDEX_OUT_OF_RANGE',
  );
});
