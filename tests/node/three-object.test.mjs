// kergen-wasm/three on whole scenes: computeKernelOfObject / KernelWorker.computeObject merge every
// mesh under a node with its world transform (a box scaled ×2 along x: volume 12, where the
// geometry alone gives 6), through three.js objects built here and through a GLB written by
// three's GLTFExporter and read back by GLTFLoader; meshes that meet along seams are welded into
// one closed surface; mirroring transforms keep the faces outward; the scene is not modified.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import * as THREE from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { assertBuilt } from './lib/env.mjs';
import { installWorkerShim } from './lib/web-worker-shim.mjs';
import { glbOf, scaledBoxScene } from './lib/example-meshes.mjs';

let T;
const workers = [];
before(async () => {
  assertBuilt();
  installWorkerShim();
  T = await import('../../wasm/three.js');
});
after(() => {
  for (const w of workers) w.dispose();
});

function newWorker() {
  const w = new T.KernelWorker();
  workers.push(w);
  return w;
}

const close = (a, b, what) => assert.ok(Math.abs(a - b) <= 1e-12 * Math.abs(b), `${what}: ${a}, expected ${b}`);

test('a box scaled ×2 (three.js objects): volume 12 on the main thread and in the worker; the geometry alone gives 6', async () => {
  const { scene, box } = scaledBoxScene();
  const arrays = [box.geometry.attributes.position.array, box.geometry.index.array];
  const bytes = arrays.map((a) => Buffer.from(a.buffer).toString('base64'));
  const main = await T.computeKernelOfObject(scene);
  const inWorker = await newWorker().computeObject(scene);
  for (const [r, where] of [
    [main, 'main thread'],
    [inWorker, 'worker'],
  ]) {
    assert.equal(r.status, 'POLYHEDRON', where);
    close(r.volume, 12, `${where}: volume`);
    close(r.shapeVolume, 12, `${where}: shape volume`);
    assert.equal(r.vertices.length / 3, 8, `${where}: 8 kernel vertices`);
    assert.equal(r.faces.length, 6, `${where}: 6 kernel faces`);
    assert.ok(
      r.warnings.some((w) => w.kind === 'VERTICES_WELDED'),
      `${where}: BoxGeometry's 24 corners welded to 8`,
    );
  }
  // The kernel is where the box is drawn: its centre is the group's position.
  const centre = [0, 1, 2].map((k) => {
    let s = 0;
    for (let i = k; i < main.vertices.length; i += 3) s += main.vertices[i];
    return s / 8;
  });
  centre.forEach((c, k) => assert.ok(Math.abs(c - [5, -3, 2][k]) < 1e-12, `kernel centre ${centre}`));
  close((await T.computeKernelOfGeometry(box.geometry)).volume, 6, 'computeKernelOfGeometry ignores the node');
  assert.ok(box.geometry.attributes.position.array === arrays[0] && box.geometry.index.array === arrays[1]);
  assert.deepEqual(
    arrays.map((a) => Buffer.from(a.buffer).toString('base64')),
    bytes,
    'the geometry keeps its bytes',
  );
});

test('a box scaled ×2 through a GLB (GLTFExporter → GLTFLoader.parse): volume 12 on the main thread and in the worker', async () => {
  const { scene } = scaledBoxScene();
  const glb = await glbOf(scene);
  assert.ok(glb instanceof ArrayBuffer && glb.byteLength > 0);
  assert.equal(String.fromCharCode(...new Uint8Array(glb, 0, 4)), 'glTF');
  const gltf = await new GLTFLoader().parseAsync(glb, '');
  let scaled = null;
  gltf.scene.traverse((o) => {
    if (o.isMesh) scaled = o;
  });
  assert.ok(scaled && scaled.scale.x === 2, 'the node keeps its scale in the GLB');
  close((await T.computeKernelOfObject(gltf.scene)).volume, 12, 'main thread');
  close((await newWorker().computeObject(gltf.scene)).volume, 12, 'worker');
  close((await T.computeKernelOfGeometry(scaled.geometry)).volume, 6, 'the geometry alone');
});

