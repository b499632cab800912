import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { STLLoader } from 'three/addons/loaders/STLLoader.js';
import { OBJLoader } from 'three/addons/loaders/OBJLoader.js';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { KernelWorker, kernelToGeometry } from 'kergen-wasm/three';

const renderer = new THREE.WebGLRenderer({ antialias: true });
renderer.setSize(innerWidth, innerHeight);
document.body.append(renderer.domElement);
const scene = new THREE.Scene();
scene.add(new THREE.HemisphereLight(0xffffff, 0x444444, 3));
const camera = new THREE.PerspectiveCamera(45, innerWidth / innerHeight, 0.01, 1000);
const controls = new OrbitControls(camera, renderer.domElement);
renderer.setAnimationLoop(() => renderer.render(scene, camera));
const shown = new THREE.Group(); // the shape and its kernel, replaced by the next file's
scene.add(shown);
const output = document.querySelector('output');
const worker = new KernelWorker();

// A mesh as the package's readers give it (polygons, faceSizes) as a three.js mesh: fan triangles.
function meshObject({ positions, indices, faceSizes }) {
  const triangles = [];
  let at = 0;
  for (const n of faceSizes ?? Array(indices.length / 3).fill(3)) {
    for (let i = 1; i + 1 < n; i++) triangles.push(indices[at], indices[at + i], indices[at + i + 1]);
    at += n;
  }
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(Float32Array.from(positions), 3));
  geometry.setIndex(triangles);
  return new THREE.Mesh(geometry);
}

// The file as a three.js object and its kernel. STL, OBJ and glTF (.glb, or a .gltf with its
// buffers embedded) through three.js's loaders, the kernel computed in the worker from the
// object; any other file (OFF, PLY, ...) read by the package's own readers, in the worker.
async function shapeAndKernel(file) {
  const bytes = await file.arrayBuffer();
  const name = file.name.toLowerCase();
  let shape;
  if (name.endsWith('.stl')) shape = new THREE.Mesh(new STLLoader().parse(bytes));
  else if (name.endsWith('.obj')) shape = new OBJLoader().parse(new TextDecoder().decode(bytes));
  else if (name.endsWith('.glb') || name.endsWith('.gltf'))
    shape = (await new GLTFLoader().parseAsync(bytes, '')).scene;
  else {
    const { mesh, result } = await worker.computeFile(bytes, { name: file.name });
    return { shape: meshObject(mesh), kernel: result };
  }
  const kernel = await worker.computeObject(shape); // every mesh, world transforms applied
  return { shape, kernel };
}

// The last file's shape and kernel go as the next file comes: a file that fails leaves nothing.
function clearShown() {
  shown.traverse((o) => o.geometry?.dispose());
  shown.clear();
}

document.querySelector('input').onchange = async (event) => {
  const file = event.target.files[0];
  clearShown();
  output.textContent = `Reading ${file.name}…`;
  try {
    const { shape, kernel } = await shapeAndKernel(file);
    const { mesh, edges } = kernelToGeometry(kernel);
    const glass = new THREE.MeshBasicMaterial({
      color: 'steelblue',
      transparent: true,
      opacity: 0.25,
      depthWrite: false,
    });
    shape.traverse((o) => o.isMesh && (o.material = glass));
    const kernelMesh = new THREE.Mesh(mesh, new THREE.MeshStandardMaterial({ color: 'orange' }));
    shown.add(shape, kernelMesh, new THREE.LineSegments(edges));
    const { center, radius } = new THREE.Box3().setFromObject(shape).getBoundingSphere(new THREE.Sphere());
    camera.position.copy(center).add(new THREE.Vector3(radius, radius, 2.5 * radius));
    controls.target.copy(center);
    controls.update();
    output.textContent = `${kernel.status}, volume ${kernel.volume} of ${kernel.shapeVolume}`;
  } catch (err) {
    output.textContent = `${err.code ?? 'ERROR'}: ${err.message}`; // a KergenError has a .code
  }
};
