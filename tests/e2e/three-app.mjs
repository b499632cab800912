// A fresh three.js app that uses `kergen-wasm/three` as a web developer would: draws a
// SphereGeometry, computes its kernel in a KernelWorker (from the geometry, and from the
// geometry's own attribute arrays: the trap of copying vs. transferring), draws the input again
// and the kernel, and reports pixels, GL errors and results in `window.__result`.
// Used by tests/node/vite-three.test.mjs (built with Vite 7 from the packed tarball and with the
// current Vite) and by run.mjs (built, served and run in Chromium).
import fs from 'node:fs';
import path from 'node:path';

const MAIN_JS = `
import * as THREE from 'three';
import { KernelWorker, kernelToGeometry } from 'kergen-wasm/three';
import { init } from 'kergen-wasm';

const canvas = document.querySelector('canvas');
const renderer = new THREE.WebGLRenderer({ canvas, preserveDrawingBuffer: true });
renderer.setSize(200, 200, false);
const camera = new THREE.PerspectiveCamera(45, 1, 0.1, 100);
camera.position.set(0, 0, 5);
const gl = renderer.getContext();
const pixel = () => {
  const p = new Uint8Array(4);
  gl.readPixels(100, 100, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, p);
  return Array.from(p);
};
const draw = (object) => {
  const scene = new THREE.Scene();
  scene.add(object);
  renderer.render(scene, camera);
  return pixel();
};

async function main() {
  const geometry = new THREE.SphereGeometry(1, 32, 16);
  const input = new THREE.Mesh(geometry, new THREE.MeshBasicMaterial({ color: 0xff0000 }));
  const before = draw(input);
  const positions = geometry.attributes.position.array;
  const index = geometry.index.array;
  const kw = new KernelWorker();
  const kernel = await kw.computeGeometry(geometry);
  const raw = await kw.compute(positions, index, { weld: true });
  const after = draw(input);
  const glErrorAfterInput = gl.getError();
  const { mesh, edges } = kernelToGeometry(kernel);
  const group = new THREE.Group();
  group.add(new THREE.Mesh(mesh, new THREE.MeshBasicMaterial({ color: 0x00ff00 })), new THREE.LineSegments(edges));
  const kernelPixel = draw(group);
  let wasm404 = null;
  try {
    await init({ wasmUrl: '/no-such-dir/kergen.wasm' });
  } catch (err) {
    wasm404 = err.code + ': ' + err.message;
  }
  kw.dispose();
  return {
    before, after, kernelPixel, glErrorAfterInput, glError: gl.getError(), wasm404,
    status: kernel.status, volume: kernel.volume, rawStatus: raw.status, rawVolume: raw.volume,
    sameArrays: geometry.attributes.position.array === positions && geometry.index.array === index,
    lengths: [positions.length, index.length], kernelTriangles: mesh.index.count / 3, kernelEdges: edges.index.count / 2,
  };
}

main().then(
  (r) => { window.__result = r; document.title = 'done'; },
  (err) => { window.__result = { error: String(err && err.stack || err) }; document.title = 'done'; },
);
`;

/** Writes the app (index.html, main.js) into `dir`. */
export function writeThreeApp(dir) {
  fs.writeFileSync(
    path.join(dir, 'index.html'),
    '<!doctype html><canvas width="200" height="200"></canvas><script type="module" src="./main.js"></script>\n',
  );
  fs.writeFileSync(path.join(dir, 'main.js'), MAIN_JS);
}

/** Runs the built app (`dist`) in a page of `context`; returns window.__result. */
export async function runThreeApp(context, dist) {
  const { serve } = await import('./page-tools.mjs'); // playwright-core: only where a browser runs
  const server = await serve(dist);
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(`pageerror: ${e.message}`));
  page.on('console', (m) => {
    // The 404 of the deliberately wrong wasmUrl is logged by the browser itself.
    if (m.type() === 'error' && !/404/.test(m.text())) errors.push(`console.error: ${m.text()}`);
  });
  try {
    await page.goto(`http://127.0.0.1:${server.address().port}/`);
    await page.waitForFunction(() => document.title === 'done', null, { timeout: 60000 });
    const result = await page.evaluate(() => window.__result);
    return { ...result, errors };
  } finally {
    await page.close();
    server.close();
  }
}
