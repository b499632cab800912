// The heap blocks shared with wasm/bindings.cpp (layouts declared there, read from W): the
// request written into the heap, the result block and step events copied out of it.
import { KergenError } from './errors.js';
import { W } from './load.js';
import { inJsWords } from './checks.js';

// Data crosses as one request block and one result block instead of embind values: each embind
// value costs JS<->wasm round trips, which on small meshes cost as much as the computation.

export const OUT_OF_MEMORY = 'out of memory (the wasm heap is limited to 4 GB)';
const textDecoder = new TextDecoder();

// An option slot: NaN = not given (the core's default applies), booleans as 1 / 0.
const slot = (v) => (v === undefined ? NaN : Number(v));

// Writes the checked options into the option slots at f64 index `at` of `f64` (a heap view).
export function writeOptionSlots(f64, at, opts) {
  const o = W.option;
  const from = opts.from;
  f64[at + o.fromX] = from ? from[0] : NaN;
  f64[at + o.fromY] = from ? from[1] : NaN;
  f64[at + o.fromZ] = from ? from[2] : NaN;
  f64[at + o.maxSteps] = slot(opts.maxSteps);
  f64[at + o.allowOpen] = slot(opts.allowOpen);
  f64[at + o.deepestPoint] = slot(opts.deepestPoint);
  f64[at + o.maxFaces] = slot(opts.maxFaces);
  f64[at + o.maxVertices] = slot(opts.maxVertices);
  f64[at + o.cullFaces] = slot(opts.cullFaces);
  f64[at + o.seed] = slot(opts.seed);
  f64[at + o.weld] = opts.weld ? opts.weld.distance : NaN;
  f64[at + o.weldRelative] = opts.weld ? Number(opts.weld.relative) : NaN;
  f64[at + o.repair] = slot(opts.repair);
  f64[at + o.openBoundary] = slot(opts.openBoundary);
  f64[at + o.flipFaces] = slot(opts.flipFaces);
}

// Copies the mesh and the checked options into one malloc'd block; returns its address (the
// caller frees it).
export function writeRequest(m, positions, indices, faceSizes, opts) {
  const numFaceSizes = faceSizes ? faceSizes.length : 0;
  const slots = W.option.slots;
  const bytes = 8 * (slots + positions.length) + 4 * (indices.length + numFaceSizes);
  // malloc takes a 32-bit size; anything larger cannot fit into the heap anyway.
  const ptr = bytes < 2 ** 32 ? m._malloc(bytes) : 0;
  if (!ptr) throw new KergenError('OUT_OF_MEMORY', OUT_OF_MEMORY);
  // Views are read after malloc: growing the heap replaces them.
  const f64 = m.HEAPF64;
  const at = ptr / 8;
  writeOptionSlots(f64, at, opts);
  f64.set(positions, at + slots);
  const u32 = m.HEAPU32;
  const indexAt = (at + slots + positions.length) * 2;
  u32.set(indices, indexAt);
  if (numFaceSizes) u32.set(faceSizes, indexAt + indices.length);
  return ptr;
}

// A step event from the StepOut at `address` (valid during the callback).
export function readStep(m, address) {
  const u32 = m.HEAPU32;
  const st = W.step;
  const kind = W.stepKinds[u32[(address + st.kind) / 4]];
  const id = u32[(address + st.id) / 4];
  if (kind === 'vertex') {
    const f64 = m.HEAPF64;
    const d = (address + st.position) / 8;
    return { type: 'vertex', id, position: [f64[d], f64[d + 1], f64[d + 2]] };
  }
  if (kind === 'edge') return { type: 'edge', id, a: u32[(address + st.a) / 4], b: u32[(address + st.b) / 4] };
  const first = u32[(address + st.loop) / 4] / 4;
  const loop = [];
  for (let i = 0, n = u32[(address + st.loopSize) / 4]; i < n; i++) loop.push(u32[first + i]);
  return { type: 'face', id, loop };
}

// The NUL-terminated strings from byte `start` to `end`. ASCII (the core's names and messages) is
// decoded here: a TextDecoder call costs more than the short status string it would decode.
export function readStrings(u8, start, end) {
  const out = [];
  let s = '';
  for (let i = start; i < end; i++) {
    const c = u8[i];
    if (c === 0) {
      out.push(s);
      s = '';
    } else if (c < 0x80) {
      s += String.fromCharCode(c);
    } else {
      return textDecoder.decode(u8.subarray(start, end)).split('\0');
    }
  }
  return out;
}

// The result block's stats: kergen::stats_fields in order, named as the layout names them (in
// camelCase). The object gets its keys in the same order every call, so V8 gives every result
// the same shape.
function readStats(f64, st) {
  const out = {};
  const names = W.statsKeys;
  for (let i = 0; i < names.length; i++) out[names[i]] = f64[st + i];
  return out;
}

const xyz = (f64, at) => [f64[at], f64[at + 1], f64[at + 2]];

