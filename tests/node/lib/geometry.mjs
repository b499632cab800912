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
    for (const [i, j, k] of splitPolygon(positions, orientation > 0 ? loop : [...loop].reverse())) {
      const a = vtx(positions, i);
      const n = cross(sub(vtx(positions, j), a), sub(vtx(positions, k), a));
      const len = norm(n);
      if (len === 0) continue;
      planes.push({ n: [n[0] / len, n[1] / len, n[2] / len], d: dot(n, a) / len });
    }
  }
  return planes;
}

// The core's split of a convex polygon that is not planar (see triangulate_polygon in
// core/src/input/mesh_prep.cpp), restated in double precision: a fan from the first corner, then every
// diagonal where the surface folds inward is flipped while both new triangles keep a positive
// area in the projection along the dominant axis of the Newell normal. Folds of rounding size
// may be judged differently here, but they move a plane by far less than the checks' tolerance.
function splitPolygon(positions, loop) {
  const k = loop.length;
  const tris = [];
  for (let i = 1; i + 1 < k; i++) tris.push([loop[0], loop[i], loop[i + 1]]);
  if (k <= 3 || k > 128) return tris;
  const P = (v) => vtx(positions, v);
  const nw = [0, 0, 0];
  for (let i = 0; i < k; i++) {
    const a = P(loop[i]),
      b = P(loop[(i + 1) % k]);
    nw[0] += (a[1] - b[1]) * (a[2] + b[2]);
    nw[1] += (a[2] - b[2]) * (a[0] + b[0]);
    nw[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  let axis = 0;
  for (let c = 1; c < 3; c++) if (Math.abs(nw[c]) > Math.abs(nw[axis])) axis = c;
  const u = (axis + 1) % 3,
    w = (axis + 2) % 3,
    s = nw[axis] >= 0 ? 1 : -1;
  const area2 = (a, b, c) => {
    const pa = P(a),
      pb = P(b),
      pc = P(c);
    return s * ((pb[u] - pa[u]) * (pc[w] - pa[w]) - (pb[w] - pa[w]) * (pc[u] - pa[u]));
  };
  for (let i = 0; i < k; i++) if (area2(loop[(i + k - 1) % k], loop[i], loop[(i + 1) % k]) < 0) return tris; // non-convex
  const orient = (a, b, c, p) => dot(cross(sub(P(b), P(a)), sub(P(c), P(a))), sub(P(p), P(a)));
  let changed = true;
  let flips = 0;
  while (changed && flips < 4 * k * k) {
    changed = false;
    for (let i = 0; i < tris.length; i++) {
      for (let e = 0; e < 3; e++) {
        const x = tris[i][e],
          y = tris[i][(e + 1) % 3],
          p = tris[i][(e + 2) % 3];
        let j = -1,
          g = -1;
        for (let t = 0; t < tris.length && j < 0; t++) {
          if (t === i) continue;
          for (let h = 0; h < 3; h++)
            if (tris[t][h] === y && tris[t][(h + 1) % 3] === x) {
              j = t;
              g = h;
            }
        }
        if (j < 0) continue;
        const q = tris[j][(g + 2) % 3];
        if (!(orient(x, y, p, q) > 0) || !(area2(x, q, p) > 0 && area2(q, y, p) > 0)) continue;
        tris[i] = [x, q, p];
        tris[j] = [q, y, p];
        flips++;
        changed = true;
        break;
      }
    }
  }
  return tris;
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

/**
 * A unit cube whose top is two rectangles split at x = 0.5, while the -y and +y sides keep their
 * whole top edge: the split points are T-junctions, closed geometrically but OPEN_MESH as indexed.
 * Flat xyz `vertices` and quad loops `quads`; tJunctionCube() gives it as package arrays.
 */
export const T_JUNCTION_CUBE = {
  vertices: [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1, 0.5, 0, 1, 0.5, 1, 1],
  quads: [
    [0, 3, 2, 1],
    [4, 8, 9, 7],
    [8, 5, 6, 9],
    [0, 1, 5, 4],
    [1, 2, 6, 5],
    [2, 3, 7, 6],
    [3, 0, 4, 7],
  ],
};

export function tJunctionCube() {
  const { vertices, quads } = T_JUNCTION_CUBE;
  return {
    positions: Float64Array.from(vertices),
    indices: Uint32Array.from(quads.flat()),
    faceSizes: Uint32Array.from(quads.map((q) => q.length)),
  };
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
    return {
      positions: Float64Array.from(positions),
      indices: Uint32Array.from(q.flat()),
      faceSizes: Uint32Array.from(q.map(() => 4)),
    };
  }
  const tri = q.flatMap(([a, b, c, d]) => [a, b, c, a, c, d]);
  return { positions: Float64Array.from(positions), indices: Uint32Array.from(tri), faceSizes: null };
}

/** Plus-shaped prism: arms of half-width w reaching to ±r, height h. Kernel: [-w,w]²×[0,h]. */
export function plusPrism(w, r, h = 1) {
  const poly = [
    [w, -r],
    [w, -w],
    [r, -w],
    [r, w],
    [w, w],
    [w, r],
    [-w, r],
    [-w, w],
    [-r, w],
    [-r, -w],
    [-w, -w],
    [-w, -r],
  ];
  return extrude(poly, 0, h);
}

/** L-shaped prism over (0,0)-(2,0)-(2,1)-(1,1)-(1,2)-(0,2), height 1. Kernel: the unit cube. */
export function lPrism() {
  return extrude(
    [
      [0, 0],
      [2, 0],
      [2, 1],
      [1, 1],
      [1, 2],
      [0, 2],
    ],
    0,
    1,
  );
}

/** U-shaped prism: not star-shaped (the two arms' tips cannot see each other's far walls). */
export function uPrism() {
  return extrude(
    [
      [0, 0],
      [3, 0],
      [3, 3],
      [2, 3],
      [2, 1],
      [1, 1],
      [1, 3],
      [0, 3],
    ],
    0,
    1,
  );
}

/** Moves / scales a mesh: p' = p * s + t. */
export function transform({ positions, indices, faceSizes }, s, t = [0, 0, 0]) {
  const p = Float64Array.from(positions, (v, i) => v * s + t[i % 3]);
  return {
    positions: p,
    indices: Uint32Array.from(indices),
    faceSizes: faceSizes ? Uint32Array.from(faceSizes) : null,
  };
}

/** Reverses every face (inward orientation). */
export function flip({ positions, indices, faceSizes }) {
  const loops = faceLoops(indices, faceSizes).map((l) => l.slice().reverse());
  return {
    positions: Float64Array.from(positions),
    indices: Uint32Array.from(loops.flat()),
    faceSizes: faceSizes ? Uint32Array.from(faceSizes) : null,
  };
}

export { vtx, sub, cross, dot, norm };
