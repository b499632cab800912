// Mesh files → { positions: Float64Array (xyz), indices: Uint32Array, faceSizes?: Uint32Array }.
//
// STL (ascii and binary) is read with three.js's loader and welded by exact coordinate equality —
// the same rule as the project's native reader — so the welded mesh is closed exactly when the
// file is. (BufferGeometryUtils.mergeVertices hashes coordinates rounded to a fixed absolute grid,
// 1e-4 by default, which merges distinct vertices of small-scale models; an exact key cannot.)
// OBJ and OFF are read by the small parsers below, in double precision, with their polygon faces
// kept: indices then holds the loops one after another and faceSizes their lengths (absent when
// every face is a triangle), which is how the package takes polygons. (three.js's OBJLoader would
// round coordinates to float32 and split every polygon as a fan from its first corner, which
// folds over a non-convex polygon and gives the kernel of another shape.) OBJ vertices are welded
// by exact coordinate equality too, as the triangle soups that three.js's loader produced were.
// Indices are not range-checked here: the kernel package validates the mesh and reports
// INDEX_OUT_OF_RANGE, OPEN_MESH, … itself.

import { STLLoader } from 'three/examples/jsm/loaders/STLLoader.js';

export class MeshParseError extends Error {
  // code: PARSE_ERROR, or EMPTY_INPUT for a file without faces (the native readers' codes)
  constructor(message, code = 'PARSE_ERROR') {
    super(message);
    this.name = 'MeshParseError';
    this.code = code;
  }
}

export const SUPPORTED_EXTENSIONS = ['stl', 'obj', 'off'];

export function extensionOf(name) {
  const m = /\.([a-z0-9]+)$/i.exec(name);
  return m ? m[1].toLowerCase() : '';
}

// Welds a triangle soup (xyz per corner, 9 values per triangle) by exact coordinate equality.
export function weldExact(corners) {
  const n = corners.length / 3;
  const map = new Map();
  const positions = [];
  const indices = new Uint32Array(n);
  for (let i = 0; i < n; i++) {
    const x = corners[3 * i], y = corners[3 * i + 1], z = corners[3 * i + 2];
    const key = `${x},${y},${z}`; // Number → string round-trips exactly (and -0 prints as 0)
    let id = map.get(key);
    if (id === undefined) {
      id = positions.length / 3;
      map.set(key, id);
      positions.push(x, y, z);
    }
    indices[i] = id;
  }
  return { positions: Float64Array.from(positions), indices };
}

// UTF-8 text (a byte order mark dropped); UTF-16 is refused with its reason, as the native
// readers do, instead of reading as a file without faces.
function decodeText(buffer) {
  const b = new Uint8Array(buffer.buffer ?? buffer, buffer.byteOffset ?? 0, Math.min(2, buffer.byteLength));
  if (b.length === 2 && ((b[0] === 0xff && b[1] === 0xfe) || (b[0] === 0xfe && b[1] === 0xff) || (b[0] === 0) !== (b[1] === 0))) {
    throw new MeshParseError('line 1: UTF-16 is not supported (save the file as UTF-8 or ASCII)');
  }
  return new TextDecoder().decode(buffer);
}

export function parseSTL(buffer) {
  let geometry;
  try {
    geometry = new STLLoader().parse(buffer);
  } catch (e) {
    throw new MeshParseError(`not a readable STL file (${e.message})`);
  }
  const pos = geometry.getAttribute('position');
  if (!pos || pos.count < 3) throw new MeshParseError('no triangles found in the STL file');
  return weldExact(pos.array);
}

// Text lines without comments, split into tokens; calls visit(tokens, lineNumber) for each
// non-empty one.
function eachLine(text, comment, visit) {
  const lines = text.split(/\r\n|\n|\r/);
  for (let i = 0; i < lines.length; i++) {
    const cut = lines[i].indexOf(comment);
    const body = (cut >= 0 ? lines[i].slice(0, cut) : lines[i]).trim();
    if (body) visit(body.split(/\s+/), i + 1);
  }
}

function parseCoordinate(token, line) {
  const v = Number(token);
  // (NaN and infinities are read as such: the package reports NON_FINITE_COORDINATE)
  if (Number.isNaN(v) && !/^[+-]?nan$/i.test(token)) throw new MeshParseError(`line ${line}: "${token.slice(0, 20)}" is not a number`);
  return v;
}

// The faces' loops and sizes as typed arrays; faceSizes only when some face is not a triangle.
function polygonMesh(positions, loops, sizes) {
  const mesh = { positions, indices: Uint32Array.from(loops) };
  if (sizes.some((k) => k !== 3)) mesh.faceSizes = Uint32Array.from(sizes);
  return mesh;
}

