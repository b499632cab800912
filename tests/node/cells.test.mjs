// Volume meshes in the package (cells.js): readVolumeMesh reads .vtu, legacy .vtk and the
// .node + .ele pair with the core's readers; computeCellKernels gives, for every cell, exactly
// what computeKernel gives for that cell's surface alone, both as the core extracts it
// (cellSurface) and as the generator wrote it; and the agglomerated grid's analytic kernels
// (web/cells-sample.js: boxes, L cells whose kernel is their elbow box, U cells that are not
// star-shaped). Bad input: a clear KergenError with its code, or one cell's own error.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { assertBuilt } from './lib/env.mjs';
import { agglomeratedGrid, volumeMeshToVtu } from '../../web/cells-sample.js';

let K;
before(async () => {
  assertBuilt();
  K = await import('../../wasm/index.js');
  await K.init();
});

const enc = (text) => new TextEncoder().encode(text);
const close = (a, b, rel, what) =>
  assert.ok(Math.abs(a - b) <= rel * Math.max(1, Math.abs(b)), `${what}: ${a} vs ${b}`);

// The grid as the .node + .ele pair (1-based ids, every face occurrence its own face id).
function nodeEle({ positions, cells }) {
  const node = [`${positions.length / 3} 3 0 0`];
  for (let v = 0; v < positions.length / 3; v++)
    node.push(`${v + 1} ${positions[3 * v]} ${positions[3 * v + 1]} ${positions[3 * v + 2]}`);
  const ele = [`${cells.length} 0`];
  let faceId = 1;
  cells.forEach((faces, c) => {
    ele.push(`${c + 1} ${faces.length}`);
    for (const f of faces) ele.push(`${faceId++} ${f.length} ${f.map((v) => v + 1).join(' ')}`);
  });
  return { node: enc(node.join('\n') + '\n'), ele: enc(ele.join('\n') + '\n') };
}

// The grid as legacy VTK (polyhedra in CELLS as [n, nfaces, (npts, ids...)...]).
function legacyVtk({ positions, cells }) {
  const lines = ['# vtk DataFile Version 4.2', 'agglomerated grid', 'ASCII', 'DATASET UNSTRUCTURED_GRID'];
  lines.push(`POINTS ${positions.length / 3} double`);
  for (let v = 0; v < positions.length; v += 3) lines.push(`${positions[v]} ${positions[v + 1]} ${positions[v + 2]}`);
  const records = cells.map((faces) => {
    const stream = [faces.length];
    for (const f of faces) stream.push(f.length, ...f);
    return [stream.length, ...stream];
  });
  lines.push(`CELLS ${cells.length} ${records.reduce((s, r) => s + r.length, 0)}`);
  for (const r of records) lines.push(r.join(' '));
  lines.push(`CELL_TYPES ${cells.length}`);
  for (let c = 0; c < cells.length; c++) lines.push('42');
  return enc(lines.join('\n') + '\n');
}

// A cell of the generator as a surface of its own (its vertices renumbered), without the core.
function generatorSurface(grid, c) {
  const ids = new Map();
  const positions = [];
  const indices = [];
  const faceSizes = [];
  for (const f of grid.cells[c]) {
    for (const v of f) {
      if (!ids.has(v)) {
        ids.set(v, ids.size);
        positions.push(grid.positions[3 * v], grid.positions[3 * v + 1], grid.positions[3 * v + 2]);
      }
      indices.push(ids.get(v));
    }
    faceSizes.push(f.length);
  }
  return {
    positions: Float64Array.from(positions),
    indices: Uint32Array.from(indices),
    faceSizes: Uint32Array.from(faceSizes),
  };
}

const GRID = [9, 6, 3];

