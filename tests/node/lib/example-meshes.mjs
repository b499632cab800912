// Mesh files with known kernels, for the example apps' tests (tests/node/examples.test.mjs,
// tests/e2e/examples.mjs) and the scene tests (three-object.test.mjs):
//   L prism (OFF / OBJ, polygon faces): the L (0,0)-(2,0)-(2,1)-(1,1)-(1,2)-(0,2) × [0,1];
//     kernel: the unit cube [0,1]³ (volume 1), shape volume 3.
//   plus prism (binary STL, a triangle soup): arms of width 1 reaching to ±1.5, z in [-0.5, 0.5];
//     kernel: the central unit cube (volume 1), shape volume 5.
//   scaled box (GLB): a 1×2×3 box (volume 6) in a node scaled ×2 along x: world volume 12.
import * as THREE from 'three';
import { GLTFExporter } from 'three/examples/jsm/exporters/GLTFExporter.js';

/** The L prism's 12 corners ([x, y, z]) and 8 faces (corner ids, outward order). */
export function lPrismPolygons() {
  const base = [
    [0, 0],
    [2, 0],
    [2, 1],
    [1, 1],
    [1, 2],
    [0, 2],
  ];
  const points = base.flatMap(([x, y]) => [
    [x, y, 0],
    [x, y, 1],
  ]);
  // Both caps start at the corner (0, 0): three.js's OBJLoader fans polygons from their first
  // corner, and only a fan from a corner in the L's kernel (the unit square) stays inside the L.
  const faces = [
    [0, 10, 8, 6, 4, 2],
    [1, 3, 5, 7, 9, 11],
  ];
  for (let i = 0; i < 6; i++) faces.push([2 * i, 2 * ((i + 1) % 6), 2 * ((i + 1) % 6) + 1, 2 * i + 1]);
  return { points, faces };
}

/** The L prism as flat arrays (polygon faces with faceSizes). */
export function lPrismMesh() {
  const { points, faces } = lPrismPolygons();
  return {
    positions: Float64Array.from(points.flat()),
    indices: Uint32Array.from(faces.flat()),
    faceSizes: Uint32Array.from(faces.map((f) => f.length)),
  };
}

export function lPrismFiles() {
  const { points, faces } = lPrismPolygons();
  const off = [
    'OFF',
    `${points.length} ${faces.length} 0`,
    ...points.map((p) => p.join(' ')),
    ...faces.map((f) => `${f.length} ${f.join(' ')}`),
  ];
  const obj = [
    '# L prism',
    ...points.map((p) => `v ${p.join(' ')}`),
    ...faces.map((f) => `f ${f.map((v) => v + 1).join(' ')}`),
  ];
  // The same prism with its top face left out: an open mesh.
  const open = [
    'OFF',
    `${points.length} ${faces.length - 1} 0`,
    ...points.map((p) => p.join(' ')),
    ...faces.filter((_, i) => i !== 1).map((f) => `${f.length} ${f.join(' ')}`),
  ];
  return { off: off.join('\n') + '\n', obj: obj.join('\n') + '\n', openOff: open.join('\n') + '\n' };
}

/** The plus prism as a binary STL (80-byte header, count, 50 bytes per triangle; zero normals). */
export function plusPrismStl() {
  const plus = [
    [0.5, -1.5],
    [0.5, -0.5],
    [1.5, -0.5],
    [1.5, 0.5],
    [0.5, 0.5],
    [0.5, 1.5],
    [-0.5, 1.5],
    [-0.5, 0.5],
    [-1.5, 0.5],
    [-1.5, -0.5],
    [-0.5, -0.5],
    [-0.5, -1.5],
  ];
  const p = [];
  for (const z of [-0.5, 0.5]) for (const [x, y] of plus) p.push([x, y, z]);
  const cap = [
    [1, 4, 7],
    [1, 7, 10],
    [1, 2, 3],
    [1, 3, 4],
    [4, 5, 6],
    [4, 6, 7],
    [7, 8, 9],
    [7, 9, 10],
    [10, 11, 0],
    [10, 0, 1],
  ];
  const tris = [];
  for (const [a, b, c] of cap) tris.push([a, c, b], [12 + a, 12 + b, 12 + c]);
  for (let i = 0; i < 12; i++) {
    const j = (i + 1) % 12;
    tris.push([i, j, 12 + j], [i, 12 + j, 12 + i]);
  }
  const buf = Buffer.alloc(84 + 50 * tris.length);
  buf.writeUInt32LE(tris.length, 80);
  tris.forEach((t, k) =>
    t.forEach((v, c) => p[v].forEach((x, d) => buf.writeFloatLE(x, 84 + 50 * k + 12 + 12 * c + 4 * d))),
  );
  return buf;
}

/** A 1×2×3 box in a node scaled ×2 along x (world volume 12), under a translated group. */
export function scaledBoxScene() {
  const scene = new THREE.Scene();
  const group = new THREE.Group();
  group.position.set(5, -3, 2);
  const box = new THREE.Mesh(new THREE.BoxGeometry(1, 2, 3), new THREE.MeshBasicMaterial());
  box.scale.set(2, 1, 1);
  group.add(box);
  scene.add(group);
  return { scene, box };
}

// Node has Blob but no FileReader, which GLTFExporter uses to assemble a GLB.
class BlobFileReader {
  readAsArrayBuffer(blob) {
    blob.arrayBuffer().then((buffer) => {
      this.result = buffer;
      this.onloadend?.();
    });
  }
}

/** The object written as GLB bytes (an ArrayBuffer) by three.js's GLTFExporter. */
export async function glbOf(object) {
  const saved = globalThis.FileReader;
  globalThis.FileReader = BlobFileReader;
  try {
    return await new GLTFExporter().parseAsync(object, { binary: true });
  } finally {
    globalThis.FileReader = saved;
  }
}
