// Procedurally generated sample models for the demo gallery.
//
// Every generator returns a closed, watertight triangle mesh: shared vertices (no duplicates),
// every edge used by exactly two triangles in opposite directions, triangles counter-clockwise
// seen from outside (outward normals). tests/e2e/samples-check.mjs verifies this in Node.
//
// `expected` records what the kernel must be, derived by hand from the geometry (used by the
// browser tests): status, and for some samples the exact volume and vertex/face counts.

import { ShapeUtils, Vector2 } from 'three';

class MeshBuilder {
  constructor() {
    this.positions = [];
    this.indices = [];
  }
  vertex(x, y, z) {
    this.positions.push(x, y, z);
    return this.positions.length / 3 - 1;
  }
  tri(a, b, c) {
    this.indices.push(a, b, c);
  }
  // Quad a,b,c,d counter-clockwise seen from outside.
  quad(a, b, c, d) {
    this.tri(a, b, c);
    this.tri(a, c, d);
  }
  build() {
    return { positions: Float64Array.from(this.positions), indices: Uint32Array.from(this.indices) };
  }
}

// Triangulates a simple polygon (counter-clockwise in the xy plane) with three.js's ear clipping;
// returns index triples into the polygon, each counter-clockwise.
function triangulatePolygon(poly) {
  const contour = poly.map(([x, y]) => new Vector2(x, y));
  return ShapeUtils.triangulateShape(contour, []).map(([a, b, c]) => {
    const [ax, ay] = poly[a],
      [bx, by] = poly[b],
      [cx, cy] = poly[c];
    const area2 = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
    return area2 > 0 ? [a, b, c] : [a, c, b];
  });
}

// Extrudes a simple polygon (counter-clockwise, xy) from z0 to z1.
export function prism(poly, z0, z1) {
  const m = new MeshBuilder();
  const n = poly.length;
  for (const [x, y] of poly) m.vertex(x, y, z0);
  for (const [x, y] of poly) m.vertex(x, y, z1);
  for (const [a, b, c] of triangulatePolygon(poly)) {
    m.tri(n + a, n + b, n + c); // top, normal +z
    m.tri(a, c, b); // bottom, normal -z
  }
  for (let i = 0; i < n; i++) {
    const j = (i + 1) % n;
    m.quad(i, j, n + j, n + i);
  }
  return m.build();
}

export function starPolygon(points, outer, inner) {
  const poly = [];
  for (let i = 0; i < 2 * points; i++) {
    const r = i % 2 === 0 ? outer : inner;
    const a = Math.PI / 2 + (i * Math.PI) / points;
    poly.push([r * Math.cos(a), r * Math.sin(a)]);
  }
  return poly;
}

// Plus / cross outline: arms of half-width w reaching out to ±len.
export function plusPolygon(w, len) {
  return [
    [len, -w],
    [len, w],
    [w, w],
    [w, len],
    [-w, len],
    [-w, w],
    [-len, w],
    [-len, -w],
    [-w, -w],
    [-w, -len],
    [w, -len],
    [w, -w],
  ];
}

export function gearPolygon(teeth, root, tip) {
  const poly = [];
  const pitch = (2 * Math.PI) / teeth;
  for (let i = 0; i < teeth; i++) {
    const a = i * pitch;
    for (const [f, r] of [
      [0, root],
      [0.2, tip],
      [0.45, tip],
      [0.65, root],
    ]) {
      poly.push([r * Math.cos(a + f * pitch), r * Math.sin(a + f * pitch)]);
    }
  }
  return poly;
}

// Unit cube [0,1]^3 whose top face is pushed in to a pyramidal dent with its apex at
// (0.5, 0.5, 1 - depth).
export function dentedCube(depth) {
  const m = new MeshBuilder();
  const v = [];
  for (let z = 0; z < 2; z++) for (let y = 0; y < 2; y++) for (let x = 0; x < 2; x++) v.push(m.vertex(x, y, z));
  const c = (x, y, z) => v[x + 2 * y + 4 * z];
  const apex = m.vertex(0.5, 0.5, 1 - depth);
  m.quad(c(0, 0, 0), c(0, 1, 0), c(1, 1, 0), c(1, 0, 0)); // bottom (-z)
  m.quad(c(0, 0, 0), c(1, 0, 0), c(1, 0, 1), c(0, 0, 1)); // -y
  m.quad(c(1, 0, 0), c(1, 1, 0), c(1, 1, 1), c(1, 0, 1)); // +x
  m.quad(c(1, 1, 0), c(0, 1, 0), c(0, 1, 1), c(1, 1, 1)); // +y
  m.quad(c(0, 1, 0), c(0, 0, 0), c(0, 0, 1), c(0, 1, 1)); // -x
  const top = [c(0, 0, 1), c(1, 0, 1), c(1, 1, 1), c(0, 1, 1)]; // counter-clockwise from above
  for (let i = 0; i < 4; i++) m.tri(top[i], top[(i + 1) % 4], apex);
  return m.build();
}

