// PLY through the package: ascii and binary (LE, BE) files with extra properties and elements read
// as the same mesh as their source with the CLI's outcome, and broken PLY files refused with the
// CLI's code and message (line or byte offset).
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { assertBuilt, sharedMeshes, sharedMeshesMissing } from './lib/env.mjs';
import { box, faceLoops } from './lib/geometry.mjs';
import { cliMissing, runPackage, compareOutcome } from './lib/cli-compare.mjs';

let K;
let tmp;
before(async () => {
  assertBuilt();
  K = await import('../../wasm/index.js');
  await K.init();
  tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'kergen-read-ply-'));
});
after(() => fs.rmSync(tmp, { recursive: true, force: true }));

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
        const problem = compareOutcome(K, name);
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
      const outcome = runPackage(K, file);
      assert.equal(outcome.ok, false, `${base} is refused`);
      codes.add(outcome.error);
      t.diagnostic(`${base}: ${outcome.error} ${path.basename(outcome.message)}`);
      const problem = compareOutcome(K, file);
      if (problem) problems.push(problem);
    }
    assert.deepEqual(problems, [], problems.join('\n'));
    assert.deepEqual([...codes].sort(), ['EMPTY_INPUT', 'PARSE_ERROR']);
    // The byte offsets are those of the values at fault.
    const msg = (base) => runPackage(K, path.join(dir, base)).message;
    assert.match(
      msg('index-out-of-range-le.ply'),
      new RegExp(`byte ${faceStart(le) + 3 + 8}: vertex index 8 out of range \\(the file has 8 vertices\\)$`),
    );
    assert.match(msg('negative-count-be.ply'), new RegExp(`byte ${faceStart(be) + 2}: negative list count -2$`));
    assert.match(msg('nan-le.ply'), new RegExp(`byte ${bodyStart(le) + 9}: non-finite coordinate in vertex 0$`));
  },
);
