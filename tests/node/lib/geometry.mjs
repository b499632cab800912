// Test-only geometry: mesh generators with known kernels and independent checks (plain JS,
// no code shared with the C++ core).

/** Faces of a mesh as arrays of vertex ids. */
export function faceLoops(indices, faceSizes) {
  const loops = [];
  if (!faceSizes) {
    for (let i = 0; i < indices.length; i += 3) loops.push([indices[i], indices[i + 1], indices[i + 2]]);
    return loops;
  }
  let at = 0;
  for (const n of faceSizes) {
    loops.push(Array.from(indices.slice(at, at + n)));
    at += n;
  }
  return loops;
}

const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const norm = (a) => Math.hypot(a[0], a[1], a[2]);
const vtx = (P, i) => [P[3 * i], P[3 * i + 1], P[3 * i + 2]];

/** Signed volume enclosed by (CCW-from-outside) polygon loops, by the divergence theorem. */
export function signedVolume(positions, loops) {
  let v = 0;
  for (const loop of loops) {
    const a = vtx(positions, loop[0]);
    for (let k = 1; k + 1 < loop.length; k++) {
      v += dot(a, cross(vtx(positions, loop[k]), vtx(positions, loop[k + 1]))) / 6;
    }
  }
  return v;
}

export function bboxDiagonal(positions) {
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < positions.length; i += 3) {
    for (let k = 0; k < 3; k++) {
      lo[k] = Math.min(lo[k], positions[i + k]);
      hi[k] = Math.max(hi[k], positions[i + k]);
    }
  }
  return Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}

/**
 * Inner half-spaces of every non-degenerate triangle of the input's faces (fan-split), as
 * unit normals n and offsets d with n·x <= d inside. `orientation` = +1 for outward loops.
 */
export function halfSpaces(positions, loops, orientation = 1) {
  const planes = [];
  for (const loop of loops) {
    const a = vtx(positions, loop[0]);
    for (let k = 1; k + 1 < loop.length; k++) {
      const n = cross(sub(vtx(positions, loop[k]), a), sub(vtx(positions, loop[k + 1]), a));
      const len = norm(n);
      if (len === 0) continue;
      const u = [(orientation * n[0]) / len, (orientation * n[1]) / len, (orientation * n[2]) / len];
      planes.push({ n: u, d: dot(u, a) });
    }
  }
  return planes;
}

/** Largest violation max(n·p − d) of point p over the half-spaces (<= 0 inside). */
export function maxViolation(planes, p) {
  let worst = -Infinity;
  for (const { n, d } of planes) worst = Math.max(worst, dot(n, p) - d);
  return worst;
}

/** Ear clipping of a simple CCW polygon given as [[x, y], ...]; returns index triples. */
export function triangulatePolygon(poly) {
  const idx = poly.map((_, i) => i);
  const tris = [];
  const area2 = (a, b, c) => (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
  const inside = (p, a, b, c) => area2(a, b, p) >= 0 && area2(b, c, p) >= 0 && area2(c, a, p) >= 0;
  while (idx.length > 3) {
    let clipped = false;
    for (let i = 0; i < idx.length; i++) {
      const ia = idx[(i + idx.length - 1) % idx.length];
      const ib = idx[i];
      const ic = idx[(i + 1) % idx.length];
      const [a, b, c] = [poly[ia], poly[ib], poly[ic]];
      if (area2(a, b, c) <= 0) continue;
      if (idx.some((j) => j !== ia && j !== ib && j !== ic && inside(poly[j], a, b, c))) continue;
      tris.push([ia, ib, ic]);
      idx.splice(i, 1);
      clipped = true;
      break;
    }
    if (!clipped) throw new Error('triangulatePolygon: not a simple CCW polygon');
  }
  tris.push([idx[0], idx[1], idx[2]]);
  return tris;
}

/** Prism over a simple CCW polygon, z in [z0, z1], all triangles, outward CCW. */
export function extrude(poly, z0 = 0, z1 = 1) {
  const n = poly.length;
  const positions = [];
  for (const [x, y] of poly) positions.push(x, y, z0);
  for (const [x, y] of poly) positions.push(x, y, z1);
  const indices = [];
  for (const [a, b, c] of triangulatePolygon(poly)) {
    indices.push(a + n, b + n, c + n); // top, CCW seen from +z
    indices.push(a, c, b); // bottom, reversed
  }
  for (let i = 0; i < n; i++) {
    const j = (i + 1) % n;
    indices.push(i, j, j + n, i, j + n, i + n);
  }
  return { positions: Float64Array.from(positions), indices: Uint32Array.from(indices), faceSizes: null };
}

/** Axis-aligned box as 6 quads (polygon input) or 12 triangles. */
export function box(lo = [0, 0, 0], hi = [1, 1, 1], { quads = false } = {}) {
  const positions = [];
  for (let i = 0; i < 8; i++) positions.push(i & 1 ? hi[0] : lo[0], i & 2 ? hi[1] : lo[1], i & 4 ? hi[2] : lo[2]);
  const q = [
    [0, 2, 3, 1], // z = lo
    [4, 5, 7, 6], // z = hi
    [0, 1, 5, 4], // y = lo
    [2, 6, 7, 3], // y = hi
    [0, 4, 6, 2], // x = lo
    [1, 3, 7, 5], // x = hi
  ];
  if (quads) {
    return { positions: Float64Array.from(positions), indices: Uint32Array.from(q.flat()), faceSizes: Uint32Array.from(q.map(() => 4)) };
  }
  const tri = q.flatMap(([a, b, c, d]) => [a, b, c, a, c, d]);
  return { positions: Float64Array.from(positions), indices: Uint32Array.from(tri), faceSizes: null };
}

/** Plus-shaped prism: arms of half-width w reaching to ±r, height h. Kernel: [-w,w]²×[0,h]. */
export function plusPrism(w, r, h = 1) {
  const poly = [
    [w, -r], [w, -w], [r, -w], [r, w], [w, w], [w, r],
    [-w, r], [-w, w], [-r, w], [-r, -w], [-w, -w], [-w, -r],
  ];
  return extrude(poly, 0, h);
}

/** L-shaped prism over (0,0)-(2,0)-(2,1)-(1,1)-(1,2)-(0,2), height 1. Kernel: the unit cube. */
export function lPrism() {
  return extrude([[0, 0], [2, 0], [2, 1], [1, 1], [1, 2], [0, 2]], 0, 1);
}

/** U-shaped prism: not star-shaped (the two arms' tips cannot see each other's far walls). */
export function uPrism() {
  return extrude([[0, 0], [3, 0], [3, 3], [2, 3], [2, 1], [1, 1], [1, 3], [0, 3]], 0, 1);
}

/** Moves / scales a mesh: p' = p * s + t. */
export function transform({ positions, indices, faceSizes }, s, t = [0, 0, 0]) {
  const p = Float64Array.from(positions, (v, i) => v * s + t[i % 3]);
  return { positions: p, indices: Uint32Array.from(indices), faceSizes: faceSizes ? Uint32Array.from(faceSizes) : null };
}

/** Reverses every face (inward orientation). */
export function flip({ positions, indices, faceSizes }) {
  const loops = faceLoops(indices, faceSizes).map((l) => l.slice().reverse());
  return { positions: Float64Array.from(positions), indices: Uint32Array.from(loops.flat()), faceSizes: faceSizes ? Uint32Array.from(faceSizes) : null };
}

export { vtx, sub, cross, dot, norm };
