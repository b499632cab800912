// Node checks of the demo's procedural sample meshes (web/samples.js): closed, watertight,
// consistently outward oriented, no duplicate or unused vertices, no zero-area triangles, one
// component, expected Euler characteristic; for prism samples the enclosed volume equals
// outline area × height and the kernel expectation comes from an independent 2D half-plane
// clipping of the outline. Run alone: `node tests/e2e/samples-check.mjs`.

import { SAMPLES } from '../../web/samples.js';

const sub = (a, b) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const cross = (a, b) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

function polygonArea(poly) {
  let a = 0;
  for (let i = 0; i < poly.length; i++) {
    const [x0, y0] = poly[i],
      [x1, y1] = poly[(i + 1) % poly.length];
    a += x0 * y1 - x1 * y0;
  }
  return a / 2;
}

// Kernel of a simple polygon (counter-clockwise): clip a large square by the inner half-plane of
// every edge. Returns the kernel polygon with duplicate and collinear vertices removed ([] = empty).
export function polygonKernel(poly, { raw = false } = {}) {
  let k = [
    [-1e3, -1e3],
    [1e3, -1e3],
    [1e3, 1e3],
    [-1e3, 1e3],
  ];
  for (let i = 0; i < poly.length && k.length; i++) {
    const p = poly[i],
      q = poly[(i + 1) % poly.length];
    const side = (x) => (q[0] - p[0]) * (x[1] - p[1]) - (q[1] - p[1]) * (x[0] - p[0]);
    const out = [];
    for (let j = 0; j < k.length; j++) {
      const a = k[j],
        b = k[(j + 1) % k.length];
      const sa = side(a),
        sb = side(b);
      if (sa >= 0) out.push(a);
      if ((sa > 0 && sb < 0) || (sa < 0 && sb > 0)) {
        const t = sa / (sa - sb);
        out.push([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]);
      }
    }
    k = out;
  }
  if (raw) return k;
  const eps = 1e-12;
  let changed = true;
  while (changed && k.length) {
    changed = false;
    for (let i = 0; i < k.length; i++) {
      const a = k[(i + k.length - 1) % k.length],
        b = k[i],
        c = k[(i + 1) % k.length];
      const dup = Math.hypot(b[0] - c[0], b[1] - c[1]) < eps;
      const col = Math.abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])) < eps;
      if (dup || col) {
        k.splice(i, 1);
        changed = true;
        break;
      }
    }
  }
  return k.length >= 3 && polygonArea(k) > eps ? k : [];
}

// What the kernel of a sample must be: the sample's own `expected`, completed for prisms by the 2D
// kernel of the outline (a prism's kernel is the prism over its outline's kernel).
export function expectedKernel(sample) {
  const e = { ...sample.expected };
  if (sample.polygon && e.status !== 'POLYGON') {
    const k = polygonKernel(sample.polygon);
    if (k.length === 0) return { ...e, status: 'EMPTY' };
    // Analytic values stated by the sample take precedence over the clipped (rounded) ones.
    return {
      status: 'POLYHEDRON',
      volume: polygonArea(k) * sample.height,
      vertices: 2 * k.length,
      edges: 3 * k.length,
      faces: k.length + 2,
      ...e,
    };
  }
  return e;
}

export function checkMesh({ positions, indices }) {
  const problems = [];
  const nv = positions.length / 3,
    nt = indices.length / 3;
  const P = (i) => [positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]];
  if (indices.length % 3 !== 0 || positions.length % 3 !== 0) problems.push('array lengths not multiples of 3');
  for (const i of indices)
    if (i >= nv) {
      problems.push(`index ${i} out of range`);
      return { problems };
    }
  const keys = new Set();
  for (let i = 0; i < nv; i++) keys.add(P(i).join(','));
  if (keys.size !== nv) problems.push(`${nv - keys.size} duplicate vertices`);
  const used = new Uint8Array(nv);
  for (const i of indices) used[i] = 1;
  const unused = used.reduce((s, u) => s + (u ? 0 : 1), 0);
  if (unused) problems.push(`${unused} unused vertices`);

  let diag = 0;
  for (let i = 0; i < nv; i++) diag = Math.max(diag, Math.hypot(...P(i)));
  const directed = new Map();
  let volume6 = 0,
    degenerate = 0;
  for (let t = 0; t < nt; t++) {
    const v = [indices[3 * t], indices[3 * t + 1], indices[3 * t + 2]];
    const [a, b, c] = v.map(P);
    if (Math.hypot(...cross(sub(b, a), sub(c, a))) <= 1e-12 * diag * diag) degenerate++;
    volume6 += dot(a, cross(b, c));
    for (let k = 0; k < 3; k++) {
      const key = `${v[k]},${v[(k + 1) % 3]}`;
      directed.set(key, (directed.get(key) ?? 0) + 1);
    }
  }
  if (degenerate) problems.push(`${degenerate} zero-area triangles`);
  let badEdges = 0;
  for (const [key, n] of directed) {
    const [a, b] = key.split(',');
    if (n !== 1 || directed.get(`${b},${a}`) !== 1) badEdges++;
  }
  if (badEdges) problems.push(`${badEdges} directed edges not matched by exactly one opposite edge`);
  const volume = volume6 / 6;
  if (!(volume > 0)) problems.push(`signed volume ${volume} is not positive`);

  const parent = Int32Array.from({ length: nv }, (_, i) => i);
  const find = (x) => {
    while (parent[x] !== x) x = parent[x] = parent[parent[x]];
    return x;
  };
  for (let t = 0; t < nt; t++) {
    parent[find(indices[3 * t])] = find(indices[3 * t + 1]);
    parent[find(indices[3 * t])] = find(indices[3 * t + 2]);
  }
  let components = 0;
  for (let i = 0; i < nv; i++) if (used[i] && find(i) === i) components++;
  if (components !== 1) problems.push(`${components} connected components`);
  const edges = directed.size / 2;
  return { problems, volume, euler: nv - edges + nt, vertices: nv, triangles: nt };
}

