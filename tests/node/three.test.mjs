// kergen-wasm/three: the kernel of three.js geometries (generators, STLLoader, OBJLoader,
// interleaved / normalized / Uint8-indexed attributes) equals the core's kernel of the welded
// mesh (computeKernel, and the native CLI when built); the caller's geometry is never modified,
// its arrays never detached; kernelToGeometry gives flat-shaded faces and the edges.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { execFileSync } from 'node:child_process';
import * as THREE from 'three';
import { STLLoader } from 'three/examples/jsm/loaders/STLLoader.js';
import { STLExporter } from 'three/examples/jsm/exporters/STLExporter.js';
import { OBJLoader } from 'three/examples/jsm/loaders/OBJLoader.js';
import { assertBuilt, nativeCli } from './lib/env.mjs';
import { installWorkerShim } from './lib/web-worker-shim.mjs';

let K;
let T;
let tmp;
const workers = [];
before(async () => {
  assertBuilt();
  installWorkerShim();
  K = await import('../../wasm/index.js');
  T = await import('../../wasm/three.js');
  await K.init();
  tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'kergen-three-'));
});
after(() => {
  for (const w of workers) w.dispose();
  fs.rmSync(tmp, { recursive: true, force: true });
});

// Test-only reference weld: vertices closer than `tol` share the first one's id (O(n^2): small meshes).
function weldReference(positions, indices, tol) {
  const n = positions.length / 3;
  const id = new Int32Array(n).fill(-1);
  const kept = [];
  for (let i = 0; i < n; i++) {
    for (const j of kept) {
      const d = Math.hypot(
        positions[3 * i] - positions[3 * j],
        positions[3 * i + 1] - positions[3 * j + 1],
        positions[3 * i + 2] - positions[3 * j + 2],
      );
      if (d <= tol) {
        id[i] = id[j];
        break;
      }
    }
    if (id[i] < 0) {
      id[i] = kept.length;
      kept.push(i);
    }
  }
  const out = new Float64Array(3 * kept.length);
  kept.forEach((v, k) => out.set(positions.subarray(3 * v, 3 * v + 3), 3 * k));
  return { positions: out, indices: Uint32Array.from(indices, (v) => id[v]) };
}

function diagonal(positions) {
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < positions.length; i++) {
    lo[i % 3] = Math.min(lo[i % 3], positions[i]);
    hi[i % 3] = Math.max(hi[i % 3], positions[i]);
  }
  return Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}

// The core's kernel of the geometry's triangles, welded by the test's own reference weld.
function referenceKernel(geometry) {
  const { positions, indices } = T.geometryToMesh(geometry);
  const welded = weldReference(positions, indices, 1e-9 * diagonal(positions));
  return { welded, kernel: K.computeKernelSync(welded.positions, welded.indices) };
}

function nativeKernel(mesh, name) {
  const file = path.join(tmp, `${name}.off`);
  const nv = mesh.positions.length / 3;
  const nf = mesh.indices.length / 3;
  const lines = ['OFF', `${nv} ${nf} 0`];
  for (let i = 0; i < nv; i++)
    lines.push(Array.from(mesh.positions.subarray(3 * i, 3 * i + 3), (x) => x.toPrecision(17)).join(' '));
  for (let f = 0; f < nf; f++)
    lines.push(`3 ${mesh.indices[3 * f]} ${mesh.indices[3 * f + 1]} ${mesh.indices[3 * f + 2]}`);
  fs.writeFileSync(file, lines.join('\n') + '\n');
  const out = execFileSync(nativeCli, ['--json', file], { encoding: 'utf8' });
  return JSON.parse(out.split('\n').find((l) => l.startsWith('{')));
}

// Every attribute and the index of a geometry: the objects, their arrays, buffers and bytes.
function snapshot(geometry) {
  const arrays = [...Object.values(geometry.attributes), geometry.index]
    .filter(Boolean)
    .map((a) => (a.isInterleavedBufferAttribute ? a.data.array : a.array));
  return {
    attributes: { ...geometry.attributes },
    index: geometry.index,
    arrays,
    buffers: arrays.map((a) => a.buffer),
    bytes: arrays.map((a) => Buffer.from(a.buffer, a.byteOffset, a.byteLength).toString('base64')),
    groups: JSON.stringify(geometry.groups),
  };
}

