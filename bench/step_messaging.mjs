#!/usr/bin/env node
// What step events cost the thread that receives them: KernelWorker.compute() on a mesh whose
// trace has about a million step events (the 199,200-triangle UV sphere of browser_bench.mjs:
// kernel 310k vertices), with an onStep that only counts, against the same call without onStep.
//
//   node bench/step_messaging.mjs [--runs N] [--node] [--chromium] [--nlat A --nlon B] [--json]
//                                 [--pkg DIR[,DIR...]]
//
// --pkg: the package folders to compare, relative to the checkout (default `wasm`); runs
// alternate between them, e.g. `--pkg wasm,build/old/wasm` with an older worker.js,
// kergen-worker.js, index.js and errors.js copied to build/old/wasm and build/old/dist linked to
// dist/.
//
// Node: KernelWorker over worker_threads (the tests' Web Worker shim); the receiving thread's busy
// time is its CPU time (Linux: /proc/self/task/<pid>/stat, the main thread's utime + stime, 10 ms
// ticks: deserializing messages, decoding, onStep) during the call, which a loaded machine does
// not inflate. Chromium (headless, /usr/bin/chromium): the package's ES modules served from this
// checkout; the busy time is the time spent in the worker's onmessage handler for 'steps'
// messages (MessageEvent.data is deserialized there, on first access): wall time, inflated when
// the machine is loaded (the minimum over the runs is the best estimate). Both print per run:
// events, messages, busy ms with onStep (and, Node, without), call ms with and without onStep.
// Needs dist/ built.
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { performance } from 'node:perf_hooks';
import { radialSphere } from '../web/samples.js';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const args = process.argv.slice(2);
const opt = (name, dflt) => (args.includes(name) ? args[args.indexOf(name) + 1] : dflt);
const runs = Number(opt('--runs', '3'));
const nlat = Number(opt('--nlat', '250'));
const nlon = Number(opt('--nlon', '400'));
const json = args.includes('--json');
const wantNode = args.includes('--node') || !args.includes('--chromium');
const wantChromium = args.includes('--chromium') || !args.includes('--node');
const pkgs = opt('--pkg', 'wasm').split(',');

const mesh = radialSphere(nlat, nlon, () => 1);
const rows = [];

function median(xs) {
  const s = [...xs].sort((a, b) => a - b);
  return s[Math.floor(s.length / 2)];
}

// The main thread's CPU time in ms (Linux), or NaN elsewhere.
function threadCpuMs() {
  try {
    const stat = fs.readFileSync(`/proc/self/task/${process.pid}/stat`, 'utf8');
    const fields = stat.slice(stat.lastIndexOf(')') + 2).split(' ');
    return ((Number(fields[11]) + Number(fields[12])) * 1000) / 100; // utime + stime, USER_HZ = 100
  } catch {
    return NaN;
  }
}

async function nodeRuns() {
  const { installWorkerShim } = await import('../tests/node/lib/web-worker-shim.mjs');
  installWorkerShim();
  const positions = Float64Array.from(mesh.positions),
    indices = Uint32Array.from(mesh.indices);
  const workers = [];
  for (const pkg of pkgs) {
    const { KernelWorker } = await import(pathToFileURL(path.join(repo, pkg, 'worker.js')).href);
    const kw = new KernelWorker();
    await kw.compute([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1], [0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3]); // load the module
    workers.push(kw);
  }
  const one = async (kw, withSteps) => {
    let events = 0,
      messages = 0;
    const shim = kw._worker;
    const handler = shim.onmessage;
    shim.onmessage = (e) => {
      if (e.data?.type === 'steps') messages++;
      handler(e);
    };
    const cpu0 = threadCpuMs();
    const t0 = performance.now();
    await kw.compute(positions, indices, withSteps ? { onStep: () => void events++ } : {});
    const wall = performance.now() - t0;
    const busy = threadCpuMs() - cpu0;
    shim.onmessage = handler;
    return { events, messages, busy, wall };
  };
  for (let r = 0; r < runs; r++) {
    for (let i = 0; i < pkgs.length; i++) {
      const plain = await one(workers[i], false);
      const steps = await one(workers[i], true);
      rows.push({ where: 'node', pkg: pkgs[i], run: r + 1, ...summary(steps, plain) });
      print(rows.at(-1));
    }
  }
  for (const kw of workers) kw.dispose();
}

