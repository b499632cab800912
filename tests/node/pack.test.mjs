// `npm pack` produces a tarball with only the runtime files and the package README, which
// publint, @arethetypeswrong/cli and `npm publish --dry-run` find clean, which stays under the
// size budget, and which installs offline into an empty folder and computes a kernel from plain
// Node. Packing leaves the work tree's README.md as it was.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { execFileSync, spawnSync } from 'node:child_process';
import { assertBuilt, repoRoot } from './lib/env.mjs';
import { extractTarball, npmEnv, packTarball } from './lib/pack.mjs';

let tmp;
let packInfo;

// bytes, packed (npm's "package size"): 350 kB, plus 50 kB for volume meshes (the .vtu / .vtk /
// .node + .ele readers, the per-cell kernels and their bindings) and the convex answer: kergen.wasm
// 699,808 -> 863,995 B raw, 266,860 -> 324,381 B gzip -9; 394,665 B packed. Plus 15 kB for the
// small-input path, the orient3d stage of side() and computeKernels' bindings: kergen.wasm
// 899,059 B raw, 338,313 B gzip -9; 412,952 B packed (with validation's vector lanes). (Measured instead: the readers and the
// volume code at -Os fit in 400 kB, 399,445 B, but read OFF/OBJ files 17-33 % slower in Node and
// binary STL 2-3x; with stl.cpp and numbers.cpp kept at -O3, 402,560 B and still 15-30 % slower.)
const SIZE_BUDGET = 415000;
let readmeBefore;

before(() => {
  assertBuilt();
  tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'kergen-pack-'));
  readmeBefore = fs.readFileSync(path.join(repoRoot, 'README.md'), 'utf8');
  packInfo = packTarball(tmp);
});

const bin = (name) => path.join(repoRoot, 'node_modules', '.bin', name);
// Runs a checker; returns { status, out } (stdout + stderr).
function run(cmd, args, cwd = tmp) {
  const r = spawnSync(cmd, args, { cwd, encoding: 'utf8', env: { ...npmEnv, NO_COLOR: '1', FORCE_COLOR: '0' } });
  return { status: r.status, out: `${r.stdout}${r.stderr}` };
}

test(`the packed size is within the budget (${SIZE_BUDGET} B)`, (t) => {
  t.diagnostic(`${packInfo.filename}: ${packInfo.size} B packed, ${packInfo.unpackedSize} B unpacked`);
  assert.ok(packInfo.size <= SIZE_BUDGET, `${packInfo.size} B packed > ${SIZE_BUDGET} B`);
});

test('publint (strict) finds nothing in the tarball', (t) => {
  const r = run(bin('publint'), ['run', packInfo.tarball, '--strict']);
  t.diagnostic(r.out.trim().split('\n').pop());
  assert.equal(r.status, 0, r.out);
  assert.match(r.out, /All good!/);
});

