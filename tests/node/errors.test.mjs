// Bad input: every failure is a KergenError with the core's error name (or INVALID_ARGUMENT for
// malformed JS arguments) and a readable message; nothing crashes, nothing is thrown as a number.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { assertBuilt } from './lib/env.mjs';
import { box, faceLoops } from './lib/geometry.mjs';
import { freshWrapper } from './lib/fresh-wrapper.mjs';

let K;
before(async () => {
  assertBuilt();
  K = await import('../../wasm/index.js');
  await K.init();
});

async function expectCode(code, fn) {
  let error = null;
  try {
    await fn();
  } catch (err) {
    error = err;
  }
  assert.ok(error, `expected a KergenError with code ${code}, nothing was thrown`);
  assert.ok(
    error instanceof K.KergenError,
    `expected KergenError, got ${error && error.constructor && error.constructor.name}: ${error}`,
  );
  assert.ok(error instanceof Error);
  assert.equal(error.name, 'KergenError');
  assert.equal(error.code, code, `code (message: ${error.message})`);
  assert.equal(typeof error.message, 'string');
  assert.ok(error.message.length > 3, `a readable message: "${error.message}"`);
  return error;
}

/** Concatenates meshes, welding vertices with identical coordinates. */
function weld(...meshes) {
  const ids = new Map();
  const positions = [];
  const indices = [];
  for (const m of meshes) {
    const remap = [];
    for (let v = 0; v < m.positions.length / 3; v++) {
      const key = `${m.positions[3 * v]},${m.positions[3 * v + 1]},${m.positions[3 * v + 2]}`;
      if (!ids.has(key)) {
        ids.set(key, positions.length / 3);
        positions.push(m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]);
      }
      remap.push(ids.get(key));
    }
    for (const i of m.indices) indices.push(remap[i]);
  }
  return { positions: Float64Array.from(positions), indices: Uint32Array.from(indices) };
}

test('NaN and infinite coordinates → NON_FINITE_COORDINATE', async () => {
  for (const bad of [NaN, Infinity, -Infinity]) {
    const m = box();
    m.positions[7] = bad;
    await expectCode('NON_FINITE_COORDINATE', () => K.computeKernel(m.positions, m.indices));
    await expectCode('NON_FINITE_COORDINATE', () => K.findKernelPoint(Float32Array.from(m.positions), m.indices));
    await expectCode('NON_FINITE_COORDINATE', () => K.isStarShaped(Array.from(m.positions), m.indices));
  }
});

test('index out of range → INDEX_OUT_OF_RANGE (core check and JS check for negative numbers)', async () => {
  const m = box();
  const idx = Uint32Array.from(m.indices);
  idx[5] = 8;
  await expectCode('INDEX_OUT_OF_RANGE', () => K.computeKernel(m.positions, idx));
  idx[5] = 0xffffffff;
  await expectCode('INDEX_OUT_OF_RANGE', () => K.computeKernel(m.positions, idx));
  const arr = Array.from(m.indices);
  arr[0] = -1;
  await expectCode('INDEX_OUT_OF_RANGE', () => K.computeKernel(m.positions, arr));
});

test('a hole → OPEN_MESH; with allowOpen an open box is UNBOUNDED', async () => {
  const m = box();
  const loops = faceLoops(m.indices, null);
  const oneMissing = Uint32Array.from(loops.slice(0, -1).flat());
  await expectCode('OPEN_MESH', () => K.computeKernel(m.positions, oneMissing));
  await expectCode('OPEN_MESH', () => K.findKernelPoint(m.positions, oneMissing));
  // Remove both triangles of the top (z = 1) quad: the kernel is unbounded towards +z.
  const topless = loops.filter((l) => !l.every((v) => m.positions[3 * v + 2] === 1));
  assert.equal(topless.length, 10);
  const r = await K.computeKernel(m.positions, Uint32Array.from(topless.flat()), { allowOpen: true });
  assert.equal(r.status, 'UNBOUNDED');
  const p = await K.findKernelPoint(m.positions, Uint32Array.from(topless.flat()), { allowOpen: true });
  assert.equal(p.starShaped, true);
});

