#!/usr/bin/env node
// The volume-mesh page (web/cells.html) under load, in headless Chromium: a .vtu dropped on the
// view, timed from the drop to the kernel of every cell (the page's own "Time": read in the
// worker by the core's reader, then computed range by range), with the time until the mesh is
// drawn, the progress bar's updates seen on the way and the longest main-thread task
// (PerformanceObserver 'longtask').
//
//   node bench/cells_browser_bench.mjs [--cells N] [--file MESH.vtu] [--runs R] [--deepest on|off|both]
//
// Default: the agglomerated box grid of scripts/gen-volume-mesh.mjs with about 100,000 cells,
// generated into a temporary folder (never committed). Needs dist/ (npm run build:wasm) and
// web/dist (npm run build:web).
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { serve, launch } from '../tests/e2e/page-tools.mjs';
import { agglomeratedGrid, gridForCells, volumeMeshToVtu } from '../web/cells-sample.js';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const args = process.argv.slice(2);
const opt = (name, dflt) => (args.includes(name) ? args[args.indexOf(name) + 1] : dflt);
const runs = Number(opt('--runs', '1'));
const deepestModes = { on: [true], off: [false], both: [false, true] }[opt('--deepest', 'both')];

async function dropAndTime(page, deepest) {
  await page.evaluate((deepest) => {
    document.getElementById('cells-deepest').value = deepest ? 'always' : 'never';
    const status = document.getElementById('cells-status');
    status.dataset.state = 'bench-pending';
    window.__bench = { tasks: [], progress: new Set(), meshAt: null, doneAt: null };
    new PerformanceObserver((list) => {
      for (const e of list.getEntries()) window.__bench.tasks.push([e.startTime - window.__bench.t0, e.duration]);
    }).observe({ type: 'longtask' });
    new MutationObserver(() => {
      window.__bench.progress.add(document.getElementById('cells-progress-text').textContent);
    }).observe(document.getElementById('cells-progress-text'), { childList: true, characterData: true, subtree: true });
    new MutationObserver(() => {
      const s = status.dataset.state;
      if (s === 'computing' && window.__bench.meshAt == null) window.__bench.meshAt = performance.now();
      if ((s === 'done' || s === 'error') && window.__bench.doneAt == null) window.__bench.doneAt = performance.now();
    }).observe(status, { attributes: true });
    const dt = new DataTransfer();
    dt.items.add(window.__file);
    window.__bench.t0 = performance.now();
    document
      .getElementById('viewport')
      .dispatchEvent(new DragEvent('drop', { dataTransfer: dt, bubbles: true, cancelable: true }));
  }, deepest);
  await page.waitForFunction(
    () => ['done', 'error'].includes(document.getElementById('cells-status').dataset.state),
    null,
    {
      timeout: 600000,
      polling: 100,
    },
  );
  return page.evaluate(() => {
    const b = window.__bench;
    const text = (id) => document.getElementById(id).textContent;
    return {
      state: document.getElementById('cells-status').dataset.state,
      message: text('cells-message'),
      cells: text('sum-cells'),
      nonStar: text('sum-nonstar'),
      pageMs: Number(document.getElementById('sum-time').dataset.value),
      meshMs: b.meshAt - b.t0,
      doneMs: b.doneAt - b.t0,
      progressUpdates: b.progress.size,
      longest: Math.max(0, ...b.tasks.map((t) => t[1])),
      top: b.tasks
        .sort((x, y) => y[1] - x[1])
        .slice(0, 3)
        .map(([at, d]) => `${d.toFixed(0)} ms at +${(at / 1000).toFixed(2)} s`),
      longTasks: b.tasks.length,
      timings: window.kergenCells.state.timings,
      workers: document.getElementById('sum-workers').textContent,
      frame: `rebuild ${window.kergenCells.view.rebuildMs.toFixed(0)} ms, last frame ${window.kergenCells.view.renderMs.toFixed(0)} ms`,
    };
  });
}

const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'kergen-cells-bench-'));
let file = opt('--file', null);
if (!file) {
  file = path.join(tmp, 'agglomerated.vtu');
  const grid = gridForCells(Number(opt('--cells', '100000')));
  fs.writeFileSync(file, volumeMeshToVtu(agglomeratedGrid(...grid)));
}
const server = await serve(path.join(repo, 'web/dist'), new Map([['/__files/mesh.vtu', file]]));
const base = `http://127.0.0.1:${server.address().port}/`;
const { page, close } = await launch();
try {
  // As a visitor finds it: the page with its sample computed and drawn (shaders compiled) first.
  await page.goto(`${base}cells.html`, { waitUntil: 'load' });
  await page.waitForFunction(() => document.getElementById('cells-status').dataset.state === 'done', null, {
    timeout: 120000,
  });
  await page.evaluate(async (name) => {
    const blob = await (await fetch('/__files/mesh.vtu')).blob();
    window.__file = new File([blob], name);
  }, path.basename(file));
  console.log(
    `# cells_browser_bench | ${path.basename(file)} ${(fs.statSync(file).size / 1e6).toFixed(1)} MB | Chromium headless, SwiftShader | load average ${os.loadavg()[0].toFixed(2)} at start`,
  );
  console.log(
    '| deepest | cells | not star | drop → mesh drawn | drop → all kernels | page "Time" | progress updates | longest task |',
  );
  console.log('|---|---|---|---|---|---|---|---|');
  const stages = [];
  for (const deepest of deepestModes) {
    for (let r = 0; r < runs; r++) {
      const m = await dropAndTime(page, deepest);
      if (m.state !== 'done') throw new Error(`the page ended in ${m.state}: ${m.message}`);
      console.log(
        `| ${deepest ? 'yes' : 'no'} | ${m.cells} | ${m.nonStar} | ${(m.meshMs / 1000).toFixed(2)} s | ${(m.doneMs / 1000).toFixed(2)} s | ${(m.pageMs / 1000).toFixed(2)} s | ${m.progressUpdates} | ${m.longest.toFixed(0)} ms (${m.longTasks} over 50 ms) |`,
      );
      stages.push(
        `${deepest ? 'deepest' : 'kernels'}, ${m.workers}: ${Object.entries(m.timings)
          .map(([k, v]) => `${k} ${(v / 1000).toFixed(2)} s`)
          .join(', ')}; longest tasks ${m.top.join(', ')}; ${m.frame}`,
      );
    }
  }
  console.log("\nStages (ms from the drop, the page's own marks):");
  for (const line of stages) console.log(`- ${line}`);
} finally {
  await close();
  server.close();
  fs.rmSync(tmp, { recursive: true, force: true });
}
