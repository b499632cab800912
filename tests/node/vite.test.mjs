// Bundler check: a Vite 7 production build of an app that imports `kergen-wasm` and
// `kergen-wasm/worker` (through node_modules, as a user would) emits the module worker and the
// .wasm asset, the worker refers to the emitted .wasm, and nothing Node-only leaks into the bundle.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { assertBuilt, distWasm, repoRoot, viteUnsupported } from './lib/env.mjs';

let app;
before(() => {
  assertBuilt();
  app = fs.mkdtempSync(path.join(os.tmpdir(), 'kergen-vite-'));
  fs.mkdirSync(path.join(app, 'node_modules'));
  fs.symlinkSync(repoRoot, path.join(app, 'node_modules', 'kergen-wasm'), 'dir');
  fs.writeFileSync(path.join(app, 'index.html'), '<!doctype html><script type="module" src="./main.js"></script>');
  fs.writeFileSync(
    path.join(app, 'main.js'),
    `import { computeKernel } from 'kergen-wasm';
     import { KernelWorker } from 'kergen-wasm/worker';
     import wasmUrl from 'kergen-wasm/kergen.wasm?url';
     console.log(wasmUrl);
     const cube = [0,0,0, 1,0,0, 0,1,0, 1,1,0, 0,0,1, 1,0,1, 0,1,1, 1,1,1];
     const idx = [0,2,3,0,3,1, 4,5,7,4,7,6, 0,1,5,0,5,4, 2,6,7,2,7,3, 0,4,6,0,6,2, 1,3,7,1,7,5];
     const kw = new KernelWorker();
     Promise.all([computeKernel(cube, idx), kw.compute(cube, idx)]).then(([a, b]) => {
       document.title = a.status + ' ' + b.volume;
     });`,
  );
});
after(() => fs.rmSync(app, { recursive: true, force: true }));

test('vite build: worker chunk + hashed .wasm, no Node built-ins in the web bundle', { timeout: 120000 }, async (t) => {
  if (viteUnsupported()) return t.skip(viteUnsupported());
  let vite;
  try {
    vite = await import('vite');
  } catch {
    return t.skip('vite is not installed (npm ci)');
  }
  const warnings = [];
  const logger = vite.createLogger('warn', { allowClearScreen: false });
  const customLogger = {
    ...logger,
    warn: (msg) => warnings.push(msg),
    warnOnce: (msg) => warnings.push(msg),
    info() {},
  };
  await vite.build({
    root: app,
    logLevel: 'warn',
    customLogger,
    build: { outDir: 'dist', emptyOutDir: true },
    configFile: false,
  });

  const out = path.join(app, 'dist', 'assets');
  const files = fs.readdirSync(out);
  t.diagnostic(`emitted: ${files.join(', ')}`);
  const wasmFiles = files.filter((f) => f.endsWith('.wasm'));
  assert.equal(wasmFiles.length, 1, 'one .wasm asset');
  assert.ok(
    fs.readFileSync(path.join(out, wasmFiles[0])).equals(fs.readFileSync(distWasm)),
    'the emitted .wasm is the package binary',
  );
  const workerFiles = files.filter((f) => /^kergen-worker.*\.js$/.test(f));
  assert.equal(workerFiles.length, 1, 'the module worker is emitted as its own chunk');
  const workerCode = fs.readFileSync(path.join(out, workerFiles[0]), 'utf8');
  assert.ok(workerCode.includes(wasmFiles[0]), 'the worker locates the emitted .wasm');
  const mainFiles = files.filter((f) => f.endsWith('.js') && !workerFiles.includes(f));
  const allJs = [...mainFiles, ...workerFiles].map((f) => fs.readFileSync(path.join(out, f), 'utf8')).join('\n');
  assert.ok(allJs.includes(workerFiles[0]), 'the main bundle spawns the worker chunk');
  const mainJs = mainFiles.map((f) => fs.readFileSync(path.join(out, f), 'utf8')).join('\n');
  assert.ok(
    mainJs.includes(wasmFiles[0]),
    "the 'kergen-wasm/kergen.wasm?url' import builds and names the same single asset",
  );
  assert.ok(!allJs.includes('__vite-browser-external'), 'no Node built-in was pulled into the web bundle');
  assert.deepEqual(
    warnings.filter((w) => /externalized|node:|Critical/i.test(w)),
    [],
    'no bundler warnings about Node modules',
  );
});
