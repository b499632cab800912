// The web demo's readers (web/loaders.js) follow the native ones: OBJ and OFF keep polygon faces,
// ascii STL, OBJ and OFF keep double precision, so the demo computes the kernel of the file's own
// shape: an L prism whose caps are single non-convex hexagons has the unit cube for kernel
// (volume 1), in OFF and in every OBJ face form; and on every OBJ/OFF/STL fixture (the bad ones
// too) the demo's reader + the package give the native CLI's answer (same status or error code,
// volume within 1e-9 relative).
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import os from 'node:os';
import { execFileSync } from 'node:child_process';
import { assertBuilt, nativeCli, sharedMeshes, sharedMeshesMissing } from './lib/env.mjs';

let K, L;
before(async () => {
  assertBuilt();
  K = await import('../../wasm/index.js');
  await K.init();
  L = await import('../../web/loaders.js');
});

// The L prism: base (0,0) (2,0) (2,1) (1,1) (1,2) (0,2), height 1; its kernel is [0,1]^2 x [0,1].
const L_POINTS = [[0, 0], [2, 0], [2, 1], [1, 1], [1, 2], [0, 2]].flatMap(([x, y]) => [[x, y, 0], [x, y, 1]]);
const L_FACES = [[10, 8, 6, 4, 2, 0], [1, 3, 5, 7, 9, 11]];
for (let i = 0; i < 6; i++) {
  const j = (i + 1) % 6;
  L_FACES.push([2 * i, 2 * j, 2 * j + 1, 2 * i + 1]);
}

function bytes(text) {
  return new TextEncoder().encode(text).buffer;
}

function kernelOf(mesh) {
  return K.computeKernelSync(mesh.positions, mesh.indices, mesh.faceSizes ? { faceSizes: mesh.faceSizes } : {});
}

test('OFF: non-convex polygon faces are kept (L prism: kernel volume 1)', () => {
  const text = ['OFF', `${L_POINTS.length} ${L_FACES.length} 0`, ...L_POINTS.map((p) => p.join(' ')),
    ...L_FACES.map((f) => `${f.length} ${f.join(' ')}`)].join('\n');
  const mesh = L.parseMeshFile('l.off', bytes(text));
  assert.deepEqual(Array.from(mesh.faceSizes), L_FACES.map((f) => f.length));
  const k = kernelOf(mesh);
  assert.equal(k.status, 'POLYHEDRON');
  assert.ok(Math.abs(k.volume - 1) < 1e-12, `volume ${k.volume}`);
  assert.equal(k.vertices.length / 3, 8);
});

test('OBJ: polygon faces in the forms i, i/t, i//n, i/t/n and negative, double precision, not welded', () => {
  const forms = [(i) => `${i + 1}`, (i) => `${i + 1}/1`, (i) => `${i + 1}//1`, (i) => `${i + 1}/1/1`, (i) => `${i - L_POINTS.length}`];
  // Coordinates that float32 would round (0.1 + 2^-40 steps): the kernel must keep them.
  const e = 2 ** -40;
  const pts = L_POINTS.map(([x, y, z]) => [x + e, y, z]);
  for (const [n, form] of forms.entries()) {
    const lines = ['# L prism', 'mtllib none.mtl', 'o L', ...pts.map((p) => `v ${p.join(' ')}`), 'vt 0 0', 'vn 0 0 1', 'usemtl x', 's off'];
    for (const f of L_FACES) lines.push(`f ${f.map(form).join(' ')}`);
    const mesh = L.parseMeshFile('l.obj', bytes(lines.join('\n')));
    assert.equal(mesh.positions[0], e, `form ${n}: coordinates in double precision`);
    const k = kernelOf(mesh);
    assert.equal(k.status, 'POLYHEDRON', `form ${n}`);
    assert.ok(Math.abs(k.volume - 1) < 1e-12, `form ${n}: volume ${k.volume}`);
  }
  // The same faces as a soup (every face with its own vertices) are not welded: to the CLI such a
  // file is open (each edge of one face only), and so it is to the page.
  const soup = [], faces = [];
  for (const f of L_FACES) {
    faces.push(`f ${f.map((_, c) => soup.length + c + 1).join(' ')}`);
    for (const v of f) soup.push(`v ${L_POINTS[v].join(' ')}`);
  }
  const unwelded = L.parseMeshFile('soup.obj', bytes([...soup, ...faces].join('\n')));
  assert.equal(unwelded.positions.length / 3, soup.length);
  assert.throws(() => kernelOf(unwelded), (e) => e.code === 'OPEN_MESH');
});