test('the agglomerated grid: every cell equals computeKernel on its surface and its analytic kernel', () => {
  const grid = agglomeratedGrid(...GRID);
  const r = K.computeCellKernelsSync(enc(volumeMeshToVtu(grid)), {
    name: 'grid.vtu',
    deepestPoint: true,
    rangeSize: 17,
  });
  assert.equal(r.numCells, grid.cells.length);
  assert.ok(grid.kinds.includes('U') && grid.kinds.includes('L') && grid.kinds.includes('S'));
  for (let c = 0; c < r.numCells; c++) {
    const s = K.cellSurfaceSync(r.mesh, c);
    const k = K.computeKernelSync(s.positions, s.indices, { faceSizes: s.faceSizes, deepestPoint: true });
    const own = generatorSurface(grid, c);
    const g = K.computeKernelSync(own.positions, own.indices, { faceSizes: own.faceSizes, deepestPoint: true });
    const name = r.statusNames[r.status[c]];
    assert.equal(name, k.status, `cell ${c} status`);
    assert.equal(g.status, k.status, `cell ${c}: the generator's own surface`);
    // The same computation on the same surface: the same bits.
    assert.equal(r.kernelVolume[c], k.volume, `cell ${c} kernel volume`);
    assert.equal(r.cellVolume[c], k.shapeVolume, `cell ${c} cell volume`);
    assert.equal(r.kernelRatio[c], k.volumeRatio, `cell ${c} ratio`);
    assert.equal(r.inscribedRadius[c], k.inscribedRadius, `cell ${c} radius`);
    assert.deepEqual([...r.witnessFaces.subarray(r.witnessOffsets[c], r.witnessOffsets[c + 1])], [...k.witnessFaces]);
    close(g.volume, k.volume, 1e-12, `cell ${c}: generator surface volume`);
    // The analytic kernel (web/cells-sample.js).
    const e = grid.expected[c];
    assert.equal(k.status, e.starShaped ? 'POLYHEDRON' : 'EMPTY', `cell ${c} (${grid.kinds[c]})`);
    close(r.kernelVolume[c], e.kernelVolume, 1e-12, `cell ${c} analytic kernel volume`);
    close(r.cellVolume[c], e.cellVolume, 1e-12, `cell ${c} analytic cell volume`);
    close(r.diameter[c], e.diameter, 1e-12, `cell ${c} diameter`);
    close(r.inscribedRadius[c], e.inscribedRadius, 1e-9, `cell ${c} inscribed radius`);
    close(r.rhoOverH[c], e.inscribedRadius / e.diameter, 1e-9, `cell ${c} rho/h`);
    if (!e.starShaped) {
      const w = r.witnessGlobalFaces.subarray(r.witnessOffsets[c], r.witnessOffsets[c + 1]);
      assert.ok(w.length >= 2 && w.length <= 4, `cell ${c}: ${w.length} witness faces`);
    }
  }
  // The summary (the core's) agrees with the arrays.
  const u = grid.kinds.filter((k) => k === 'U').length;
  assert.equal(r.summary.byType.EMPTY, u);
  assert.equal(r.summary.byType.POLYHEDRON, r.numCells - u);
  assert.equal(r.summary.minRatio, Math.min(...r.kernelRatio));
  assert.equal(r.summary.maxRatio, Math.max(...r.kernelRatio));
  assert.equal(r.summary.maxRhoOverH, Math.max(...r.rhoOverH));
  assert.equal(r.errors.length, 0);
});

test('.vtu, legacy .vtk and .node + .ele read to the same mesh and the same cells', () => {
  const grid = agglomeratedGrid(...GRID);
  const vtu = K.readVolumeMeshSync(enc(volumeMeshToVtu(grid)), { name: 'grid.vtu' });
  const vtk = K.readVolumeMeshSync(legacyVtk(grid), { name: 'grid.vtk' });
  const pair = K.readVolumeMeshSync(nodeEle(grid), { name: 'grid.node', eleName: 'grid.ele' });
  assert.deepEqual([...vtu.positions], [...grid.positions]);
  assert.equal(vtu.cellOffsets.length - 1, grid.cells.length);
  for (const m of [vtk, pair]) {
    for (const key of ['positions', 'faceIndices', 'faceOffsets', 'cellFaces', 'cellOffsets'])
      assert.deepEqual([...m[key]], [...vtu[key]], key);
  }
  const a = K.computeCellKernelsSync(vtu);
  const b = K.computeCellKernelsSync(nodeEle(grid));
  assert.deepEqual([...b.status], [...a.status]);
  assert.deepEqual([...b.kernelVolume], [...a.kernelVolume]);
});

