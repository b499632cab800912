// computeKernels (wasm/batch.js, wasm/batch_bindings.cpp): many meshes in one call through the
// module's KernelBatch. Each result equals, bit for bit, computeKernel's on that mesh alone (every
// array's bytes, every number, the warnings; only the stats' times may differ) over every shared
// polyhedra cell and the small thingi and refinement meshes, with several options; bad meshes
// mixed in get their own errors, with computeKernel's code and message, and the others are still
// computed; progress comes after every range, a signal cancels between ranges and the heap is
// freed; the worker's computeKernels equals the package's; the docs' example runs.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { spawnSync } from 'node:child_process';
import { usePackageWithWorker } from './lib/package-with-worker.mjs';
import { offFiles, repoRoot, sharedMeshes, sharedMeshesMissing } from './lib/env.mjs';

let K;
let W;
const { newWorker } = usePackageWithWorker((pkg) => ({ K, W } = pkg));

const SMALL = ['thingi/bot_eye.off', 'thingi/plus.off', 'thingi/button.off', 'refinements/spiral1.off'];
const readFile = (file) => K.readMeshSync(fs.readFileSync(file), { name: path.basename(file) });

// a and b equal bit for bit, stats' times excepted; `what` names the mesh.
function assertSameResult(a, b, what) {
  assert.deepEqual(Object.keys(a).sort(), Object.keys(b).sort(), what);
  for (const key of Object.keys(b)) {
    const x = a[key];
    const y = b[key];
    if (ArrayBuffer.isView(y)) {
      assert.equal(x.constructor, y.constructor, `${what}: ${key}'s type`);
      const bytes = (v) => Buffer.from(v.buffer, v.byteOffset, v.byteLength);
      assert.ok(bytes(x).equals(bytes(y)), `${what}: ${key} differs`);
    } else if (key === 'faces') {
      assert.equal(x.length, y.length, `${what}: faces`);
    } else if (key === 'stats') {
      for (const s of Object.keys(y)) if (!s.startsWith('ms')) assert.ok(Object.is(x[s], y[s]), `${what}: stats.${s}`);
    } else if (typeof y === 'number') {
      assert.ok(Object.is(x, y), `${what}: ${key} ${x} vs ${y}`);
    } else assert.deepEqual(x, y, `${what}: ${key}`);
  }
}

// computeKernelSync's result, or the KergenError it throws.
function alone(mesh, options = {}) {
  try {
    return K.computeKernelSync(mesh.positions, mesh.indices, { ...options, faceSizes: mesh.faceSizes });
  } catch (err) {
    if (!(err instanceof K.KergenError)) throw err;
    return err;
  }
}

function assertSameEntry(entry, expected, what) {
  if (expected instanceof K.KergenError) {
    assert.ok(entry instanceof K.KergenError, `${what}: an error entry (got ${entry && entry.status})`);
    assert.equal(entry.code, expected.code, what);
    assert.equal(entry.message, expected.message, what);
  } else {
    assert.ok(!(entry instanceof Error), `${what}: ${entry && entry.message}`);
    assertSameResult(entry, expected, what);
  }
}

test('every shared polyhedra cell: computeKernelsSync equals computeKernelSync on each cell alone', (t) => {
  if (sharedMeshesMissing()) return t.skip(sharedMeshesMissing());
  for (const set of ['tet10', 'tet20', 'tet30', 'voro']) {
    const files = offFiles(path.join('polyhedra', set));
    assert.equal(files.length, 1000, set);
    const meshes = files.map(readFile);
    const results = K.computeKernelsSync(meshes);
    assert.equal(results.length, meshes.length);
    const byStatus = {};
    results.forEach((r, i) => {
      assertSameEntry(r, alone(meshes[i]), `${set}/${path.basename(files[i])}`);
      byStatus[r.status ?? r.code] = (byStatus[r.status ?? r.code] ?? 0) + 1;
    });
    t.diagnostic(`${set}: ${JSON.stringify(byStatus)}`);
  }
});

test('small meshes with options (deepestPoint, from, cullFaces, seed, weld): equal to computeKernel', (t) => {
  if (sharedMeshesMissing()) return t.skip(sharedMeshesMissing());
  const meshes = SMALL.map((f) => readFile(path.join(sharedMeshes, f)));
  for (const options of [{}, { deepestPoint: true }, { from: [1, 2, 3], cullFaces: false, seed: 7 }, { weld: true }]) {
    const results = K.computeKernelsSync(meshes, options);
    results.forEach((r, i) => assertSameEntry(r, alone(meshes[i], options), `${SMALL[i]} ${JSON.stringify(options)}`));
    assert.ok(results.every((r) => r.status === 'POLYHEDRON' && r.volume > 0));
  }
});

// A cube (quads), its open variant and malformed ones, for the error entries.
const CUBE = {
  positions: Float64Array.of(0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1),
  indices: Uint32Array.of(0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7),
  faceSizes: Uint32Array.of(4, 4, 4, 4, 4, 4),
};