function assertUntouched(geometry, before, what) {
  const now = snapshot(geometry);
  assert.deepEqual(Object.keys(now.attributes), Object.keys(before.attributes), `${what}: same attributes`);
  for (const k of Object.keys(now.attributes))
    assert.ok(now.attributes[k] === before.attributes[k], `${what}: attribute ${k} is the same object`);
  assert.ok(now.index === before.index, `${what}: same index object`);
  now.arrays.forEach((a, i) => {
    assert.ok(
      a === before.arrays[i] && a.buffer === before.buffers[i],
      `${what}: array ${i} is the same, on the same buffer`,
    );
    assert.ok(a.byteLength > 0, `${what}: array ${i} is not detached`);
  });
  assert.deepEqual(now.bytes, before.bytes, `${what}: the same bytes`);
  assert.equal(now.groups, before.groups, `${what}: the same groups`);
}

function newWorker() {
  const w = new T.KernelWorker();
  workers.push(w);
  return w;
}

// Main thread and worker: same kernel as the reference, the geometry untouched by both calls.
async function checkGeometry(name, geometry, expect = {}) {
  const { welded, kernel: ref } = referenceKernel(geometry);
  const before = snapshot(geometry);
  const main = await T.computeKernelOfGeometry(geometry);
  assertUntouched(geometry, before, `${name} (main thread)`);
  const inWorker = await newWorker().computeGeometry(geometry);
  assertUntouched(geometry, before, `${name} (worker)`);
  for (const r of [main, inWorker]) {
    assert.equal(r.status, ref.status, `${name}: status`);
    assert.equal(r.vertices.length, ref.vertices.length, `${name}: kernel vertices`);
    assert.ok(
      Math.abs(r.volume - ref.volume) <= 1e-9 * Math.abs(ref.volume),
      `${name}: volume ${r.volume} vs ${ref.volume}`,
    );
    assert.ok(
      r.warnings.some((w) => w.kind === 'VERTICES_WELDED'),
      `${name}: the weld is reported (${r.warnings.map((w) => w.kind)})`,
    );
  }
  if (expect.status) assert.equal(main.status, expect.status, `${name}: expected status`);
  if (expect.volume !== undefined)
    assert.ok(
      Math.abs(main.volume - expect.volume) <= 1e-12 * expect.volume,
      `${name}: volume ${main.volume}, expected ${expect.volume}`,
    );
  if (fs.existsSync(nativeCli)) {
    const n = nativeKernel(welded, name);
    assert.equal(n.status, main.status, `${name}: native status`);
    assert.ok(
      Math.abs(n.volume - main.volume) <= 1e-9 * Math.abs(main.volume),
      `${name}: native volume ${n.volume} vs ${main.volume}`,
    );
  }
  return main;
}

test('SphereGeometry (seams and poles): the whole sphere, as the core and the CLI compute it', async () => {
  const r = await checkGeometry('sphere', new THREE.SphereGeometry(1, 24, 16), { status: 'POLYHEDRON' });
  assert.ok(r.volume > 3.9 && r.volume < (4 * Math.PI) / 3, `volume ${r.volume}`);
});

test('TorusKnotGeometry: not star-shaped (EMPTY), as the core and the CLI say', async () => {
  await checkGeometry('torus-knot', new THREE.TorusKnotGeometry(1, 0.3, 64, 8), { status: 'EMPTY' });
});

test('BoxGeometry (24 vertices, 4 per face): the box itself', async () => {
  await checkGeometry('box', new THREE.BoxGeometry(1, 2, 3), { status: 'POLYHEDRON', volume: 6 });
});

test('STLLoader (non-indexed, a normal per corner): the same kernel as readMesh + computeKernel (weld) on the same bytes', async () => {
  const source = new THREE.Mesh(new THREE.SphereGeometry(2, 16, 10));
  const bytes = new STLExporter().parse(source, { binary: true });
  const stlBuffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
  const geometry = new STLLoader().parse(stlBuffer.slice(0));
  assert.equal(geometry.index, null);
  const r = await checkGeometry('stl', geometry, { status: 'POLYHEDRON' });
  const read = await K.readMesh(new Uint8Array(stlBuffer), { name: 'sphere.stl' });
  // readMesh merges equal corners; the seam's corners differ by float32 rounding (sin 2π ≠ 0),
  // which only the weld closes.
  await assert.rejects(
    K.computeKernel(read.positions, read.indices),
    (e) => e.code === 'OPEN_MESH' && /weld: true/.test(e.message),
  );
  const core = await K.computeKernel(read.positions, read.indices, { weld: true });
  assert.equal(r.status, core.status);
  assert.equal(r.volume, core.volume, 'the same welded mesh, the same kernel');
  if (fs.existsSync(nativeCli)) {
    const file = path.join(tmp, 'sphere.stl');
    fs.writeFileSync(file, new Uint8Array(stlBuffer));
    const n = JSON.parse(
      execFileSync(nativeCli, ['--json', '--weld', '--', file], { encoding: 'utf8' })
        .split('\n')
        .find((l) => l.startsWith('{')),
    );
    assert.equal(n.status, r.status, 'kergen --weld: the same status');
    assert.ok(Math.abs(n.volume - r.volume) <= 1e-12 * r.volume, `kergen --weld: volume ${n.volume} vs ${r.volume}`);
  }
});

