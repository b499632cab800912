// Mesh files → { positions: Float64Array (xyz), indices: Uint32Array, faceSizes?: Uint32Array }.
//
// Small readers of ours that follow the native ones (core/src/io.cpp), so that the page computes
// the kernel of the same mesh as the CLI: coordinates in double precision (ascii STL, OBJ, OFF;
// binary STL stores float32, which converts exactly), OBJ and OFF polygon faces kept as polygons
// (indices holds the loops one after another and faceSizes their lengths, absent when every face
// is a triangle: how the package takes polygons), STL corners welded by exact coordinate equality
// (a triangle soup welded so is closed exactly when the file is; a rounded grid, as
// BufferGeometryUtils.mergeVertices uses, merges distinct vertices of small models). three.js's
// loaders, used before, rounded every coordinate to float32 and split polygons as fans from their
// first corner, which fold over a non-convex polygon and give the kernel of another shape. OBJ
// and OFF vertices are kept as given (the CLI refuses two at one position, and so does the page).
// What a reader refuses, and with which code (PARSE_ERROR, EMPTY_INPUT), is what the CLI's reader
// refuses: the same line and token rules, the same number grammar, indices range-checked; the
// kernel package then validates the mesh itself (OPEN_MESH, NON_MANIFOLD_EDGE, …).

export class MeshParseError extends Error {
  // code: PARSE_ERROR, or EMPTY_INPUT for a file without faces (the native readers' codes)
  constructor(message, code = 'PARSE_ERROR') {
    super(message);
    this.name = 'MeshParseError';
    this.code = code;
  }
}

// A reader's refusal at a line (the native readers' "<file>:<line>: <reason>", without the file).
function fail(line, why) {
  throw new MeshParseError(`line ${line}: ${why}`);
}

export const SUPPORTED_EXTENSIONS = ['stl', 'obj', 'off'];