test('bad meshes mixed in: each gets its own error with its code; the others are computed', async () => {
  const open = { ...CUBE, indices: CUBE.indices.subarray(0, 20), faceSizes: CUBE.faceSizes.subarray(0, 5) };
  const nan = { ...CUBE, positions: CUBE.positions.map((v, i) => (i === 4 ? NaN : v)) };
  const outOfRange = { ...CUBE, indices: CUBE.indices.map((v, i) => (i === 7 ? 99 : v)) };
  const meshes = [
    CUBE,
    open,
    { positions: [0, 0], indices: [0, 1, 2] },
    nan,
    null,
    outOfRange,
    { positions: new Float64Array(0), indices: new Uint32Array(0) },
    { ...CUBE, faceSizes: Uint32Array.of(4, 4, 4) },
    { positions: CUBE.positions, indices: 'abc' },
    CUBE,
  ];
  const codes = [
    null,
    'OPEN_MESH',
    'INVALID_ARGUMENT',
    'NON_FINITE_COORDINATE',
    'INVALID_ARGUMENT',
    'INDEX_OUT_OF_RANGE',
    'EMPTY_INPUT',
    'INVALID_ARGUMENT',
    'INVALID_ARGUMENT',
    null,
  ];
  for (const results of [K.computeKernelsSync(meshes), await K.computeKernels(meshes, { rangeSize: 3 })]) {
    assert.equal(results.length, meshes.length);
    results.forEach((r, i) => {
      if (codes[i] === null) {
        assert.equal(r.status, 'POLYHEDRON');
        assert.equal(r.volume, 1);
        assertSameResult(r, alone(CUBE), `mesh ${i}`);
      } else {
        assert.ok(r instanceof K.KergenError, `mesh ${i} is an error entry`);
        assert.equal(r.code, codes[i], `mesh ${i}: ${r.message}`);
        assert.match(r.message, /\S/);
        // The core's errors are computeKernel's own; the argument checks name the mesh.
        if (meshes[i] !== null && r.code !== 'INVALID_ARGUMENT') assertSameEntry(r, alone(meshes[i]), `mesh ${i}`);
        else assert.match(r.message, new RegExp(`^computeKernels: meshes\\[${i}\\]: `));
      }
    });
  }
  // An open mesh with allowOpen: the options apply to every mesh.
  const [clipped] = K.computeKernelsSync([open], { open: 'clip' });
  assertSameResult(clipped, alone(open, { open: 'clip' }), 'open, clipped');
});

test('bad arguments reject the whole call with INVALID_ARGUMENT', async () => {
  const bad = (fn, re) =>
    assert.throws(fn, (err) => err instanceof K.KergenError && err.code === 'INVALID_ARGUMENT' && re.test(err.message));
  bad(() => K.computeKernelsSync(CUBE), /meshes must be an array/);
  bad(() => K.computeKernelsSync([CUBE], { deepestPoint: 'yes' }), /deepestPoint must be a boolean/);
  bad(() => K.computeKernelsSync([CUBE], { onStep: () => {} }), /onStep/);
  bad(() => K.computeKernelsSync([CUBE], { faceSizes: [3] }), /each mesh gives its own faceSizes/);
  bad(() => K.computeKernelsSync([CUBE], { rangeSize: 0 }), /rangeSize/);
  await assert.rejects(K.computeKernels([CUBE], { signal: {} }), (err) => err.code === 'INVALID_ARGUMENT');
  assert.deepEqual(K.computeKernelsSync([]), []);
});

test('progress after every range; a signal cancels between ranges and the heap is freed', async () => {
  const meshes = Array.from({ length: 20 }, () => CUBE);
  const seen = [];
  K.computeKernelsSync(meshes, { rangeSize: 7, onProgress: (p) => seen.push(p) });
  assert.deepEqual(
    seen,
    [0, 7, 14, 20].map((count) => ({ phase: 'meshes', count, total: 20 })),
  );
  const before = K.memoryStats().heapUsed;
  const controller = new AbortController();
  const counts = [];
  await assert.rejects(
    K.computeKernels(meshes, {
      rangeSize: 5,
      signal: controller.signal,
      onProgress: ({ count }) => {
        counts.push(count);
        if (count === 10) controller.abort();
      },
    }),
    (err) => err instanceof K.KergenError && err.code === 'CANCELLED',
  );
  assert.deepEqual(counts, [0, 5, 10]);
  assert.equal(K.memoryStats().heapUsed, before, 'the batch and its ranges are freed');
  const aborted = AbortSignal.abort();
  await assert.rejects(K.computeKernels(meshes, { signal: aborted }), (err) => err.code === 'CANCELLED');
  // Results and errors leave nothing in the heap either.
  K.computeKernelsSync([
    CUBE,
    null,
    { ...CUBE, faceSizes: CUBE.faceSizes.subarray(0, 5), indices: CUBE.indices.subarray(0, 20) },
  ]);
  assert.equal(K.memoryStats().heapUsed, before);
  assert.equal(K.memoryStats().jsHandles, 0);
});

