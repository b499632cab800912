// GLB / glTF input, read with three.js's GLTFLoader (the one reader the page does not take from
// the package: glTF is a scene format, not a mesh file the core reads). Every triangle mesh of
// the default scene is merged in world space (node transforms applied) into one triangle soup by
// kergen-wasm/three's objectToMesh; the package then welds it (weld: true), as it welds an STL.
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { objectToMesh } from 'kergen-wasm/three';

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
  // Every mesh of the scene in world space (node transforms applied, mirrored nodes kept
  // outward), merged by the package: the same merge computeKernelOfObject makes.
  try {
    return objectToMesh(scene);
  } catch (err) {
    if (err?.code === 'EMPTY_INPUT') throw new Error(`${name}: the scene has no triangle mesh`);
    throw err;
  }
}
