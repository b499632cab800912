// The demo's drawing preparation (web/draw-prep.js), in Node: what the view draws must be the
// input's faces (polygons split into exactly k - 2 triangles covering the polygon), each face
// edge once, and a simplified copy of a big mesh that stays within a grid cell of it.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import {
  prepareDrawing,
  faceEdges,
  boundaryEdges,
  drawnTriangles,
  simplify,
  simplifySurface,
} from '../../web/draw-prep.js';
import { bumpySphere } from '../../scripts/gen-big-mesh.mjs';
import { lPrismMesh } from './lib/example-meshes.mjs';

// An L prism (non-convex hexagon caps, quad sides): 12 vertices, 8 faces, 18 edges.
const lPrism = lPrismMesh;

const area = (P, a, b, c) => {
  const u = [0, 1, 2].map((k) => P[3 * b + k] - P[3 * a + k]),
    v = [0, 1, 2].map((k) => P[3 * c + k] - P[3 * a + k]);
  return Math.hypot(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]) / 2;
};

test('polygons are split into k - 2 triangles that cover them (non-convex caps included)', () => {
  const m = lPrism();
  const tris = drawnTriangles(m.positions, m.indices, m.faceSizes);
  assert.equal(tris.length / 3, 2 * 4 + 6 * 2);
  // The caps (area 3 each) and the six side quads (the outline is 8 long, the height 1).
  let total = 0;
  for (let t = 0; t < tris.length; t += 3) total += area(m.positions, tris[t], tris[t + 1], tris[t + 2]);
  assert.ok(Math.abs(total - (3 + 3 + 8)) < 1e-12, `drawn area ${total}`);
  // Triangles are drawn with the mesh's own indices.
  const tri = { positions: m.positions, indices: Uint32Array.of(0, 1, 2), faceSizes: null };
  assert.equal(drawnTriangles(tri.positions, tri.indices, null), tri.indices);
});

test('face edges: each edge of the faces once, no polygon diagonals', () => {
  const m = lPrism();
  const e = faceEdges(m.indices, m.faceSizes, 12);
  assert.equal(e.length / 2, 18);
  const keys = new Set();
  for (let i = 0; i < e.length; i += 2) keys.add(`${Math.min(e[i], e[i + 1])}-${Math.max(e[i], e[i + 1])}`);
  assert.equal(keys.size, 18);
  assert.ok(!keys.has('0-4'), 'a cap diagonal is not an edge');
});

const edgeSet = (pairs) => {
  const keys = new Set();
  for (let i = 0; i < pairs.length; i += 2)
    keys.add(`${Math.min(pairs[i], pairs[i + 1])}-${Math.max(pairs[i], pairs[i + 1])}`);
  return keys;
};

test('boundary edges: the rim of a removed face, each once; none on a closed mesh; polygon and triangle faces', () => {
  const m = lPrism();
  assert.equal(boundaryEdges(m.indices, m.faceSizes, 12).length, 0, 'closed: no open edge');
  // Without the top hexagon (face 1: 1 3 5 7 9 11), its six edges are open.
  const sizes = Array.from(m.faceSizes);
  const faces = [];
  for (let f = 0, at = 0; f < sizes.length; at += sizes[f], f++)
    if (f !== 1) faces.push(Array.from(m.indices.subarray(at, at + sizes[f])));
  const open = boundaryEdges(Uint32Array.from(faces.flat()), Uint32Array.from(faces.map((f) => f.length)), 12);
  assert.deepEqual([...edgeSet(open)].sort(), ['1-3', '3-5', '5-7', '7-9', '9-11', '1-11'].sort());
  assert.equal(open.length / 2, 6);
  // Triangles (faceSizes null): one triangle has three open edges; a triangle repeating a vertex
  // walks its one real edge both ways (no open edge) and adds no edge from a vertex to itself.
  assert.equal(edgeSet(boundaryEdges(Uint32Array.of(0, 1, 2), null, 3)).size, 3);
  assert.equal(boundaryEdges(Uint32Array.of(0, 1, 1), null, 3).length, 0);
  assert.deepEqual([...edgeSet(faceEdges(Uint32Array.of(0, 1, 1), null, 3))], ['0-1']);
  // faceEdges and boundaryEdges agree on the edges of one triangle.
  assert.deepEqual(
    edgeSet(faceEdges(Uint32Array.of(0, 1, 2), null, 3)),
    edgeSet(boundaryEdges(Uint32Array.of(0, 1, 2), null, 3)),
  );
});

