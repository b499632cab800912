// Mesh files → { positions: Float64Array (xyz), indices: Uint32Array (triangles) }.
//
// STL (ascii and binary) and OBJ are read with three.js's loaders; OFF, which three.js lacks, with
// the small parser below. Triangle soups (STL, OBJ as three.js returns it) are welded by exact
// coordinate equality — the same rule as the project's native reader — so the welded mesh is
// closed exactly when the file is. (BufferGeometryUtils.mergeVertices hashes coordinates rounded
// to a fixed absolute grid, 1e-4 by default, which merges distinct vertices of small-scale models;
// an exact key cannot.) Indices are not range-checked here: the kernel
// package validates the mesh and reports INDEX_OUT_OF_RANGE, OPEN_MESH, … itself.

import { STLLoader } from 'three/examples/jsm/loaders/STLLoader.js';
import { OBJLoader } from 'three/examples/jsm/loaders/OBJLoader.js';

export class MeshParseError extends Error {
  constructor(message) {
    super(message);
    this.name = 'MeshParseError';
    this.code = 'PARSE_ERROR';
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

function decodeText(buffer) {
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

export function parseOBJ(buffer) {
  let group;
  try {
    group = new OBJLoader().parse(decodeText(buffer));
  } catch (e) {
    throw new MeshParseError(`not a readable OBJ file (${e.message})`);
  }
  const parts = [];
  group.traverse((o) => {
    if (o.isMesh && o.geometry) {
      const g = o.geometry.index ? o.geometry.toNonIndexed() : o.geometry;
      parts.push(g.getAttribute('position').array);
    }
  });
  const total = parts.reduce((s, a) => s + a.length, 0);
  if (total < 9) throw new MeshParseError('no faces found in the OBJ file (only points or lines?)');
  const soup = new Float32Array(total);
  let off = 0;
  for (const a of parts) {
    soup.set(a, off);
    off += a.length;
  }
  return weldExact(soup);
}

// OFF: optional header word (OFF, COFF, NOFF, STOFF, …), counts "V F E", V vertex lines (x y z,
// extra values such as colours ignored), F face lines "n i1 … in" (colours ignored); '#' starts a
// comment. Polygons are fan-triangulated.
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
  const indices = [];
  for (let f = 0; f < nf; f++) {
    const r = next();
    if (!r) fail(0, `the file ends after ${f} of ${nf} faces`);
    const n = Number(r.tokens[0]);
    if (!Number.isInteger(n) || n < 3) fail(r.line, `a face needs at least 3 vertices (found "${r.tokens[0]}")`);
    if (r.tokens.length < n + 1) fail(r.line, `face lists ${r.tokens.length - 1} of ${n} vertex indices`);
    const loop = [];
    for (let k = 1; k <= n; k++) {
      const t = r.tokens[k];
      if (!/^\d+$/.test(t)) fail(r.line, `"${t.slice(0, 20)}" is not a vertex index`);
      loop.push(Number(t));
    }
    for (let k = 1; k + 1 < n; k++) indices.push(loop[0], loop[k], loop[k + 1]);
  }
  if (nv === 0 || nf === 0) fail(0, 'the file has no vertices or no faces');
  return { positions, indices: Uint32Array.from(indices) };
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