// True when p is strictly on the inner side of every triangle's plane.
export function strictlyInside(p, { positions, indices }) {
  const P = (i) => [positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]];
  for (let t = 0; t < indices.length; t += 3) {
    const a = P(indices[t]),
      b = P(indices[t + 1]),
      c = P(indices[t + 2]);
    const n = cross(sub(b, a), sub(c, a));
    if (dot(n, sub(p, a)) >= -1e-12 * Math.hypot(...n)) return false;
  }
  return true;
}

// A point that must lie in the kernel's interior, per sample (null = none claimed).
function witness(sample, mesh) {
  if (sample.polygon) {
    const k = polygonKernel(sample.polygon);
    if (!k.length) return null;
    const cx = k.reduce((s, p) => s + p[0], 0) / k.length,
      cy = k.reduce((s, p) => s + p[1], 0) / k.length;
    return [cx, cy, sample.height / 2];
  }
  if (sample.id === 'dented-cube') return [0.5, 0.5, 0.1];
  if (sample.id === 'bumpy-sphere') return [0, 0, 0];
  if (sample.id === 'vase') {
    const zmax = mesh.positions.reduce((m, v, i) => (i % 3 === 2 ? Math.max(m, v) : m), -Infinity);
    for (let z = 0; z <= zmax; z += zmax / 200) if (strictlyInside([0, 0, z], mesh)) return [0, 0, z];
    return [0, 0, NaN];
  }
  return null;
}

export function checkSamples() {
  const results = [];
  for (const sample of SAMPLES) {
    const mesh = sample.build();
    const r = checkMesh(mesh);
    const problems = [...r.problems];
    const euler = sample.id === 'torus' ? 0 : 2;
    if (r.euler !== euler) problems.push(`Euler characteristic ${r.euler}, expected ${euler}`);
    if (sample.polygon) {
      const v = polygonArea(sample.polygon) * sample.height;
      if (Math.abs(r.volume - v) > 1e-12 * v) problems.push(`volume ${r.volume} != outline area × height ${v}`);
    }
    if (sample.polygon && sample.expected.volume != null) {
      const clipped = polygonArea(polygonKernel(sample.polygon)) * sample.height;
      if (Math.abs(clipped - sample.expected.volume) > 1e-9 * sample.expected.volume) {
        problems.push(`stated kernel volume ${sample.expected.volume} != clipped outline kernel ${clipped}`);
      }
    }
    if (sample.polygon && sample.expected.status === 'POLYGON') {
      // Flat kernel of a prism: the outline's kernel is a segment (no area) of length area / height.
      const k = polygonKernel(sample.polygon, { raw: true });
      let len = 0;
      for (const a of k) for (const b of k) len = Math.max(len, Math.hypot(a[0] - b[0], a[1] - b[1]));
      const area = k.length >= 3 ? Math.abs(polygonArea(k)) : 0;
      if (!(k.length >= 2 && area < 1e-12 && Math.abs(len * sample.height - sample.expected.area) < 1e-12)) {
        problems.push(
          `outline kernel is not a segment of length ${sample.expected.area / sample.height} (${k.length} points, area ${area}, length ${len})`,
        );
      }
    }
    const exp = expectedKernel(sample);
    if (exp.status !== sample.expected.status)
      problems.push(`2D kernel says ${exp.status}, sample claims ${sample.expected.status}`);
    const w = witness(sample, mesh);
    if (w && !strictlyInside(w, mesh))
      problems.push(`claimed kernel point ${w} is not strictly inside every face plane`);
    if (exp.status === 'POLYHEDRON' && !w) problems.push('no kernel witness point');
    if (sample.id === 'z-prism') {
      // Points on the flat kernel sit on two opposite face planes: not strictly inside.
      if (strictlyInside([1.5, 1, 0.5], mesh)) problems.push('the flat kernel has an interior point');
    }
    results.push({
      name: `sample ${sample.id}: ${r.vertices} vertices, ${r.triangles} triangles, volume ${r.volume.toFixed(6)}`,
      ok: problems.length === 0,
      detail: problems.join('; '),
    });
  }
  return results;
}

if (import.meta.url === `file://${process.argv[1]}`) {
  const results = checkSamples();
  for (const r of results) console.log(`${r.ok ? 'ok  ' : 'FAIL'} ${r.name}${r.detail ? ` — ${r.detail}` : ''}`);
  for (const s of SAMPLES) console.log(`  expected kernel of ${s.id}: ${JSON.stringify(expectedKernel(s))}`);
  const failed = results.filter((r) => !r.ok).length;
  console.log(`samples-check: ${results.length - failed} passed, ${failed} failed`);
  process.exit(failed ? 1 : 0);
}
