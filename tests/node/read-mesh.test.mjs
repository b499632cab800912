// readMesh / writeMesh / onProgress: the package reads and writes mesh files with the core's own
// readers and writers, so it must give exactly the native CLI's outcome: the same error code and
// message for a bad file, the same kernel (status and volume) for a good one, and the same bytes
// as `kergen -o`.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { execFileSync } from 'node:child_process';
import { assertBuilt, nativeCli, repoRoot, sharedMeshes, sharedMeshesMissing } from './lib/env.mjs';
import { box, faceLoops, lPrism, uPrism } from './lib/geometry.mjs';

let K;
let tmp;
before(async () => {
  assertBuilt();
  K = await import('../../wasm/index.js');
  await K.init();
  tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'kergen-read-mesh-'));
});
after(() => fs.rmSync(tmp, { recursive: true, force: true }));

const cliMissing = () =>
  fs.existsSync(nativeCli)
    ? ''
    : `native CLI ${path.relative(repoRoot, nativeCli)} not built (npm run build:native): skipping`;

// `kergen --json FILE [args]`: the one JSON object it prints (exit code 1 for rejected input).
function runCli(file, args = []) {
  let stdout;
  try {
    stdout = execFileSync(nativeCli, ['--json', ...args, file], {
      encoding: 'utf8',
      stdio: ['ignore', 'pipe', 'pipe'],
      timeout: 120000,
    });
  } catch (err) {
    stdout = err.stdout || '';
    if (!stdout.trim())
      throw new Error(`native CLI failed on ${file} without JSON output: ${err.stderr || err.message}`);
  }
  const lines = stdout.split('\n').filter((l) => l.startsWith('{'));
  assert.equal(lines.length, 1, `one JSON object from the CLI for ${file}`);
  return JSON.parse(lines[0]);
}

// The package's outcome for a file, in the CLI's JSON terms: read with readMesh (named as the CLI
// names it: the path), then computeKernel.
function runPackage(file) {
  try {
    const mesh = K.readMeshSync(fs.readFileSync(file), { name: file });
    const k = K.computeKernelSync(mesh.positions, mesh.indices, { faceSizes: mesh.faceSizes ?? undefined });
    return { ok: true, error: null, message: '', status: k.status, volume: k.volume };
  } catch (err) {
    if (!(err instanceof K.KergenError)) throw err;
    return { ok: false, error: err.code, message: err.message, status: null, volume: null };
  }
}

// Each front end names the options a message suggests in its own words (CLI flags, JS option
// names); the rest of the message is the core's and must be the same.
const cliWords = (m) =>
  m
    .replaceAll('--weld', '<weld>')
    .replaceAll('--allow-open', '<allowOpen>')
    .replaceAll('--repair', '<repair>')
    .replaceAll('--open perpendicular', '<open>');
const jsWords = (m) =>
  m
    .replaceAll('weld: true', '<weld>')
    .replaceAll('allowOpen: true', '<allowOpen>')
    .replaceAll('repair: true', '<repair>')
    .replaceAll("open: 'perpendicular'", '<open>');

// Differences between the CLI's and the package's outcome for one file ('' when they agree).
function compareOutcome(file) {
  const n = runCli(file);
  const w = runPackage(file);
  const expected = { ok: n.ok, error: n.error, message: cliWords(n.message), status: n.status };
  const actual = { ok: w.ok, error: w.error, message: jsWords(w.message), status: w.status };
  try {
    assert.deepEqual(actual, expected);
  } catch {
    return `${file}: CLI ${JSON.stringify(expected)} vs package ${JSON.stringify(actual)}`;
  }
  if (n.ok && Math.abs(n.volume - w.volume) > 1e-9 * Math.max(Math.abs(n.volume), Math.abs(w.volume))) {
    return `${file}: volume CLI ${n.volume} vs package ${w.volume}`;
  }
  return '';
}

function filesUnder(dir) {
  const out = [];
  for (const entry of fs.readdirSync(dir, { withFileTypes: true })) {
    const full = path.join(dir, entry.name);
    if (entry.isDirectory()) out.push(...filesUnder(full));
    else if (entry.isFile()) out.push(full);
  }
  return out.sort();
}