function summary(steps, plain) {
  return {
    events: steps.events,
    messages: steps.messages,
    busyMs: Math.round(steps.busy),
    busyPlainMs: Math.round(plain.busy),
    wallMs: Math.round(steps.wall),
    wallPlainMs: Math.round(plain.wall),
  };
}

function print(r) {
  if (json) return;
  console.log(
    `${r.where} ${r.pkg} run ${r.run}: ${r.events} events in ${r.messages} messages; receiving thread busy ${r.busyMs} ms ` +
      `(without onStep ${r.busyPlainMs} ms); call ${r.wallMs} ms (without onStep ${r.wallPlainMs} ms)`,
  );
}

const PAGE = `<!doctype html><meta charset="utf-8"><title>step messaging</title>
<script type="module">
const { KernelWorker } = await import('/' + new URLSearchParams(location.search).get('pkg') + '/worker.js');
const get = async (u, T) => new T(await (await fetch(u)).arrayBuffer());
const positions = await get('/__bench/positions.bin', Float64Array);
const indices = await get('/__bench/indices.bin', Uint32Array);
const kw = new KernelWorker();
await kw.compute([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1], [0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3]);
window.one = async (withSteps) => {
  let events = 0, messages = 0, busy = 0;
  const w = kw._worker, handler = w.onmessage;
  w.onmessage = (e) => {
    const t = performance.now();
    const steps = e.data?.type === 'steps';
    handler(e);
    if (steps) {
      messages++;
      busy += performance.now() - t;
    }
  };
  const t0 = performance.now();
  await kw.compute(positions, indices, withSteps ? { onStep: () => void events++ } : {});
  const wall = performance.now() - t0;
  w.onmessage = handler;
  return { events, messages, busy, wall };
};
window.ready = true;
</script>`;

async function chromiumRuns() {
  const { serve, launch } = await import('../tests/e2e/page-tools.mjs');
  const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'kergen-steps-'));
  const files = new Map();
  const put = (name, data) => {
    const file = path.join(tmp, name);
    fs.writeFileSync(file, data);
    files.set(`/__bench/${name}`, file);
  };
  put('index.html', PAGE);
  put('positions.bin', Buffer.from(Float64Array.from(mesh.positions).buffer));
  put('indices.bin', Buffer.from(Uint32Array.from(mesh.indices).buffer));
  const server = await serve(repo, files);
  const browser = await launch();
  try {
    const pages = [];
    for (const pkg of pkgs) {
      const page = await browser.context.newPage();
      await page.goto(`http://127.0.0.1:${server.address().port}/__bench/index.html?pkg=${encodeURIComponent(pkg)}`);
      await page.waitForFunction(() => window.ready === true, null, { timeout: 60000 });
      pages.push(page);
    }
    for (let r = 0; r < runs; r++) {
      for (let i = 0; i < pkgs.length; i++) {
        const plain = await pages[i].evaluate(() => window.one(false));
        const steps = await pages[i].evaluate(() => window.one(true));
        rows.push({ where: 'chromium', pkg: pkgs[i], run: r + 1, ...summary(steps, plain) });
        print(rows.at(-1));
      }
    }
  } finally {
    await browser.close();
    server.close();
    fs.rmSync(tmp, { recursive: true, force: true });
  }
}

if (!json)
  console.log(
    `mesh: UV sphere ${nlat} x ${nlon}, ${mesh.indices.length / 3} triangles; ${runs} runs each; ` +
      `load average ${os
        .loadavg()
        .map((x) => x.toFixed(1))
        .join(' ')}`,
  );
if (wantNode) await nodeRuns();
if (wantChromium) await chromiumRuns();
for (const [where, pkg] of ['node', 'chromium'].flatMap((w) => pkgs.map((p) => [w, p]))) {
  const rs = rows.filter((r) => r.where === where && r.pkg === pkg);
  if (!rs.length || json) continue;
  console.log(
    `${where} ${pkg}: busy min ${Math.min(...rs.map((r) => r.busyMs))} / median ${median(rs.map((r) => r.busyMs))} ms with onStep, ` +
      `median ${median(rs.map((r) => r.busyPlainMs))} ms without; ` +
      `call median ${median(rs.map((r) => r.wallMs))} ms with, ${median(rs.map((r) => r.wallPlainMs))} ms without`,
  );
}
if (json) console.log(JSON.stringify(rows));