test('ranges: progress after every range, and a range equals that slice of the whole', async () => {
  const grid = agglomeratedGrid(...GRID);
  const mesh = K.readVolumeMeshSync(enc(volumeMeshToVtu(grid)));
  const whole = K.computeCellKernelsSync(mesh);
  const seen = [];
  const part = await K.computeCellKernels(mesh, {
    firstCell: 10,
    count: 50,
    rangeSize: 8,
    onProgress: (p) => seen.push(p),
  });
  assert.equal(part.firstCell, 10);
  assert.equal(part.numCells, 50);
  assert.deepEqual(
    seen.map((p) => p.count),
    [0, 8, 16, 24, 32, 40, 48, 50],
  );
  assert.ok(seen.every((p) => p.phase === 'cells' && p.total === 50));
  assert.deepEqual([...part.status], [...whole.status.subarray(10, 60)]);
  assert.deepEqual([...part.kernelVolume], [...whole.kernelVolume.subarray(10, 60)]);
  assert.equal(part.witnessOffsets.length, 51);
  const w = (r, c) => [
    ...r.witnessGlobalFaces.subarray(r.witnessOffsets[c - r.firstCell], r.witnessOffsets[c - r.firstCell + 1]),
  ];
  for (let c = 10; c < 60; c++) assert.deepEqual(w(part, c), w(whole, c), `cell ${c} witness`);
  for (const c of part.summary.worstCells) assert.ok(c >= 10 && c < 60, `worst cell ${c} in the range`);
});

test('the async variant yields between ranges and stops on its AbortSignal', async () => {
  const mesh = K.readVolumeMeshSync(enc(volumeMeshToVtu(agglomeratedGrid(...GRID))));
  const controller = new AbortController();
  let ranges = 0;
  const run = K.computeCellKernels(mesh, {
    rangeSize: 5,
    onProgress: () => {
      if (++ranges === 3) setImmediate(() => controller.abort());
    },
    signal: controller.signal,
  });
  await assert.rejects(run, (err) => err instanceof K.KergenError && err.code === 'CANCELLED');
  assert.ok(ranges < mesh.cellOffsets.length - 1, `stopped after ${ranges} progress calls`);
});

test('one bad cell gets its own error; the others are computed', () => {
  const grid = agglomeratedGrid(...GRID);
  const cells = grid.cells.map((faces) => faces.slice());
  cells[5] = cells[5].slice(1); // an open cell: one face missing
  const r = K.computeCellKernelsSync(enc(volumeMeshToVtu({ positions: grid.positions, cells })), { name: 'open.vtu' });
  assert.equal(r.statusNames[r.status[5]], 'OPEN_MESH');
  assert.deepEqual(
    r.errors.map((e) => [e.cell, e.code]),
    [[5, 'OPEN_MESH']],
  );
  assert.match(r.errors[0].message, /^cell 5: /);
  assert.equal(r.summary.byError.OPEN_MESH, 1);
  assert.equal(r.summary.okCells, grid.cells.length - 1);
  for (let c = 0; c < r.numCells; c++)
    if (c !== 5) close(r.kernelVolume[c], grid.expected[c].kernelVolume, 1e-12, `cell ${c}`);
  assert.throws(() => K.cellSurfaceSync(r.mesh, r.numCells), { code: 'INVALID_ARGUMENT' });
});