test('STL: ascii in double precision and welded, binary float32 values welded', () => {
  const e = 2 ** -40;
  const tri = [[0, 0, 0], [1 + e, 0, 0], [0, 1, 0]];
  const ascii = ['solid t', ...[0, 1].flatMap(() => ['facet normal 0 0 1', 'outer loop', ...tri.map((p) => `vertex ${p.join(' ')}`), 'endloop', 'endfacet']), 'endsolid t'];
  const a = L.parseMeshFile('t.stl', bytes(ascii.join('\n')));
  assert.equal(a.positions.length / 3, 3, 'two copies of one triangle weld to 3 vertices');
  assert.equal(a.positions[3], 1 + e);
  assert.deepEqual(Array.from(a.indices), [0, 1, 2, 0, 1, 2]);
  const bin = new DataView(new ArrayBuffer(84 + 50));
  bin.setUint32(80, 1, true);
  tri.forEach((p, c) => p.forEach((x, k) => bin.setFloat32(84 + 12 + 12 * c + 4 * k, x, true)));
  const b = L.parseMeshFile('t.stl', bin.buffer);
  assert.equal(b.positions[3], Math.fround(1 + e));
  assert.throws(() => L.parseMeshFile('t.stl', bytes('solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 x\n')), /line 4: invalid number "x"/);
});

