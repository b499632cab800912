// kergen-wasm/three — the kernel of a three.js BufferGeometry, and the kernel as geometries to draw.
//
//   import { computeKernelOfGeometry, kernelToGeometry, KernelWorker } from 'kergen-wasm/three';
//   const kernel = await new KernelWorker().computeGeometry(geometry);   // or computeKernelOfGeometry
//   const ofScene = await new KernelWorker().computeObject(gltf.scene);  // or computeKernelOfObject
//   const { mesh, edges } = kernelToGeometry(kernel);
//   scene.add(new THREE.Mesh(mesh, material), new THREE.LineSegments(edges, lineMaterial));
//
// The geometry is read, never modified: its position attribute (any typed array, normalized or
// interleaved) and index (Uint8/16/32, or none) are copied into fresh Float64Array/Uint32Array,
// so nothing of the caller's is transferred or detached. three.js is an optional peer dependency:
// only this entry imports it.
import { BufferAttribute, BufferGeometry, Matrix4, Vector3 } from 'three';
import { computeKernel, KergenError } from './index.js';
import { KernelWorker as PlainKernelWorker } from './worker.js';

export { KergenError };

// three.js geometries duplicate vertices along UV seams and at poles (SphereGeometry,
// TorusKnotGeometry), per face (BoxGeometry) or per triangle (STLLoader, OBJLoader): as triangles
// they are a closed surface only once equal positions are welded, so this path welds by default
// (the core's weld: 1e-9 of the bounding box diagonal). `weld: false` turns it off.
const GEOMETRY_DEFAULTS = { weld: true };

const invalid = (fn, what) => new KergenError('INVALID_ARGUMENT', `${fn}: ${what}`);

// Typed arrays whose values are vertex ids as they are (no sign, no fraction to check).
const isUintArray = (a) => a instanceof Uint32Array || a instanceof Uint16Array || a instanceof Uint8Array;

/** Positions (fresh Float64Array, flat x, y, z) of a geometry's 'position' attribute. */
function readPositions(fn, geometry) {
  const attr = geometry.attributes ? geometry.attributes.position : undefined;
  if (!attr || typeof attr.getX !== 'function') {
    throw invalid(fn, "the geometry has no 'position' attribute");
  }
  if (attr.itemSize < 3)
    throw invalid(fn, `the 'position' attribute has itemSize ${attr.itemSize}; a 3D mesh needs x, y, z`);
  const n = attr.count;
  const out = new Float64Array(3 * n);
  const plain = !attr.isInterleavedBufferAttribute && !attr.normalized && attr.itemSize === 3;
  if (plain && (attr.array instanceof Float32Array || attr.array instanceof Float64Array)) {
    out.set(attr.array.subarray(0, 3 * n)); // Float32 → Float64 is exact
  } else {
    // getX/getY/getZ follow the interleaving stride and undo normalization (Int16 positions).
    for (let i = 0; i < n; i++) {
      out[3 * i] = attr.getX(i);
      out[3 * i + 1] = attr.getY(i);
      out[3 * i + 2] = attr.getZ(i);
    }
  }
  return out;
}

/** Triangle vertex ids (fresh Uint32Array): the index, or 0 .. n-1 for a non-indexed geometry. */
function readIndices(fn, geometry, numVertices) {
  const index = geometry.index;
  if (index == null) {
    if (numVertices % 3 !== 0) {
      throw invalid(fn, `a non-indexed geometry needs 3 vertices per triangle, but this one has ${numVertices}`);
    }
    const out = new Uint32Array(numVertices);
    for (let i = 0; i < numVertices; i++) out[i] = i;
    return out;
  }
  const n = index.count;
  const out = new Uint32Array(n);
  if (!index.isInterleavedBufferAttribute && isUintArray(index.array)) {
    out.set(index.array.subarray(0, n));
    return out;
  }
  for (let i = 0; i < n; i++) {
    const v = index.getX(i);
    if (!Number.isInteger(v) || v < 0)
      throw new KergenError('INDEX_OUT_OF_RANGE', `${fn}: index ${i} is ${v}, not a vertex id`);
    out[i] = v;
  }
  return out;
}

/**
 * The triangle mesh of a BufferGeometry as fresh arrays `{ positions: Float64Array, indices:
 * Uint32Array }` (groups, draw range and the other attributes are ignored). The geometry is not
 * modified and none of its arrays is shared with the result.
 */
export function geometryToMesh(geometry) {
  return meshOf('geometryToMesh', geometry);
}

function meshOf(fn, geometry) {
  if (geometry === null || typeof geometry !== 'object' || typeof geometry.attributes !== 'object') {
    throw invalid(fn, 'geometry must be a three.js BufferGeometry');
  }
  const positions = readPositions(fn, geometry);
  const indices = readIndices(fn, geometry, positions.length / 3);
  return { positions, indices };
}