test('@arethetypeswrong/cli: every entry point resolves to its types (ESM-only profile)', (t) => {
  const major = Number(process.versions.node.split('.')[0]);
  if (major < 20)
    return t.skip(`@arethetypeswrong/cli needs Node >= 20 (this is ${process.version}); npm run test:node runs it`);
  // ESM only (`"type": "module"`, no require entry): the profile leaves out CommonJS resolution.
  // kergen.wasm is a binary asset exported for bundlers (`?url`), not a module with types.
  const r = run(bin('attw'), [
    packInfo.tarball,
    '--profile',
    'esm-only',
    '--exclude-entrypoints',
    'kergen.wasm',
    '--format',
    'ascii',
  ]);
  t.diagnostic(
    r.out
      .trim()
      .split('\n')
      .filter((l) => /"kergen-wasm/.test(l))
      .join('; '),
  );
  assert.equal(r.status, 0, r.out);
  assert.doesNotMatch(r.out, /💀|❌|Resolution failed/);
});

test('npm publish --dry-run --offline of the tarball is clean (no network, no login needed)', (t) => {
  const r = run('npm', ['publish', '--dry-run', '--offline', '--loglevel', 'notice', packInfo.tarball]);
  assert.equal(r.status, 0, r.out);
  assert.match(r.out, /\+ kergen-wasm@\d+\.\d+\.\d+/);
  // The one warning a dry run gives without `npm login` is that a real publish would need it.
  // (Under the oldest Node tested, npm itself also warns that it does not support that Node: a
  // remark on the npm CLI's runtime, not on the package.)
  const warnings = r.out
    .split('\n')
    .filter((l) => /npm (warn|error|ERR)/i.test(l) && !/npm warn cli npm v\S+ does not support Node\.js/.test(l));
  t.diagnostic(warnings.join(' | ') || 'no warnings');
  assert.ok(
    warnings.every((l) => /requires you to be logged in .*\(dry-run\)/.test(l)),
    `unexpected warnings: ${warnings.join(' | ')}`,
  );
});

// GitHub's heading anchors: lower case, punctuation dropped, spaces to hyphens.
const slug = (heading) =>
  heading
    .toLowerCase()
    .replace(/[^a-z0-9 _-]/g, '')
    .replace(/ /g, '-');

test("the tarball's README is the package README, every link of it resolves inside the tarball, and the work tree's README.md is unchanged", () => {
  const unpacked = path.join(tmp, 'unpacked');
  extractTarball(packInfo.tarball, unpacked);
  const pkgDir = path.join(unpacked, 'node_modules', 'kergen-wasm');
  const readme = fs.readFileSync(path.join(pkgDir, 'README.md'), 'utf8');
  assert.equal(readme, fs.readFileSync(path.join(repoRoot, 'wasm', 'README.md'), 'utf8'));
  assert.equal(
    fs.readFileSync(path.join(repoRoot, 'README.md'), 'utf8'),
    readmeBefore,
    'README.md restored by postpack',
  );
  assert.ok(!fs.existsSync(path.join(repoRoot, 'build', 'pack-readme', 'README.md')), 'no saved copy left behind');
  const anchors = new Set([...readme.matchAll(/^#+ (.*)$/gm)].map((m) => slug(m[1])));
  const links = [...readme.replace(/```[\s\S]*?```/g, '').matchAll(/\]\(([^)\s]+)\)/g)].map((m) => m[1]);
  assert.ok(links.length > 0);
  for (const link of links) {
    if (/^https:\/\/|^http:\/\//.test(link)) assert.fail(`${link}: the package README links no web page`);
    if (link.startsWith('#')) assert.ok(anchors.has(link.slice(1)), `${link}: no such heading`);
    else assert.ok(fs.existsSync(path.join(pkgDir, link.split('#')[0])), `${link}: not in the tarball`);
  }
  for (const f of ['CHANGELOG.md', 'LICENSE']) assert.ok(fs.existsSync(path.join(pkgDir, f)), `${f} is packed`);
  const pkg = JSON.parse(fs.readFileSync(path.join(pkgDir, 'package.json'), 'utf8'));
  assert.equal(pkg.repository, undefined, 'no invented repository URL');
  assert.equal(pkg.homepage, undefined, 'no invented homepage');
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
    'dist/constants.js',
    'wasm/index.js',
    'wasm/index.d.ts',
    'wasm/worker.js',
    'wasm/worker.d.ts',
    'wasm/kergen-worker.js',
    'wasm/step-batch.js',
    'wasm/errors.js',
    'wasm/load.js',
    'wasm/checks.js',
    'wasm/option-names.js',
    'wasm/wire.js',
    'wasm/files.js',
    'wasm/three.js',
    'wasm/three.d.ts',
    'README.md',
    'CHANGELOG.md',
  ]) {
    assert.ok(files.includes(needed), `${needed} is packed`);
  }
  // Every relative import of a packed module is packed too (a new wasm/*.js file needs its line in
  // package.json's "files").
  for (const f of files.filter((name) => name.endsWith('.js'))) {
    const source = fs.readFileSync(path.join(repoRoot, f), 'utf8');
    for (const [, spec] of source.matchAll(/(?:from|import)\s*\(?\s*'(\.{1,2}\/[^']+)'/g)) {
      const target = path.posix.normalize(path.posix.join(path.posix.dirname(f), spec));
      assert.ok(files.includes(target), `${f} imports ${spec}, which is not packed`);
    }
  }
  for (const f of files) {
    assert.ok(!/^(tests|core|cli|bench|web|scripts|build|node_modules)\//.test(f), `${f} should not be packed`);
    assert.ok(!/\.(cpp|h|hpp|txt|sh|off|stl)$/.test(f), `${f} should not be packed`);
  }
  // The package README once, at the root (npm packs a README of any packed folder: the pack
  // moves wasm/README.md to the root for its duration).
  assert.deepEqual(
    files.filter((f) => /(^|\/)readme(\.|$)/i.test(f)),
    ['README.md'],
    'one README in the tarball',
  );
  assert.ok(fs.existsSync(path.join(repoRoot, 'wasm', 'README.md')), 'wasm/README.md is back after packing');
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
    execFileSync('npm', ['install', '--offline', packInfo.tarball], {
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
