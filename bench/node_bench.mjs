// node_bench.mjs: the wasm package's computeKernelSync timed in Node, optionally next to the
// native build (kergen_bench --json) on the same meshes. One Markdown row (or JSON object) per mesh.
//
//   node bench/node_bench.mjs [--runs N] [--rounds K] [--json] [--quick | --small] [--cpu-time] [--liftoff]
//                             [--native build/bench/kergen_bench] [--meshes DIR] [mesh.off ...]
//   node bench/node_bench.mjs --cells [--runs N] [--rounds K] [--json] [--native ...] [DIR ...]
//
// --small: the small meshes only (thingi bot_eye, plus, button; refinements/spiral1).
// --cpu-time: time with the process's CPU clock (process.cpuUsage: the main thread and V8's helper
// threads; each timed run is as many calls as take ~2 ms, its time the mean per call) and pass
// --cpu-time to kergen_bench (its thread's CPU clock): on a machine shared with builds, wall time
// counts other processes' time slices.
// --cells: cells per second of whole folders of small meshes (default: the four polyhedra sets of
// the mesh folder), as kergen_bench --cells measures them natively: CPU time per cell of one warm
// round over the folder, by single calls (computeKernelSync per mesh) and by one batch call
// (computeKernelsSync over the folder: one KernelBatch, one call into wasm per range of meshes);
// kergen_bench --cells on the same folder alternates with them.
//
// Needs dist/kergen.{mjs,wasm} (npm run build:wasm). Timed: computeKernelSync(positions, indices,
// {faceSizes}) including the copies in and out of the wasm heap; not timed: reading the OFF file
// and the warm-up calls per mesh (at least 20, up to 300 ms on small meshes: see below).
//
// Which code V8 runs: by default it starts every wasm function on its baseline compiler (Liftoff)
// and swaps in optimized code once the function has run enough, which on a tiny mesh takes on the
// order of a thousand calls (tet20/0 ran ~2x slower for its first ~1000 calls, spiral2 similar).
// The timings here are of the optimized code, the steady state of a long-lived page: V8 is told
// to compile with its optimizing tier from the start (--no-liftoff, set below before the module
// is compiled). --liftoff keeps V8's default tiering (then small meshes in a short run measure
// partly baseline code).
import fs from 'node:fs';
import path from 'node:path';
import v8 from 'node:v8';
import { execFileSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { performance } from 'node:perf_hooks';

if (!process.argv.includes('--liftoff')) v8.setFlagsFromString('--no-liftoff');

const repoRoot = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');

function parseArgs(argv) {
  const a = {
    runs: 5,
    rounds: 3,
    json: false,
    quick: false,
    liftoff: false,
    small: false,
    cpuTime: false,
    cells: false,
    native: '',
    meshes: path.resolve(repoRoot, '..', 'shared', 'meshes'),
    files: [],
  };
  let runsGiven = false;
  for (let i = 0; i < argv.length; ++i) {
    const s = argv[i];
    const next = () => {
      if (i + 1 >= argv.length) throw new Error(`${s} needs a value`);
      return argv[++i];
    };
    if (s === '--runs') {
      a.runs = Math.max(1, parseInt(next(), 10) || 1);
      runsGiven = true;
    } else if (s === '--rounds') a.rounds = Math.max(1, parseInt(next(), 10) || 1);
    else if (s === '--json') a.json = true;
    else if (s === '--liftoff') a.liftoff = true;
    else if (s === '--quick') a.quick = true;
    else if (s === '--small') a.small = true;
    else if (s === '--cpu-time') a.cpuTime = true;
    else if (s === '--cells') a.cells = true;
    else if (s === '--native') a.native = next();
    else if (s === '--meshes') a.meshes = next();
    else if (s === '-h' || s === '--help') {
      console.log(
        'usage: node bench/node_bench.mjs [--runs N] [--rounds K] [--json] [--quick | --small] [--cpu-time] [--liftoff] [--native path/to/kergen_bench] [--meshes DIR] [files.off ...]\n' +
          '       node bench/node_bench.mjs --cells [--runs N] [--rounds K] [--json] [--native path/to/kergen_bench] [DIR ...]',
      );
      process.exit(0);
    } else if (s.startsWith('-')) throw new Error(`unknown option ${s}`);
    else a.files.push(s);
  }
  if (a.quick && !runsGiven) {
    a.runs = 1;
    a.rounds = 1;
  }
  return a;
}

// Minimal OFF reader (the benchmark's own): comments and polygons; no per-face colours (the word
// stream has no line breaks), which the shared mesh sets do not use.
function readOff(file) {
  const words = fs
    .readFileSync(file, 'utf8')
    .replace(/#[^\n]*/g, ' ')
    .split(/\s+/)
    .filter(Boolean);
  let p = 0;
  if (!/^OFF$/i.test(words[p])) throw new Error(`${file}: not an OFF file`);
  ++p;
  const nv = +words[p++],
    nf = +words[p++];
  ++p; // edge count
  const positions = new Float64Array(3 * nv);
  for (let i = 0; i < 3 * nv; ++i) positions[i] = +words[p++];
  const indices = [],
    faceSizes = [];
  let allTriangles = true;
  for (let f = 0; f < nf; ++f) {
    const k = +words[p++];
    faceSizes.push(k);
    if (k !== 3) allTriangles = false;
    for (let j = 0; j < k; ++j) indices.push(+words[p++]);
  }
  return {
    positions,
    indices: Uint32Array.from(indices),
    faceSizes: allTriangles ? null : Uint32Array.from(faceSizes),
    faces: nf,
  };
}

function defaultList(a) {
  const rel = [];
  if (a.small) rel.push('thingi/bot_eye.off', 'thingi/plus.off', 'thingi/button.off', 'refinements/spiral1.off');
  else if (a.quick)
    rel.push(
      'princeton/350.off',
      'princeton/200.off',
      'refinements/spiral1.off',
      'refinements/vase1.off',
      'polyhedra/tet10/0.off',
      'polyhedra/voro/0.off',
    );
  else {
    for (const p of ['325', '326', '337', '350', '1', '10', '100', '200', '300']) rel.push(`princeton/${p}.off`);
    for (const s of ['spiral', 'vase']) for (let i = 1; i <= 6; ++i) rel.push(`refinements/${s}${i}.off`);
    for (const d of ['tet10', 'tet20', 'tet30', 'voro'])
      for (const i of ['0', '500']) rel.push(`polyhedra/${d}/${i}.off`);
  }
  return rel.map((r) => ({ file: path.join(a.meshes, r), label: r }));
}

const median = (v) => {
  const s = [...v].sort((x, y) => x - y);
  const n = s.length;
  return n % 2 ? s[(n - 1) / 2] : 0.5 * (s[n / 2 - 1] + s[n / 2]);
};
const fmt = (x, d = 2) => (Number.isFinite(x) ? x.toFixed(d) : '');
// The process's CPU time in ms (user + system; the main thread and V8's helper threads).
const cpuMs = () => {
  const u = process.cpuUsage();
  return (u.user + u.system) / 1000;
};

// ---- --cells: whole folders of small meshes, single calls and one batch call -----------------

function cellFolders(a) {
  if (a.files.length) return a.files.map((dir) => ({ dir, label: dir }));
  return ['tet10', 'tet20', 'tet30', 'voro'].map((d) => ({
    dir: path.join(a.meshes, 'polyhedra', d),
    label: `polyhedra/${d}`,
  }));
}

async function cellRows(a, kergen) {
  if (!a.json) {
    console.log(
      `# node_bench --cells | Node ${process.version} | V8 ${a.liftoff ? 'default tiering' : 'optimizing tier only'} | median of ${a.rounds} x ${a.runs} round(s) over each folder, alternating with kergen_bench --cells | CPU µs per cell (process CPU time; native: thread CPU time)`,
    );
    console.log(
      '| cells | meshes | mean faces | wasm single µs/cell | wasm batch µs/cell | wasm batch cells/s | single/batch (wasm) | native single µs/cell | native batch µs/cell | wasm/native single | wasm/native batch |',
    );
    console.log('|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|');
  }
  for (const { dir, label } of cellFolders(a)) {
    const files = fs
      .readdirSync(dir)
      .filter((f) => f.endsWith('.off'))
      .sort();
    const meshes = files.map((f) => readOff(path.join(dir, f)));
    let sink = 0;
    const singleRound = () => {
      const t = cpuMs();
      for (const m of meshes)
        sink += kergen.computeKernelSync(m.positions, m.indices, { faceSizes: m.faceSizes }).volume;
      return cpuMs() - t;
    };
    const batchRound = () => {
      const t = cpuMs();
      for (const r of kergen.computeKernelsSync(meshes)) sink += r.volume ?? 0;
      return cpuMs() - t;
    };
    for (let w = 0; w < 2; ++w) {
      // warm-up, not timed: the wrapper's JavaScript optimized by V8
      singleRound();
      batchRound();
    }
    const single = [],
      batch = [],
      nativeSingle = [],
      nativeBatch = [];
    for (let round = 0; round < a.rounds; ++round) {
      if (a.native) {
        const out = execFileSync(a.native, ['--cells', dir, '--json', '--runs', String(a.runs)], {
          encoding: 'utf8',
          stdio: ['ignore', 'pipe', 'ignore'],
        });
        const row = JSON.parse(out.split('\n').find((l) => l.startsWith('{')));
        nativeSingle.push(row.single_us_per_cell);
        nativeBatch.push(row.batch_us_per_cell);
      }
      for (let r = 0; r < a.runs; ++r) {
        single.push((1000 * singleRound()) / meshes.length);
        batch.push((1000 * batchRound()) / meshes.length);
      }
    }
    const o = {
      cells: label,
      meshes: meshes.length,
      mean_faces: meshes.reduce((s, m) => s + m.faces, 0) / meshes.length,
      wasm_single_us_per_cell: median(single),
      wasm_batch_us_per_cell: median(batch),
      native_single_us_per_cell: nativeSingle.length ? median(nativeSingle) : NaN,
      native_batch_us_per_cell: nativeBatch.length ? median(nativeBatch) : NaN,
    };
    if (a.json) {
      console.log(JSON.stringify({ ...o, node: process.version, runs: a.runs, rounds: a.rounds, sink }));
      continue;
    }
    const x = (v) => (Number.isFinite(v) ? `${fmt(v)}x` : '-');
    console.log(
      `| ${label} | ${o.meshes} | ${fmt(o.mean_faces, 1)} | ${fmt(o.wasm_single_us_per_cell, 1)} | ${fmt(o.wasm_batch_us_per_cell, 1)} | ${fmt(1e6 / o.wasm_batch_us_per_cell, 0)} | ${x(o.wasm_single_us_per_cell / o.wasm_batch_us_per_cell)} | ${fmt(o.native_single_us_per_cell, 1)} | ${fmt(o.native_batch_us_per_cell, 1)} | ${x(o.wasm_single_us_per_cell / o.native_single_us_per_cell)} | ${x(o.wasm_batch_us_per_cell / o.native_batch_us_per_cell)} |`,
    );
  }
}

async function main() {
  const a = parseArgs(process.argv.slice(2));
  const wasmPath = path.join(repoRoot, 'dist', 'kergen.wasm');
  if (!fs.existsSync(wasmPath)) {
    console.error('dist/kergen.wasm is missing: run `npm run build:wasm` first');
    process.exit(1);
  }
  const kergen = await import('../wasm/index.js');
  await kergen.init();
  if (a.cells) return cellRows(a, kergen);
  const clock = a.cpuTime ? cpuMs : () => performance.now();
  const list = a.files.length ? a.files.map((f) => ({ file: f, label: f })) : defaultList(a);
  if (!a.files.length && !fs.existsSync(a.meshes)) {
    console.error(`mesh folder ${a.meshes} not found: pass --meshes DIR or files`);
    process.exit(1);
  }

  // The native runs of a mesh come right before its wasm runs (one process per mesh), so a
  // change of machine speed during the benchmark (shared hosts) does not skew the ratio.
  const nativeRow = (file) => {
    if (!a.native) return null;
    const flags = [
      '--json',
      '--no-epick',
      '--no-epeck',
      '--no-qhull',
      '--no-cgal62',
      ...(a.cpuTime ? ['--cpu-time'] : []),
    ];
    const out = execFileSync(a.native, [...flags, '--runs', String(a.runs), file], {
      encoding: 'utf8',
      maxBuffer: 1 << 26,
      stdio: ['ignore', 'pipe', 'ignore'],
    });
    const line = out.split('\n').find(Boolean);
    return line ? JSON.parse(line) : null;
  };

  const wasmStat = fs.statSync(wasmPath);
  if (!a.json) {
    console.log(
      `# node_bench | Node ${process.version} | dist/kergen.wasm ${(wasmStat.size / 1024).toFixed(0)} KiB, built ${wasmStat.mtime.toISOString()} | median of ${a.rounds} x ${a.runs} run(s), alternating with native | V8 ${a.liftoff ? 'default tiering (Liftoff first)' : 'optimizing tier only (--no-liftoff)'} | ms${a.cpuTime ? ' of CPU time' : ''}, parse excluded`,
    );
    console.log(
      '| mesh | faces | kernel | V | E | F | wasm | native | wasm/native | validate | planes | lp | trace | assemble |',
    );
    console.log('|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|');
  }
  for (const { file, label } of list) {
    let mesh;
    try {
      mesh = readOff(file);
    } catch (e) {
      console.log(
        a.json ? JSON.stringify({ mesh: label, error: String(e.message) }) : `| ${label} | | ERROR ${e.message} |`,
      );
      continue;
    }
    const options = mesh.faceSizes ? { faceSizes: mesh.faceSizes } : {};
    let callsPerRun = 1;
    const times = [],
      results = [];
    let result = null,
      error = null;
    // Warm-up, not timed: 20 calls, and on small meshes more, up to 300 ms in all. The wasm code is
    // optimized from the start (above), but the wrapper's JavaScript is not: V8 optimizes it only
    // after many calls, and until then it added up to ~0.1 ms per call (tet10/0 timed right
    // after start-up: 0.16 ms, after a large mesh: 0.05 ms).
    try {
      const w0 = performance.now();
      let w = 0;
      for (; w < 20 || (w < 20000 && performance.now() - w0 < 300); ++w)
        kergen.computeKernelSync(mesh.positions, mesh.indices, options);
      // With --cpu-time a timed run is as many calls as take ~2 ms (the process CPU clock is
      // read around them, and a single call of a tiny mesh is shorter than the clock's steps
      // and V8's helper threads' bursts); its time is the mean per call.
      if (a.cpuTime) callsPerRun = Math.max(1, Math.round(2 / ((performance.now() - w0) / w)));
    } catch {
      /* reported by the timed runs */
    }
    // Rounds alternate the native runs (a child process, median of --runs) with as many wasm
    // runs: the machine's speed drifts over seconds, and alternating spreads the drift over both.
    // Reported: the median of all wasm runs and the median of the rounds' native medians.
    const nativeMs = [];
    let nat = null;
    for (let round = 0; round < a.rounds && !error; ++round) {
      nat = nativeRow(file);
      if (nat && !nat.error) nativeMs.push(nat.ours_ms);
      for (let r = 0; r < a.runs; ++r) {
        const t0 = clock();
        try {
          for (let c = 0; c < callsPerRun; ++c)
            result = kergen.computeKernelSync(mesh.positions, mesh.indices, options);
        } catch (e) {
          error = e;
        }
        times.push((clock() - t0) / callsPerRun);
        if (error) break;
        results.push(result);
      }
    }
    const ms = median(times);
    if (!error) {
      // The run whose time is the median supplies the phase split (as in kergen_bench).
      const order = times.map((t, i) => i).sort((x, y) => times[x] - times[y]);
      result = results[order[Math.floor(order.length / 2)]];
    }
    const natMs = nativeMs.length ? median(nativeMs) : NaN;
    if (a.json) {
      const o = {
        mesh: label,
        node: process.version,
        v8_tiering: a.liftoff ? 'default' : 'no-liftoff',
        runs: a.runs,
        rounds: a.rounds,
        faces: mesh.faces,
        wasm_ms: ms,
      };
      if (error) o.error = `${error.code ?? ''} ${error.message}`;
      else
        Object.assign(o, {
          type: result.status,
          V: result.vertices.length / 3,
          E: result.edges.length / 2,
          F: result.faceSizes.length,
          volume: result.volume,
          stats: result.stats,
        });
      if (Number.isFinite(natMs)) Object.assign(o, { native_ms: natMs, wasm_over_native: ms / natMs });
      console.log(JSON.stringify(o));
      continue;
    }
    if (error) {
      console.log(
        `| ${label} | ${mesh.faces} | ERROR | | | | ${fmt(ms)} | ${fmt(natMs)} | | | | | | | ${error.code ?? ''} ${error.message} |`,
      );
      continue;
    }
    const s = result.stats;
    console.log(
      `| ${label} | ${mesh.faces} | ${result.status} | ${result.vertices.length / 3} | ${result.edges.length / 2} | ${result.faceSizes.length} | ${fmt(ms)} | ${fmt(natMs)} | ${Number.isFinite(natMs) ? fmt(ms / natMs) + 'x' : '-'} | ${fmt(s.msValidate)} | ${fmt(s.msPlanes)} | ${fmt(s.msLp)} | ${fmt(s.msTrace)} | ${fmt(s.msAssemble)} |`,
    );
  }
}

main().catch((e) => {
  console.error(e);
  process.exit(1);
});