// Catmull-Rom resampling of a polyline profile [[r, z], ...].
function smoothProfile(points, perSegment) {
  const out = [];
  const p = (i) => points[Math.max(0, Math.min(points.length - 1, i))];
  for (let i = 0; i < points.length - 1; i++) {
    for (let s = 0; s < perSegment; s++) {
      const t = s / perSegment,
        t2 = t * t,
        t3 = t2 * t;
      const [p0, p1, p2, p3] = [p(i - 1), p(i), p(i + 1), p(i + 2)];
      out.push(
        [0, 1].map(
          (k) =>
            0.5 *
            (2 * p1[k] +
              (-p0[k] + p2[k]) * t +
              (2 * p0[k] - 5 * p1[k] + 4 * p2[k] - p3[k]) * t2 +
              (-p0[k] + 3 * p1[k] - 3 * p2[k] + p3[k]) * t3),
        ),
      );
    }
  }
  out.push(points[points.length - 1].slice());
  return out;
}

// Solid of revolution about the z axis: profile [[r, z], ...] with z increasing, closed by flat
// discs at both ends (fanned around a centre vertex).
export function revolution(profile, segments) {
  const m = new MeshBuilder();
  const rings = profile.map(([r, z]) => {
    const ring = [];
    for (let j = 0; j < segments; j++) {
      const a = (2 * Math.PI * j) / segments;
      ring.push(m.vertex(r * Math.cos(a), r * Math.sin(a), z));
    }
    return ring;
  });
  const bottom = m.vertex(0, 0, profile[0][1]);
  const top = m.vertex(0, 0, profile[profile.length - 1][1]);
  for (let k = 0; k + 1 < rings.length; k++) {
    for (let j = 0; j < segments; j++) {
      const jn = (j + 1) % segments;
      m.quad(rings[k][j], rings[k][jn], rings[k + 1][jn], rings[k + 1][j]);
    }
  }
  const last = rings[rings.length - 1];
  for (let j = 0; j < segments; j++) {
    const jn = (j + 1) % segments;
    m.tri(bottom, rings[0][jn], rings[0][j]);
    m.tri(top, last[j], last[jn]);
  }
  return m.build();
}

export function torus(R, r, nu, nv) {
  const m = new MeshBuilder();
  const id = [];
  for (let i = 0; i < nu; i++) {
    id.push([]);
    const u = (2 * Math.PI * i) / nu;
    for (let j = 0; j < nv; j++) {
      const v = (2 * Math.PI * j) / nv;
      const rho = R + r * Math.cos(v);
      id[i].push(m.vertex(rho * Math.cos(u), rho * Math.sin(u), r * Math.sin(v)));
    }
  }
  for (let i = 0; i < nu; i++) {
    for (let j = 0; j < nv; j++) {
      const i1 = (i + 1) % nu,
        j1 = (j + 1) % nv;
      m.quad(id[i][j], id[i1][j], id[i1][j1], id[i][j1]);
    }
  }
  return m.build();
}

// Latitude/longitude sphere with radius radius(theta, phi) (theta from the +z pole).
export function radialSphere(nlat, nlon, radius) {
  const m = new MeshBuilder();
  const point = (theta, phi) => {
    const r = radius(theta, phi);
    return m.vertex(r * Math.sin(theta) * Math.cos(phi), r * Math.sin(theta) * Math.sin(phi), r * Math.cos(theta));
  };
  const north = point(0, 0);
  const rows = [];
  for (let i = 1; i < nlat; i++) {
    const row = [];
    for (let j = 0; j < nlon; j++) row.push(point((Math.PI * i) / nlat, (2 * Math.PI * j) / nlon));
    rows.push(row);
  }
  const south = point(Math.PI, 0);
  for (let j = 0; j < nlon; j++) {
    const jn = (j + 1) % nlon;
    m.tri(north, rows[0][j], rows[0][jn]);
    for (let i = 0; i + 1 < rows.length; i++) m.quad(rows[i][j], rows[i + 1][j], rows[i + 1][jn], rows[i][jn]);
    m.tri(rows[rows.length - 1][j], south, rows[rows.length - 1][jn]);
  }
  return m.build();
}

const PLUS_W = 0.3;
const DENT = 0.4;

