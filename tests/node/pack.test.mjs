// `npm pack` produces a tarball with only the runtime files, and that tarball installs offline
// into an empty folder and computes a kernel from plain Node.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { execFileSync } from 'node:child_process';
import { assertBuilt, repoRoot } from './lib/env.mjs';

const npmEnv = {
  ...process.env,
  npm_config_audit: 'false',
  npm_config_fund: 'false',
  npm_config_update_notifier: 'false',
  npm_config_loglevel: 'error',
};
let tmp;
let packInfo;

before(() => {
  assertBuilt();
  tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'kergen-pack-'));
  const out = execFileSync('npm', ['pack', '--json', '--pack-destination', tmp], {
    cwd: repoRoot,
    encoding: 'utf8',
    env: npmEnv,
    stdio: ['ignore', 'pipe', 'pipe'],
  });
  packInfo = JSON.parse(out.slice(out.indexOf('[')))[0];
});

after(() => {
  if (tmp) fs.rmSync(tmp, { recursive: true, force: true });
});

test('the tarball holds the runtime files only', (t) => {
  const files = packInfo.files.map((f) => f.path).sort();
  t.diagnostic(
    `${packInfo.filename}: ${packInfo.size} B packed, ${packInfo.unpackedSize} B unpacked, ${files.length} files`,
  );
  for (const needed of [
    'package.json',
    'LICENSE',
    'dist/kergen.mjs',
    'dist/kergen.wasm',
    'wasm/index.js',
    'wasm/index.d.ts',
    'wasm/worker.js',
    'wasm/worker.d.ts',
    'wasm/kergen-worker.js',
    'wasm/step-batch.js',
    'wasm/errors.js',
    'wasm/three.js',
    'wasm/three.d.ts',
  ]) {
    assert.ok(files.includes(needed), `${needed} is packed`);
  }
  for (const f of files) {
    assert.ok(!/^(tests|core|cli|bench|web|scripts|build|node_modules)\//.test(f), `${f} should not be packed`);
    assert.ok(!/\.(cpp|h|hpp|txt|sh|off|stl)$/.test(f), `${f} should not be packed`);
  }
  const wasmEntry = packInfo.files.find((f) => f.path === 'dist/kergen.wasm');
  assert.equal(wasmEntry.size, fs.statSync(path.join(repoRoot, 'dist/kergen.wasm')).size);
});

test(
  'npm install <tarball> --offline into an empty folder, then compute a cube kernel from Node',
  { timeout: 120000 },
  () => {
    const app = path.join(tmp, 'app');
    fs.mkdirSync(app);
    fs.writeFileSync(
      path.join(app, 'package.json'),
      JSON.stringify({ name: 'kergen-smoke', version: '1.0.0', private: true, type: 'module' }),
    );
    execFileSync('npm', ['install', '--offline', path.join(tmp, packInfo.filename)], {
      cwd: app,
      encoding: 'utf8',
      env: npmEnv,
      stdio: ['ignore', 'pipe', 'pipe'],
    });
    assert.ok(fs.existsSync(path.join(app, 'node_modules/kergen-wasm/dist/kergen.wasm')));
    assert.ok(!fs.existsSync(path.join(app, 'node_modules/kergen-wasm/tests')));
    const script = `
    import { computeKernel, isStarShaped, KergenError } from 'kergen-wasm';
    import { KernelWorker } from 'kergen-wasm/worker';
    const wasmPath = import.meta.resolve('kergen-wasm/kergen.wasm');
    // A 2×3×4 box, 12 triangles, outward CCW.
    const s = [2, 3, 4];
    const positions = [];
    for (let i = 0; i < 8; i++) positions.push(i & 1 ? s[0] : 0, i & 2 ? s[1] : 0, i & 4 ? s[2] : 0);
    const quads = [[0,2,3,1],[4,5,7,6],[0,1,5,4],[2,6,7,3],[0,4,6,2],[1,3,7,5]];
    const indices = quads.flatMap(([a,b,c,d]) => [a,b,c,a,c,d]);
    const r = await computeKernel(new Float32Array(positions), new Uint32Array(indices));
    let code = null;
    try { await computeKernel(positions, indices.slice(0, 33)); } catch (e) { code = e instanceof KergenError ? e.code : String(e); }
    // three is an optional peer, not installed here: only kergen-wasm/three needs it.
    let three = null;
    try { await import('kergen-wasm/three'); } catch (e) { three = e.code + ' ' + e.message; }
    console.log(JSON.stringify({ three, status: r.status, volume: r.volume, v: r.vertices.length / 3, f: r.faces.length,
      star: await isStarShaped(positions, indices), code, worker: typeof KernelWorker, wasmPath }));
  `;
    fs.writeFileSync(path.join(app, 'smoke.mjs'), script);
    const out = JSON.parse(execFileSync(process.execPath, ['smoke.mjs'], { cwd: app, encoding: 'utf8' }).trim());
    assert.equal(out.status, 'POLYHEDRON');
    assert.match(
      out.three,
      /^ERR_MODULE_NOT_FOUND .*'three'/,
      'the core and worker entries work without three; kergen-wasm/three asks for it',
    );
    assert.equal(out.volume, 24);
    assert.equal(out.v, 8);
    assert.equal(out.f, 6);
    assert.equal(out.star, true);
    assert.equal(out.code, 'OPEN_MESH');
    assert.equal(out.worker, 'function');
    assert.ok(out.wasmPath.endsWith('/node_modules/kergen-wasm/dist/kergen.wasm'), out.wasmPath);
  },
);
