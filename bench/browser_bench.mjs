#!/usr/bin/env node
// The demo page under load, in headless Chromium (SwiftShader WebGL): for each mesh, a file drop
// on web/dist served from 127.0.0.1, timed from the drop to the final kernel on screen, with the
// worker's compute time (stats.msTotal), the same compute without step events (?stream=0), and
// the longest main-thread task seen (PerformanceObserver 'longtask').
//
//   node bench/browser_bench.mjs [--runs N] [--json] [--only SUBSTRING] [--timeout S]
//
// Needs dist/ (npm run build:wasm) and web/dist (built here when missing). Meshes: princeton
// 325.off and refinements/vase6.off from ../shared/meshes (skipped when absent), and two generated
// here into a temporary folder (never committed): a 199,200-triangle UV sphere (OFF; nearly
// convex: its quads' diagonals leave slight dents, so its kernel is a little smaller) and a
// 1,000,000-triangle bumpy sphere as binary STL (50 MB; scripts/gen-big-mesh.mjs).
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { serve, launch, writeBinarySTL, dropAndMeasure } from '../tests/e2e/page-tools.mjs';
import { bumpySphere } from '../scripts/gen-big-mesh.mjs';
import { radialSphere } from '../web/samples.js';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const shared = path.resolve(repo, '../shared/meshes');
const args = process.argv.slice(2);
const opt = (name, dflt) => (args.includes(name) ? args[args.indexOf(name) + 1] : dflt);
const runs = Number(opt('--runs', '3'));
const only = opt('--only', '');
const timeoutMs = 1000 * Number(opt('--timeout', '600'));
const json = args.includes('--json');

function writeOFF(file, { positions, indices }) {
  const lines = ['OFF', `${positions.length / 3} ${indices.length / 3} 0`];
  for (let i = 0; i < positions.length; i += 3) lines.push(`${positions[i]} ${positions[i + 1]} ${positions[i + 2]}`);
  for (let i = 0; i < indices.length; i += 3) lines.push(`3 ${indices[i]} ${indices[i + 1]} ${indices[i + 2]}`);
  fs.writeFileSync(file, lines.join('\n') + '\n');
}

function meshList(tmp) {
  const list = [
    { name: 'princeton/325.off', file: path.join(shared, 'princeton/325.off') },
    { name: 'refinements/vase6.off', file: path.join(shared, 'refinements/vase6.off') },
    {
      name: 'UV sphere 199k (OFF)',
      file: path.join(tmp, 'sphere-199k.off'),
      make: (f) =>
        writeOFF(
          f,
          radialSphere(250, 400, () => 1),
        ),
    },
    {
      name: 'bumpy sphere 1M (binary STL)',
      file: path.join(tmp, 'bumpy-1m.stl'),
      make: (f) => writeBinarySTL(f, bumpySphere(1000, 501)),
    },
  ];
  return list.filter((m) => !only || m.name.includes(only));
}

const median = (xs) => {
  const s = xs.filter(Number.isFinite).sort((a, b) => a - b);
  return s.length ? s[Math.floor((s.length - 1) / 2)] : NaN;
};

// One drop on a fresh page (so earlier meshes leave no replay or memory behind) that has computed
// a small sample first: the worker and its wasm module are loaded, as on a page in use.
async function dropOnce(page, base, url, name, stream) {
  await page.goto(`${base}?sample=l-prism${stream ? '' : '&stream=0'}`, { waitUntil: 'load' });
  await page.waitForFunction(() => document.getElementById('status').dataset.state === 'done', null, {
    timeout: 60000,
  });
  await page.click('#jump-end');
  await page.waitForTimeout(300);
  return dropAndMeasure(page, url, name, { timeout: timeoutMs });
}

async function measure(page, base, mesh, served) {
  const url = `/__files/${path.basename(mesh.file)}`;
  served.set(url, mesh.file);
  const streamed = [],
    plain = [];
  for (let i = 0; i < runs; i++) {
    streamed.push(await dropOnce(page, base, url, path.basename(mesh.file), true));
    plain.push(await dropOnce(page, base, url, path.basename(mesh.file), false));
  }
  const last = streamed.at(-1);
  if (last.state !== 'done') throw new Error(`${mesh.name}: ${last.state} ${last.statusText} ${last.message ?? ''}`);
  return {
    mesh: mesh.name,
    inputFaces: last.inputFaces,
    status: last.status,
    kernel: `${last.vertices}/${last.edges}/${last.faces}`,
    steps: last.steps,
    shownMs: median(streamed.map((r) => r.shownMs)),
    workerMs: median(streamed.map((r) => r.workerMs)),
    workerNoStreamMs: median(plain.map((r) => r.workerMs)),
    longestMs: Math.max(...streamed.map((r) => r.longest)),
    longestNoStreamMs: Math.max(...plain.map((r) => r.longest)),
    runs,
  };
}

function printTable(rows) {
  const f = (ms) => (Number.isFinite(ms) ? (ms < 1000 ? `${ms.toFixed(0)} ms` : `${(ms / 1000).toFixed(2)} s`) : 'n/a');
  console.log(
    '| mesh | input faces | kernel V/E/F | steps | drop → kernel shown | worker compute (streaming) | worker compute (no onStep) | longest main-thread task (streaming / no onStep) |',
  );
  console.log('|---|---:|---:|---:|---:|---:|---:|---:|');
  for (const r of rows) {
    if (r.skipped) console.log(`| ${r.mesh} | skipped: ${r.skipped} | | | | | | |`);
    else
      console.log(
        `| ${r.mesh} | ${r.inputFaces.toLocaleString('en-US')} | ${r.kernel} | ${r.steps.toLocaleString('en-US')} | ${f(r.shownMs)} | ${f(r.workerMs)} | ${f(r.workerNoStreamMs)} | ${f(r.longestMs)} / ${f(r.longestNoStreamMs)} |`,
      );
  }
}

async function main() {
  if (!fs.existsSync(path.join(repo, 'web/dist/index.html'))) {
    const r = spawnSync(
      process.execPath,
      [
        path.join(repo, 'node_modules/vite/bin/vite.js'),
        'build',
        '--config',
        'web/vite.config.js',
        '--logLevel',
        'warn',
      ],
      { cwd: repo, stdio: 'inherit' },
    );
    if (r.status !== 0) throw new Error('vite build failed');
  }
  const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'kergen-browser-bench-'));
  const served = new Map();
  const server = await serve(path.join(repo, 'web/dist'), served);
  const base = `http://127.0.0.1:${server.address().port}/`;
  const { page, close } = await launch({ executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium' });
  const rows = [];
  try {
    for (const mesh of meshList(tmp)) {
      if (mesh.make) mesh.make(mesh.file);
      if (!fs.existsSync(mesh.file)) {
        rows.push({ mesh: mesh.name, skipped: `${mesh.file} not found` });
        continue;
      }
      const row = await measure(page, base, mesh, served);
      rows.push(row);
      if (!json) console.error(`${mesh.name}: done`);
      if (mesh.make) fs.rmSync(mesh.file, { force: true });
    }
  } finally {
    await close();
    server.close();
    fs.rmSync(tmp, { recursive: true, force: true });
  }
  if (json) for (const r of rows) console.log(JSON.stringify(r));
  else printTable(rows);
}

await main();
