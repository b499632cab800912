// readMesh / writeMesh: the package reads and writes mesh files with the core's own readers and
// writers, so it must give exactly the native CLI's outcome: the same error code and
// message for a bad file, the same kernel (status and volume) for a good one, and the same bytes
// as `kergen -o`.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { assertBuilt, sharedMeshes, sharedMeshesMissing } from './lib/env.mjs';
import { box, faceLoops, lPrism, uPrism } from './lib/geometry.mjs';
import { cliMissing, runCli, runPackage, compareOutcome, filesUnder, countBy } from './lib/cli-compare.mjs';

let K;
let tmp;
before(async () => {
  assertBuilt();
  K = await import('../../wasm/index.js');
  await K.init();
  tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'kergen-read-mesh-'));
});
after(() => fs.rmSync(tmp, { recursive: true, force: true }));

test(
  'every file of fixtures/ (formats/ and bad/ too): readMesh + computeKernel give the CLI outcome',
  { timeout: 600000 },
  async (t) => {
    const missing = sharedMeshesMissing() || cliMissing();
    if (missing) return t.skip(missing);
    const files = filesUnder(path.join(sharedMeshes, 'fixtures'));
    assert.ok(files.length > 60, `fixtures has its files (${files.length})`);
    const problems = files.map((f) => compareOutcome(K, f)).filter(Boolean);
    const outcomes = files.map((f) => runPackage(K, f));
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
