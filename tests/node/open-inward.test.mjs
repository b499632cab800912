// An open surface whose faces point inward, through the package: said so in the refusal (in the
// package's words), a FACES_POINT_INWARD warning when accepted (never turned over by itself), and
// `flipFaces: true` turns it over: the walled kernel is then the solid it bounds. Its shape
// volume is that of the surface closed over its hole, with no ratio. The three.js helpers weld
// already: their OPEN_MESH message does not suggest `weld: true`.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { assertBuilt } from './lib/env.mjs';

let K;
before(async () => {
  assertBuilt();
  K = await import('../../wasm/index.js');
  await K.init();
});

// The unit cube without its top face, its triangles facing into the cube.
const positions = Float64Array.from([0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1]);
const outward = [
  [0, 2, 3, 1],
  [0, 1, 5, 4],
  [2, 6, 7, 3],
  [0, 4, 6, 2],
  [1, 3, 7, 5],
].flatMap(([a, b, c, d]) => [a, b, c, a, c, d]);
const inward = Uint32Array.from(
  outward.flatMap((_, i) => (i % 3 === 0 ? [outward[i + 2], outward[i + 1], outward[i]] : [])),
);

test('refused: the message says the faces point inward and names flipFaces, not Options::', async () => {
  await assert.rejects(K.computeKernel(positions, inward), (err) => {
    assert.equal(err.code, 'OPEN_MESH');
    assert.match(err.message, /its faces point inward \(closed over its hole, it encloses a volume of -1\)/);
    assert.match(err.message, /flipFaces: true turns every face over/);
    assert.doesNotMatch(err.message, /Options::/);
    return true;
  });
  // Given outward, nothing is said about the faces.
  await assert.rejects(K.computeKernel(positions, Uint32Array.from(outward)), (err) => !/inward/.test(err.message));
});

test('accepted as given: EMPTY with a FACES_POINT_INWARD warning offering the flip; flipped: the cube', async () => {
  for (const open of ['clip', 'perpendicular']) {
    const r = await K.computeKernel(positions, inward, { open });
    assert.equal(r.status, 'EMPTY', open);
    const w = r.warnings.find((x) => x.kind === 'FACES_POINT_INWARD');
    assert.ok(w, `${open}: ${JSON.stringify(r.warnings)}`);
    assert.equal(w.count, 10);
    assert.match(w.message, /flipFaces: true turns every face over; turned over, its kernel is not empty$/);
    assert.equal(r.shapeVolume, -1);
    assert.equal(r.volumeRatio, 0);
  }
  const f = await K.computeKernel(positions, inward, { open: 'perpendicular', flipFaces: true });
  assert.equal(f.status, 'POLYHEDRON');
  assert.equal(f.vertices.length / 3, 8);
  assert.equal(f.volume, 1); // the unit cube: the five faces and the walls at the open top's edges (z = 1)
  assert.equal(f.shapeVolume, 1);
  assert.equal(f.volumeRatio, 0);
  assert.ok(!f.warnings.some((x) => x.kind === 'FACES_POINT_INWARD'));
  assert.throws(() => K.computeKernelSync(positions, inward, { flipFaces: 1 }), /flipFaces must be a boolean/);
});

test('the shared fixture open_cube.off: read by the core, inward, flipped: the 100-cube', async (t) => {
  const file = path.resolve(
    path.dirname(fileURLToPath(import.meta.url)),
    '../../../shared/meshes/fixtures/open_cube.off',
  );
  if (!fs.existsSync(file)) return t.skip(`${file} is absent`);
  const mesh = await K.readMesh(fs.readFileSync(file), { name: 'open_cube.off' });
  const given = await K.computeKernel(mesh.positions, mesh.indices, { open: 'perpendicular' });
  assert.equal(given.status, 'EMPTY');
  assert.ok(given.warnings.some((x) => x.kind === 'FACES_POINT_INWARD'));
  const flipped = await K.computeKernel(mesh.positions, mesh.indices, { open: 'perpendicular', flipFaces: true });
  assert.equal(flipped.status, 'POLYHEDRON');
  assert.equal(flipped.volume, 1e6);
});

test('the three.js helpers weld: their OPEN_MESH message does not suggest weld: true', async () => {
  const three = await import('../../wasm/three.js');
  const THREE = await import('three');
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(Float32Array.from(positions), 3));
  geometry.setIndex(new THREE.BufferAttribute(Uint32Array.from(outward), 1));
  await assert.rejects(three.computeKernelOfGeometry(geometry), (err) => {
    assert.equal(err.code, 'OPEN_MESH');
    assert.doesNotMatch(err.message, /weld: true/);
    assert.match(err.message, /repair: true/);
    return true;
  });
});