export const VASE_PROFILE = [
  [0.45, 0],
  [0.62, 0.15],
  [0.72, 0.4],
  [0.7, 0.7],
  [0.58, 1.0],
  [0.42, 1.25],
  [0.36, 1.45],
  [0.38, 1.6],
  [0.45, 1.72],
];

export const SAMPLES = [
  {
    id: 'star-prism',
    name: 'Star prism',
    description: 'A five-pointed star extruded; the kernel is the prism over the region that sees every tip.',
    polygon: starPolygon(5, 1, 0.42),
    height: 0.5,
    expected: { status: 'POLYHEDRON' },
  },
  {
    id: 'plus-prism',
    name: 'Plus prism',
    description: `Cross with arms of half-width ${PLUS_W}, height 1; the kernel is the central column, volume 4w²h.`,
    polygon: plusPolygon(PLUS_W, 1),
    height: 1,
    expected: { status: 'POLYHEDRON', volume: 4 * PLUS_W * PLUS_W, vertices: 8, edges: 12, faces: 6 },
  },
  {
    id: 'gear',
    name: 'Gear',
    description:
      'A 12-tooth gear; the lines of the tooth flanks cut the kernel down to a many-sided prism around the axle.',
    polygon: gearPolygon(12, 0.78, 1),
    height: 0.3,
    expected: { status: 'POLYHEDRON' },
  },
  {
    id: 'dented-cube',
    name: 'Dented cube',
    description: `Unit cube with a pyramidal dent of depth ${DENT} in its top; the kernel has 9 vertices, 9 faces, volume 1 − 5d/3 = 1/3.`,
    build: () => dentedCube(DENT),
    expected: { status: 'POLYHEDRON', volume: 1 - (5 * DENT) / 3, vertices: 9, faces: 9 },
  },
  {
    id: 'vase',
    name: 'Vase',
    description:
      'A solid of revolution with a belly, a neck and a flared lip; the lip limits the kernel to a slender cone-like body.',
    build: () => revolution(smoothProfile(VASE_PROFILE, 4), 48),
    expected: { status: 'POLYHEDRON' },
  },
  {
    id: 'l-prism',
    name: 'L prism',
    description: 'An L-shaped prism (2×2 with a 1×1 notch, height 1); the kernel is the corner cube, volume 1.',
    polygon: [
      [0, 0],
      [2, 0],
      [2, 1],
      [1, 1],
      [1, 2],
      [0, 2],
    ],
    height: 1,
    expected: { status: 'POLYHEDRON', volume: 1, vertices: 8, edges: 12, faces: 6 },
  },
  {
    id: 'z-prism',
    name: 'Z prism (flat kernel)',
    description:
      'Two offset blocks meeting along a line: only the points of the 1 × 1 rectangle where their walls meet see everything — a flat (POLYGON) kernel of area 1, no volume.',
    polygon: [
      [0, 0],
      [2, 0],
      [2, 1],
      [3, 1],
      [3, 2],
      [1, 2],
      [1, 1],
      [0, 1],
    ],
    height: 1,
    expected: { status: 'POLYGON', area: 1, vertices: 4, edges: 4, faces: 1 },
  },
  {
    id: 'u-prism',
    name: 'U prism (not star-shaped)',
    description:
      'A U-shaped prism: the inner walls of the two prongs face each other, so no point sees both prongs — the kernel is empty.',
    polygon: [
      [0, 0],
      [3, 0],
      [3, 2],
      [2, 2],
      [2, 1],
      [1, 1],
      [1, 2],
      [0, 2],
    ],
    height: 1,
    expected: { status: 'EMPTY' },
  },
  {
    id: 'torus',
    name: 'Torus (not star-shaped)',
    description: 'A ring has a hole: no point inside it sees the whole ring, so the kernel is empty.',
    build: () => torus(1, 0.35, 36, 18),
    expected: { status: 'EMPTY' },
  },
  {
    id: 'bumpy-sphere',
    name: 'Bumpy sphere',
    description:
      'A sphere with radial bumps (3,968 triangles): star-shaped about its centre; the kernel is a many-faceted convex body — watch it grow edge by edge.',
    build: () => radialSphere(32, 64, (t, p) => 1 + 0.22 * Math.sin(3 * t) * Math.sin(4 * p)),
    expected: { status: 'POLYHEDRON' },
  },
];

// Prism samples are described by their outline (`polygon`, counter-clockwise) and `height`.
for (const s of SAMPLES) if (s.polygon) s.build = () => prism(s.polygon, 0, s.height);

export function sampleById(id) {
  return SAMPLES.find((s) => s.id === id) ?? null;
}
