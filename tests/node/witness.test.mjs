// The non-star witness in the package: KernelResult.witnessFaces and findKernelPoint's
// witnessFaces (Uint32Array) name at most four input faces whose inner half-spaces have no
// common point. Checked here with the faces' own planes (test-only JS, in double precision with a
// margin): no point of a large box lies inside all of them (every vertex of the box cut by the
// planes is enumerated, and a non-empty bounded polytope has one), and without any one face the
// others' half-spaces do meet in the box. The same faces come from every path: sync, async,
// findKernelPoint, the worker (compute and computeFile).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { usePackageWithWorker } from './lib/package-with-worker.mjs';
import fs from 'node:fs';
import path from 'node:path';
import { offFiles, sharedMeshesMissing, sharedMeshes } from './lib/env.mjs';
import { box, faceLoops, signedVolume, uPrism } from './lib/geometry.mjs';
import { readOff } from './lib/off.mjs';

let K;
const { newWorker } = usePackageWithWorker((pkg) => (K = pkg.K));

const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const vtx = (P, i) => [P[3 * i], P[3 * i + 1], P[3 * i + 2]];

// A face's plane n·x <= d inside (unit n), from its Newell normal; null when the face is not
// planar (its corners more than 1e-9 of the normal's scale off that plane: the core splits it,
// and the C++ oracle test checks such witnesses).
function facePlane(positions, loop, orientation) {
  const n = [0, 0, 0];
  for (let i = 0; i < loop.length; i++) {
    const a = vtx(positions, loop[i]),
      b = vtx(positions, loop[(i + 1) % loop.length]);
    n[0] += (a[1] - b[1]) * (a[2] + b[2]);
    n[1] += (a[2] - b[2]) * (a[0] + b[0]);
    n[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  const len = Math.hypot(...n) * orientation;
  const u = n.map((x) => x / len);
  let d = 0;
  for (const v of loop) d += dot(u, vtx(positions, v)) / loop.length;
  const scale = Math.max(...loop.map((v) => Math.hypot(...vtx(positions, v))));
  if (loop.some((v) => Math.abs(dot(u, vtx(positions, v)) - d) > 1e-9 * scale)) return null;
  return { n: u, d };
}

// Whether the half-spaces meet inside the box |x_k| <= R: some vertex of three of the planes (or
// box faces) satisfies all of them within `tol`.
function meetInBox(planes, R, tol) {
  const all = [...planes];
  for (let k = 0; k < 3; k++) {
    const e = [0, 0, 0];
    e[k] = 1;
    all.push({ n: e, d: R }, { n: e.map((x) => -x), d: R });
  }
  for (let i = 0; i < all.length; i++) {
    for (let j = i + 1; j < all.length; j++) {
      for (let k = j + 1; k < all.length; k++) {
        const [a, b, c] = [all[i], all[j], all[k]];
        const det = dot(a.n, cross(b.n, c.n));
        if (Math.abs(det) < 1e-12) continue;
        // Cramer: x = (d_a (n_b x n_c) + d_b (n_c x n_a) + d_c (n_a x n_b)) / det
        const x = [0, 1, 2].map(
          (t) => (a.d * cross(b.n, c.n)[t] + b.d * cross(c.n, a.n)[t] + c.d * cross(a.n, b.n)[t]) / det,
        );
        if (all.every((p) => dot(p.n, x) - p.d <= tol * (1 + Math.abs(p.d)))) return true;
      }
    }
  }
  return false;
}

// Checks the witness; false when a witness face is not planar (not checked here).
function checkWitness(mesh, witness, what) {
  const loops = faceLoops(mesh.indices, mesh.faceSizes);
  const orientation = signedVolume(mesh.positions, loops) < 0 ? -1 : 1;
  assert.ok(witness instanceof Uint32Array, `${what}: witnessFaces is a Uint32Array`);
  assert.ok(witness.length >= 2 && witness.length <= 4, `${what}: ${witness.length} witness faces`);
  for (let i = 1; i < witness.length; i++) assert.ok(witness[i - 1] < witness[i], `${what}: increasing`);
  const planes = Array.from(witness, (f) => {
    assert.ok(f < loops.length, `${what}: face ${f} exists`);
    return facePlane(mesh.positions, loops[f], orientation);
  });
  if (planes.includes(null)) return false;
  const R = 1e3 * Math.max(...Array.from(mesh.positions, Math.abs));
  assert.equal(meetInBox(planes, R, 1e-9), false, `${what}: the witness faces' half-spaces meet`);
  for (let i = 0; i < planes.length; i++) {
    const others = planes.filter((_, j) => j !== i);
    assert.equal(meetInBox(others, R, 1e-9), true, `${what}: not minimal (face ${witness[i]} is not needed)`);
  }
  return true;
}

test('U prism: an empty kernel with two witness faces, the inner walls', () => {
  const m = uPrism();
  const r = K.computeKernelSync(m.positions, m.indices, { faceSizes: m.faceSizes ?? undefined });
  assert.equal(r.status, 'EMPTY');
  assert.equal(checkWitness(m, r.witnessFaces, 'uPrism'), true);
  assert.equal(r.witnessFaces.length, 2);
});

test('a star-shaped mesh has no witness (an empty Uint32Array), sync and findKernelPoint', () => {
  const m = box();
  const r = K.computeKernelSync(m.positions, m.indices, { faceSizes: m.faceSizes ?? undefined });
  assert.equal(r.status, 'POLYHEDRON');
  assert.ok(r.witnessFaces instanceof Uint32Array);
  assert.equal(r.witnessFaces.length, 0);
  const p = K.findKernelPointSync(m.positions, m.indices, { faceSizes: m.faceSizes ?? undefined });
  assert.ok(p.witnessFaces instanceof Uint32Array);
  assert.equal(p.witnessFaces.length, 0);
});

test(
  'shared non-star meshes: the same witness from sync, async, findKernelPoint (both) and the worker (compute, computeFile)',
  { timeout: 600000 },
  async (t) => {
    const missing = sharedMeshesMissing();
    if (missing) return t.skip(missing);
    const files = [...offFiles('princeton'), ...offFiles('fixtures')];
    const kw = newWorker();
    let checked = 0;
    let nonPlanar = 0;
    for (const file of files) {
      const name = path.relative(sharedMeshes, file);
      let mesh;
      try {
        mesh = readOff(file);
      } catch {
        continue; // (files the test's parser does not read: covered by native.test.mjs)
      }
      const options = { faceSizes: mesh.faceSizes ?? undefined };
      let r;
      try {
        r = K.computeKernelSync(mesh.positions, mesh.indices, options);
      } catch (err) {
        if (err instanceof K.KergenError) continue; // refused input: no kernel
        throw err;
      }
      if (r.status !== 'EMPTY') {
        assert.equal(r.witnessFaces.length, 0, `${name}: no witness for ${r.status}`);
        continue;
      }
      if (!checkWitness(mesh, r.witnessFaces, name)) nonPlanar++;
      const expected = Array.from(r.witnessFaces);
      const async = await K.computeKernel(mesh.positions, mesh.indices, options);
      assert.deepEqual(Array.from(async.witnessFaces), expected, `${name}: computeKernel`);
      const p = K.findKernelPointSync(mesh.positions, mesh.indices, options);
      assert.equal(p.starShaped, false);
      assert.ok(p.witnessFaces instanceof Uint32Array);
      assert.deepEqual(Array.from(p.witnessFaces), expected, `${name}: findKernelPointSync`);
      const pa = await K.findKernelPoint(mesh.positions, mesh.indices, options);
      assert.deepEqual(Array.from(pa.witnessFaces), expected, `${name}: findKernelPoint`);
      const w = await kw.compute(mesh.positions, mesh.indices, options);
      assert.ok(w.witnessFaces instanceof Uint32Array, `${name}: worker witnessFaces is a Uint32Array`);
      assert.deepEqual(Array.from(w.witnessFaces), expected, `${name}: KernelWorker.compute`);
      const { result } = await kw.computeFile(fs.readFileSync(file), { name: path.basename(file), transfer: true });
      assert.deepEqual(Array.from(result.witnessFaces), expected, `${name}: KernelWorker.computeFile`);
      checked++;
    }
    t.diagnostic(
      `${checked} non-star shared meshes, the same witness on every path; ${checked - nonPlanar} checked here (${nonPlanar} with a non-planar witness face)`,
    );
    assert.ok(checked >= 10, `${checked} non-star meshes checked`);
  },
);
