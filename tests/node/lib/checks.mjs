// Independent structural checks of a KernelResult (plain JS; nothing shared with the core).
import assert from 'node:assert/strict';
import { bboxDiagonal, faceLoops, halfSpaces, maxViolation, signedVolume, vtx, sub, cross, dot } from './geometry.mjs';

export function relClose(actual, expected, rel, what) {
  const scale = Math.max(Math.abs(expected), Math.abs(actual), Number.MIN_VALUE);
  assert.ok(Math.abs(actual - expected) <= rel * scale, `${what}: ${actual} vs ${expected} (rel tol ${rel})`);
}

/**
 * Checks a result against its input: every kernel vertex inside every input half-space, ids in
 * range, and for a complete polyhedron a closed convex manifold whose volume matches its faces.
 */
export function checkKernel(result, mesh, { orientation = 1, tol = 1e-9 } = {}) {
  const V = result.vertices.length / 3;
  assert.ok(Number.isInteger(V), 'vertices is flat xyz');
  assert.equal(result.edges.length % 2, 0, 'edges are pairs');
  assert.equal(result.triangles.length % 3, 0, 'triangles are triples');
  for (const arr of [result.edges, result.triangles, result.faceIndices]) {
    for (const id of arr) assert.ok(id < V, `vertex id ${id} < ${V}`);
  }
  assert.equal(result.faces.length, result.faceSizes.length);

  const loops = faceLoops(mesh.indices, mesh.faceSizes);
  const planes = halfSpaces(mesh.positions, loops, orientation);
  const diag = bboxDiagonal(mesh.positions);
  for (let v = 0; v < V; v++) {
    const worst = maxViolation(planes, vtx(result.vertices, v));
    assert.ok(worst <= tol * diag, `kernel vertex ${v} violates an input half-space by ${worst} (diag ${diag})`);
  }
  if (result.kernelPoint) {
    assert.ok(maxViolation(planes, result.kernelPoint) <= tol * diag, 'kernelPoint lies in the kernel');
  }

  if (result.status === 'POLYHEDRON' && result.complete) {
    const F = result.faces.length;
    const E = result.edges.length / 2;
    assert.equal(V - E + F, 2, `Euler characteristic V - E + F = ${V} - ${E} + ${F}`);
    // Every edge in exactly two face loops, in opposite directions; same set as result.edges.
    const directed = new Map();
    for (const f of result.faces) {
      for (let k = 0; k < f.length; k++) {
        const key = `${f[k]},${f[(k + 1) % f.length]}`;
        assert.ok(!directed.has(key), `directed edge ${key} used twice`);
        directed.set(key, true);
      }
    }
    for (const key of directed.keys()) {
      const [a, b] = key.split(',');
      assert.ok(directed.has(`${b},${a}`), `edge ${key} has no opposite`);
    }
    assert.equal(directed.size, 2 * E, 'face loops use exactly the reported edges');
    for (let e = 0; e < E; e++) {
      assert.ok(directed.has(`${result.edges[2 * e]},${result.edges[2 * e + 1]}`), `edge ${e} is on a face`);
    }
    // Faces convex and CCW seen from outside: every other vertex is behind each face's plane.
    const centroid = [0, 0, 0];
    for (let v = 0; v < V; v++) for (let k = 0; k < 3; k++) centroid[k] += result.vertices[3 * v + k] / V;
    for (const f of result.faces) {
      const a = vtx(result.vertices, f[0]);
      let n = [0, 0, 0];
      for (let k = 1; k + 1 < f.length; k++) {
        const c = cross(sub(vtx(result.vertices, f[k]), a), sub(vtx(result.vertices, f[k + 1]), a));
        n = [n[0] + c[0], n[1] + c[1], n[2] + c[2]];
      }
      assert.ok(dot(n, sub(a, centroid)) > 0, 'face normal points away from the kernel centroid');
    }
    const triVolume = signedVolume(result.vertices, faceLoops(result.triangles, null));
    relClose(triVolume, result.volume, 1e-9, 'volume of the output triangles');
    relClose(
      signedVolume(
        result.vertices,
        result.faces.map((f) => Array.from(f)),
      ),
      result.volume,
      1e-9,
      'volume of the output faces',
    );
    assert.ok(result.volume > 0, 'positive volume');
    if (result.shapeVolume > 0) relClose(result.volumeRatio, result.volume / result.shapeVolume, 1e-12, 'volumeRatio');
  }
  return { V, E: result.edges.length / 2, F: result.faces.length };
}