test('two boxes sharing only an edge → NON_MANIFOLD_EDGE', async () => {
  const m = weld(box([0, 0, 0], [1, 1, 1]), box([1, 1, 0], [2, 2, 1]));
  assert.equal(m.positions.length / 3, 14, 'the two boxes share two vertices');
  await expectCode('NON_MANIFOLD_EDGE', () => K.computeKernel(m.positions, m.indices));
});

test('two separate boxes → EMPTY with SEPARATE_SHELLS; crossing ones → SELF_INTERSECTION', async () => {
  const m = weld(box([0, 0, 0], [1, 1, 1]), box([3, 0, 0], [4, 1, 1]));
  const r = await K.computeKernel(m.positions, m.indices);
  assert.equal(r.status, 'EMPTY');
  assert.ok(r.warnings.some((w) => w.kind === 'SEPARATE_SHELLS' && w.count === 2));
  const crossing = weld(box([0, 0, 0], [2, 2, 2]), box([1, 1, 1], [3, 3, 3]));
  await expectCode('SELF_INTERSECTION', () => K.computeKernel(crossing.positions, crossing.indices));
});

// A bipyramid over a polygon of n corners that winds `turns` times around the z axis (n odd):
// every face is seen from inside at the origin, so only the embedding certificates refuse it.
function woundBipyramid(n, turns) {
  const positions = [0, 0, 1, 0, 0, -1];
  const indices = [];
  for (let i = 0; i < n; i++) {
    const a = (2 * Math.PI * turns * i) / n;
    positions.push(Math.cos(a), Math.sin(a), 0);
  }
  for (let i = 0; i < n; i++) {
    const v = 2 + i,
      w = 2 + ((i + 1) % n);
    indices.push(0, v, w, 1, w, v);
  }
  return { positions, indices };
}

test('a surface wound twice → SELF_INTERSECTION from computeKernel and findKernelPoint alike', async () => {
  const once = woundBipyramid(7, 1);
  assert.equal((await K.findKernelPoint(once.positions, once.indices)).starShaped, true);
  const twice = woundBipyramid(7, 2);
  await expectCode('SELF_INTERSECTION', () => K.computeKernel(twice.positions, twice.indices));
  await expectCode('SELF_INTERSECTION', () => K.findKernelPoint(twice.positions, twice.indices));
});

test('one flipped triangle → INCONSISTENT_ORIENTATION', async () => {
  const m = box();
  const idx = Uint32Array.from(m.indices);
  [idx[1], idx[2]] = [idx[2], idx[1]];
  await expectCode('INCONSISTENT_ORIENTATION', () => K.computeKernel(m.positions, idx));
});

test('empty input → EMPTY_INPUT', async () => {
  await expectCode('EMPTY_INPUT', () => K.computeKernel(new Float64Array(0), new Uint32Array(0)));
  await expectCode('EMPTY_INPUT', () => K.computeKernel([0, 0, 0, 1, 0, 0, 0, 1, 0], []));
  await expectCode('EMPTY_INPUT', () => K.findKernelPoint([], []));
});

test('1e-60 next to 1 → COORDINATE_RANGE, the message arrives whole (it is not plain ASCII)', async () => {
  const m = box();
  m.positions[0] = 1e-60;
  for (const call of [K.computeKernel, K.findKernelPoint]) {
    const err = await expectCode('COORDINATE_RANGE', () => call(m.positions, m.indices));
    assert.match(
      err.message,
      /^coordinates span about 75 decimal orders of magnitude .* about 66 — snap tiny coordinates to 0 or rescale$/,
    );
  }
});

test('a face with two vertices → FACE_TOO_SMALL; a flat closed mesh → DEGENERATE_INPUT', async () => {
  const m = box([0, 0, 0], [1, 1, 1], { quads: true });
  const sizes = Uint32Array.from(m.faceSizes);
  sizes[0] = 2;
  sizes[1] = 6;
  await expectCode('FACE_TOO_SMALL', () => K.computeKernel(m.positions, m.indices, { faceSizes: sizes }));
  // Two triangles back to back: closed and consistently oriented but enclosing nothing.
  await expectCode('DEGENERATE_INPUT', () => K.computeKernel([0, 0, 0, 1, 0, 0, 0, 1, 0], [0, 1, 2, 0, 2, 1]));
});

