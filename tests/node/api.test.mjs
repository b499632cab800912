// The package's main API on meshes whose kernels are known analytically.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { assertBuilt } from './lib/env.mjs';
import { box, extrude, flip, lPrism, plusPrism, transform, uPrism, faceLoops, signedVolume } from './lib/geometry.mjs';
import { checkKernel, relClose } from './lib/checks.mjs';

let K;
before(async () => {
  assertBuilt();
  K = await import('../../wasm/index.js');
  await K.init();
});

function inputVolume(mesh) {
  return signedVolume(mesh.positions, faceLoops(mesh.indices, mesh.faceSizes));
}

test('init is idempotent and the sync API works after it', async () => {
  await K.init();
  await K.init({ wasmUrl: 'ignored-once-loaded.wasm' });
  assert.equal(K.isInitialized(), true);
  const cube = box();
  assert.equal(K.computeKernelSync(cube.positions, cube.indices).status, 'POLYHEDRON');
});

test('convex box: the kernel is the box itself (triangles and quads, number[] and Float32Array input)', async () => {
  const lo = [-1, 2, 0.5];
  const hi = [3, 2.5, 4];
  const expected = (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
  for (const quads of [false, true]) {
    const m = box(lo, hi, { quads });
    for (const positions of [m.positions, Float32Array.from(m.positions), Array.from(m.positions)]) {
      const r = await K.computeKernel(positions, Array.from(m.indices), { faceSizes: m.faceSizes ?? undefined });
      assert.equal(r.status, 'POLYHEDRON');
      assert.equal(r.complete, true);
      const { V, E, F } = checkKernel(r, m);
      assert.deepEqual([V, E, F], [8, 12, 6], 'coplanar triangles merge into 6 quads');
      relClose(r.volume, expected, 1e-12, 'box volume');
      relClose(r.shapeVolume, expected, 1e-12, 'shape volume');
      relClose(r.volumeRatio, 1, 1e-12, 'volume ratio');
      assert.ok(
        r.vertices instanceof Float64Array && r.edges instanceof Uint32Array && r.triangles instanceof Uint32Array,
      );
      assert.equal(r.triangles.length, 12 * 3, 'six quads fan-triangulated');
      assert.ok(r.faces.every((f) => f instanceof Uint32Array && f.length === 4));
    }
  }
});

test('result arrays are copies out of the heap: later calls and heap growth leave them intact', async () => {
  const m = lPrism();
  const r = K.computeKernelSync(m.positions, m.indices, { faceSizes: m.faceSizes ?? undefined });
  assert.equal(r.status, 'POLYHEDRON');
  const names = [
    'vertices',
    'edges',
    'faceIndices',
    'faceSizes',
    'triangles',
    'faceSources',
    'witnessFaces',
    'witnessBoundaryEdges',
  ];
  const saved = names.map((k) => Array.from(r[k]));
  // One fresh buffer (not the wasm memory), shared by the eight arrays, each aligned for its type.
  for (const k of names) {
    assert.equal(r[k].buffer, r.vertices.buffer, `${k} is a view of the result's buffer`);
    assert.equal(r[k].byteOffset % r[k].BYTES_PER_ELEMENT, 0, `${k} aligned`);
  }
  const ends = names
    .map((k) => [r[k].byteOffset, r[k].byteOffset + r[k].byteLength])
    .sort((a, b) => a[0] - b[0] || a[1] - b[1]); // (an empty view first at its offset)
  for (let i = 1; i < ends.length; i++) assert.ok(ends[i][0] >= ends[i - 1][1], 'the views do not overlap');
  assert.equal(r.vertices.buffer.byteLength, ends[ends.length - 1][1], 'the buffer holds the arrays and nothing else');
  // A different mesh, then a large one (a prism over a 50,000-gon: the heap grows), then the
  // same mesh again.
  K.computeKernelSync(box().positions, box().indices);
  const n = 50000;
  const heapBefore = K.memoryStats().heapSize;
  const prism = {
    positions: new Float64Array(6 * n),
    indices: new Uint32Array(6 * n),
    faceSizes: new Uint32Array(n + 2),
  };
  for (let i = 0; i < n; i++) {
    const a = (2 * Math.PI * i) / n;
    prism.positions.set([Math.cos(a), Math.sin(a), 0], 3 * i);
    prism.positions.set([Math.cos(a), Math.sin(a), 1], 3 * (n + i));
    prism.indices[i] = n + i; // top, counter-clockwise seen from +z
    prism.indices[n + i] = n - 1 - i; // bottom, reversed
    const j = (i + 1) % n;
    prism.indices.set([i, j, n + j, n + i], 2 * n + 4 * i);
    prism.faceSizes[2 + i] = 4;
  }
  prism.faceSizes[0] = prism.faceSizes[1] = n;
  const p = K.computeKernelSync(prism.positions, prism.indices, { faceSizes: prism.faceSizes });
  assert.equal(p.status, 'POLYHEDRON');
  assert.ok(K.memoryStats().heapSize > heapBefore, 'the large mesh grew the heap');
  names.forEach((k, i) => assert.deepEqual(Array.from(r[k]), saved[i], `${k} unchanged`));
  const again = K.computeKernelSync(m.positions, m.indices, { faceSizes: m.faceSizes ?? undefined });
  names.forEach((k, i) => assert.deepEqual(Array.from(again[k]), saved[i], `${k} the same on a second call`));
});

test('scale and translation do not change the answer (unit cube ×1e-3, ×1e3, moved by 1e6)', async () => {
  for (const [s, t] of [
    [1e-3, [0, 0, 0]],
    [1e3, [0, 0, 0]],
    [1, [1e6, -1e6, 1e6]],
  ]) {
    const m = transform(box(), s, t);
    const r = await K.computeKernel(m.positions, m.indices);
    assert.equal(r.status, 'POLYHEDRON');
    const { V, E, F } = checkKernel(r, m);
    assert.deepEqual([V, E, F], [8, 12, 6]);
    relClose(r.volume, s * s * s, 1e-9, `volume at scale ${s}`);
  }
});

test('L prism: kernel is the unit cube at the corner', async () => {
  const m = lPrism();
  const r = await K.computeKernel(m.positions, m.indices);
  assert.equal(r.status, 'POLYHEDRON');
  assert.deepEqual(Object.values(checkKernel(r, m)), [8, 12, 6]);
  relClose(r.volume, 1, 1e-12, 'L kernel volume');
  relClose(r.shapeVolume, inputVolume(m), 1e-12, 'L shape volume');
  for (let i = 0; i < r.vertices.length; i++)
    assert.ok([0, 1].includes(r.vertices[i]), `vertex coordinate ${r.vertices[i]} is 0 or 1`);
});

test('plus prism: kernel volume 4·w²·h for several arm widths', async () => {
  for (const [w, reach, h] of [
    [0.25, 2, 1],
    [0.1, 3, 2],
    [1, 1.5, 0.5],
  ]) {
    const m = plusPrism(w, reach, h);
    const r = await K.computeKernel(m.positions, m.indices);
    assert.equal(r.status, 'POLYHEDRON');
    assert.deepEqual(Object.values(checkKernel(r, m)), [8, 12, 6]);
    relClose(r.volume, 4 * w * w * h, 1e-12, `plus kernel w=${w}`);
    relClose(r.volumeRatio, (4 * w * w * h) / inputVolume(m), 1e-12, 'volume ratio');
  }
});

test('U prism is not star-shaped: EMPTY everywhere in the API', async () => {
  const m = uPrism();
  const r = await K.computeKernel(m.positions, m.indices);
  assert.equal(r.status, 'EMPTY');
  assert.equal(r.vertices.length, 0);
  assert.equal(r.kernelPoint, null);
  assert.equal(r.volume, 0);
  const p = await K.findKernelPoint(m.positions, m.indices);
  assert.deepEqual([p.starShaped, p.point], [false, null]);
  assert.equal(await K.isStarShaped(m.positions, m.indices), false);
});

test('findKernelPoint returns a point inside the kernel of star-shaped meshes', async () => {
  for (const m of [lPrism(), plusPrism(0.2, 1), box([0, 0, 0], [2, 3, 4])]) {
    const p = await K.findKernelPoint(m.positions, m.indices);
    assert.equal(p.starShaped, true);
    assert.equal(p.point.length, 3);
    checkKernel(
      {
        vertices: Float64Array.from(p.point),
        edges: new Uint32Array(),
        triangles: new Uint32Array(),
        faceIndices: new Uint32Array(),
        faces: [],
        faceSizes: new Uint32Array(),
        kernelPoint: p.point,
        status: 'POINT',
        complete: true,
      },
      m,
    );
    assert.equal(await K.isStarShaped(m.positions, m.indices), true);
  }
});

test('inward-oriented input is flipped and reported', async () => {
  const m = flip(lPrism());
  const r = await K.computeKernel(m.positions, m.indices);
  assert.equal(r.status, 'POLYHEDRON');
  relClose(r.volume, 1, 1e-12, 'volume after flip');
  assert.ok(r.shapeVolume > 0, 'shape volume reported after the fix');
  assert.ok(
    r.warnings.some((w) => w.kind === 'ORIENTATION_FLIPPED' && w.count > 0 && w.message.length > 0),
    JSON.stringify(r.warnings),
  );
  checkKernel(r, m, { orientation: -1 });
});

test('polygon input with faceSizes equals the triangulated input', async () => {
  const quads = box([0, 0, 0], [1, 2, 3], { quads: true });
  const tris = box([0, 0, 0], [1, 2, 3]);
  const a = await K.computeKernel(quads.positions, quads.indices, { faceSizes: quads.faceSizes });
  const b = await K.computeKernel(tris.positions, tris.indices);
  assert.equal(a.status, b.status);
  relClose(a.volume, b.volume, 1e-12, 'same volume');
  assert.equal(a.vertices.length, b.vertices.length);
  assert.equal(a.stats.inputFaces, 6);
  assert.equal(b.stats.inputFaces, 12);
});

test('deepestPoint: centre of the largest inscribed ball of a box', async () => {
  const m = box([0, 0, 0], [4, 2, 6]);
  const r = await K.computeKernel(m.positions, m.indices, { deepestPoint: true });
  assert.ok(Array.isArray(r.deepestPoint), 'deepest point present');
  relClose(r.inscribedRadius, 1, 1e-9, 'inscribed radius = half the smallest side');
  // Any centre with x in [1,3], y = 1, z in [1,5] is a largest ball's centre.
  const [x, y, z] = r.deepestPoint;
  assert.ok(
    x >= 1 - 1e-9 && x <= 3 + 1e-9 && Math.abs(y - 1) <= 1e-9 && z >= 1 - 1e-9 && z <= 5 + 1e-9,
    `deepest point ${r.deepestPoint}`,
  );
  const plain = await K.computeKernel(m.positions, m.indices);
  assert.equal(plain.deepestPoint, null, 'only computed on request');
});

test('stats describe the input and add up', async () => {
  const m = plusPrism(0.3, 1.2);
  const r = await K.computeKernel(m.positions, m.indices);
  assert.equal(r.stats.inputVertices, m.positions.length / 3);
  assert.equal(r.stats.inputFaces, m.indices.length / 3);
  assert.equal(r.stats.droppedFaces, 0);
  assert.equal(r.stats.culledFaces, 0, 'small meshes keep every face');
  assert.equal(r.stats.distinctPlanes, 10, '12 walls on 8 planes (collinear arm sides merge) + top + bottom');
  assert.ok(r.stats.activePlanes >= 6 && r.stats.activePlanes <= 10);
  for (const k of ['msValidate', 'msPlanes', 'msLp', 'msTrace', 'msAssemble', 'msTotal']) assert.ok(r.stats[k] >= 0, k);
  assert.ok(r.stats.msTotal + 1e-9 >= r.stats.msTrace, 'total includes tracing');
});

test('a large star-shaped mesh: most faces are culled before plane merging, the kernel stays valid', async () => {
  const { bumpySphere } = await import('../../scripts/gen-big-mesh.mjs');
  const m = bumpySphere(80, 40); // 6320 triangles, kernel far smaller than the shape
  const r = await K.computeKernel(m.positions, m.indices);
  assert.equal(r.status, 'POLYHEDRON');
  assert.ok(r.stats.culledFaces > m.indices.length / 3 / 2, `culled ${r.stats.culledFaces}`);
  assert.ok(r.stats.distinctPlanes + r.stats.culledFaces <= r.stats.inputFaces);
  checkKernel(r, m);
});

test('an extruded star polygon: kernel vertices inside every half-space, volume from its own faces', async () => {
  const n = 7;
  const poly = [];
  for (let i = 0; i < 2 * n; i++) {
    const rad = i % 2 ? 0.45 : 1;
    const a = (Math.PI * i) / n;
    poly.push([rad * Math.cos(a), rad * Math.sin(a)]);
  }
  const m = extrude(poly, -0.5, 0.75);
  const r = await K.computeKernel(m.positions, m.indices, { from: [0.2, 0.1, 0] });
  assert.equal(r.status, 'POLYHEDRON');
  checkKernel(r, m);
  assert.ok(r.volume < inputVolume(m));
});