test('a non-indexed Float64 geometry whose seam is 1e-12 apart: welded (relative 1e-9), the kernel of the closed mesh', async () => {
  const exact = new THREE.SphereGeometry(1, 12, 8);
  exact.setAttribute('position', new THREE.BufferAttribute(Float64Array.from(exact.attributes.position.array), 3));
  const soup = exact.toNonIndexed();
  const p = soup.attributes.position.array;
  for (let i = 0; i < p.length; i += 9) p[i] += 1e-12; // the first corner of every triangle moves 1e-12
  const ref = K.computeKernelSync(
    ...Object.values(weldReference(T.geometryToMesh(exact).positions, T.geometryToMesh(exact).indices, 1e-9 * 2)),
  );
  const before = snapshot(soup);
  const r = await T.computeKernelOfGeometry(soup);
  assertUntouched(soup, before, 'seam');
  assert.equal(r.status, 'POLYHEDRON');
  assert.ok(Math.abs(r.volume - ref.volume) < 1e-9, `volume ${r.volume} vs ${ref.volume}`);
  await assert.rejects(
    T.computeKernelOfGeometry(soup, { weld: false }),
    (err) => err.code === 'OPEN_MESH' && /weld/.test(err.message),
    'weld: false: the triangles are loose',
  );
});

test('OBJLoader mesh with two material groups: groups ignored, the same kernel as readMesh of the OBJ', async () => {
  const obj = [
    'o cube',
    'v 0 0 0',
    'v 1 0 0',
    'v 0 1 0',
    'v 1 1 0',
    'v 0 0 1',
    'v 1 0 1',
    'v 0 1 1',
    'v 1 1 1',
    'usemtl red',
    'f 1 3 4 2',
    'f 5 6 8 7',
    'f 1 2 6 5',
    'usemtl blue',
    'f 3 7 8 4',
    'f 1 5 7 3',
    'f 2 4 8 6',
  ].join('\n');
  const group = new OBJLoader().parse(obj);
  const mesh = group.children[0];
  assert.equal(mesh.geometry.groups.length, 2, 'two material groups');
  const r = await checkGeometry('obj', mesh.geometry, { status: 'POLYHEDRON', volume: 1 });
  const read = await K.readMesh(new TextEncoder().encode(obj), { name: 'cube.obj' });
  assert.equal(r.volume, (await K.computeKernel(read.positions, read.indices, { faceSizes: read.faceSizes })).volume);
});

test('interleaved positions, Uint8 index, normalized Int16 positions: read through the attribute accessors', async () => {
  const box = new THREE.BoxGeometry(2, 2, 2); // corners at ±1
  const { positions, indices } = T.geometryToMesh(box);
  const n = positions.length / 3;
  const interleaved = new THREE.InterleavedBuffer(new Float32Array(6 * n), 6);
  for (let i = 0; i < n; i++)
    interleaved.array.set([positions[3 * i], positions[3 * i + 1], positions[3 * i + 2], 7, 7, 7], 6 * i);
  const g1 = new THREE.BufferGeometry();
  g1.setAttribute('position', new THREE.InterleavedBufferAttribute(interleaved, 3, 0));
  g1.setAttribute('normal', new THREE.InterleavedBufferAttribute(interleaved, 3, 3));
  g1.setIndex(new THREE.BufferAttribute(Uint8Array.from(indices), 1));
  await checkGeometry('interleaved', g1, { status: 'POLYHEDRON', volume: 8 });

  const g2 = new THREE.BufferGeometry();
  g2.setAttribute(
    'position',
    new THREE.BufferAttribute(
      Int16Array.from(positions, (x) => x * 32767),
      3,
      true,
    ),
  );
  g2.setIndex(new THREE.BufferAttribute(Uint16Array.from(indices), 1));
  await checkGeometry('int16-normalized', g2, { status: 'POLYHEDRON', volume: 8 });
});

