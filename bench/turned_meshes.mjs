// turned_meshes.mjs: writes meshes whose flat faces are planar only up to rounding, for
// kergen_bench (they are not in ../shared/meshes):
//   turned_cube_N.off   the cube [-1, 1]^3, each face split into N x N squares of two triangles
//   turned_gear_K.off   a prism over a K-corner gear (radii 1 and 0.8 alternating), height 1,
//                       each cap one K-corner polygon, the sides quads
//   turned_star_K.off   the same over a star polygon with K random angles and radii in [0.2, 1]
//                       (a fixed seed: the same file on every machine)
//   turned_spiral_K.off the same over three turns of a spiral band (K / 2 corners on each side)
// all turned by one fixed rotation, so that the coordinates are rounded: the triangles of a
// face, and the caps' split triangles, lie on distinct, nearly coplanar planes. The kernels of
// the cube and the gear: the cube itself and the gear's inner polygon region x [0, 1], up to
// slivers of rounding size. The large caps are for the validation's polygon split.
//
//   node bench/turned_meshes.mjs OUTDIR [N...] [--gear K...] [--star K...] [--spiral K...]
//        (default: cubes 16 64, gears 128 4096)
//   build/bench/kergen_bench OUTDIR/*.off
import fs from 'node:fs';
import path from 'node:path';

// The rotation of the tests' fixture turned() (tests/core/fixtures.h), about (0.3, 0.2, 0.1).
const R = [
  [0.36, 0.48, -0.8],
  [-0.8, 0.6, 0],
  [0.48, 0.64, 0.6],
];
function turn([x, y, z]) {
  const p = [x - 0.3, y - 0.2, z - 0.1];
  return R.map((r) => r[0] * p[0] + r[1] * p[1] + r[2] * p[2]);
}

function writeOff(file, points, faces) {
  // String(x) is the shortest decimal that reads back as the same double.
  const lines = ['OFF', `${points.length} ${faces.length} 0`];
  for (const p of points) lines.push(p.map(String).join(' '));
  for (const f of faces) lines.push(`${f.length} ${f.join(' ')}`);
  fs.writeFileSync(file, lines.join('\n') + '\n');
}

function tessellatedCube(n) {
  const ids = new Map();
  const points = [];
  const id = (x, y, z) => {
    const key = `${x},${y},${z}`;
    if (!ids.has(key)) {
      ids.set(key, points.length);
      points.push(turn([(2 * x) / n - 1, (2 * y) / n - 1, (2 * z) / n - 1]));
    }
    return ids.get(key);
  };
  // Per face: origin corner and two in-face axes u, v with u x v = the outward normal.
  const sides = [
    [
      [n, 0, 0],
      [0, 1, 0],
      [0, 0, 1],
    ],
    [
      [0, 0, 0],
      [0, 0, 1],
      [0, 1, 0],
    ],
    [
      [0, n, 0],
      [0, 0, 1],
      [1, 0, 0],
    ],
    [
      [0, 0, 0],
      [1, 0, 0],
      [0, 0, 1],
    ],
    [
      [0, 0, n],
      [1, 0, 0],
      [0, 1, 0],
    ],
    [
      [0, 0, 0],
      [0, 1, 0],
      [1, 0, 0],
    ],
  ];
  const faces = [];
  for (const [o, u, v] of sides) {
    const P = (a, b) => id(o[0] + a * u[0] + b * v[0], o[1] + a * u[1] + b * v[1], o[2] + a * u[2] + b * v[2]);
    for (let i = 0; i < n; i++) {
      for (let j = 0; j < n; j++) {
        const a = P(i, j),
          b = P(i + 1, j),
          c = P(i + 1, j + 1),
          d = P(i, j + 1);
        faces.push([a, b, c], [a, c, d]);
      }
    }
  }
  return { points, faces };
}

// A prism over the polygon (counter-clockwise in the xy plane), height 1, turned.
function turnedPrism(poly) {
  const k = poly.length;
  const points = [];
  for (const z of [0, 1]) for (const [x, y] of poly) points.push(turn([x, y, z]));
  const bottom = [],
    top = [];
  for (let i = 0; i < k; i++) {
    bottom.push(k - 1 - i);
    top.push(k + i);
  }
  const faces = [bottom, top];
  for (let i = 0; i < k; i++) {
    const j = (i + 1) % k;
    faces.push([i, j, k + j, k + i]);
  }
  return { points, faces };
}

function gear(k) {
  const poly = [];
  for (let i = 0; i < k; i++) {
    const r = i % 2 ? 0.8 : 1,
      t = (2 * Math.PI * i) / k;
    poly.push([r * Math.cos(t), r * Math.sin(t)]);
  }
  return poly;
}

// mulberry32: a small seeded generator, so that the star is the same on every machine.
function random(seed) {
  return () => {
    seed = (seed + 0x6d2b79f5) | 0;
    let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

function star(k) {
  const next = random(k);
  const angles = [];
  for (let i = 0; i < k; i++) angles.push(2 * Math.PI * next());
  angles.sort((a, b) => a - b);
  return angles.map((t) => {
    const r = 0.2 + 0.8 * next();
    return [r * Math.cos(t), r * Math.sin(t)];
  });
}

// Three turns between r = 1 + t outside and r = t - 1.5 (at least 0.3) inside.
function spiral(k) {
  const half = Math.floor(k / 2),
    outside = [],
    inside = [];
  for (let i = 0; i < half; i++) {
    const t = (3 * 2 * Math.PI * i) / (half - 1);
    outside.push([(1 + t) * Math.cos(t), (1 + t) * Math.sin(t)]);
    const r = Math.max(t - 1.5, 0.3);
    inside.push([r * Math.cos(t), r * Math.sin(t)]);
  }
  return outside.concat(inside.reverse());
}

const args = process.argv.slice(2);
if (args.length === 0 || args[0].startsWith('-')) {
  console.error('usage: node bench/turned_meshes.mjs OUTDIR [N...] [--gear K...]');
  process.exit(2);
}
const outDir = args[0];
const cubes = [],
  polygons = { gear: [], star: [], spiral: [] };
let list = cubes;
for (const a of args.slice(1)) {
  if (a.startsWith('--') && a.slice(2) in polygons) {
    list = polygons[a.slice(2)];
    continue;
  }
  const v = parseInt(a, 10);
  if (!(v >= 1) || String(v) !== a) {
    console.error(`not a size: ${a}`);
    process.exit(2);
  }
  list.push(v);
}
if (cubes.length === 0 && Object.values(polygons).every((l) => l.length === 0)) {
  cubes.push(16, 64);
  polygons.gear.push(128, 4096);
}
fs.mkdirSync(outDir, { recursive: true });
for (const n of cubes) {
  const { points, faces } = tessellatedCube(n);
  const file = path.join(outDir, `turned_cube_${n}.off`);
  writeOff(file, points, faces);
  console.log(`${file}: ${faces.length} triangles`);
}
const shapes = { gear, star, spiral };
for (const [name, sizes] of Object.entries(polygons)) {
  for (const k of sizes) {
    if (name === 'gear' && (k < 4 || k % 2)) {
      console.error(`a gear needs an even number of corners >= 4: ${k}`);
      process.exit(2);
    }
    if (name !== 'gear' && k < 8) {
      console.error(`a ${name} needs at least 8 corners: ${k}`);
      process.exit(2);
    }
    const { points, faces } = turnedPrism(shapes[name](k));
    const file = path.join(outDir, `turned_${name}_${k}.off`);
    writeOff(file, points, faces);
    console.log(`${file}: ${faces.length} faces (caps of ${points.length / 2} corners)`);
  }
}
