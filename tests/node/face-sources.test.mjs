// What bounds the kernel, in the package: KernelResult.faceSources (Int32Array, one per face: the
// input face whose plane the face lies on, or FACE_SOURCE_BOX / FACE_SOURCE_WALL) and the walls of
// a witness, witnessBoundaryEdges (Uint32Array, vertex id pairs), on computeKernelSync,
// computeKernel, findKernelPoint and the worker. Checked with test-only JS geometry on shapes with
// small integer coordinates (every product below is exact in doubles): each face's corners lie on
// its source face's plane, the kernel behind it, and no earlier face lies on that plane facing the
// same way; a wall witness's half-spaces (the walls rebuilt from their edges) do not meet, and
// without any one of them they do. The two marks come from the core's wire format.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { usePackageWithWorker } from './lib/package-with-worker.mjs';
import fs from 'node:fs';
import { execFileSync } from 'node:child_process';
import { pathToFileURL } from 'node:url';
import { distGlue, distWasm, repoRoot } from './lib/env.mjs';
import { box, cross, dot, faceLoops, lPrism, sub, vtx } from './lib/geometry.mjs';

let K;
let W;
const { newWorker } = usePackageWithWorker((pkg) => ({ K, W } = pkg));

// Input face `loop`'s outward normal (Newell's, exact for small integer coordinates).
function normalOf(positions, loop) {
  const n = [0, 0, 0];
  for (let i = 0; i < loop.length; i++) {
    const a = vtx(positions, loop[i]);
    const b = vtx(positions, loop[(i + 1) % loop.length]);
    n[0] += (a[1] - b[1]) * (a[2] + b[2]);
    n[1] += (a[2] - b[2]) * (a[0] + b[0]);
    n[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  return n;
}
// Whether point p lies on the plane of `loop` (through its first corner, normal n).
const onPlane = (positions, loop, n, p) => dot(n, sub(p, vtx(positions, loop[0]))) === 0;

// Checks result.faceSources against mesh; returns the counts of input, box and wall faces.
function checkSources(mesh, result, what) {
  const loops = faceLoops(mesh.indices, mesh.faceSizes);
  const sources = result.faceSources;
  assert.ok(sources instanceof Int32Array, `${what}: faceSources is an Int32Array`);
  assert.equal(sources.length, result.faces.length, `${what}: one source per face`);
  const counts = { input: 0, box: 0, wall: 0 };
  const kernelPoints = [];
  for (let v = 0; v < result.vertices.length / 3; v++) kernelPoints.push(vtx(result.vertices, v));
  result.faces.forEach((face, f) => {
    const s = sources[f];
    if (s === K.FACE_SOURCE_BOX) return counts.box++;
    if (s === K.FACE_SOURCE_WALL) return counts.wall++;
    counts.input++;
    assert.ok(Number.isInteger(s) && s >= 0 && s < loops.length, `${what}: face ${f}'s source ${s} is an input face`);
    const n = normalOf(mesh.positions, loops[s]);
    for (const v of face)
      assert.ok(onPlane(mesh.positions, loops[s], n, kernelPoints[v]), `${what}: face ${f} on ${s}`);
    for (const p of kernelPoints)
      assert.ok(dot(n, sub(p, vtx(mesh.positions, loops[s][0]))) <= 0, `${what}: the kernel behind face ${s}`);
    for (let g = 0; g < s; g++) {
      const m = normalOf(mesh.positions, loops[g]);
      const same = loops[g].every((v) => onPlane(mesh.positions, loops[s], n, vtx(mesh.positions, v)));
      assert.ok(!(same && dot(m, n) > 0), `${what}: input face ${g} < ${s} lies on face ${f}'s plane`);
    }
  });
  return counts;
}

// The unit cube without its top (two triangles at z = 1).
function openCube() {
  const m = box();
  const keep = [];
  for (let t = 0; t < m.indices.length; t += 3) {
    const tri = m.indices.slice(t, t + 3);
    if (!Array.from(tri).every((v) => m.positions[3 * v + 2] === 1)) keep.push(...tri);
  }
  return { positions: m.positions, indices: Uint32Array.from(keep), faceSizes: null };
}

// A flat square frustum open at the top: bottom [-3, 3]^2 at z = 0 (faces 0, 1), rim [-2, 2]^2 at
// z = 1. Its walls (perpendicular to the sides, through the rim) leave nothing above the bottom.
function openFrustum() {
  const positions = [];
  for (const [z, r] of [
    [0, 3],
    [1, 2],
  ])
    for (const [x, y] of [
      [-r, -r],
      [r, -r],
      [r, r],
      [-r, r],
    ])
      positions.push(x, y, z);
  const indices = [0, 2, 1, 0, 3, 2];
  for (let i = 0; i < 4; i++) {
    const j = (i + 1) % 4;
    indices.push(i, j, 4 + j, i, 4 + j, 4 + i);
  }
  return { positions: Float64Array.from(positions), indices: Uint32Array.from(indices), faceSizes: null };
}

// Whether the half-spaces n.x <= d meet inside the box |x_k| <= R (some vertex of three planes or
// box faces satisfies all of them within tol), as in witness.test.mjs.
function meetInBox(planes, R, tol) {
  const all = [...planes];
  for (let k = 0; k < 3; k++) {
    const e = [0, 0, 0];
    e[k] = 1;
    all.push({ n: e, d: R }, { n: e.map((x) => -x), d: R });
  }
  for (let i = 0; i < all.length; i++)
    for (let j = i + 1; j < all.length; j++)
      for (let k = j + 1; k < all.length; k++) {
        const [a, b, c] = [all[i], all[j], all[k]];
        const det = dot(a.n, cross(b.n, c.n));
        if (Math.abs(det) < 1e-12) continue;
        const x = [0, 1, 2].map(
          (t) => (a.d * cross(b.n, c.n)[t] + b.d * cross(c.n, a.n)[t] + c.d * cross(a.n, b.n)[t]) / det,
        );
        if (all.every((p) => dot(p.n, x) - p.d <= tol * (1 + Math.abs(p.d)))) return true;
      }
  return false;
}

// The witness of an empty walled kernel: its faces' planes and its walls, each rebuilt from its
// edge a -> b (a boundary edge as its face runs) as the plane through the edge and its face's
// normal, facing away from the face; checked to have no common point, and to be minimal.
function checkWallWitness(mesh, faces, edges, what) {
  const loops = faceLoops(mesh.indices, mesh.faceSizes);
  assert.ok(edges instanceof Uint32Array && edges.length % 2 === 0, `${what}: witnessBoundaryEdges are pairs`);
  const planes = Array.from(faces, (f) => {
    const n = normalOf(mesh.positions, loops[f]);
    return { n, d: dot(n, vtx(mesh.positions, loops[f][0])) };
  });
  for (let i = 0; i < edges.length; i += 2) {
    const [a, b] = [edges[i], edges[i + 1]];
    const runs = loops.filter((l) => l.some((v, k) => v === a && l[(k + 1) % l.length] === b));
    const back = loops.filter((l) => l.some((v, k) => v === b && l[(k + 1) % l.length] === a));
    assert.equal(runs.length, 1, `${what}: a face runs ${a} -> ${b}`);
    assert.equal(back.length, 0, `${what}: ${a} -> ${b} is a boundary edge`);
    const pa = vtx(mesh.positions, a);
    const n = cross(sub(vtx(mesh.positions, b), pa), normalOf(mesh.positions, runs[0]));
    planes.push({ n, d: dot(n, pa) });
  }
  const R = 1e3 * Math.max(...Array.from(mesh.positions, Math.abs));
  assert.equal(meetInBox(planes, R, 1e-12), false, `${what}: the witness's half-spaces meet`);
  for (let i = 0; i < planes.length; i++)
    assert.equal(
      meetInBox(
        planes.filter((_, j) => j !== i),
        R,
        1e-12,
      ),
      true,
      `${what}: not minimal (half-space ${i} is not needed)`,
    );
}

test('FACE_SOURCE_BOX and FACE_SOURCE_WALL: the core values from the wire format, before init()', async () => {
  const { default: createKergenModule } = await import(pathToFileURL(distGlue).href);
  const m = await createKergenModule({ wasmBinary: fs.readFileSync(distWasm) });
  const { box: boxMark, wall } = m.wireFormat().faceSource;
  assert.equal(K.FACE_SOURCE_BOX, boxMark);
  assert.equal(K.FACE_SOURCE_WALL, wall);
  assert.equal(W.FACE_SOURCE_BOX, boxMark);
  assert.equal(W.FACE_SOURCE_WALL, wall);
  assert.ok(boxMark < 0 && wall < 0 && boxMark !== wall, 'marks are no face index');
  const out = execFileSync(
    process.execPath,
    [
      '--input-type=module',
      '-e',
      "const K = await import('./wasm/index.js'); console.log(K.isInitialized(), K.FACE_SOURCE_BOX, K.FACE_SOURCE_WALL)",
    ],
    { cwd: repoRoot, encoding: 'utf8' },
  );
  assert.equal(out.trim(), `false ${boxMark} ${wall}`);
});

test('L prism: each face on its source face, the same from sync, async and the worker', async () => {
  const m = lPrism();
  const r = K.computeKernelSync(m.positions, m.indices);
  assert.equal(r.status, 'POLYHEDRON');
  assert.deepEqual(checkSources(m, r, 'L prism'), { input: 6, box: 0, wall: 0 });
  const expected = Array.from(r.faceSources);
  assert.deepEqual(Array.from((await K.computeKernel(m.positions, m.indices)).faceSources), expected);
  const kw = newWorker();
  const w = await kw.compute(m.positions, m.indices);
  assert.ok(w.faceSources instanceof Int32Array);
  assert.deepEqual(Array.from(w.faceSources), expected, 'worker');
  assert.ok(w.witnessBoundaryEdges instanceof Uint32Array && w.witnessBoundaryEdges.length === 0);
  // Stopped early: one source per face returned.
  const partial = K.computeKernelSync(m.positions, m.indices, { maxSteps: 25 });
  assert.equal(partial.complete, false);
  assert.equal(partial.faceSources.length, partial.faces.length);
  checkSources(m, partial, 'L prism, partial');
});

test('the open box: a box face where it is clipped, a wall face where it is walled', async () => {
  const m = openCube();
  const clipped = K.computeKernelSync(m.positions, m.indices, { allowOpen: true });
  assert.equal(clipped.status, 'UNBOUNDED');
  assert.deepEqual(checkSources(m, clipped, 'open box, clipped'), { input: 5, box: 1, wall: 0 });
  const top = clipped.faces[clipped.faceSources.indexOf(K.FACE_SOURCE_BOX)];
  for (const v of top) assert.ok(clipped.vertices[3 * v + 2] > 1, 'the box face is above the hole');
  const kw = newWorker();
  for (const r of [
    K.computeKernelSync(m.positions, m.indices, { open: 'perpendicular' }),
    await K.computeKernel(m.positions, m.indices, { open: 'perpendicular' }),
    await kw.compute(m.positions, m.indices, { open: 'perpendicular' }),
  ]) {
    assert.equal(r.status, 'POLYHEDRON');
    assert.equal(r.volume, 1);
    assert.deepEqual(checkSources(m, r, 'open box, walled'), { input: 5, box: 0, wall: 1 });
    const lid = r.faces[r.faceSources.indexOf(K.FACE_SOURCE_WALL)];
    for (const v of lid) assert.equal(r.vertices[3 * v + 2], 1, 'the wall face is the plane z = 1');
  }
});

test('walls in the witness: the open frustum, from sync, async, findKernelPoint and the worker', async () => {
  const m = openFrustum();
  assert.notEqual(K.computeKernelSync(m.positions, m.indices, { allowOpen: true }).status, 'EMPTY');
  const r = K.computeKernelSync(m.positions, m.indices, { open: 'perpendicular' });
  assert.equal(r.status, 'EMPTY');
  assert.deepEqual(Array.from(r.witnessFaces), [0], 'the bottom (walls alone leave room below it)');
  assert.ok(r.witnessBoundaryEdges.length >= 4, 'two walls at least');
  checkWallWitness(m, r.witnessFaces, r.witnessBoundaryEdges, 'open frustum');
  const expected = [Array.from(r.witnessFaces), Array.from(r.witnessBoundaryEdges)];
  const kw = newWorker();
  const options = { open: 'perpendicular' };
  for (const [what, other] of [
    ['computeKernel', await K.computeKernel(m.positions, m.indices, options)],
    ['findKernelPointSync', K.findKernelPointSync(m.positions, m.indices, options)],
    ['findKernelPoint', await K.findKernelPoint(m.positions, m.indices, options)],
    ['KernelWorker.compute', await kw.compute(m.positions, m.indices, options)],
  ]) {
    assert.ok(other.witnessBoundaryEdges instanceof Uint32Array, `${what}: a Uint32Array`);
    assert.deepEqual([Array.from(other.witnessFaces), Array.from(other.witnessBoundaryEdges)], expected, what);
  }
  // Without walls no wall is named; a star-shaped mesh has no witness at all.
  const u = K.findKernelPointSync(m.positions, m.indices, { allowOpen: true });
  assert.equal(u.witnessBoundaryEdges.length, 0);
  const cube = box();
  assert.equal(K.findKernelPointSync(cube.positions, cube.indices).witnessBoundaryEdges.length, 0);
});