test('OBJ/OFF reader errors: code and line', () => {
  const cases = [
    ['f.obj', 'v 0 0 0\nv 1 0 0\nf 1 2', 'PARSE_ERROR', /line 3: face has 2 vertices \(at least 3 needed\)/],
    ['f.obj', 'v 0 0 0\nv x 0 0', 'PARSE_ERROR', /line 2: invalid number "x"/],
    ['f.obj', 'v 0 0 nan', 'PARSE_ERROR', /line 1: non-finite coordinate "nan"/],
    ['f.obj', 'v 0 0 0\nf 0 1 1', 'PARSE_ERROR', /line 2: vertex index 0/],
    ['f.obj', 'v 0 0 0\nf -2 1 1', 'PARSE_ERROR', /line 2: relative vertex index -2 points before the first vertex \(1 vertices so far\)/],
    ['f.obj', 'v 0 0 0\nf 1 1 99999999999', 'PARSE_ERROR', /line 2: vertex index 99999999999 out of range/],
    ['f.obj', 'v 0 0 0\nl 1 1', 'EMPTY_INPUT', /no faces \(only points\/lines\)/],
    ['f.off', 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 4294967296', 'PARSE_ERROR', /line 6: vertex index 4294967296 out of range \(the file has 3 vertices\)/],
    ['f.off', 'OFF\n0 0 0\n', 'EMPTY_INPUT', /no vertices and no faces/],
  ];
  for (const [name, text, code, message] of cases) {
    assert.throws(() => L.parseMeshFile(name, bytes(text)), (e) => e instanceof L.MeshParseError && e.code === code && message.test(e.message), text);
  }
  const utf16 = new Uint8Array([0xfe, 0xff, 0, 0x76]).buffer;
  assert.throws(() => L.parseMeshFile('u.obj', utf16), /UTF-16 is not supported/);
});

// A file's outcome: the kernel's status (and volume), or the error code. From the native CLI:
function nativeOutcome(file) {
  let out;
  try {
    out = execFileSync(nativeCli, ['--json', file], { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
  } catch (err) {
    out = err.stdout || '';
  }
  const r = JSON.parse(out);
  return r.ok ? { outcome: r.status, volume: r.volume } : { outcome: r.error, message: r.message };
}
// and from the demo reader + package (buffer: the file's bytes).
function webOutcome(name, buffer) {
  try {
    const k = kernelOf(L.parseMeshFile(name, buffer));
    return { outcome: k.status, volume: k.volume };
  } catch (e) {
    return { outcome: e.code, message: e.message };
  }
}
// The same status or error code, and the same volume to 1e-9 relative.
function assertSameOutcome(web, native, label) {
  assert.equal(web.outcome, native.outcome, `${label}: demo ${JSON.stringify(web)}, CLI ${JSON.stringify(native)}`);
  if (native.volume !== undefined) {
    assert.ok(Math.abs(web.volume - native.volume) <= 1e-9 * Math.max(1, Math.abs(native.volume)), `${label}: volume ${web.volume} vs ${native.volume}`);
  }
}

test('every OBJ/OFF/STL fixture: the demo reader + package give the native CLI answer', (t) => {
  const missing = sharedMeshesMissing() || (fs.existsSync(nativeCli) ? '' : `${nativeCli} not built`);
  if (missing) {
    t.skip(missing);
    return;
  }
  let compared = 0;
  for (const dir of ['fixtures', 'fixtures/formats', 'fixtures/bad']) {
    for (const name of fs.readdirSync(path.join(sharedMeshes, dir)).sort()) {
      if (!/\.(obj|off|stl)$/i.test(name)) continue;
      const file = path.join(sharedMeshes, dir, name);
      const bytesOfFile = fs.readFileSync(file);
      const buffer = bytesOfFile.buffer.slice(bytesOfFile.byteOffset, bytesOfFile.byteOffset + bytesOfFile.byteLength);
      assertSameOutcome(webOutcome(name, buffer), nativeOutcome(file), name);
      compared++;
    }
  }
  assert.ok(compared >= 55, `only ${compared} fixtures`);
});

// Texts on the edges of the readers' grammar: each case's expected outcome follows the native
// reader's rules (io.cpp), and the CLI is asked too when it is built. Before the readers followed
// those rules, an OBJ index past the last vertex, a count "4.0", a lower-case header, lone '\r'
// line ends or a U+00A0 inside a number gave the demo another answer than the CLI.
test('grammar edge cases: the same outcome as the native reader', (t) => {
  const tetV = ['0 0 0', '1 0 0', '0 1 0', '0 0 1'];
  const tetF = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
  const obj = (opts = {}) => {
    const v = tetV.map((p) => `v ${p}`);
    const f = tetF.map((face, i) => `${opts.keyword?.(i) ?? 'f'} ${face.map((x) => (opts.ref ?? ((j) => String(j + 1)))(x, i)).join(' ')}`);
    return (opts.facesFirst ? [...f, ...v] : [...v, ...f]).join(opts.eol ?? '\n') + '\n';
  };
  const off = (opts = {}) => {
    const head = opts.head ?? ['OFF', '4 4 0'];
    const v = tetV.map((p) => p + (opts.vertexTail ?? ''));
    const f = tetF.map((face) => `3 ${face.map(opts.ref ?? String).join(' ')}${opts.faceTail ?? ''}`);
    return [...head, ...v, ...f].join(opts.eol ?? '\n') + '\n';
  };
  const stl = (normal = '0 0 0') => {
    const p = tetV.map((s) => s.split(' '));
    return ['solid t', ...tetF.flatMap((face) => [`facet normal ${normal}`, 'outer loop', ...face.map((i) => `vertex ${p[i].join(' ')}`), 'endloop', 'endfacet']), 'endsolid t'].join('\n');
  };
  const cases = [
    ['obj: a face index past the last vertex', 'obj', obj({ ref: (j, i) => String(i === 3 ? 9 : j + 1) }), 'PARSE_ERROR'],
    ['obj: faces before their vertices', 'obj', obj({ facesFirst: true }), 'POLYHEDRON'],
    ['obj: "fo" faces', 'obj', obj({ keyword: () => 'fo' }), 'POLYHEDRON'],
    ['obj: i// and i/t/ forms', 'obj', obj({ ref: (j, i) => `${j + 1}${i % 2 ? '//' : '/1/'}` }), 'POLYHEDRON'],
    ['obj: four parts', 'obj', obj({ ref: (j) => `${j + 1}/1/1/1` }), 'PARSE_ERROR'],
    ['obj: a texture part that is no integer', 'obj', obj({ ref: (j) => `${j + 1}/x` }), 'PARSE_ERROR'],
    ['obj: "+1" indices', 'obj', obj({ ref: (j) => `+${j + 1}` }), 'POLYHEDRON'],
    ['obj: "F" is not a face record', 'obj', obj({ keyword: (i) => (i === 0 ? 'F' : 'f') }), 'OPEN_MESH'],
    ['obj: U+00A0 inside a number', 'obj', obj().replace('v 1 0 0', 'v 1\u00a0 0 0'), 'PARSE_ERROR'],
    ['obj: CRLF line ends', 'obj', obj({ eol: '\r\n' }), 'POLYHEDRON'],
    ['obj: lone CR line ends (one line)', 'obj', obj({ eol: '\r' }), 'EMPTY_INPUT'],
    ['off: lower-case header', 'off', off({ head: ['off', '4 4 0'] }), 'PARSE_ERROR'],
    ['off: no header', 'off', off({ head: ['4 4 0'] }), 'PARSE_ERROR'],
    ['off: 4OFF', 'off', off({ head: ['4OFF', '4 4 0'] }), 'PARSE_ERROR'],
    ['off: OFF BINARY', 'off', off({ head: ['OFF BINARY', '4 4 0'] }), 'PARSE_ERROR'],
    ['off: a count "4.0"', 'off', off({ head: ['OFF', '4.0 4 0'] }), 'PARSE_ERROR'],
    ['off: counts on the header line, no edge count', 'off', off({ head: ['OFF 4 4'] }), 'POLYHEDRON'],
    ['off: STCNOFF with values after xyz and colours after faces', 'off', off({ head: ['STCNOFF', '4 4 0'], vertexTail: ' 0.5 0.5 1 0 0 1 0.2 0.3', faceTail: ' 255 0 0' }), 'POLYHEDRON'],
    ['off: "+1" indices', 'off', off({ ref: (j) => `+${j}` }), 'POLYHEDRON'],
    ['off: an index past the last vertex', 'off', off({ ref: (j) => String(j === 3 ? 4 : j) }), 'PARSE_ERROR'],
    ['off: CRLF line ends', 'off', off({ eol: '\r\n' }), 'POLYHEDRON'],
    ['off: lone CR line ends (one line)', 'off', off({ eol: '\r' }), 'PARSE_ERROR'],
    ['stl: an overflowing facet normal (ignored, as nan)', 'stl', stl('1e400 0 nan'), 'POLYHEDRON'],
    ['stl: a facet normal that is no number', 'stl', stl('1 0 x'), 'PARSE_ERROR'],
    ['stl: "solid" followed by U+00A0 (not ascii STL)', 'stl', stl().replace('solid t', 'solid\u00a0t'), 'PARSE_ERROR'],
  ];
  const cli = fs.existsSync(nativeCli) ? nativeCli : null;
  const dir = cli ? fs.mkdtempSync(path.join(os.tmpdir(), 'kergen-grammar-')) : null;
  try {
    for (const [what, ext, text, expected] of cases) {
      assert.equal(webOutcome(`case.${ext}`, bytes(text)).outcome, expected, `${what}: demo reader + package`);
      if (cli) {
        const file = path.join(dir, `case.${ext}`);
        fs.writeFileSync(file, text);
        assert.equal(nativeOutcome(file).outcome, expected, `${what}: native CLI`);
      }
    }
  } finally {
    if (dir) fs.rmSync(dir, { recursive: true, force: true });
  }
  if (!cli) t.diagnostic(`${nativeCli} not built: the expected outcomes were checked against the demo reader only`);
});

// Differential check: OBJ, OFF and ascii STL texts of a cube with random oddities (number forms,
// headers, keywords, index forms, blanks, line ends, then a few random character edits), each read
// by the demo reader + package and by the CLI: the same status or error code, and the same
// volume. Seeded, so a failure names a case that can be replayed.
test('random odd texts: the demo reader + package give the CLI outcome', (t) => {
  if (!fs.existsSync(nativeCli)) {
    t.skip(`${nativeCli} not built`);
    return;
  }
  let state = 0x5eed;
  const rnd = () => {
    state = (state + 0x6d2b79f5) | 0;
    let x = Math.imul(state ^ (state >>> 15), 1 | state);
    x = (x + Math.imul(x ^ (x >>> 7), 61 | x)) ^ x;
    return ((x ^ (x >>> 14)) >>> 0) / 4294967296;
  };
  const odd = 0.03;
  const pick = (usual, oddities) => (rnd() < odd ? oddities[Math.floor(rnd() * oddities.length)] : usual);
  const P = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]];
  const Q = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]];
  const num = (v) => pick(String(v), [`${v}.`, `${v}.0`, `${v}e0`, `${v}E+0`, `+${v}`, `0${v}`, `-${v}`, `.${v}`, `${v}e`, `${v}.0.0`,
    `0x${v}`, 'Infinity', 'inf', 'nan', `${v},0`, `${v}f`, `${v}\u00a0`, `${v}#c`, '1e400', '1e-400', `${v}/`, '.', '-']);
  const sp = () => pick(' ', ['\t', '  ', ' \t ', '\v', '\f', '\u00a0']);
  const nl = () => pick('\n', ['\r\n', '\r', ' \n', '\t\n', ' # c\n', '#\n']);
  const idx = (i, base) => pick(String(i + base), [`${i + base}.0`, `+${i + base}`, '9', '-1', 'a', `${i + base}e0`, `${i + base}/1`, `${i + base}//1/1`]);
  const texts = {
    off: () => {
      let s = pick('OFF', ['off', 'COFF', 'NOFF', 'STCNOFF', '4OFF', 'OFF BINARY', '# c\nOFF', 'OFFX', '']);
      s += nl() + pick('8 6 0', ['8 6', '8 6 0 0', '9 6 0', '8 7 0', '8 5 0', '-8 6 0', '8.0 6 0', '+8 6 0']) + nl();
      for (const p of P) s += p.map(num).join(sp()) + pick('', [' 0.5 0.5 0.5', ' x']) + nl();
      for (const f of Q) s += pick('4', ['3', '5', '4.0', '+4', 'x']) + sp() + f.map((i) => idx(i, 0)).join(sp()) + pick('', [' 255 0 0']) + nl();
      return s;
    },
    obj: () => {
      let s = pick('', ['o cube\n', 'g g\n', 's off\n', 'mtllib a.mtl\n']);
      for (const p of P) s += pick('v', ['V', 'vn', 'vt', 'v\t']) + sp() + p.map(num).join(sp()) + pick('', [' 1', ' 0.5 0.5 0.5']) + nl();
      for (const f of Q) s += pick('f', ['F', 'fo', 'l', 'p']) + sp() + f.map((i) => idx(i, 1)).join(sp()) + nl();
      return s + pick('', ['f 1 2\n', 'f\n', 'v 1 2\n', 'l 1 2\n']);
    },
    stl: () => {
      let s = pick('solid cube', ['solid', 'SOLID x', 'solidx', 'solid\u00a0x']) + nl();
      for (const f of Q) {
        for (const tri of [[f[0], f[1], f[2]], [f[0], f[2], f[3]]]) {
          s += pick('facet normal', ['facet  normal', 'facet', 'FACET NORMAL']) + sp() + [0, 0, 0].map(num).join(sp()) + nl();
          s += pick('outer loop', ['outerloop', 'outer loop x']) + nl();
          for (const i of tri) s += pick('vertex', ['VERTEX', 'vert']) + sp() + P[i].map(num).join(sp()) + nl();
          s += pick('endloop', ['end loop']) + nl() + pick('endfacet', ['endfacet x']) + nl();
        }
      }
      return s + pick('endsolid cube', ['', 'endsolid\nsolid b\nendsolid b']) + nl();
    },
  };
  const edits = ' \t\r\v\f\n\u00a0#/-+.eE0179xfvOFnaNI';
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'kergen-odd-'));
  const outcomes = {};
  try {
    for (let c = 0; c < 1500; c++) {
      const ext = ['off', 'obj', 'stl'][c % 3];
      let text = texts[ext]();
      if (rnd() < 0.3) {
        const at = Math.floor(rnd() * text.length), op = rnd(), ch = edits[Math.floor(rnd() * edits.length)];
        text = text.slice(0, at) + (op < 0.4 ? ch + text[at] : op < 0.7 ? '' : ch) + text.slice(at + 1);
      }
      const file = path.join(dir, `case.${ext}`);
      fs.writeFileSync(file, text);
      const native = nativeOutcome(file);
      outcomes[native.outcome] = (outcomes[native.outcome] ?? 0) + 1;
      assertSameOutcome(webOutcome(`case.${ext}`, bytes(text)), native, `case ${c} (${ext}) ${JSON.stringify(text.slice(0, 400))}`);
    }
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
  // The mix must exercise both sides: files the readers refuse and files they take.
  assert.ok((outcomes.PARSE_ERROR ?? 0) > 100 && (outcomes.POLYHEDRON ?? 0) > 100, JSON.stringify(outcomes));
  t.diagnostic(JSON.stringify(outcomes));
});
