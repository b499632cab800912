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

/**
 * Writes the README's smallest three.js app (the code block between the three-readme-app markers
 * of `readme`) into `dir`: index.html + main.js. It loads `shape.stl` next to the page.
 */
export function writeReadmeApp(dir, readme) {
  const text = fs.readFileSync(readme, 'utf8');
  const block = /<!-- three-readme-app:begin -->\s*```js\n([\s\S]*?)```\s*<!-- three-readme-app:end -->/.exec(text);
  if (!block) throw new Error(`${readme} has no three-readme-app code block`);
  fs.writeFileSync(
    path.join(dir, 'index.html'),
    '<!doctype html><link rel="icon" href="data:,"><body style="margin:0"><script type="module" src="./main.js"></script></body>\n',
  );
  fs.writeFileSync(path.join(dir, 'main.js'), block[1]);
  return block[1];
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

/**
 * A plus-shaped prism (arms of width 1 reaching to ±1.5, z in [-0.5, 0.5]) as triangles, CCW seen
 * from outside: its kernel is the central unit cube, around the origin (the view's centre).
 */
export function plusPrism() {
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
  const positions = [];
  for (const z of [-0.5, 0.5]) for (const [x, y] of plus) positions.push(x, y, z);
  // The cap: the central square and the four arms, each as two CCW triangles (no T-junction).
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
  const indices = [];
  for (const [a, b, c] of cap) indices.push(a, c, b, 12 + a, 12 + b, 12 + c);
  for (let i = 0; i < 12; i++) {
    const j = (i + 1) % 12;
    indices.push(i, j, 12 + j, i, 12 + j, 12 + i);
  }
  return { positions: new Float64Array(positions), indices: new Uint32Array(indices) };
}
