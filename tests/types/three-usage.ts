// Type-level usage of `kergen-wasm/three` with real three.js types (@types/three), under --strict:
// geometries from generators and loaders go in without casts, results come out as geometries.
import * as THREE from 'three';
import { STLLoader } from 'three/examples/jsm/loaders/STLLoader.js';
import { OBJLoader } from 'three/examples/jsm/loaders/OBJLoader.js';
import {
  computeKernelOfGeometry,
  computeKernelOfObject,
  geometryToMesh,
  objectToMesh,
  type MergedMesh,
  kernelToGeometry,
  KernelWorker,
  KergenError,
  type GeometryKernelOptions,
  type KergenErrorCode,
  type KernelGeometries,
  type KernelResult,
} from 'kergen-wasm/three';
import { computeKernel, type IndicesInput } from 'kergen-wasm';
import { KernelWorker as PlainWorker } from 'kergen-wasm/worker';

async function three(): Promise<void> {
  const sphere = new THREE.SphereGeometry(1, 32, 16);
  const options: GeometryKernelOptions = { from: [0, 0, 0], deepestPoint: true, weld: { relative: 1e-8 } };
  const k: KernelResult = await computeKernelOfGeometry(sphere, options);
  const { mesh, edges }: KernelGeometries = kernelToGeometry(k);
  const scene = new THREE.Scene();
  scene.add(
    new THREE.Mesh(mesh, new THREE.MeshNormalMaterial()),
    new THREE.LineSegments(edges, new THREE.LineBasicMaterial()),
  );

  const stl: THREE.BufferGeometry = new STLLoader().parse(new ArrayBuffer(84));
  const group = new OBJLoader().parse('v 0 0 0');
  const objMesh = group.children[0] as THREE.Mesh;
  const worker = new KernelWorker({ wasmUrl: '/kergen.wasm' });
  const fromWorker: KernelResult = await worker.computeGeometry(stl, {
    onProgress: (p) => void p.phase,
    onStep: (e) => e.type !== 'face',
  });
  const fromObj = await worker.computeGeometry(objMesh.geometry, { weld: 1e-6 });
  const knot = await computeKernelOfGeometry(new THREE.TorusKnotGeometry());
  void [fromWorker.volume, fromObj.status, knot.status];
  // KernelWorker from kergen-wasm/three is the worker helper, with the plain compute too.
  const plain: PlainWorker = worker;
  const { positions, indices } = geometryToMesh(new THREE.BoxGeometry());
  await plain.compute(positions, indices, { transfer: true });
  // A whole scene (a glTF scene, a Group): world transforms applied, merged.
  const group3 = new THREE.Group().add(new THREE.Mesh(new THREE.BoxGeometry()));
  const ofScene: KernelResult = await computeKernelOfObject(group3, { weld: true });
  const ofSceneInWorker: KernelResult = await worker.computeObject(group3, { onStep: () => true });
  const merged: MergedMesh = objectToMesh(new THREE.Scene());
  void [ofScene.volume, ofSceneInWorker.volume, merged.meshes];
  worker.dispose();

  // The index arrays of three.js geometries (Uint16Array / Uint32Array, even Uint8Array) fit IndicesInput.
  const index: IndicesInput = new Uint8Array([0, 1, 2]);
  await computeKernel(new Float32Array(9), index, { allowOpen: true });

  try {
    await computeKernelOfGeometry(new THREE.PlaneGeometry());
  } catch (err) {
    if (err instanceof KergenError) {
      const code: KergenErrorCode = err.code;
      if (err.code === 'OPEN_MESH') void code;
    }
  }
}

// @ts-expect-error: KergenError.code is a closed set: a typo does not compile
const typo = (e: KergenError) => e.code === 'OPEN_MSH';
// @ts-expect-error: a geometry is triangles; faceSizes does not apply
void computeKernelOfGeometry(new THREE.BoxGeometry(), { faceSizes: [3] });
// @ts-expect-error: computeGeometry copies the geometry's arrays itself
void new KernelWorker().computeGeometry(new THREE.BoxGeometry(), { transfer: true });
// @ts-expect-error: a geometry is not an Object3D
void computeKernelOfObject(new THREE.BoxGeometry());
// @ts-expect-error: an Int8Array is not an index array the core accepts
const badIndex: IndicesInput = new Int8Array(3);

void [three, typo, badIndex];