test('meshes meeting along seams are merged and welded into one surface; a mirrored mesh keeps its faces outward', async () => {
  // A 2×3×4 box as two meshes: the triangles of its -z, -y, -x faces in one, the rest in the
  // other, the second under a mirroring parent (scale -1 in x) that maps it back into place.
  const whole = new THREE.BoxGeometry(2, 3, 4).toNonIndexed();
  const pos = whole.attributes.position.array;
  const firstHalf = [];
  const secondHalf = [];
  for (let t = 0; t < pos.length / 9; t++) {
    const tri = Array.from(pos.subarray(9 * t, 9 * t + 9));
    const c = [0, 1, 2].map((k) => (tri[k] + tri[k + 3] + tri[k + 6]) / 3);
    const low = c.some((v, k) => Math.abs(v + [1, 1.5, 2][k]) < 1e-9);
    (low ? firstHalf : secondHalf).push(tri);
  }
  const geom = (tris, mirror) => {
    const flat = tris.flatMap((tri) => {
      const p = mirror ? tri.map((v, i) => (i % 3 === 0 ? -v : v)) : tri;
      return mirror ? [...p.slice(0, 3), ...p.slice(6, 9), ...p.slice(3, 6)] : p; // mirrored: re-wound
    });
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.Float32BufferAttribute(flat, 3));
    return g;
  };
  const root = new THREE.Group();
  const mirrorParent = new THREE.Group();
  mirrorParent.scale.set(-1, 1, 1);
  mirrorParent.add(new THREE.Mesh(geom(secondHalf, true)));
  root.add(
    new THREE.Mesh(geom(firstHalf, false)),
    mirrorParent,
    new THREE.LineSegments(new THREE.EdgesGeometry(whole)),
  );
  const merged = T.objectToMesh(root);
  assert.equal(merged.meshes, 2, 'two meshes merged; the lines skipped');
  assert.equal(merged.indices.length, 36);
  const main = await T.computeKernelOfObject(root);
  const inWorker = await newWorker().computeObject(root);
  for (const r of [main, inWorker]) {
    assert.equal(r.status, 'POLYHEDRON');
    close(r.volume, 24, 'volume');
    assert.ok(!r.warnings.some((w) => w.kind === 'ORIENTATION_FLIPPED'), 'no face turned inside out');
  }
  // Without the weld the two halves do not close: an open mesh.
  await assert.rejects(T.computeKernelOfObject(root, { weld: false }), { code: 'OPEN_MESH' });
});

test('an InstancedMesh counts once per instance, each with its matrix', async () => {
  const mesh = new THREE.InstancedMesh(new THREE.BoxGeometry(1, 1, 1), undefined, 1);
  mesh.setMatrixAt(0, new THREE.Matrix4().makeScale(2, 3, 4));
  const r = await T.computeKernelOfObject(mesh);
  close(r.volume, 24, 'instance scaled 2×3×4');
  const two = new THREE.InstancedMesh(new THREE.BoxGeometry(1, 1, 1), undefined, 2);
  two.setMatrixAt(0, new THREE.Matrix4());
  two.setMatrixAt(1, new THREE.Matrix4().makeTranslation(3, 0, 0));
  assert.equal(T.objectToMesh(two).indices.length, 72);
  // Two disjoint closed boxes: no point sees both from inside.
  const apart = await T.computeKernelOfObject(two);
  assert.equal(apart.status, 'EMPTY');
});

test('objects without meshes and non-objects get specific errors', async () => {
  const lines = new THREE.Group().add(new THREE.LineSegments(new THREE.EdgesGeometry(new THREE.BoxGeometry())));
  await assert.rejects(T.computeKernelOfObject(lines), { code: 'EMPTY_INPUT', message: /no triangle mesh/ });
  await assert.rejects(newWorker().computeObject(new THREE.Group()), { code: 'EMPTY_INPUT' });
  await assert.rejects(T.computeKernelOfObject(new THREE.BoxGeometry()), {
    code: 'INVALID_ARGUMENT',
    message: /Object3D/,
  });
  await assert.rejects(T.computeKernelOfObject(null), { code: 'INVALID_ARGUMENT' });
  assert.throws(() => T.objectToMesh({}), { code: 'INVALID_ARGUMENT' });
});