test(
  'every file of fixtures/ (formats/ and bad/ too): readMesh + computeKernel give the CLI outcome',
  { timeout: 600000 },
  async (t) => {
    const missing = sharedMeshesMissing() || cliMissing();
    if (missing) return t.skip(missing);
    const files = filesUnder(path.join(sharedMeshes, 'fixtures'));
    assert.ok(files.length > 60, `fixtures has its files (${files.length})`);
    const problems = files.map(compareOutcome).filter(Boolean);
    const outcomes = files.map((f) => runPackage(f));
    const errors = outcomes.filter((o) => !o.ok).map((o) => o.error);
    t.diagnostic(
      `${files.length} files: ${outcomes.length - errors.length} kernels, errors ${JSON.stringify(countBy(errors))}`,
    );
    assert.deepEqual(problems, [], problems.join('\n'));
    assert.ok(
      errors.includes('PARSE_ERROR') && errors.includes('EMPTY_INPUT'),
      'read errors are among the compared outcomes',
    );
    assert.ok(
      outcomes.some((o) => o.status === 'POLYHEDRON'),
      'kernels are among the compared outcomes',
    );
  },
);

function countBy(values) {
  const counts = {};
  for (const v of values) counts[v] = (counts[v] ?? 0) + 1;
  return counts;
}

test('readMesh: the format comes from options.format, else the name, else the content', async () => {
  const off = new TextEncoder().encode('OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n');
  const triangle = {
    positions: new Float64Array([0, 0, 0, 1, 0, 0, 0, 1, 0]),
    indices: new Uint32Array([0, 1, 2]),
    faceSizes: null,
  };
  assert.deepEqual(await K.readMesh(off), triangle, 'detected from the content');
  assert.deepEqual(await K.readMesh(off, { name: 'shape.OFF' }), triangle, 'extension, any case');
  assert.deepEqual(await K.readMesh(off, { name: 'no-extension' }), triangle, 'content again');
  // The name's extension wins over the content, and options.format over the name.
  await assert.rejects(K.readMesh(off, { name: 'shape.obj' }), {
    code: 'EMPTY_INPUT',
    message: 'shape.obj: no vertices and no faces',
  });
  assert.deepEqual(await K.readMesh(off, { name: 'shape.obj', format: 'off' }), triangle);
  await assert.rejects(K.readMesh(off, { format: 'stl' }), {
    code: 'PARSE_ERROR',
    message: /^<memory>: byte 0: not an STL file/,
  });
  await assert.rejects(K.readMesh(new TextEncoder().encode('hello\n'), { name: 'notes.txt' }), {
    code: 'PARSE_ERROR',
    message: /^notes\.txt: unknown mesh format/,
  });
  await assert.rejects(K.readMesh(new Uint8Array(0)), { code: 'EMPTY_INPUT', message: '<memory>: empty file' });
  const obj = new TextEncoder().encode(
    '# a comment first\n\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4 \n',
  );
  const tet = await K.readMesh(obj);
  assert.equal(tet.indices.length, 12);
  const k = await K.computeKernel(tet.positions, tet.indices);
  assert.equal(k.status, 'POLYHEDRON');
});

test("readMesh: any ArrayBufferView or ArrayBuffer in; the caller's bytes are left alone; own buffers out", async () => {
  const text = 'OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n';
  const encoded = new TextEncoder().encode(text);
  // The file in the middle of a larger buffer, seen through several view types.
  const backing = new ArrayBuffer(encoded.length + 16);
  new Uint8Array(backing).fill(0x23); // '#' around it: a wrong offset would be visible
  new Uint8Array(backing, 8, encoded.length).set(encoded);
  const before = new Uint8Array(backing).slice();
  const expected = await K.readMesh(encoded);
  for (const view of [
    new Uint8Array(backing, 8, encoded.length),
    new DataView(backing, 8, encoded.length),
    new Int8Array(backing, 8, encoded.length),
    encoded.buffer,
    Buffer.from(text),
  ]) {
    const mesh = await K.readMesh(view);
    assert.deepEqual(mesh, expected, view.constructor.name);
  }
  assert.deepEqual(new Uint8Array(backing), before, "the caller's buffer is unchanged");
  assert.equal(encoded.length, text.length, 'not detached');
  const mesh = K.readMeshSync(encoded);
  assert.notEqual(mesh.positions.buffer, mesh.indices.buffer, 'each array has its own buffer');
  assert.equal(mesh.positions.byteLength, mesh.positions.buffer.byteLength);
  assert.equal(mesh.indices.byteLength, mesh.indices.buffer.byteLength);
});