test('bad files and arguments: KergenError with a code', () => {
  const grid = agglomeratedGrid(3, 2, 1);
  const vtu = volumeMeshToVtu(grid);
  const codeOf = (fn) => {
    try {
      fn();
    } catch (err) {
      assert.ok(err instanceof K.KergenError, String(err));
      assert.ok(err.message.length > 10, err.message);
      return err.code;
    }
    return 'no error';
  };
  assert.equal(
    codeOf(() => K.readVolumeMeshSync(enc(vtu.slice(0, vtu.length / 2)), { name: 'cut.vtu' })),
    'PARSE_ERROR',
  );
  assert.equal(
    codeOf(() => K.readVolumeMeshSync(enc(''), { name: 'empty.vtu' })),
    'EMPTY_INPUT',
  );
  assert.equal(
    codeOf(() => K.readVolumeMeshSync(enc('hello'), { name: 'x' })),
    'PARSE_ERROR',
  );
  const pair = nodeEle(grid);
  const badEle = enc(new TextDecoder().decode(pair.ele).replace(/\n1 4 \d+ /, '\n1 4 999 '));
  assert.equal(
    codeOf(() => K.readVolumeMeshSync({ node: pair.node, ele: badEle })),
    'PARSE_ERROR',
  );
  assert.equal(
    codeOf(() => K.readVolumeMeshSync({ node: pair.node })),
    'INVALID_ARGUMENT',
  );
  assert.equal(
    codeOf(() => K.readVolumeMeshSync(42)),
    'INVALID_ARGUMENT',
  );
  assert.equal(
    codeOf(() => K.readVolumeMeshSync(enc(vtu), { format: 'stl' })),
    'INVALID_ARGUMENT',
  );
  const mesh = K.readVolumeMeshSync(enc(vtu));
  assert.equal(
    codeOf(() => K.computeCellKernelsSync(mesh, { rangeSize: 0 })),
    'INVALID_ARGUMENT',
  );
  assert.equal(
    codeOf(() => K.computeCellKernelsSync(mesh, { deepestPoint: 'yes' })),
    'INVALID_ARGUMENT',
  );
  assert.equal(
    codeOf(() => K.computeCellKernelsSync({ ...mesh, cellOffsets: [0, 99] })),
    'INVALID_ARGUMENT',
  );
  assert.equal(
    codeOf(() => K.computeCellKernelsSync({ ...mesh, positions: 'no' })),
    'INVALID_ARGUMENT',
  );
  assert.equal(
    codeOf(() => K.cellSurfaceSync(mesh, -1)),
    'INVALID_ARGUMENT',
  );
});

test('nothing stays in the wasm heap after the calls', () => {
  const bytes = enc(volumeMeshToVtu(agglomeratedGrid(...GRID)));
  K.computeCellKernelsSync(bytes, { deepestPoint: true }); // warm up the allocator
  const before = K.memoryStats().heapUsed;
  for (let i = 0; i < 3; i++) {
    const r = K.computeCellKernelsSync(bytes, { rangeSize: 7 });
    K.cellSurfaceSync(r.mesh, 3);
    assert.throws(() => K.readVolumeMeshSync(bytes.subarray(0, 500)));
  }
  assert.equal(K.memoryStats().heapUsed, before);
  assert.equal(K.memoryStats().jsHandles, 0);
});

test('joinCellKernels: ranges computed apart join to the whole, summary included', () => {
  const grid = agglomeratedGrid(...GRID);
  const mesh = K.readVolumeMeshSync(enc(volumeMeshToVtu(grid)));
  const cells = grid.cells.length;
  const whole = K.computeCellKernelsSync(mesh, { deepestPoint: true });
  const cut = [0, 37, 61, cells];
  const parts = [2, 0, 1].map((i) =>
    K.computeCellKernelsSync(mesh, { deepestPoint: true, firstCell: cut[i], count: cut[i + 1] - cut[i] }),
  );
  const joined = K.joinCellKernelsSync(parts);
  assert.equal(joined.firstCell, 0);
  assert.equal(joined.numCells, cells);
  for (const key of [
    'status',
    'kernelVolume',
    'kernelRatio',
    'rhoOverH',
    'deepestPoints',
    'witnessOffsets',
    'witnessGlobalFaces',
  ])
    assert.deepEqual([...joined[key]], [...whole[key]], key);
  assert.deepEqual(joined.summary, whole.summary);
  const noBalls = K.joinCellKernelsSync([
    K.computeCellKernelsSync(mesh, { count: 20 }),
    K.computeCellKernelsSync(mesh, { firstCell: 20 }),
  ]);
  assert.deepEqual(noBalls.summary, K.computeCellKernelsSync(mesh).summary);
  assert.throws(() => K.joinCellKernelsSync([parts[0], parts[1]]), { code: 'INVALID_ARGUMENT' });
  assert.throws(() => K.joinCellKernelsSync([]), { code: 'INVALID_ARGUMENT' });
});