test('malformed JS arguments → INVALID_ARGUMENT', async () => {
  const m = box();
  const cases = [
    () => K.computeKernel('0 0 0', m.indices),
    () => K.computeKernel(new Int8Array(24), m.indices),
    () => K.computeKernel(m.positions.subarray(0, 23), m.indices),
    () => K.computeKernel([0, 0, '1'], [0, 0, 0]),
    () => K.computeKernel(m.positions, m.indices.subarray(0, 35)),
    () => K.computeKernel(m.positions, [0, 1, 2.5]),
    () => K.computeKernel(m.positions, new Float32Array(36)),
    () => K.computeKernel(m.positions, m.indices, { faceSizes: [3, 3] }),
    () => K.computeKernel(m.positions, m.indices, { from: [1, 2] }),
    () => K.computeKernel(m.positions, m.indices, { from: [1, 2, NaN] }),
    () => K.computeKernel(m.positions, m.indices, { maxSteps: -1 }),
    () => K.computeKernel(m.positions, m.indices, { maxSteps: 1.5 }),
    () => K.computeKernel(m.positions, m.indices, { onStep: 'yes' }),
    () => K.computeKernel(m.positions, m.indices, { allowOpen: 1 }),
    () => K.computeKernel(m.positions, m.indices, 42),
    () => K.findKernelPoint(m.positions, m.indices, { from: 'centre' }),
  ];
  for (const c of cases) await expectCode('INVALID_ARGUMENT', c);
});

test('a detached typed array → INVALID_ARGUMENT, and the module stays usable', async () => {
  const m = box();
  const detached = (a) => {
    const c = a.slice();
    structuredClone(c.buffer, { transfer: [c.buffer] });
    assert.equal(c.length, 0);
    return c;
  };
  const e1 = await expectCode('INVALID_ARGUMENT', () => K.computeKernel(detached(m.positions), m.indices));
  assert.match(e1.message, /positions is a detached/);
  const e2 = await expectCode('INVALID_ARGUMENT', () => K.findKernelPoint(m.positions, detached(m.indices)));
  assert.match(e2.message, /indices is a detached/);
  // A fresh empty array is not mistaken for a detached one: it reaches the core's own check.
  await expectCode('EMPTY_INPUT', () => K.computeKernel(new Float64Array(0), new Uint32Array(0)));
  const r = K.computeKernelSync(m.positions, m.indices); // still loaded: no reload was needed
  assert.ok(r.volume > 0);
});

test('an exception thrown by onStep stops the trace and reaches the caller unchanged', async () => {
  const m = box();
  const mine = new Error('stop from user code');
  let calls = 0;
  await assert.rejects(
    K.computeKernel(m.positions, m.indices, {
      onStep() {
        calls++;
        throw mine;
      },
    }),
    (err) => err === mine,
  );
  assert.equal(calls, 1, 'no further events after the throw');
  const r = await K.computeKernel(m.positions, m.indices);
  assert.equal(r.status, 'POLYHEDRON', 'the module still works afterwards');
});

test('sync calls before init → NOT_INITIALIZED; a bad wasm location → WASM_LOAD_FAILED, then a retry works', async () => {
  const fresh = await freshWrapper();
  assert.equal(fresh.isInitialized(), false);
  const m = box();
  await expectCode('NOT_INITIALIZED', () => fresh.computeKernelSync(m.positions, m.indices));
  await expectCode('NOT_INITIALIZED', () => fresh.findKernelPointSync(m.positions, m.indices));
  await expectCode('WASM_LOAD_FAILED', () => fresh.init({ wasmUrl: '/nonexistent/dir/kergen.wasm' }));
  await expectCode('WASM_LOAD_FAILED', () => fresh.init({ wasmBinary: new Uint8Array([0, 97, 115, 109, 9, 9, 9, 9]) }));
  await expectCode('INVALID_ARGUMENT', () => fresh.init({ wasmBinary: 'bytes' }));
  assert.equal(fresh.isInitialized(), false);
  await fresh.init();
  assert.equal(fresh.computeKernelSync(m.positions, m.indices).status, 'POLYHEDRON');
});