test('readMesh: bad arguments are INVALID_ARGUMENT', async () => {
  const off = new TextEncoder().encode('OFF\n');
  const invalid = { code: 'INVALID_ARGUMENT' };
  await assert.rejects(K.readMesh('OFF\n3 1 0\n'), invalid);
  await assert.rejects(K.readMesh([1, 2, 3]), invalid);
  await assert.rejects(K.readMesh(off, { format: 'gltf' }), invalid);
  await assert.rejects(K.readMesh(off, { format: 'OFF' }), invalid);
  await assert.rejects(K.readMesh(off, { name: 7 }), invalid);
  await assert.rejects(K.readMesh(off, 'off'), invalid);
  const transferred = new Uint8Array(16);
  structuredClone(transferred.buffer, { transfer: [transferred.buffer] });
  await assert.rejects(K.readMesh(transferred), { code: 'INVALID_ARGUMENT', message: /detached/ });
  const buffer = new ArrayBuffer(8);
  structuredClone(buffer, { transfer: [buffer] });
  await assert.rejects(K.readMesh(buffer), { code: 'INVALID_ARGUMENT', message: /detached/ });
});

// ---- writeMesh ----------------------------------------------------------------------------------

// The fan triangles of a mesh as float-rounded corner coordinates (what binary STL keeps).
function stlTriangles({ positions, indices, faceSizes }) {
  const out = [];
  for (const loop of faceLoops(indices, faceSizes)) {
    for (let k = 1; k + 1 < loop.length; k++) {
      out.push([loop[0], loop[k], loop[k + 1]].flatMap((v) => [0, 1, 2].map((d) => Math.fround(positions[3 * v + d]))));
    }
  }
  return out;
}

test('writeMesh → readMesh round trips: OBJ and OFF give the same mesh, STL the same float triangles', async () => {
  const meshes = [box(), box([-1, 2, 0.1], [3, 2.5, 4], { quads: true }), lPrism(), uPrism()];
  for (const mesh of meshes) {
    const plain = {
      positions: Float64Array.from(mesh.positions),
      indices: Uint32Array.from(mesh.indices),
      faceSizes: mesh.faceSizes ? Uint32Array.from(mesh.faceSizes) : null,
    };
    const allTriangles = !plain.faceSizes || plain.faceSizes.every((k) => k === 3);
    const expected = { ...plain, faceSizes: allTriangles ? null : plain.faceSizes };
    for (const format of ['obj', 'off']) {
      const bytes = K.writeMesh(mesh, format);
      assert.ok(bytes instanceof Uint8Array);
      assert.deepEqual(await K.readMesh(bytes, { format }), expected, format);
      assert.deepEqual(await K.readMesh(bytes), expected, `${format}, detected from the content`);
    }
    const stl = K.writeMesh(mesh, 'stl');
    const back = await K.readMesh(stl, { name: 'x.stl' });
    assert.equal(back.faceSizes, null);
    assert.deepEqual(stlTriangles(back), stlTriangles(plain));
  }
  // A kernel result writes its polygon faces.
  const k = await K.computeKernel(lPrism().positions, lPrism().indices);
  const back = await K.readMesh(K.writeMesh(k, 'off'));
  assert.deepEqual(back.positions, k.vertices);
  assert.deepEqual(back.indices, k.faceIndices);
  assert.deepEqual(back.faceSizes, k.faceSizes);
});