test('bad geometries get specific errors', async () => {
  const kw = newWorker();
  for (const call of [(g, o) => T.computeKernelOfGeometry(g, o), (g, o) => kw.computeGeometry(g, o)]) {
    await assert.rejects(
      call(null),
      (e) => e.code === 'INVALID_ARGUMENT' && /must be a three\.js BufferGeometry/.test(e.message),
    );
    await assert.rejects(
      call(new THREE.BufferGeometry()),
      (e) => e.code === 'INVALID_ARGUMENT' && /no 'position' attribute/.test(e.message),
    );
    const two = new THREE.BufferGeometry();
    two.setAttribute('position', new THREE.Float32BufferAttribute(new Float32Array(6), 2));
    await assert.rejects(call(two), (e) => e.code === 'INVALID_ARGUMENT' && /itemSize 2/.test(e.message));
    const loose = new THREE.BufferGeometry();
    loose.setAttribute('position', new THREE.Float32BufferAttribute(new Float32Array(12), 3));
    await assert.rejects(
      call(loose),
      (e) => e.code === 'INVALID_ARGUMENT' && /3 vertices per triangle, but this one has 4/.test(e.message),
    );
    await assert.rejects(
      call(new THREE.BoxGeometry(), { faceSizes: [3] }),
      (e) => e.code === 'INVALID_ARGUMENT' && /faceSizes does not apply/.test(e.message),
    );
  }
  const negative = new THREE.BoxGeometry();
  negative.setIndex(
    new THREE.BufferAttribute(
      Int32Array.from(negative.index.array, (v, i) => (i === 5 ? -1 : v)),
      1,
    ),
  );
  await assert.rejects(
    T.computeKernelOfGeometry(negative),
    (e) => e.code === 'INDEX_OUT_OF_RANGE' && /index 5 is -1/.test(e.message),
  );
});

test('kernelToGeometry: flat-shaded faces (corners per face, outward unit normals) and the edges as LineSegments', async () => {
  const k = await T.computeKernelOfGeometry(new THREE.BoxGeometry(1, 2, 3));
  const { mesh, edges } = T.kernelToGeometry(k);
  assert.ok(mesh instanceof THREE.BufferGeometry && edges instanceof THREE.BufferGeometry);
  const pos = mesh.attributes.position;
  const nrm = mesh.attributes.normal;
  assert.equal(pos.count, k.faceIndices.length, 'each face has its own corners');
  assert.equal(mesh.index.count, 3 * (k.faceIndices.length - 2 * k.faces.length), 'fans of (n - 2) triangles');
  const centre = [0, 0, 0];
  for (let i = 0; i < k.vertices.length; i++) centre[i % 3] += k.vertices[i] / (k.vertices.length / 3);
  for (let t = 0; t < mesh.index.count; t += 3) {
    const [a, b, c] = [0, 1, 2].map((j) => new THREE.Vector3().fromBufferAttribute(pos, mesh.index.getX(t + j)));
    const faceNormal = new THREE.Vector3().crossVectors(b.clone().sub(a), c.clone().sub(a)).normalize();
    const n = new THREE.Vector3().fromBufferAttribute(nrm, mesh.index.getX(t));
    assert.ok(
      Math.abs(n.length() - 1) < 1e-6 && n.dot(faceNormal) > 0.999999,
      "the corner normal is the triangle's (CCW seen from outside)",
    );
    assert.ok(n.dot(a.clone().sub(new THREE.Vector3(...centre))) > 0, 'outward');
  }
  assert.equal(edges.attributes.position.count, k.vertices.length / 3);
  assert.deepEqual(Array.from(edges.attributes.position.array), Array.from(new Float32Array(k.vertices)));
  assert.deepEqual(Array.from(edges.index.array), Array.from(k.edges));
  assert.equal(edges.index.count, 24, 'a box has 12 edges');
  const line = new THREE.LineSegments(edges);
  assert.equal(line.geometry.index.count / 2, 12);

  const empty = await T.computeKernelOfGeometry(new THREE.TorusKnotGeometry(1, 0.3, 64, 8));
  const g = T.kernelToGeometry(empty);
  assert.equal(empty.status, 'EMPTY');
  assert.ok(
    g.mesh.attributes.position.count === 0 && g.mesh.index.count === 0 && g.edges.index.count === 0,
    'an empty kernel gives empty geometries',
  );
  assert.throws(
    () => T.kernelToGeometry({}),
    (e) => e.code === 'INVALID_ARGUMENT' && /must be a kernel result/.test(e.message),
  );
});

test("the worker trap of the issue: a geometry's own attribute arrays passed to compute() stay attached and drawable", async () => {
  const g = new THREE.BoxGeometry(1, 1, 1);
  const before = snapshot(g);
  const kw = newWorker();
  await assert.rejects(
    kw.compute(g.attributes.position.array, g.index.array),
    (e) => e.code === 'NON_MANIFOLD_EDGE' || e.code === 'OPEN_MESH',
  );
  assertUntouched(g, before, 'compute() with the raw attribute arrays');
  const r = await kw.compute(g.attributes.position.array, g.index.array, { weld: true });
  assert.equal(r.volume, 1);
  assertUntouched(g, before, 'compute() with weld');
});