test('no heap room for a range: its meshes one by one, only the one that does not fit is OUT_OF_MEMORY', async () => {
  const { requireModule } = await import('../../wasm/load.js');
  const m = requireModule('test');
  const malloc = m._malloc;
  // A big mesh: CUBE's vertices repeated (unreferenced vertices are allowed), ~80 kB of positions.
  const big = { ...CUBE, positions: new Float64Array(30000).map((_, i) => CUBE.positions[i % 24]) };
  const limit = 8 * big.positions.length; // a range holding the big mesh does not fit; the others do
  const before = K.memoryStats().heapUsed;
  m._malloc = (n) => (n > limit ? 0 : malloc(n));
  let results;
  try {
    results = K.computeKernelsSync([CUBE, big, CUBE]);
  } finally {
    m._malloc = malloc;
  }
  assert.equal(results[0].volume, 1);
  assert.ok(results[1] instanceof K.KergenError && results[1].code === 'OUT_OF_MEMORY', String(results[1]));
  assertSameResult(results[2], alone(CUBE), 'the mesh after it');
  assert.equal(K.memoryStats().heapUsed, before);
  // With room, the big mesh is computed (its unreferenced vertices change nothing).
  assert.equal(K.computeKernelsSync([big])[0].volume, 1);
});

test('KernelWorker.computeKernels equals computeKernels: results, error entries, progress; cancel', async (t) => {
  if (sharedMeshesMissing()) return t.skip(sharedMeshesMissing());
  const files = offFiles('polyhedra/voro').slice(0, 60);
  const meshes = [
    ...files.map(readFile),
    null,
    { ...CUBE, indices: CUBE.indices.subarray(0, 20), faceSizes: CUBE.faceSizes.subarray(0, 5) },
  ];
  const expected = K.computeKernelsSync(meshes, { deepestPoint: true });
  const kw = newWorker();
  const events = [];
  const results = await kw.computeKernels(meshes, {
    deepestPoint: true,
    rangeSize: 25,
    onProgress: (p) => events.push(p),
  });
  assert.ok(meshes[0].positions.length > 0, 'the arrays were copied, not transferred');
  assert.equal(results.length, expected.length);
  results.forEach((r, i) => assertSameEntry(r, expected[i], `mesh ${i}`));
  assert.ok(results[60] instanceof W.KergenError && results[61].code === 'OPEN_MESH');
  assert.equal(results[0].faces.length, results[0].faceSizes.length, 'faces rebuilt as views');
  const counts = events.filter((e) => e.phase === 'meshes').map((e) => [e.count, e.total]);
  assert.deepEqual(counts, [
    [0, 62],
    [25, 62],
    [50, 62],
    [62, 62],
  ]);
  assert.equal(events.at(-1).phase, 'done');
  await assert.rejects(kw.computeKernels([CUBE], { onStep: () => {} }), (err) => err.code === 'INVALID_ARGUMENT');
  // Cancelled through a signal while it runs (many ranges of one mesh), then the worker works again.
  const many = Array.from({ length: 3000 }, (_, i) => meshes[i % 60]);
  const controller = new AbortController();
  const running = kw.computeKernels(many, {
    rangeSize: 1,
    signal: controller.signal,
    onProgress: ({ count }) => count === 10 && controller.abort(),
  });
  await assert.rejects(running, (err) => err.code === 'CANCELLED');
  const again = await kw.computeKernels([CUBE], { transfer: true });
  assert.equal(again[0].volume, 1);
});

test("docs/js-api.md's computeKernels example runs: one line per file, as computeKernel computes it", (t) => {
  if (sharedMeshesMissing()) return t.skip(sharedMeshesMissing());
  const tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'kergen-batch-'));
  try {
    const open = path.join(tmp, 'open.off');
    fs.writeFileSync(open, 'OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n');
    const files = [...SMALL.map((f) => path.join(sharedMeshes, f)), open];
    const r = spawnSync(process.execPath, [path.join(repoRoot, 'tests/node/lib/batch-example.mjs'), ...files], {
      encoding: 'utf8',
    });
    assert.equal(r.status, 0, r.stderr);
    assert.match(r.stderr, /5 of 5 meshes/);
    const lines = r.stdout.trim().split('\n');
    assert.equal(lines.length, files.length);
    files.forEach((file, i) => {
      const k = alone(readFile(file), { deepestPoint: true });
      const line =
        k instanceof K.KergenError
          ? `${file}: ${k.code} (${k.message})`
          : `${file}: ${k.status}, volume ${k.volume}, inscribed radius ${k.inscribedRadius}`;
      assert.equal(lines[i], line);
    });
    assert.match(lines.at(-1), /OPEN_MESH/);
  } finally {
    fs.rmSync(tmp, { recursive: true, force: true });
  }
});