test('writeMesh: bad arguments and meshes the readers would refuse are errors, not files', () => {
  const m = box();
  assert.throws(() => K.writeMesh(m, 'ply'), { code: 'INVALID_ARGUMENT' });
  assert.throws(() => K.writeMesh(m), { code: 'INVALID_ARGUMENT' });
  assert.throws(() => K.writeMesh(null, 'obj'), { code: 'INVALID_ARGUMENT' });
  assert.throws(() => K.writeMesh({ positions: m.positions, indices: m.indices.subarray(0, 4) }, 'obj'), {
    code: 'INVALID_ARGUMENT',
  });
  assert.throws(
    () =>
      K.writeMesh(
        { status: 'CONVEX', vertices: m.positions, faceIndices: m.indices, faceSizes: new Uint32Array() },
        'obj',
      ),
    { code: 'INVALID_ARGUMENT' },
  );
  const nan = Float64Array.from(m.positions);
  nan[4] = NaN;
  assert.throws(() => K.writeMesh({ positions: nan, indices: m.indices }, 'obj'), { code: 'NON_FINITE_COORDINATE' });
  const far = Uint32Array.from(m.indices);
  far[5] = 8;
  assert.throws(() => K.writeMesh({ positions: m.positions, indices: far }, 'off'), {
    code: 'INDEX_OUT_OF_RANGE',
    message: /indices\[5\] = 8 but the mesh has 8 vertices/,
  });
});

test('writeMesh(kernel) writes what kernel_mesh makes of it: point, segment and empty kernels have no faces', async () => {
  const text = (bytes) => new TextDecoder().decode(bytes);
  const vertices = new Float64Array([0, 0, 0, 1, 0.5, 0.25]);
  const none = new Uint32Array(0);
  assert.equal(
    text(K.writeMesh({ status: 'SEGMENT', vertices, faceIndices: none, faceSizes: none }, 'off')),
    'OFF\n2 0 0\n0 0 0\n1 0.5 0.25\n',
  );
  assert.equal(
    text(
      K.writeMesh({ status: 'POINT', vertices: vertices.subarray(0, 3), faceIndices: none, faceSizes: none }, 'obj'),
    ),
    '# written by kergen\nv 0 0 0\n',
  );
  // An empty kernel drops even the vertices it is given; a mesh keeps them.
  assert.equal(
    text(K.writeMesh({ status: 'EMPTY', vertices, faceIndices: none, faceSizes: none }, 'off')),
    'OFF\n0 0 0\n',
  );
  assert.equal(text(K.writeMesh({ positions: vertices, indices: none }, 'off')), 'OFF\n2 0 0\n0 0 0\n1 0.5 0.25\n');
  const stl = K.writeMesh(
    { status: 'EMPTY', vertices: new Float64Array(0), faceIndices: none, faceSizes: none },
    'stl',
  );
  assert.equal(stl.length, 84, 'a binary STL header with 0 triangles');
  assert.equal(new DataView(stl.buffer).getUint32(80, true), 0);
});

test('readMesh and writeMesh leave the heap where it was (1000 calls, good and bad files)', async () => {
  const cube = box([0, 0, 0], [1, 1, 1], { quads: true });
  const off = K.writeMesh(cube, 'off');
  const bad = new TextEncoder().encode('OFF\n8 6 0\n0 0 zero\n');
  K.readMeshSync(off);
  const before = K.memoryStats();
  for (let i = 0; i < 500; i++) {
    const mesh = K.readMeshSync(off, { name: `cube-${i}.off` });
    K.writeMesh(mesh, ['obj', 'off', 'stl'][i % 3]);
    assert.throws(() => K.readMeshSync(bad, { name: 'bad.off' }), {
      code: 'PARSE_ERROR',
      message: 'bad.off:2: header declares 8 vertices and 6 faces but only 9 bytes follow',
    });
  }
  const after = K.memoryStats();
  assert.equal(after.heapUsed, before.heapUsed);
  assert.equal(after.jsHandles, 0);
});

// Fixture meshes whose kernels cover the statuses the CLI reaches without options.
const WRITE_FIXTURES = [
  'cube_quad.off',
  'star.off',
  'cross.off',
  'tetrahedron.off',
  'dodecahedron_pentagons.off',
  'u.off',
  'fandisk.off',
  'sphere.stl',
];