// OBJ: "v x y z [w]" and "f a b c …" with a, b, c in the forms i, i/t, i//n, i/t/n (1-based, or
// negative: counted back from the last vertex so far); '#' starts a comment; other records
// (vt, vn, g, o, s, usemtl, mtllib, l, p, …) are ignored.
export function parseOBJ(buffer) {
  const xyz = [];
  const loops = [], sizes = [];
  eachLine(decodeText(buffer), '#', (t, line) => {
    if (t[0] === 'v') {
      if (t.length < 4) throw new MeshParseError(`line ${line}: a vertex needs 3 coordinates`);
      for (let k = 1; k <= 3; k++) xyz.push(parseCoordinate(t[k], line));
    } else if (t[0] === 'f') {
      if (t.length < 4) throw new MeshParseError(`line ${line}: a face needs at least 3 vertices (found ${t.length - 1})`);
      const nv = xyz.length / 3;
      for (let k = 1; k < t.length; k++) {
        const ref = t[k].split('/')[0];
        if (!/^[+-]?\d+$/.test(ref)) throw new MeshParseError(`line ${line}: "${t[k].slice(0, 20)}" is not a vertex reference`);
        const i = Number(ref);
        if (i === 0) throw new MeshParseError(`line ${line}: vertex index 0 (OBJ counts from 1)`);
        if (i > 0xffffffff) throw new MeshParseError(`line ${line}: vertex index ${ref.slice(0, 20)} is too large`);
        if (i < 0 && nv + i < 0) throw new MeshParseError(`line ${line}: vertex ${i} counts back past the first vertex`);
        loops.push(i > 0 ? i - 1 : nv + i);
      }
      sizes.push(t.length - 1);
    }
  });
  if (sizes.length === 0) throw new MeshParseError('no faces found in the OBJ file (only points or lines?)', 'EMPTY_INPUT');
  // Weld by exact coordinate equality (references past the last vertex are left for the package
  // to report).
  const nv = xyz.length / 3;
  const map = new Map(), weldedOf = new Uint32Array(nv), positions = [];
  for (let v = 0; v < nv; v++) {
    const key = `${xyz[3 * v]},${xyz[3 * v + 1]},${xyz[3 * v + 2]}`;
    let id = map.get(key);
    if (id === undefined) {
      id = positions.length / 3;
      map.set(key, id);
      positions.push(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]);
    }
    weldedOf[v] = id;
  }
  const welded = positions.length / 3;
  for (let i = 0; i < loops.length; i++) loops[i] = loops[i] < nv ? weldedOf[loops[i]] : welded + (loops[i] - nv);
  return polygonMesh(Float64Array.from(positions), loops, sizes);
}

// OFF: optional header word (OFF, COFF, NOFF, STOFF, …), counts "V F E", V vertex lines (x y z,
// extra values such as colours ignored), F face lines "n i1 … in" (colours ignored); '#' starts a
// comment. Polygons are kept (faceSizes).
export function parseOFF(buffer) {
  const lines = decodeText(buffer).split(/\r\n|\n|\r/);
  let li = 0;
  const next = () => {
    while (li < lines.length) {
      const raw = lines[li++];
      const text = raw.replace(/#.*/, '').trim();
      if (text) return { tokens: text.split(/\s+/), line: li };
    }
    return null;
  };
  const fail = (line, why) => {
    throw new MeshParseError(line ? `line ${line}: ${why}` : why);
  };
  let rec = next();
  if (!rec) fail(0, 'the file is empty');
  if (/^[A-Z0-9]*OFF$/i.test(rec.tokens[0])) {
    rec.tokens.shift();
    if (rec.tokens.length === 0) rec = next();
  } else if (!/^\d+$/.test(rec.tokens[0])) {
    fail(rec.line, `expected an OFF header, found "${rec.tokens[0].slice(0, 20)}"`);
  }
  if (!rec || rec.tokens.length < 2) fail(rec?.line ?? 0, 'expected the counts "vertices faces edges"');
  const nv = Number(rec.tokens[0]), nf = Number(rec.tokens[1]);
  if (!Number.isInteger(nv) || !Number.isInteger(nf) || nv < 0 || nf < 0) fail(rec.line, 'invalid vertex/face counts');
  const positions = new Float64Array(3 * nv);
  for (let i = 0; i < nv; i++) {
    const r = next();
    if (!r) fail(0, `the file ends after ${i} of ${nv} vertices`);
    if (r.tokens.length < 3) fail(r.line, 'a vertex needs 3 coordinates');
    for (let k = 0; k < 3; k++) {
      const v = Number(r.tokens[k]);
      if (Number.isNaN(v) && !/^nan$/i.test(r.tokens[k])) fail(r.line, `"${r.tokens[k].slice(0, 20)}" is not a number`);
      positions[3 * i + k] = v;
    }
  }
  const loops = [], sizes = [];
  for (let f = 0; f < nf; f++) {
    const r = next();
    if (!r) fail(0, `the file ends after ${f} of ${nf} faces`);
    const n = Number(r.tokens[0]);
    if (!Number.isInteger(n) || n < 3) fail(r.line, `a face needs at least 3 vertices (found "${r.tokens[0]}")`);
    if (r.tokens.length < n + 1) fail(r.line, `face lists ${r.tokens.length - 1} of ${n} vertex indices`);
    for (let k = 1; k <= n; k++) {
      const t = r.tokens[k];
      if (!/^\d+$/.test(t)) fail(r.line, `"${t.slice(0, 20)}" is not a vertex index`);
      if (Number(t) > 0xffffffff) fail(r.line, `vertex index ${t.slice(0, 20)} is too large`);
      loops.push(Number(t));
    }
    sizes.push(n);
  }
  if (nv === 0 || nf === 0) throw new MeshParseError('the file has no vertices or no faces', 'EMPTY_INPUT');
  return polygonMesh(positions, loops, sizes);
}

export function parseMeshFile(name, buffer) {
  const ext = extensionOf(name);
  let mesh;
  if (ext === 'stl') mesh = parseSTL(buffer);
  else if (ext === 'obj') mesh = parseOBJ(buffer);
  else if (ext === 'off') mesh = parseOFF(buffer);
  else throw new MeshParseError(`unsupported file type ".${ext}" (use STL, OBJ or OFF)`);
  return { ...mesh, format: ext.toUpperCase() };
}
