// A fresh app using `kergen-wasm/three` + KernelWorker with a three.js geometry
// (tests/e2e/three-app.mjs; run in Chromium by the e2e tests), installed from the packed tarball
// and built with Vite 7 (the repository's) and with the current Vite from the npm registry (skipped
// with a message when the registry cannot be reached): the worker chunk, the one .wasm asset (the
// package's binary), three.js in the page bundle only, no Node built-in in any bundle.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { execFileSync } from 'node:child_process';
import { assertBuilt, distWasm, repoRoot, viteUnsupported } from './lib/env.mjs';
import { npmEnv, packTarball } from './lib/pack.mjs';
import { writeThreeApp } from '../e2e/three-app.mjs';

let tmp;
let tarball;

before(() => {
  assertBuilt();
  tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'kergen-vite-three-'));
  tarball = packTarball(tmp).tarball;
});
after(() => {
  if (tmp) fs.rmSync(tmp, { recursive: true, force: true });
});

// An app folder with the tarball installed (offline) and the given extra packages.
function newApp(name) {
  const app = path.join(tmp, name);
  fs.mkdirSync(app);
  fs.writeFileSync(
    path.join(app, 'package.json'),
    JSON.stringify({ name, version: '1.0.0', private: true, type: 'module' }),
  );
  execFileSync('npm', ['install', '--offline', tarball], { cwd: app, env: npmEnv, stdio: ['ignore', 'pipe', 'pipe'] });
  writeThreeApp(app);
  return app;
}

function checkBuild(t, app, label) {
  const out = path.join(app, 'dist', 'assets');
  const files = fs.readdirSync(out);
  t.diagnostic(`${label}: ${files.join(', ')}`);
  const wasmFiles = files.filter((f) => f.endsWith('.wasm'));
  assert.equal(wasmFiles.length, 1, 'one .wasm asset');
  assert.ok(fs.readFileSync(path.join(out, wasmFiles[0])).equals(fs.readFileSync(distWasm)), 'the package binary');
  const workerFiles = files.filter((f) => /^kergen-worker.*\.js$/.test(f));
  assert.equal(workerFiles.length, 1, 'the module worker chunk');
  const read = (f) => fs.readFileSync(path.join(out, f), 'utf8');
  const worker = read(workerFiles[0]);
  assert.ok(worker.includes(wasmFiles[0]), 'the worker locates the emitted .wasm');
  const page = files
    .filter((f) => f.endsWith('.js') && !workerFiles.includes(f))
    .map(read)
    .join('\n');
  assert.ok(page.includes(workerFiles[0]), 'the page spawns the worker chunk');
  assert.ok(
    page.includes('computeGeometry') && page.includes('WebGLRenderer'),
    'kergen-wasm/three and three.js are in the page bundle',
  );
  assert.ok(
    !worker.includes('WebGLRenderer') && worker.length < 200000,
    `three.js stays out of the worker (${worker.length} B)`,
  );
  assert.ok(!`${page}\n${worker}`.includes('__vite-browser-external'), 'no Node built-in in the bundles');
}

test("Vite 7 (the repository's) builds the app from the packed tarball", { timeout: 180000 }, async (t) => {
  if (viteUnsupported()) return t.skip(viteUnsupported());
  const app = newApp('app-vite7');
  fs.symlinkSync(path.join(repoRoot, 'node_modules', 'three'), path.join(app, 'node_modules', 'three'), 'dir');
  const vite = await import('vite');
  assert.match(vite.version, /^7\./);
  await vite.build({ root: app, logLevel: 'warn', configFile: false, build: { outDir: 'dist', emptyOutDir: true } });
  checkBuild(t, app, `vite ${vite.version}`);
});

test(
  'the current Vite (npm install vite@latest three) builds the same app from the tarball',
  { timeout: 300000 },
  (t) => {
    if (viteUnsupported()) return t.skip(viteUnsupported());
    const app = newApp('app-vite-latest');
    try {
      execFileSync('npm', ['install', '--no-save', 'vite@latest', 'three@0.187.0'], {
        cwd: app,
        env: npmEnv,
        stdio: ['ignore', 'pipe', 'pipe'],
        timeout: 240000,
      });
    } catch (err) {
      return t.skip(
        `the npm registry could not provide vite@latest: ${String(err.stderr || err.message).split('\n')[0]}`,
      );
    }
    const version = JSON.parse(fs.readFileSync(path.join(app, 'node_modules/vite/package.json'), 'utf8')).version;
    execFileSync(process.execPath, [path.join(app, 'node_modules/vite/bin/vite.js'), 'build', '--logLevel', 'warn'], {
      cwd: app,
      env: npmEnv,
      stdio: ['ignore', 'pipe', 'pipe'],
    });
    checkBuild(t, app, `vite ${version}`);
  },
);