test("writeMesh(kernel) gives the bytes of the CLI's -o for obj, off and stl", { timeout: 300000 }, async (t) => {
  const missing = sharedMeshesMissing() || cliMissing();
  if (missing) return t.skip(missing);
  const statuses = new Set();
  for (const name of WRITE_FIXTURES) {
    const file = path.join(sharedMeshes, 'fixtures', name);
    const mesh = await K.readMesh(fs.readFileSync(file), { name: file });
    const kernel = await K.computeKernel(mesh.positions, mesh.indices, { faceSizes: mesh.faceSizes ?? undefined });
    statuses.add(kernel.status);
    for (const format of ['obj', 'off', 'stl']) {
      const out = path.join(tmp, `kernel.${format}`);
      const json = runCli(file, ['-o', out]);
      assert.equal(json.status, kernel.status, name);
      const cliBytes = new Uint8Array(fs.readFileSync(out));
      const ours = K.writeMesh(kernel, format);
      assert.ok(
        Buffer.from(ours).equals(Buffer.from(cliBytes)),
        `${name} → ${format}: ${ours.length} bytes vs the CLI's ${cliBytes.length}`,
      );
      fs.rmSync(out);
    }
  }
  t.diagnostic(`kernel statuses written: ${[...statuses].join(', ')}`);
  assert.ok(statuses.has('POLYHEDRON') && statuses.has('EMPTY'), 'full and empty kernels are among them');
});

// ---- onProgress ---------------------------------------------------------------------------------

test('onProgress: each phase once, in order, with its count; rejected and non-star meshes stop early', async () => {
  const L = lPrism();
  const phases = [];
  const k = await K.computeKernel(L.positions, L.indices, { onProgress: (p) => phases.push(p) });
  assert.deepEqual(
    phases.map((p) => p.phase),
    ['validating', 'planes', 'lp', 'tracing', 'assembling'],
  );
  assert.equal(phases[0].count, L.indices.length / 3, 'validating: input faces');
  assert.equal(phases[1].count, L.indices.length / 3, 'planes: faces left (none has zero area)');
  assert.equal(phases[2].count, k.stats.distinctPlanes, 'lp: distinct planes');
  assert.equal(phases[3].count, k.stats.distinctPlanes, 'tracing: distinct planes');
  assert.equal(phases[4].count, k.vertices.length / 3, 'assembling: kernel vertices');

  const open = box();
  const rejected = [];
  assert.throws(
    () =>
      K.computeKernelSync(open.positions, open.indices.subarray(0, 33), { onProgress: (p) => rejected.push(p.phase) }),
    { code: 'OPEN_MESH' },
  );
  assert.deepEqual(rejected, ['validating']);

  const U = uPrism(); // not star-shaped: the LP finds no kernel point, nothing is traced
  const notStar = [];
  const e = await K.computeKernel(U.positions, U.indices, { onProgress: (p) => notStar.push(p.phase) });
  assert.equal(e.status, 'EMPTY');
  assert.deepEqual(notStar, ['validating', 'planes', 'lp']);
});

test('onProgress: a throw is rethrown after the call, later phases are not reported, nothing leaks', async () => {
  const L = lPrism();
  const heapBefore = K.memoryStats().heapUsed;
  const seen = [];
  const boom = new Error('stop here');
  let steps = 0;
  assert.throws(
    () =>
      K.computeKernelSync(L.positions, L.indices, {
        onStep: () => void steps++,
        onProgress: (p) => {
          seen.push(p.phase);
          if (p.phase === 'lp') throw boom;
        },
      }),
    (err) => err === boom,
  );
  assert.deepEqual(seen, ['validating', 'planes', 'lp']);
  assert.ok(steps <= 1, `the trace stopped at its first step (${steps} step callbacks)`);
  assert.equal(K.memoryStats().jsHandles, 0);
  assert.equal(K.memoryStats().heapUsed, heapBefore);
  assert.throws(() => K.computeKernelSync(L.positions, L.indices, { onProgress: 1 }), { code: 'INVALID_ARGUMENT' });
});

// ---- PLY ----------------------------------------------------------------------------------------

const PLY_SIZES = { char: 1, uchar: 1, short: 2, ushort: 2, int: 4, uint: 4, float: 4, double: 8 };
const PLY_SETTERS = {
  char: 'setInt8',
  uchar: 'setUint8',
  short: 'setInt16',
  ushort: 'setUint16',
  int: 'setInt32',
  uint: 'setUint32',
  float: 'setFloat32',
  double: 'setFloat64',
};

/**
 * A PLY file of a mesh, written by this test (independently of the core's reader), in 'ascii',
 * 'le' or 'be'. Around the properties the reader uses it puts others it must read past: vertex
 * properties before x and after z (a list among them), an edge element between vertex and face,
 * face properties before and after the index list, a material element at the end.
 */
