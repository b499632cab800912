// Browser test of a fresh three.js app using the package (tests/e2e/three-app.mjs). Called by run.mjs.
import fs from 'node:fs';
import path from 'node:path';
import { writeThreeApp, runThreeApp } from './three-app.mjs';
import { test, assert, repo } from './harness.mjs';

// A fresh three.js app (tests/e2e/three-app.mjs) built with Vite against the package: the input
// mesh still renders after KernelWorker computed its kernel (its arrays were copied, not
// detached), no GL error, the kernel drawn, and a wrong wasmUrl reported with its HTTP status.
export async function threeAppTest(context, tmp) {
  await test('three.js app: the input mesh renders after the worker call, the kernel is drawn, a 404 wasmUrl says HTTP 404', async () => {
    const app = path.join(tmp, 'three-app');
    fs.mkdirSync(path.join(app, 'node_modules'), { recursive: true });
    fs.symlinkSync(repo, path.join(app, 'node_modules', 'kergen-wasm'), 'dir');
    fs.symlinkSync(path.join(repo, 'node_modules', 'three'), path.join(app, 'node_modules', 'three'), 'dir');
    writeThreeApp(app);
    const vite = await import('vite');
    await vite.build({
      root: app,
      logLevel: 'warn',
      configFile: false,
      build: { outDir: 'dist', emptyOutDir: true, chunkSizeWarningLimit: 4000 },
    });
    const r = await runThreeApp(context, path.join(app, 'dist'));
    assert(!r.error, `the app failed: ${r.error}`);
    assert(r.errors.length === 0, r.errors.join(' | '));
    assert(r.before[0] > 200 && r.before[1] < 50, `the red sphere is drawn before the call: ${r.before}`);
    assert(
      JSON.stringify(r.after) === JSON.stringify(r.before),
      `the same pixel after the worker calls: ${r.after} vs ${r.before}`,
    );
    assert(r.glErrorAfterInput === 0 && r.glError === 0, `GL errors ${r.glErrorAfterInput}, ${r.glError}`);
    assert(
      r.sameArrays && r.lengths[0] === 3 * 33 * 17 && r.lengths[1] > 0,
      `the geometry keeps its arrays: ${r.lengths}`,
    );
    assert(r.status === 'POLYHEDRON' && r.rawStatus === 'POLYHEDRON', `statuses ${r.status}, ${r.rawStatus}`);
    assert(
      Math.abs(r.volume - r.rawVolume) <= 1e-12 * r.volume && r.volume > 3.9 && r.volume < 4.19,
      `volumes ${r.volume}, ${r.rawVolume}`,
    );
    assert(
      r.kernelPixel[1] > 200 && r.kernelPixel[0] < 50 && r.kernelTriangles > 100 && r.kernelEdges > 100,
      `the kernel is drawn: ${r.kernelPixel}`,
    );
    assert(
      /^WASM_LOAD_FAILED: .*\/no-such-dir\/kergen\.wasm: HTTP 404/.test(r.wasm404 ?? ''),
      `404 message: ${r.wasm404}`,
    );
  });

  await test('three.js app under the Vite dev server: without the exclude the worker fails once (no restart loop), with it the app works', async () => {
    // The package copied (not linked) into node_modules, as npm installs it, so that the dev
    // server pre-bundles it as it would in a user's project.
    const app = path.join(tmp, 'three-dev');
    const pkg = path.join(app, 'node_modules', 'kergen-wasm');
    fs.mkdirSync(pkg, { recursive: true });
    for (const f of ['package.json', 'wasm', 'dist'])
      fs.cpSync(path.join(repo, f), path.join(pkg, f), { recursive: true });
    fs.symlinkSync(path.join(repo, 'node_modules', 'three'), path.join(app, 'node_modules', 'three'), 'dir');
    writeThreeApp(app);
    const vite = await import('vite');
    for (const exclude of [false, true]) {
      const server = await vite.createServer({
        root: app,
        configFile: false,
        logLevel: 'silent',
        clearScreen: false,
        optimizeDeps: exclude ? { exclude: ['kergen-wasm'] } : {},
        server: { host: '127.0.0.1', port: 0, strictPort: false },
      });
      await server.listen();
      const page = await context.newPage();
      const workerLoads = [];
      page.on('request', (r) => /kergen-worker/.test(r.url()) && workerLoads.push(r.url()));
      try {
        await page.goto(server.resolvedUrls.local[0]);
        await page.waitForFunction(() => document.title === 'done', null, { timeout: 60000 });
        const r = await page.evaluate(() => window.__result);
        await new Promise((res) => setTimeout(res, 2000)); // time for a restart loop to show
        if (!exclude) {
          assert(
            /WORKER_ERROR|failed to start/.test(r.error ?? '') && /optimizeDeps\.exclude/.test(r.error),
            `the call fails with the hint: ${r.error ?? JSON.stringify(r)}`,
          );
          assert(workerLoads.length === 1, `one worker load, no restart loop: ${workerLoads.length} loads`);
        } else {
          assert(!r.error && r.status === 'POLYHEDRON', `with the exclude the app works: ${r.error ?? r.status}`);
          assert(JSON.stringify(r.after) === JSON.stringify(r.before), 'the input still renders');
        }
      } finally {
        await page.close();
        await server.close();
      }
    }
  });
}
