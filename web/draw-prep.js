// What the view needs to draw an input mesh, computed from the parsed mesh without three.js
// objects so it can run in a worker (draw-worker.js) for big meshes and inline for small ones:
// float32 positions relative to the bounding-box centre (float32 rendering of far-from-origin
// models stays accurate), triangles (polygons split by earcut, in the projection along their
// largest normal axis: a fan would fold over a non-convex face), and optionally the faces' edges.
import { Earcut } from 'three/src/extras/Earcut.js';

// Returns { center, radius, maxAbs } of the finite positions' bounding box (maxAbs: the largest
// coordinate magnitude, which places the package's clip box; see unbounded.js).
function bounds(positions) {
  const lo = [Infinity, Infinity, Infinity],
    hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < positions.length; i += 3) {
    const x = positions[i],
      y = positions[i + 1],
      z = positions[i + 2];
    if (!(Number.isFinite(x) && Number.isFinite(y) && Number.isFinite(z))) continue;
    if (x < lo[0]) lo[0] = x;
    if (x > hi[0]) hi[0] = x;
    if (y < lo[1]) lo[1] = y;
    if (y > hi[1]) hi[1] = y;
    if (z < lo[2]) lo[2] = z;
    if (z > hi[2]) hi[2] = z;
  }
  if (!(lo[0] <= hi[0])) return { center: [0, 0, 0], radius: 1, maxAbs: 0 };
  const center = [0, 1, 2].map((c) => (lo[c] + hi[c]) / 2);
  const radius = Math.max(1e-30, Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) / 2);
  const maxAbs = Math.max(...lo.map(Math.abs), ...hi.map(Math.abs));
  return { center, radius, maxAbs };
}

// One polygon (k > 3 vertex ids in `loop`) as triangles appended to `out`.
function splitPolygon(positions, loop, out) {
  const k = loop.length;
  const n = [0, 0, 0];
  for (let i = 0; i < k; i++) {
    const a = 3 * loop[i],
      b = 3 * loop[(i + 1) % k];
    for (let c = 0; c < 3; c++) {
      const c1 = (c + 1) % 3,
        c2 = (c + 2) % 3;
      n[c] += (positions[a + c1] - positions[b + c1]) * (positions[a + c2] + positions[b + c2]);
    }
  }
  const ax = Math.abs(n[0]),
    ay = Math.abs(n[1]),
    az = Math.abs(n[2]);
  const axis = ax >= ay && ax >= az ? 0 : ay >= az ? 1 : 2;
  const u = (axis + 1) % 3,
    w = (axis + 2) % 3;
  const flat = new Array(2 * k);
  for (let i = 0; i < k; i++) {
    flat[2 * i] = positions[3 * loop[i] + u];
    flat[2 * i + 1] = positions[3 * loop[i] + w];
  }
  const tri = Earcut.triangulate(flat, [], 2);
  if (tri.length === 3 * (k - 2)) {
    for (const t of tri) out.push(loop[t]);
  } else {
    // earcut gives up on self-touching loops: a fan still draws something near the face.
    for (let i = 1; i + 1 < k; i++) out.push(loop[0], loop[i], loop[i + 1]);
  }
}

export function drawnTriangles(positions, indices, faceSizes) {
  if (!faceSizes) return indices;
  const out = [];
  for (let f = 0, at = 0; f < faceSizes.length; at += faceSizes[f], f++) {
    const k = faceSizes[f];
    if (k === 3) out.push(indices[at], indices[at + 1], indices[at + 2]);
    else if (k > 3) splitPolygon(positions, indices.subarray(at, at + k), out);
  }
  return Uint32Array.from(out);
}

// Every face's edges as sorted keys min·nv + max (a Float64Array: exact below 2^53, and sorting
// a typed array is several times faster than a Set of a million keys); an edge shared by two
// faces appears twice. Degenerate edges (a face repeating a vertex) are left out.
function sortedEdgeKeys(indices, faceSizes, nv) {
  const nFaces = faceSizes ? faceSizes.length : indices.length / 3;
  const keys = new Float64Array(indices.length);
  let n = 0;
  for (let f = 0, at = 0; f < nFaces; f++) {
    const k = faceSizes ? faceSizes[f] : 3;
    for (let j = 0; j < k; j++) {
      const a = indices[at + j],
        b = indices[at + ((j + 1) % k)];
      if (a !== b) keys[n++] = a < b ? a * nv + b : b * nv + a;
    }
    at += k;
  }
  return keys.subarray(0, n).sort();
}