function plyFile(
  { positions, indices, faceSizes },
  encoding,
  { xyz = 'double', countType = 'uchar', indexType = 'int' } = {},
) {
  const numVertices = positions.length / 3;
  const loops = faceLoops(indices, faceSizes);
  const format = { ascii: 'ascii', le: 'binary_little_endian', be: 'binary_big_endian' }[encoding];
  const header = [
    'ply',
    `format ${format} 1.0`,
    'comment converted by read-mesh.test.mjs',
    'obj_info test set',
    `element vertex ${numVertices}`,
    'property float nx',
    'property list uchar short tags',
    `property ${xyz} x`,
    `property ${xyz} y`,
    `property ${xyz} z`,
    'property uchar red',
    'element edge 2',
    'property int vertex1',
    'property int vertex2',
    `element face ${loops.length}`,
    'property ushort flags',
    `property list ${countType} ${indexType} vertex_indices`,
    'property list uchar float texcoord',
    'element material 1',
    'property uchar ambient_red',
    'end_header',
    '',
  ].join('\n');
  const rows = []; // one row of [type, value] per element instance
  for (let v = 0; v < numVertices; v++) {
    rows.push([
      ['float', 0.5],
      ['uchar', 2],
      ['short', -7],
      ['short', 300],
      [xyz, positions[3 * v]],
      [xyz, positions[3 * v + 1]],
      [xyz, positions[3 * v + 2]],
      ['uchar', 255],
    ]);
  }
  rows.push(
    [
      ['int', 0],
      ['int', 1],
    ],
    [
      ['int', 1],
      ['int', 2],
    ],
  );
  for (const loop of loops) {
    rows.push([
      ['ushort', 7],
      [countType, loop.length],
      ...loop.map((i) => [indexType, i]),
      ['uchar', 2],
      ['float', 0.25],
      ['float', 0.75],
    ]);
  }
  rows.push([['uchar', 9]]);
  const head = new TextEncoder().encode(header);
  if (encoding === 'ascii') {
    const text = rows
      .map((row) => row.map(([type, value]) => String(type === 'float' ? Math.fround(value) : value)).join(' '))
      .join('\n');
    return Buffer.concat([head, new TextEncoder().encode(`${text}\n`)]);
  }
  const size = rows.reduce((sum, row) => sum + row.reduce((s, [type]) => s + PLY_SIZES[type], 0), 0);
  const body = new DataView(new ArrayBuffer(size));
  let at = 0;
  for (const row of rows) {
    for (const [type, value] of row) {
      body[PLY_SETTERS[type]](at, value, encoding === 'le');
      at += PLY_SIZES[type];
    }
  }
  return Buffer.concat([head, new Uint8Array(body.buffer)]);
}

// Shared meshes converted to PLY: closed star and non-star shapes, polygons, and an open one.
const PLY_SOURCES = [
  'cube_quad.off',
  'star.off',
  'cross_quad.off',
  'dodecahedron_pentagons.off',
  'u.off',
  'fandisk.off',
  'open_cube.off',
];

test(
  "PLY (ascii, binary LE and BE, extra properties and elements): the same mesh as the source, the CLI's outcome",
  { timeout: 600000 },
  async (t) => {
    const missing = sharedMeshesMissing() || cliMissing();
    if (missing) return t.skip(missing);
    const dir = fs.mkdtempSync(path.join(tmp, 'ply-'));
    const problems = [];
    let files = 0;
    for (const source of PLY_SOURCES) {
      const file = path.join(sharedMeshes, 'fixtures', source);
      const mesh = await K.readMesh(fs.readFileSync(file), { name: file });
      const variants = [
        ['ascii', {}],
        ['le', {}],
        ['be', {}],
        ['le', { xyz: 'float', countType: 'int', indexType: 'uint' }],
        ['be', { countType: 'ushort', indexType: 'ushort' }],
      ];
      for (const [encoding, options] of variants) {
        const name = path.join(
          dir,
          `${path.basename(source, '.off')}-${encoding}-${options.xyz ?? 'double'}-${options.indexType ?? 'int'}.ply`,
        );
        const bytes = plyFile(mesh, encoding, options);
        fs.writeFileSync(name, bytes);
        files++;
        const ply = await K.readMesh(bytes, { name });
        const expected = options.xyz === 'float' ? { ...mesh, positions: mesh.positions.map(Math.fround) } : mesh;
        assert.deepEqual(ply, expected, `${name}: the source mesh`);
        assert.deepEqual(await K.readMesh(bytes), ply, `${name}: detected from the content`);
        const problem = compareOutcome(name);
        if (problem) problems.push(problem);
      }
    }
    t.diagnostic(`${files} PLY files compared with the CLI`);
    assert.deepEqual(problems, [], problems.join('\n'));
  },
);