export function extensionOf(name) {
  const m = /\.([a-z0-9]+)$/i.exec(name);
  return m ? m[1].toLowerCase() : '';
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

// Welds corners (xyz each, finite) by exact coordinate equality (-0 equals 0) into positions and
// one id per corner: an open-addressing hash table over the coordinates' bits.
class Welder {
  constructor() {
    this.xyz = new Float64Array(3 * 1024);
    this.count = 0;
    this.slots = new Int32Array(2048).fill(-1);
    this.bits = new Float64Array(1);
    this.words = new Uint32Array(this.bits.buffer);
  }
  hash(x, y, z) {
    let h = 0x811c9dc5;
    for (const v of [x, y, z]) {
      this.bits[0] = v;
      h = Math.imul(h ^ this.words[0], 0x9e3779b1);
      h = Math.imul(h ^ this.words[1], 0x85ebca77);
    }
    return (h ^ (h >>> 15)) >>> 0;
  }
  add(x, y, z) {
    x += 0; // (-0 + 0 = +0: equal coordinates hash alike)
    y += 0;
    z += 0;
    const xyz = this.xyz, slots = this.slots, mask = slots.length - 1;
    for (let i = this.hash(x, y, z) & mask; ; i = (i + 1) & mask) {
      const id = slots[i];
      if (id < 0) {
        slots[i] = this.count;
        break;
      }
      if (xyz[3 * id] === x && xyz[3 * id + 1] === y && xyz[3 * id + 2] === z) return id;
    }
    if (3 * this.count + 3 > this.xyz.length) {
      const grown = new Float64Array(2 * this.xyz.length);
      grown.set(this.xyz);
      this.xyz = grown;
    }
    this.xyz[3 * this.count] = x;
    this.xyz[3 * this.count + 1] = y;
    this.xyz[3 * this.count + 2] = z;
    const id = this.count++;
    if (2 * this.count > slots.length) this.rehash();
    return id;
  }
  rehash() {
    const slots = new Int32Array(2 * this.slots.length).fill(-1), mask = slots.length - 1;
    for (let id = 0; id < this.count; id++) {
      let i = this.hash(this.xyz[3 * id], this.xyz[3 * id + 1], this.xyz[3 * id + 2]) & mask;
      while (slots[i] >= 0) i = (i + 1) & mask;
      slots[i] = id;
    }
    this.slots = slots;
  }
  get positions() {
    return this.xyz.slice(0, 3 * this.count);
  }
}

// STL: binary when its size is 84 + 50 × the header's triangle count, else ascii if it starts with
// "solid" (many binary files start their header with "solid" too), as the native reader decides.
export function parseSTL(buffer) {
  const bytes = new Uint8Array(buffer.buffer ?? buffer, buffer.byteOffset ?? 0, buffer.byteLength);
  if (bytes.length === 0) throw new MeshParseError('empty file', 'EMPTY_INPUT');
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const declared = bytes.length >= 84 ? view.getUint32(80, true) : -1;
  const badSize = () =>
    new MeshParseError(`byte 80: binary STL header declares ${declared} triangles (${84 + 50 * declared} bytes) but the file has ` +
      `${bytes.length} bytes (room for ${Math.floor((bytes.length - 84) / 50)} triangles)`);
  if (declared >= 0 && 84 + 50 * declared === bytes.length) {
    if (declared === 0) throw new MeshParseError('no triangles', 'EMPTY_INPUT');
    const welder = new Welder();
    const indices = new Uint32Array(3 * declared);
    for (let t = 0; t < declared; t++) {
      for (let c = 0; c < 3; c++) {
        const at = 84 + 50 * t + 12 + 12 * c;
        const x = view.getFloat32(at, true), y = view.getFloat32(at + 4, true), z = view.getFloat32(at + 8, true);
        if (!Number.isFinite(x + y + z)) throw new MeshParseError(`byte ${at}: non-finite coordinate in triangle ${t} (vertex ${c})`);
        indices[3 * t + c] = welder.add(x, y, z);
      }
    }
    return { positions: welder.positions, indices };
  }
  const text = new TextDecoder().decode(bytes);
  if (/^[ \t\r\v\f\n]*solid([ \t\r\v\f\n]|$)/i.test(text)) {
    try {
      return parseAsciiSTL(text);
    } catch (e) {
      // A NUL byte means binary data whose header happens to start with "solid": the real
      // problem is then its triangle count, not its "text".
      if (e.code === 'PARSE_ERROR' && declared >= 0 && bytes.includes(0)) throw badSize();
      throw e;
    }
  }
  if (declared < 0) throw new MeshParseError(`byte 0: not an STL file: ${bytes.length} bytes is shorter than a binary STL header (84 bytes) and the text does not start with 'solid'`);
  throw badSize();
}

function parseAsciiSTL(text) {
  const welder = new Welder();
  const indices = [];
  let state = 'outside', count = 0, c0 = 0, c1 = 0, c2 = 0;
  let lastLine = 0;
  const expectEnd = (t, n, keyword, line) => {
    if (t.length > n) fail(line, `unexpected "${t[n].slice(0, 20)}" after '${keyword}'`);
  };
  const unexpected = (t, line, what) => fail(line, `expected ${what}, found "${t[0].slice(0, 20)}"`);
  eachLine(text, null, (t, line) => {
    lastLine = line;
    // (the usual spelling first: lower-case keywords)
    const word = t[0] === 'vertex' || t[0] === 'facet' || t[0] === 'endfacet' || t[0] === 'outer' || t[0] === 'endloop' ? t[0] : t[0].toLowerCase();
    if (state === 'loop') {
      if (word === 'vertex') {
        if (count === 3) fail(line, 'facet has more than 3 vertices');
        if (t.length < 4) fail(line, `vertex needs 3 coordinates, found ${t.length - 1}`);
        const id = welder.add(parseNumber(t[1], line), parseNumber(t[2], line), parseNumber(t[3], line));
        expectEnd(t, 4, 'vertex x y z', line);
        if (count === 0) c0 = id;
        else if (count === 1) c1 = id;
        else c2 = id;
        ++count;
      } else if (word === 'endloop') {
        if (count !== 3) fail(line, `facet has ${count} vertices (3 needed)`);
        expectEnd(t, 1, 'endloop', line);
        state = 'after';
      } else unexpected(t, line, "'vertex' or 'endloop'");
    } else if (state === 'solid') {
      if (word === 'facet') {
        if ((t[1] ?? '').toLowerCase() !== 'normal') fail(line, "expected 'facet normal nx ny nz'");
        for (let k = 2; k < 5; k++) {
          if (t[k] === undefined) fail(line, 'facet normal needs 3 components');
          // (some exporters write nan for degenerate facets' normals: harmless, nobody reads them;
          // a non-finite component is accepted as the CLI accepts it)
          if (numberStatus(t[k]) === 'invalid') fail(line, `invalid number "${t[k].slice(0, 20)}"`);
        }
        expectEnd(t, 5, 'facet normal', line);
        state = 'facet';
      } else if (word === 'endsolid') state = 'outside';
      else unexpected(t, line, "'facet' or 'endsolid'");
    } else if (state === 'facet') {
      if (word !== 'outer' || (t[1] ?? '').toLowerCase() !== 'loop') fail(line, `expected 'outer loop', found "${t[0].slice(0, 20)}"`);
      expectEnd(t, 2, 'outer loop', line);
      state = 'loop';
      count = 0;
    } else if (state === 'after') {
      if (word !== 'endfacet') unexpected(t, line, "'endfacet'");
      expectEnd(t, 1, 'endfacet', line);
      indices.push(c0, c1, c2);
      state = 'solid';
    } else {
      if (word !== 'solid') unexpected(t, line, "'solid'");
      state = 'solid'; // the rest of the line is the solid's name
    }
  });
  // A missing final "endsolid" is tolerated (common in hand-written files); a cut facet is not.
  if (state !== 'outside' && state !== 'solid') fail(lastLine, 'unexpected end of file inside a facet');
  if (indices.length === 0) throw new MeshParseError('no facets', 'EMPTY_INPUT');
  return { positions: welder.positions, indices: Uint32Array.from(indices) };
}

// The native readers' lines and tokens: lines end at '\n' only (a '\r' is a blank, so "\r\n" files
// read alike and a file of lone '\r's is one line, as in the CLI), tokens are separated by the
// blanks space, '\t', '\r', '\v' and '\f' (not by other Unicode spaces, which the CLI reads as
// part of a token). comment: the character that starts a comment, or null.
const BLANKS = /[ \t\r\v\f]+/;
function tokensOf(line, comment) {
  const cut = comment ? line.indexOf(comment) : -1;
  const tokens = (cut >= 0 ? line.slice(0, cut) : line).split(BLANKS);
  if (tokens.length && tokens[tokens.length - 1] === '') tokens.pop();
  if (tokens.length && tokens[0] === '') tokens.shift();
  return tokens;
}
// Calls visit(tokens, lineNumber) for each line with a token.
function eachLine(text, comment, visit) {
  const lines = text.split('\n');
  for (let i = 0; i < lines.length; i++) {
    const tokens = tokensOf(lines[i], comment);
    if (tokens.length) visit(tokens, i + 1);
  }
}

// The native readers' integers: [+]digits or -digits (no other sign, no decimal point); counts
// and sizes, which must not be negative: [+]digits.
const INTEGER = /^(\+?\d+|-\d+)$/;
const COUNT = /^\+?\d+$/;

// A number as the native readers take it: [+-](digits[.digits] | .digits)[(e|E)[+-]digits]; inf,
// infinity, nan, nan(…) and numbers too large for a double are non-finite, anything else is not
// a number. 'ok', 'nonfinite' or 'invalid'. (Fast path: Number() agrees on every finite token
// that starts with a sign, a digit or '.' and ends with a digit or '.', but hex, binary and octal
// ones; those ends keep it from trimming spaces such as U+00A0, which the CLI reads as part of
// the token.)
const DECIMAL = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/;
const NON_FINITE = /^[+-]?(inf|infinity|nan|nan\(.*\))$/i;
function numberStatus(token) {
  const first = token.charCodeAt(0), last = token.charCodeAt(token.length - 1);
  const second = token.charCodeAt(1) | 32; // (lower case)
  const v = Number(token);
  if (Number.isFinite(v) && ((first >= 48 && first <= 57) || first === 43 || first === 45 || first === 46) &&
      ((last >= 48 && last <= 57) || last === 46) && second !== 120 && second !== 98 && second !== 111) return 'ok'; // x, b, o
  if (DECIMAL.test(token)) return Number.isFinite(v) ? 'ok' : 'nonfinite';
  return NON_FINITE.test(token) ? 'nonfinite' : 'invalid';
}

// A coordinate: a finite number, else a MeshParseError naming the line.
function parseNumber(token, line) {
  const status = token === undefined ? 'invalid' : numberStatus(token);
  if (status === 'ok') return Number(token);
  if (status === 'nonfinite') fail(line, `non-finite coordinate "${token.slice(0, 20)}"`);
  fail(line, `invalid number "${String(token).slice(0, 20)}"`);
}

// The faces' loops and sizes as typed arrays; faceSizes only when some face is not a triangle.
function polygonMesh(positions, loops, sizes) {
  const mesh = { positions, indices: Uint32Array.from(loops) };
  if (sizes.some((k) => k !== 3)) mesh.faceSizes = Uint32Array.from(sizes);
  return mesh;
}

// OBJ: "v x y z [w]" and "f a b c …" (or "fo") with a, b, c in the forms i, i/t, i//n, i/t/n
// (1-based, or negative: counted back from the last vertex so far; t and n integers or empty); a
// positive index may refer to a vertex defined further down, and is checked at the end; '#'
// starts a comment; other records (vt, vn, g, o, s, usemtl, mtllib, l, p, …) are ignored.
export function parseOBJ(buffer) {
  const xyz = [];
  const loops = [], sizes = [];
  let largest = 0, largestLine = 0, pointsAndLines = 0;
  eachLine(decodeText(buffer), '#', (t, line) => {
    if (t[0] === 'v') {
      if (t.length < 4) fail(line, `vertex needs 3 coordinates, found ${t.length - 1}`);
      for (let k = 1; k <= 3; k++) xyz.push(parseNumber(t[k], line));
    } else if (t[0] === 'f' || t[0] === 'fo') {
      const nv = xyz.length / 3;
      for (let k = 1; k < t.length; k++) {
        const parts = t[k].split('/');
        const bad = () => fail(line, `invalid face vertex "${t[k].slice(0, 20)}"`);
        if (parts.length > 3 || !INTEGER.test(parts[0])) bad();
        for (let p = 1; p < parts.length; p++) if (parts[p] !== '' && !INTEGER.test(parts[p])) bad();
        const i = Number(parts[0]);
        if (i === 0) fail(line, 'vertex index 0 (OBJ indices start at 1)');
        if (i < 0) {
          if (-i > nv) fail(line, `relative vertex index ${parts[0]} points before the first vertex (${nv} vertices so far)`);
          loops.push(nv + i);
        } else {
          if (i > 0xffffffff) fail(line, `vertex index ${parts[0].slice(0, 20)} out of range`);
          if (i > largest) {
            largest = i;
            largestLine = line;
          }
          loops.push(i - 1);
        }
      }
      if (t.length < 4) fail(line, `face has ${t.length - 1} vertices (at least 3 needed)`);
      sizes.push(t.length - 1);
    } else if (t[0] === 'l' || t[0] === 'p') {
      pointsAndLines++;
    }
  });
  const nv = xyz.length / 3;
  if (largest > nv) fail(largestLine, `vertex index ${largest} out of range (the file has ${nv} vertices)`);
  if (sizes.length === 0) {
    throw new MeshParseError(pointsAndLines ? 'no faces (only points/lines)' : nv ? 'no faces' : 'no vertices and no faces', 'EMPTY_INPUT');
  }
  // Vertices are kept as the file gives them (not welded): two at one position are the CLI's
  // NON_MANIFOLD_EDGE ("weld them, or separate the pieces") here too.
  return polygonMesh(Float64Array.from(xyz), loops, sizes);
}

// OFF: the header word [ST][C][N]OFF (texture coordinates, colours and normals after xyz are
// ignored; 4OFF, nOFF and binary OFF are refused), the counts "V F [E]" on its line or the next,
// V vertex lines (x y z, then anything), F face lines "n i1 … in" (then anything, e.g. a colour);
// '#' starts a comment. Polygons are kept (faceSizes).
export function parseOFF(buffer) {
  const lines = decodeText(buffer).split('\n');
  const lastLine = lines.length - (lines[lines.length - 1] === '' ? 1 : 0); // (the CLI's count at the end)
  let li = 0;
  const next = () => {
    while (li < lines.length) {
      const tokens = tokensOf(lines[li++], '#');
      if (tokens.length) return { tokens, line: li };
    }
    return null;
  };
  let rec = next();
  if (!rec) throw new MeshParseError('empty file', 'EMPTY_INPUT');
  const keyword = rec.tokens[0];
  const kind = /^(ST)?C?N?([4n]?)OFF$/.exec(keyword);
  if (!kind) fail(rec.line, `expected an OFF header, found "${keyword.slice(0, 20)}"`);
  if (kind[2]) fail(rec.line, '4D / n-dimensional OFF is not supported');
  let at = 1;
  if (rec.tokens.length === 1) {
    const headerLine = rec.line;
    rec = next();
    if (!rec) fail(headerLine, 'missing vertex/face counts');
    at = 0;
  } else if (rec.tokens[1].toLowerCase() === 'binary') {
    fail(rec.line, 'binary OFF is not supported');
  }
  const count = (what) => {
    const token = rec.tokens[at++];
    if (token === undefined) fail(rec.line, `missing ${what} count`);
    if (!COUNT.test(token)) fail(rec.line, `invalid ${what} count "${token.slice(0, 20)}"`);
    return Number(token);
  };
  const nv = count('vertex'), nf = count('face');
  // (Arrays grow as read: a header's counts are not trusted for an allocation.)
  const xyz = [];
  for (let i = 0; i < nv; i++) {
    const r = next();
    if (!r) fail(lastLine, `unexpected end of file: ${i} of ${nv} vertices read`);
    if (r.tokens.length < 3) fail(r.line, `vertex needs 3 coordinates, found ${r.tokens.length}`);
    for (let k = 0; k < 3; k++) xyz.push(parseNumber(r.tokens[k], r.line));
  }
  const loops = [], sizes = [];
  for (let f = 0; f < nf; f++) {
    const r = next();
    if (!r) fail(lastLine, `unexpected end of file: ${f} of ${nf} faces read`);
    const t = r.tokens;
    if (!COUNT.test(t[0])) fail(r.line, `invalid face size "${t[0].slice(0, 20)}"`);
    const n = Number(t[0]);
    if (n < 3) fail(r.line, `face has ${n} vertices (at least 3 needed)`);
    for (let k = 1; k <= n; k++) {
      if (k >= t.length) fail(r.line, `face declares ${n} vertices but the line has only ${k - 1}`);
      if (!INTEGER.test(t[k])) fail(r.line, `invalid vertex index "${t[k].slice(0, 20)}"`);
      const i = Number(t[k]);
      if (i < 0 || i >= nv) fail(r.line, `vertex index ${t[k].slice(0, 20)} out of range (the file has ${nv} vertices)`);
      loops.push(i);
    }
    sizes.push(n);
  }
  if (nf === 0) throw new MeshParseError(nv === 0 ? 'no vertices and no faces' : 'no faces', 'EMPTY_INPUT');
  return polygonMesh(Float64Array.from(xyz), loops, sizes);
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