// Copies a result block out of the heap into plain JS values and frees it. Returns
// { error, message } or the fields of a result (findPoint's point is in kernelPoint).
export function readResult(m, ptr) {
  if (!ptr) throw new KergenError('OUT_OF_MEMORY', OUT_OF_MEMORY);
  try {
    const u32 = m.HEAPU32;
    const f64 = m.HEAPF64;
    const h = ptr / 4;
    const H = W.head;
    const S = W.scalar;
    const numWarnings = u32[h + H.numWarnings];
    const s = (ptr + 4 * H.words) / 8; // scalars
    const counts = s + S.count; // warning counts
    const v = counts + numWarnings;
    // The eight arrays lie back to back in the block (the vertices' f64 values, then the 32-bit
    // arrays): one copy into one fresh buffer, then views of it. (Each fresh typed array of more
    // than a few values costs about a microsecond in V8, most of a tiny mesh's overhead here.)
    const numVertexValues = u32[h + H.numVertexValues];
    const numEdgeValues = u32[h + H.numEdgeValues];
    const numFaceIndices = u32[h + H.numFaceIndices];
    const numFaces = u32[h + H.numFaces];
    const numTriangleValues = u32[h + H.numTriangleValues];
    const numWitnessFaces = u32[h + H.numWitnessFaces];
    const numFaceSources = u32[h + H.numFaceSources];
    const numWallEdgeValues = u32[h + H.numWitnessBoundaryEdgeValues];
    const arraysStart = v * 8;
    const u32Values =
      numEdgeValues +
      numFaceIndices +
      numFaces +
      numTriangleValues +
      numWitnessFaces +
      numFaceSources +
      numWallEdgeValues;
    const arrays = m.HEAPU8.slice(arraysStart, arraysStart + 8 * numVertexValues + 4 * u32Values).buffer;
    const vertices = new Float64Array(arrays, 0, numVertexValues);
    let at = 8 * numVertexValues;
    const edges = new Uint32Array(arrays, at, numEdgeValues);
    const faceIndices = new Uint32Array(arrays, (at += 4 * numEdgeValues), numFaceIndices);
    const faceSizes = new Uint32Array(arrays, (at += 4 * numFaceIndices), numFaces);
    const triangles = new Uint32Array(arrays, (at += 4 * numFaces), numTriangleValues);
    const witnessFaces = new Uint32Array(arrays, (at += 4 * numTriangleValues), numWitnessFaces);
    const faceSources = new Int32Array(arrays, (at += 4 * numWitnessFaces), numFaceSources);
    const witnessBoundaryEdges = new Uint32Array(arrays, (at += 4 * numFaceSources), numWallEdgeValues);
    const bytesStart = (v * 2 + 2 * numVertexValues + u32Values) * 4;
    const numBytes = u32[h + H.numBytes];
    const textStart = bytesStart + numBytes;
    const text = readStrings(m.HEAPU8, textStart, textStart + u32[h + H.textBytes]);
    if (u32[h + H.ok] === 0) return { error: text[0], message: text[1] };
    const warnings = new Array(numWarnings);
    for (let i = 0; i < numWarnings; i++) {
      warnings[i] = { kind: text[2 + 2 * i], count: f64[counts + i], message: inJsWords(text[3 + 2 * i]) };
    }
    const st = s + S.stats;
    return {
      status: text[0],
      message: text[1],
      complete: u32[h + H.complete] !== 0,
      starShaped: u32[h + H.starShaped] !== 0,
      vertices,
      edges,
      faceIndices,
      faceSizes,
      triangles,
      witnessFaces,
      faceSources,
      witnessBoundaryEdges,
      bytes: numBytes ? m.HEAPU8.slice(bytesStart, textStart) : null,
      volume: f64[s + S.volume],
      area: f64[s + S.area],
      shapeVolume: f64[s + S.shapeVolume],
      volumeRatio: f64[s + S.volumeRatio],
      kernelPoint: u32[h + H.hasKernelPoint] ? xyz(f64, s + S.kernelPoint) : null,
      deepestPoint: u32[h + H.hasDeepestPoint] ? xyz(f64, s + S.deepestPoint) : null,
      inscribedRadius: f64[s + S.inscribedRadius],
      warnings,
      stats: readStats(f64, st),
    };
  } finally {
    m._free(ptr);
  }
}

export function shapeResult(raw) {
  const faceIndices = raw.faceIndices;
  const faceSizes = raw.faceSizes;
  const faces = new Array(faceSizes.length);
  for (let f = 0, at = 0; f < faceSizes.length; f++) {
    faces[f] = faceIndices.subarray(at, at + faceSizes[f]);
    at += faceSizes[f];
  }
  if (!W.statuses.includes(raw.status)) throw new KergenError('INTERNAL_ERROR', `unknown kernel status ${raw.status}`);
  return {
    status: raw.status,
    complete: raw.complete,
    vertices: raw.vertices,
    edges: raw.edges,
    faces,
    faceIndices,
    faceSizes,
    triangles: raw.triangles,
    faceSources: raw.faceSources,
    witnessFaces: raw.witnessFaces,
    witnessBoundaryEdges: raw.witnessBoundaryEdges,
    volume: raw.volume,
    area: raw.area,
    shapeVolume: raw.shapeVolume,
    volumeRatio: raw.volumeRatio,
    kernelPoint: raw.kernelPoint,
    deepestPoint: raw.deepestPoint,
    inscribedRadius: raw.inscribedRadius,
    warnings: raw.warnings,
    stats: raw.stats,
  };
}