test(
  "broken PLY files: readMesh gives the CLI's error code and message (line or byte offset)",
  { timeout: 120000 },
  async (t) => {
    const missing = cliMissing();
    if (missing) return t.skip(missing);
    const dir = fs.mkdtempSync(path.join(tmp, 'bad-ply-'));
    const cube = box([0, 0, 0], [1, 1, 1], { quads: true });
    const ascii = plyFile(cube, 'ascii').toString();
    const le = plyFile(cube, 'le');
    const be = plyFile(cube, 'be', { countType: 'char' });
    const bodyStart = (bytes) => bytes.indexOf('end_header\n') + 11;
    const withByte = (bytes, at, value) => {
      const copy = Buffer.from(bytes);
      copy[at] = value;
      return copy;
    };
    const faceStart = (bytes) => bodyStart(bytes) + 8 * (4 + 1 + 4 + 24 + 1) + 2 * 8; // past vertices and edges
    const cases = {
      'truncated-le.ply': le.subarray(0, le.length - 5),
      'truncated-be.ply': be.subarray(0, be.length - 30),
      'lying-count.ply': Buffer.from(
        le.toString('latin1').replace('element vertex 8', 'element vertex 80000000'),
        'latin1',
      ),
      'negative-count-be.ply': withByte(be, faceStart(be) + 2, 0xfe), // face 0's count (char) = -2
      'index-out-of-range-le.ply': withByte(le, faceStart(le) + 3 + 4 * 2, 8), // face 0's third index = 8
      'nan-le.ply': Buffer.concat([
        le.subarray(0, bodyStart(le) + 9),
        Buffer.from([0, 0, 0, 0, 0, 0, 0xf8, 0x7f]),
        le.subarray(bodyStart(le) + 17),
      ]),
      'bad-number.ply': ascii.replace(/\n0\.5 2 -7 300 1 0 0 255\n/, '\n0.5 2 -7 300 1 0 zero 255\n'),
      'short-line.ply': ascii.replace(/\n0\.5 2 -7 300 1 0 0 255\n/, '\n0.5 2 -7 300 1 0\n'),
      'unknown-type.ply': ascii.replace('property float nx', 'property real nx'),
      'no-end-header.ply': ascii.slice(0, ascii.indexOf('end_header')),
      'version.ply': ascii.replace('format ascii 1.0', 'format ascii 1.1'),
      'no-faces.ply': plyFile(
        { positions: cube.positions, indices: new Uint32Array(0), faceSizes: new Uint32Array(0) },
        'be',
      ),
      'empty.ply': '',
    };
    const problems = [];
    const codes = new Set();
    for (const [base, content] of Object.entries(cases)) {
      const file = path.join(dir, base);
      fs.writeFileSync(file, content);
      const outcome = runPackage(file);
      assert.equal(outcome.ok, false, `${base} is refused`);
      codes.add(outcome.error);
      t.diagnostic(`${base}: ${outcome.error} ${path.basename(outcome.message)}`);
      const problem = compareOutcome(file);
      if (problem) problems.push(problem);
    }
    assert.deepEqual(problems, [], problems.join('\n'));
    assert.deepEqual([...codes].sort(), ['EMPTY_INPUT', 'PARSE_ERROR']);
    // The byte offsets are those of the values at fault.
    const msg = (base) => runPackage(path.join(dir, base)).message;
    assert.match(
      msg('index-out-of-range-le.ply'),
      new RegExp(`byte ${faceStart(le) + 3 + 8}: vertex index 8 out of range \\(the file has 8 vertices\\)$`),
    );
    assert.match(msg('negative-count-be.ply'), new RegExp(`byte ${faceStart(be) + 2}: negative list count -2$`));
    assert.match(msg('nan-le.ply'), new RegExp(`byte ${bodyStart(le) + 9}: non-finite coordinate in vertex 0$`));
  },
);
