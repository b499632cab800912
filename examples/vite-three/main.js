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

// The file as a three.js object: STL and OBJ give meshes, a GLB a whole scene.
async function load(file) {
  const bytes = await file.arrayBuffer();
  if (/\.stl$/i.test(file.name)) return new THREE.Mesh(new STLLoader().parse(bytes));
  if (/\.obj$/i.test(file.name)) return new OBJLoader().parse(new TextDecoder().decode(bytes));
  return (await new GLTFLoader().parseAsync(bytes, '')).scene;
}

document.querySelector('input').onchange = async (event) => {
  try {
    const shape = await load(event.target.files[0]);
    const kernel = await worker.computeObject(shape); // every mesh, world transforms applied
    const { mesh, edges } = kernelToGeometry(kernel);
    const glass = new THREE.MeshBasicMaterial({
      color: 'steelblue',
      transparent: true,
      opacity: 0.25,
      depthWrite: false,
    });
    shape.traverse((o) => o.isMesh && (o.material = glass));
    shown.clear(); // (a long-running app would also dispose the old geometries)
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