function geometryOptions(fn, options) {
  if (options == null) return { ...GEOMETRY_DEFAULTS };
  if (typeof options !== 'object') throw invalid(fn, 'options must be an object');
  if (options.faceSizes != null)
    throw invalid(fn, 'options.faceSizes does not apply: a BufferGeometry is made of triangles');
  return { ...GEOMETRY_DEFAULTS, ...options };
}

// One mesh's triangles written into the merged arrays at `at` ({ vertex, index }), its corners
// moved by `matrix` (the mesh's world matrix, times an instance's matrix for an InstancedMesh). A
// mirroring matrix (negative determinant) turns the faces inside out, so two corners of each
// triangle are swapped back.
function writeTransformed(merged, at, mesh, matrix) {
  const flip = matrix.determinant() < 0;
  const p = new Vector3();
  const src = mesh.positions;
  for (let i = 0; i < src.length; i += 3) {
    p.set(src[i], src[i + 1], src[i + 2]).applyMatrix4(matrix);
    const o = 3 * at.vertex + i;
    merged.positions[o] = p.x;
    merged.positions[o + 1] = p.y;
    merged.positions[o + 2] = p.z;
  }
  const ids = mesh.indices;
  const numIds = ids.length - (ids.length % 3);
  for (let t = 0; t < numIds; t += 3) {
    merged.indices[at.index++] = at.vertex + ids[t];
    merged.indices[at.index++] = at.vertex + ids[t + (flip ? 2 : 1)];
    merged.indices[at.index++] = at.vertex + ids[t + (flip ? 1 : 2)];
  }
  at.vertex += src.length / 3;
}

/**
 * Every triangle mesh under `object` (itself included: THREE.Mesh, SkinnedMesh in its bind pose,
 * InstancedMesh once per instance; visible or not; meshes without positions skipped), in world
 * coordinates, merged into fresh arrays `{ positions: Float64Array, indices: Uint32Array, meshes }`.
 * Lines and points are not surfaces and are skipped. World matrices are brought up to date first
 * (updateWorldMatrix), as three.js does before rendering; nothing else of the scene is modified.
 */
export function objectToMesh(object) {
  return mergedMeshOf('objectToMesh', object);
}

function mergedMeshOf(fn, object) {
  if (object === null || typeof object !== 'object' || typeof object.traverse !== 'function') {
    throw invalid(fn, 'object must be a three.js Object3D (a Mesh, Group, Scene, ...)');
  }
  object.updateWorldMatrix(true, true);
  const parts = []; // [mesh arrays, three.js Mesh, copies (instances)]
  let numVertices = 0;
  let numIndices = 0;
  object.traverse((node) => {
    if (!node.isMesh || !node.geometry?.attributes?.position) return; // e.g. an empty placeholder
    const mesh = meshOf(fn, node.geometry);
    const copies = node.isInstancedMesh ? node.count : 1;
    parts.push([mesh, node, copies]);
    numVertices += copies * (mesh.positions.length / 3);
    numIndices += copies * (mesh.indices.length - (mesh.indices.length % 3));
  });
  if (numIndices === 0) {
    throw new KergenError('EMPTY_INPUT', `${fn}: there is no triangle mesh under the object`);
  }
  const merged = { positions: new Float64Array(3 * numVertices), indices: new Uint32Array(numIndices) };
  const at = { vertex: 0, index: 0 };
  const instanceMatrix = new Matrix4();
  const matrix = new Matrix4();
  for (const [mesh, node, copies] of parts) {
    if (!node.isInstancedMesh) {
      writeTransformed(merged, at, mesh, node.matrixWorld);
      continue;
    }
    for (let i = 0; i < copies; i++) {
      node.getMatrixAt(i, instanceMatrix);
      writeTransformed(merged, at, mesh, matrix.multiplyMatrices(node.matrixWorld, instanceMatrix));
    }
  }
  return { ...merged, meshes: parts.length };
}

/**
 * The kernel of every mesh under a three.js object (a glTF scene, a Group), in world coordinates,
 * merged into one surface, computed on this thread (options as computeKernel; weld on: meshes
 * that meet along seams become one closed surface).
 */
export async function computeKernelOfObject(object, options) {
  const fn = 'computeKernelOfObject';
  const opts = geometryOptions(fn, options);
  const { positions, indices } = mergedMeshOf(fn, object);
  return computeKernel(positions, indices, opts);
}