// The vertex-id pairs of the sorted keys that occur `once` only (or, with once = false, of every
// distinct key).
function edgePairs(sorted, nv, once) {
  const pairs = new Uint32Array(2 * sorted.length);
  let m = 0;
  for (let i = 0; i < sorted.length;) {
    let j = i + 1;
    while (j < sorted.length && sorted[j] === sorted[i]) j++;
    if (!once || j - i === 1) {
      pairs[m++] = Math.floor(sorted[i] / nv);
      pairs[m++] = sorted[i] % nv;
    }
    i = j;
  }
  return pairs.slice(0, m);
}

// The faces' edges, each once (polygons without their drawing diagonals), as vertex-id pairs.
export function faceEdges(indices, faceSizes, nv) {
  return edgePairs(sortedEdgeKeys(indices, faceSizes, nv), nv, false);
}

// Vertex clustering on a grid of `res` cells along the longest side: every vertex moves to the
// mean of its cell's vertices; triangles that collapse are dropped, and so are repeats of a
// triangle (the same three cells: two sheets of the surface folded onto each other, which a
// translucent overlay would draw twice as dark). The shape stays within a cell of the original.
// Each cell's normal is the sum of its original triangles' area-weighted normals, so that the
// copy can be shaded smoothly, as the original surface looks, instead of facet by facet.
function cluster(pos, triangles, res) {
  const lo = [Infinity, Infinity, Infinity],
    hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < pos.length; i++) {
    const c = i % 3;
    if (pos[i] < lo[c]) lo[c] = pos[i];
    if (pos[i] > hi[c]) hi[c] = pos[i];
  }
  const h = Math.max(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) / res || 1;
  const n = [0, 1, 2].map((c) => Math.floor((hi[c] - lo[c]) / h) + 1);
  const cellOf = new Map();
  const remap = new Uint32Array(pos.length / 3);
  const sums = [];
  for (let v = 0; v < remap.length; v++) {
    const ix = Math.floor((pos[3 * v] - lo[0]) / h),
      iy = Math.floor((pos[3 * v + 1] - lo[1]) / h),
      iz = Math.floor((pos[3 * v + 2] - lo[2]) / h);
    const key = ix + n[0] * (iy + n[1] * iz);
    let id = cellOf.get(key);
    if (id === undefined) {
      id = sums.length / 4;
      cellOf.set(key, id);
      sums.push(0, 0, 0, 0);
    }
    remap[v] = id;
    sums[4 * id] += pos[3 * v];
    sums[4 * id + 1] += pos[3 * v + 1];
    sums[4 * id + 2] += pos[3 * v + 2];
    sums[4 * id + 3]++;
  }
  const cells = sums.length / 4;
  const positions = new Float32Array(cells * 3);
  for (let id = 0; id < cells; id++) {
    for (let c = 0; c < 3; c++) positions[3 * id + c] = sums[4 * id + c] / sums[4 * id + 3];
  }
  const normals = new Float32Array(cells * 3);
  const out = new Uint32Array(triangles.length);
  const seen = new Set();
  let m = 0;
  for (let t = 0; t < triangles.length; t += 3) {
    const i = triangles[t],
      j = triangles[t + 1],
      k = triangles[t + 2];
    addNormal(pos, i, j, k, normals, remap);
    const a = remap[i],
      b = remap[j],
      c = remap[k];
    if (a === b || b === c || a === c) continue;
    // The three cells in increasing order, as one number (exact: cells³ < 2^53).
    const s0 = Math.min(a, b, c),
      s2 = Math.max(a, b, c),
      s1 = a + b + c - s0 - s2;
    const key = (s0 * cells + s1) * cells + s2;
    if (seen.has(key)) continue;
    seen.add(key);
    out[m++] = a;
    out[m++] = b;
    out[m++] = c;
  }
  for (let id = 0; id < cells; id++) {
    const x = normals[3 * id],
      y = normals[3 * id + 1],
      z = normals[3 * id + 2];
    const len = Math.hypot(x, y, z) || 1;
    normals[3 * id] = x / len;
    normals[3 * id + 1] = y / len;
    normals[3 * id + 2] = z / len;
  }
  return { positions, triangles: out.slice(0, m), normals };
}

