// GLB / glTF input, read with three.js's GLTFLoader (the one reader the page does not take from
// the package: glTF is a scene format, not a mesh file the core reads). Every triangle mesh of
// the default scene is merged in world space (node transforms applied) into one triangle soup;
// the package then welds it (weld: true), as it welds an STL.
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { Vector3 } from 'three';

export const isGltfName = (name) => /\.(glb|gltf)$/i.test(name);

// The buffer and image URIs of a JSON glTF that are not embedded (data:): the loader would fetch
// them relative to the page, which cannot work for a file opened from disk. (GLB: none checked;
// its buffer is in the file.)
function externalUris(bytes) {
  const head = new Uint8Array(bytes, 0, Math.min(4, bytes.byteLength));
  if (String.fromCharCode(...head) === 'glTF') return [];
  let json;
  try {
    json = JSON.parse(new TextDecoder().decode(bytes));
  } catch {
    return []; // the loader says what is wrong
  }
  return [...(json.buffers ?? []), ...(json.images ?? [])]
    .map((b) => b?.uri)
    .filter((u) => typeof u === 'string' && !u.startsWith('data:'));
}

/**
 * Parses GLB or glTF bytes; returns { positions: Float64Array, indices: Uint32Array, meshes }.
 * Rejects with a message that says what is wrong: unreadable data, external files a single
 * .gltf cannot bring along, or no triangles at all.
 */
export async function readGltf(bytes, name) {
  const external = externalUris(bytes);
  if (external.length) {
    throw new Error(
      `${name}: the glTF file refers to files beside it (${external.slice(0, 3).join(', ')}), which a single opened file does not bring along; use a .glb or a .gltf with embedded data`,
    );
  }
  let gltf;
  try {
    gltf = await new GLTFLoader().parseAsync(bytes, '');
  } catch (err) {
    throw new Error(`${name}: not a readable glTF/GLB file (${err?.message ?? err})`);
  }
  const scene = gltf.scene ?? gltf.scenes?.[0];
  if (!scene) throw new Error(`${name}: the file has no scene`);
  scene.updateMatrixWorld(true);
  const parts = [];
  let nv = 0,
    ni = 0;
  scene.traverse((o) => {
    // Meshes only (the loader turns strips and fans into triangle lists); points and lines are
    // not surfaces.
    const g = o.isMesh && o.geometry;
    if (!g || !g.attributes.position) return;
    const count = g.index ? g.index.count : g.attributes.position.count;
    if (count < 3) return;
    parts.push(o);
    nv += g.attributes.position.count;
    ni += count - (count % 3);
  });
  if (!parts.length) throw new Error(`${name}: the scene has no triangle mesh`);
  const positions = new Float64Array(3 * nv);
  const indices = new Uint32Array(ni);
  const p = new Vector3();
  let vBase = 0,
    iAt = 0;
  for (const mesh of parts) {
    const g = mesh.geometry,
      pos = g.attributes.position;
    for (let i = 0; i < pos.count; i++) {
      p.fromBufferAttribute(pos, i).applyMatrix4(mesh.matrixWorld);
      positions.set([p.x, p.y, p.z], 3 * (vBase + i));
    }
    const count = g.index ? g.index.count : pos.count;
    // A mirroring transform (negative determinant) turns the faces inside out: swap two corners.
    const flip = mesh.matrixWorld.determinant() < 0;
    for (let t = 0; t + 2 < count; t += 3) {
      const corner = (k) => vBase + (g.index ? g.index.getX(t + k) : t + k);
      indices[iAt++] = corner(0);
      indices[iAt++] = corner(flip ? 2 : 1);
      indices[iAt++] = corner(flip ? 1 : 2);
    }
    vBase += pos.count;
  }
  return { positions, indices, meshes: parts.length };
}