/** The kernel of a BufferGeometry, computed on this thread (options as computeKernel; weld on). */
export async function computeKernelOfGeometry(geometry, options) {
  const fn = 'computeKernelOfGeometry';
  const opts = geometryOptions(fn, options);
  const { positions, indices } = meshOf(fn, geometry);
  return computeKernel(positions, indices, opts);
}

/** KernelWorker (kergen-wasm/worker) that also takes a BufferGeometry. */
export class KernelWorker extends PlainKernelWorker {
  /**
   * The kernel of a BufferGeometry, computed in the worker (options as compute; weld on). The
   * geometry's arrays are copied here, and only the copies are transferred.
   */
  computeGeometry(geometry, options) {
    const fn = 'computeGeometry';
    let mesh;
    let opts;
    try {
      opts = geometryOptions(fn, options);
      mesh = meshOf(fn, geometry);
    } catch (err) {
      return Promise.reject(err);
    }
    delete opts.copy;
    return this.compute(mesh.positions, mesh.indices, { ...opts, transfer: true });
  }

  /**
   * The kernel of every mesh under a three.js object (world coordinates, merged; see
   * computeKernelOfObject), computed in the worker. The merge is done here; only the merged
   * arrays, fresh copies, are transferred.
   */
  computeObject(object, options) {
    const fn = 'computeObject';
    let mesh;
    let opts;
    try {
      opts = geometryOptions(fn, options);
      mesh = mergedMeshOf(fn, object);
    } catch (err) {
      return Promise.reject(err);
    }
    delete opts.copy;
    return this.compute(mesh.positions, mesh.indices, { ...opts, transfer: true });
  }
}

// Unit normal of a convex polygon (Newell's method: robust for any loop of >= 3 corners).
function polygonNormal(v, loop) {
  let nx = 0;
  let ny = 0;
  let nz = 0;
  for (let i = 0; i < loop.length; i++) {
    const a = 3 * loop[i];
    const b = 3 * loop[(i + 1) % loop.length];
    nx += (v[a + 1] - v[b + 1]) * (v[a + 2] + v[b + 2]);
    ny += (v[a + 2] - v[b + 2]) * (v[a] + v[b]);
    nz += (v[a] - v[b]) * (v[a + 1] + v[b + 1]);
  }
  const len = Math.hypot(nx, ny, nz) || 1;
  return [nx / len, ny / len, nz / len];
}

// The kernel's faces as a flat-shaded triangle geometry: each face gets its own copies of its
// corners, so that each corner carries the normal of its face.
function facesGeometry(result) {
  const { vertices, faceIndices, faceSizes } = result;
  let numTriangles = 0;
  for (let f = 0; f < faceSizes.length; f++) numTriangles += Math.max(faceSizes[f] - 2, 0);
  const positions = new Float32Array(3 * faceIndices.length);
  const normals = new Float32Array(3 * faceIndices.length);
  const index = new Uint32Array(3 * numTriangles);
  let t = 0;
  for (let f = 0, at = 0; f < faceSizes.length; at += faceSizes[f], f++) {
    const loop = faceIndices.subarray(at, at + faceSizes[f]);
    const normal = polygonNormal(vertices, loop);
    for (let i = 0; i < loop.length; i++) {
      positions.set(vertices.subarray(3 * loop[i], 3 * loop[i] + 3), 3 * (at + i));
      normals.set(normal, 3 * (at + i));
    }
    for (let i = 1; i + 1 < loop.length; i++) index.set([at, at + i, at + i + 1], 3 * t++); // a fan: faces are convex
  }
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(positions, 3));
  geometry.setAttribute('normal', new BufferAttribute(normals, 3));
  geometry.setIndex(new BufferAttribute(index, 1));
  return geometry;
}

/**
 * A kernel result as three.js geometries: `mesh` (the convex faces, triangulated, flat normals:
 * corners duplicated per face; for THREE.Mesh) and `edges` (the kernel's edges: the vertices and
 * the edge pairs as index; for THREE.LineSegments). Coordinates are converted to float32, as the
 * GPU takes them. A point, segment or empty kernel gives an empty `mesh`.
 */
export function kernelToGeometry(result) {
  const fn = 'kernelToGeometry';
  if (
    result === null ||
    typeof result !== 'object' ||
    !(result.vertices instanceof Float64Array) ||
    !(result.edges instanceof Uint32Array) ||
    !(result.faceIndices instanceof Uint32Array) ||
    !(result.faceSizes instanceof Uint32Array)
  ) {
    throw invalid(fn, 'result must be a kernel result (computeKernel, KernelWorker.compute)');
  }
  const edges = new BufferGeometry();
  edges.setAttribute('position', new BufferAttribute(new Float32Array(result.vertices), 3));
  edges.setIndex(new BufferAttribute(new Uint32Array(result.edges), 1));
  return { mesh: facesGeometry(result), edges };
}