// Adds triangle (i, j, k)'s area-weighted normal to its vertices' cells (each cell once).
function addNormal(pos, i, j, k, normals, remap) {
  const ux = pos[3 * j] - pos[3 * i],
    uy = pos[3 * j + 1] - pos[3 * i + 1],
    uz = pos[3 * j + 2] - pos[3 * i + 2];
  const vx = pos[3 * k] - pos[3 * i],
    vy = pos[3 * k + 1] - pos[3 * i + 1],
    vz = pos[3 * k + 2] - pos[3 * i + 2];
  const nx = uy * vz - uz * vy,
    ny = uz * vx - ux * vz,
    nz = ux * vy - uy * vx;
  const a = remap[i],
    b = remap[j],
    c = remap[k];
  for (const cell of a === b ? (b === c ? [a] : [a, c]) : a === c || b === c ? [a, b] : [a, b, c]) {
    normals[3 * cell] += nx;
    normals[3 * cell + 1] += ny;
    normals[3 * cell + 2] += nz;
  }
}

// A coarser copy of a big surface to draw, with at most about `target` triangles. Software WebGL
// (SwiftShader) spends ~1 s per frame on a million triangles, and with a software compositor the
// page's thread waits for each frame.
export function simplify(pos, triangles, target) {
  // A closed surface on a grid of res cells per side has ~4 res² triangles after clustering.
  let res = Math.max(8, Math.floor(Math.sqrt(target / 4)));
  let best = null;
  for (let attempt = 0; attempt < 4; attempt++) {
    const c = cluster(pos, triangles, res);
    if (!best || c.triangles.length <= 3 * target * 1.2) best = c;
    if (c.triangles.length <= 3 * target * 1.2) break;
    res = Math.max(4, Math.floor(res * Math.sqrt((3 * target) / c.triangles.length) * 0.95));
  }
  return best;
}

/**
 * A simplified copy of a triangulated surface to draw (a big kernel): float64 `vertices` (xyz)
 * moved by -`center` to float32, then simplify()'d to about `maxTriangles`. Returns
 * { positions, triangles }.
 */
export function simplifySurface(vertices, triangles, center, maxTriangles) {
  const pos = new Float32Array(vertices.length);
  for (let i = 0; i < vertices.length; i += 3) {
    pos[i] = vertices[i] - center[0];
    pos[i + 1] = vertices[i + 1] - center[1];
    pos[i + 2] = vertices[i + 2] - center[2];
  }
  return simplify(pos, triangles, maxTriangles);
}

/**
 * mesh: { positions (xyz), indices, faceSizes (null: triangles) }. Returns { center, radius,
 * maxAbs, positions: Float32Array (centred), triangles: Uint32Array, edges: Uint32Array | null,
 * faces, drawable } — drawable is false when a face refers to a missing vertex (the package
 * reports it).
 */
export function prepareDrawing(mesh, { edges = false, maxTriangles = Infinity } = {}) {
  const { positions, indices, faceSizes } = mesh;
  const nv = positions.length / 3;
  const { center, radius, maxAbs } = bounds(positions);
  const faces = faceSizes ? faceSizes.length : indices.length / 3;
  let drawable = nv > 0;
  for (let i = 0; i < indices.length && drawable; i++) if (!(indices[i] < nv)) drawable = false;
  if (!drawable)
    return {
      center,
      radius,
      maxAbs,
      faces,
      drawable,
      positions: new Float32Array(0),
      triangles: new Uint32Array(0),
      edges: null,
    };
  const pos = new Float32Array(3 * nv);
  for (let i = 0; i < 3 * nv; i += 3) {
    pos[i] = positions[i] - center[0];
    pos[i + 1] = positions[i + 1] - center[1];
    pos[i + 2] = positions[i + 2] - center[2];
  }
  const triangles = drawnTriangles(positions, indices, faceSizes);
  if (triangles.length / 3 > maxTriangles) {
    // Drawn simplified; `edges` then are the drawn triangles' edges.
    const s = simplify(pos, triangles, maxTriangles);
    return {
      center,
      radius,
      maxAbs,
      faces,
      drawable,
      simplified: true,
      positions: s.positions,
      triangles: s.triangles,
      normals: s.normals,
      edges: edges ? faceEdges(s.triangles, null, s.positions.length / 3) : null,
    };
  }
  return {
    center,
    radius,
    maxAbs,
    faces,
    drawable,
    simplified: false,
    positions: pos,
    triangles,
    edges: edges ? faceEdges(indices, faceSizes, nv) : null,
  };
}