test('prepareDrawing: float32 positions centred on the bounding box; bad indices are not drawn', () => {
  const m = lPrism();
  const d = prepareDrawing(m, { edges: true });
  assert.deepEqual(d.center, [1, 1, 0.5]);
  assert.ok(Math.abs(d.radius - Math.hypot(2, 2, 1) / 2) < 1e-15);
  assert.ok(d.positions instanceof Float32Array && d.positions[0] === -1 && d.positions[2] === -0.5);
  assert.equal(d.faces, 8);
  assert.equal(d.simplified, false);
  assert.equal(d.edges.length / 2, 18);
  const bad = prepareDrawing({ positions: m.positions, indices: Uint32Array.of(0, 1, 99), faceSizes: null });
  assert.equal(bad.drawable, false);
  assert.equal(bad.triangles.length, 0);
});

test('simplify: a 40k-triangle sphere drawn with about 5k triangles, within a grid cell of the original', () => {
  const m = bumpySphere(200, 101);
  const d = prepareDrawing(m, { maxTriangles: 5000 });
  assert.equal(d.simplified, true);
  const n = d.triangles.length / 3;
  assert.ok(n > 1000 && n <= 1.2 * 5000, `${n} triangles`);
  for (let t = 0; t < d.triangles.length; t += 3) {
    const [a, b, c] = d.triangles.subarray(t, t + 3);
    assert.ok(a !== b && b !== c && a !== c, 'no collapsed triangle');
  }
  // Every drawn vertex is the mean of input vertices of one cell: within a cell of the surface,
  // whose radius is 1 ± 0.2 (the cell: the longest side / res, res ≥ sqrt(5000 / 4) ≈ 35).
  const cell = 2.4 / 35;
  for (let i = 0; i < d.positions.length; i += 3) {
    const r = Math.hypot(
      d.positions[i] + d.center[0],
      d.positions[i + 1] + d.center[1],
      d.positions[i + 2] + d.center[2],
    );
    assert.ok(r > 0.8 - 2 * cell && r < 1.2 + 2 * cell, `vertex at radius ${r}`);
  }
  // Unchanged input: simplify leaves the arrays it is given alone.
  const pos = Float32Array.of(0, 0, 0, 1, 0, 0, 0, 1, 0);
  const s = simplify(pos, Uint32Array.of(0, 1, 2), 1);
  assert.deepEqual(Array.from(pos), [0, 0, 0, 1, 0, 0, 0, 1, 0]);
  assert.ok(s.triangles.length <= 3);
});

test('simplify: no triangle repeated (folded sheets drawn once), unit normals that point outward like the original', () => {
  const m = bumpySphere(200, 101);
  const d = prepareDrawing(m, { maxTriangles: 5000 });
  const keys = new Set();
  for (let t = 0; t < d.triangles.length; t += 3) {
    const key = Array.from(d.triangles.subarray(t, t + 3))
      .sort((a, b) => a - b)
      .join(',');
    assert.ok(!keys.has(key), `triangle ${key} repeated`);
    keys.add(key);
  }
  assert.equal(d.normals.length, d.positions.length);
  // The bumpy sphere is star-shaped around its centre and outward oriented: every cell's normal
  // (the sum of its original triangles' normals) points away from the centre.
  for (let i = 0; i < d.normals.length; i += 3) {
    const n = d.normals.subarray(i, i + 3);
    assert.ok(Math.abs(Math.hypot(...n) - 1) < 1e-5, 'unit length');
    const p = [0, 1, 2].map((c) => d.positions[i + c] + d.center[c]);
    assert.ok(n[0] * p[0] + n[1] * p[1] + n[2] * p[2] > 0, `normal at ${p} points outward`);
  }
});

test('simplifySurface: a big kernel-like surface (convex sphere) to about the target, within a cell, centred', () => {
  const m = bumpySphere(300, 151); // 89,400 triangles
  const r = (i) => Math.hypot(m.positions[i], m.positions[i + 1], m.positions[i + 2]);
  const vertices = Float64Array.from(m.positions, (x, i) => x / r(i - (i % 3)) + 5); // unit sphere at (5, 5, 5)
  const s = simplifySurface(vertices, m.indices, [5, 5, 5], 20000);
  const n = s.triangles.length / 3;
  assert.ok(n > 5000 && n <= 1.2 * 20000, `${n} triangles`);
  const cell = 2 / Math.floor(Math.sqrt(20000 / 4));
  for (let i = 0; i < s.positions.length; i += 3) {
    const radius = Math.hypot(s.positions[i], s.positions[i + 1], s.positions[i + 2]);
    assert.ok(radius > 1 - 2 * cell && radius <= 1 + 1e-6, `vertex at radius ${radius}`);
  }
});