/** The buffers of a prepareDrawing() result, for a transfer list. */
export function drawingBuffers(d) {
  return [
    ...new Set(
      [d.positions.buffer, d.triangles.buffer, d.edges?.buffer, d.normals?.buffer].filter((b) => b && b.byteLength > 0),
    ),
  ];
}

// The edges used by one face only (a hole's rim), as vertex-id pairs: the keys of faceEdges()
// that occur once. (An edge used by three or more faces is a non-manifold edge, not an open one:
// the package reports it as NON_MANIFOLD_EDGE.)
export function boundaryEdges(indices, faceSizes, nv) {
  return edgePairs(sortedEdgeKeys(indices, faceSizes, nv), nv, true);
}

// Line-segment positions (float32, relative to `center`) of vertex-id pairs.
function segmentPositions(positions, pairs, center) {
  const out = new Float32Array(3 * pairs.length);
  for (let i = 0; i < pairs.length; i++) {
    for (let c = 0; c < 3; c++) out[3 * i + c] = positions[3 * pairs[i] + c] - center[c];
  }
  return out;
}

// Each vertex's first vertex at exactly the same position: a triangle soup (a glTF scene, which
// the package welds before computing) has every corner on its own, and all its edges would count
// as open.
function samePositionIds(positions) {
  const first = new Map();
  const ids = new Uint32Array(positions.length / 3);
  for (let v = 0; v < ids.length; v++) {
    const key = `${positions[3 * v]},${positions[3 * v + 1]},${positions[3 * v + 2]}`;
    let id = first.get(key);
    if (id === undefined) first.set(key, (id = v));
    ids[v] = id;
  }
  return ids;
}

/** The open edges of a mesh, ready to draw: { count, lines (float32 segment ends, centred) }. */
export function openEdgeLines(mesh, center) {
  const ids = samePositionIds(mesh.positions);
  const pairs = boundaryEdges(
    mesh.indices.map((v) => ids[v]),
    mesh.faceSizes,
    mesh.positions.length / 3,
  );
  return { count: pairs.length / 2, lines: segmentPositions(mesh.positions, pairs, center) };
}

/**
 * Some input faces (by input index) ready to draw: { triangles, lines, centers } as float32
 * positions relative to `center` — triangles (polygons split as the input's drawing splits them),
 * the faces' outlines, and each face's vertex centroid (a marker: on a big mesh a face can be a
 * few pixels). Indices past the mesh's faces are skipped.
 */
export function faceHighlight(mesh, faceIds, center) {
  const { positions, indices, faceSizes } = mesh;
  const nFaces = faceSizes ? faceSizes.length : indices.length / 3;
  const starts = new Map();
  const wanted = new Set(Array.from(faceIds).filter((f) => f < nFaces));
  for (let f = 0, at = 0; f < nFaces && starts.size < wanted.size; at += faceSizes ? faceSizes[f] : 3, f++) {
    if (wanted.has(f)) starts.set(f, at);
  }
  const tri = [],
    outline = [],
    centers = [];
  for (const [f, at] of starts) {
    const k = faceSizes ? faceSizes[f] : 3;
    const loop = indices.subarray(at, at + k);
    if (k === 3) tri.push(...loop);
    else splitPolygon(positions, loop, tri);
    for (let j = 0; j < k; j++) outline.push(loop[j], loop[(j + 1) % k]);
    for (let c = 0; c < 3; c++) centers.push(loop.reduce((sum, v) => sum + positions[3 * v + c], 0) / k - center[c]);
  }
  return {
    triangles: segmentPositions(positions, tri, center),
    lines: segmentPositions(positions, outline, center),
    centers: Float32Array.from(centers),
  };
}
