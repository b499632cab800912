#!/usr/bin/env node
// Generates a large closed, consistently oriented, star-shaped mesh (never committed):
// a UV sphere r(theta, phi) = 1 + 0.2 sin(3 theta) cos(2 phi) with nu x nv cells, 2 nu (nv - 1)
// triangles. Default ~1M faces (nu = 1000, nv = 501).
//   node scripts/gen-big-mesh.mjs OUT.off [NU] [NV]      write an OFF file (for the native CLI)
//   import { bumpySphere } from './gen-big-mesh.mjs'     the arrays, for Node tests/benchmarks
import fs from 'node:fs';
import { pathToFileURL } from 'node:url';

export function bumpySphere(nu = 1000, nv = 501) {
  const nVerts = 2 + (nv - 1) * nu;
  const positions = new Float64Array(3 * nVerts);
  positions.set([0, 0, 1, 0, 0, -1], 0);
  let p = 6;
  for (let j = 1; j < nv; j++) {
    const th = (Math.PI * j) / nv;
    for (let i = 0; i < nu; i++) {
      const ph = (2 * Math.PI * i) / nu;
      const r = 1 + 0.2 * Math.sin(3 * th) * Math.cos(2 * ph);
      positions[p++] = r * Math.sin(th) * Math.cos(ph);
      positions[p++] = r * Math.sin(th) * Math.sin(ph);
      positions[p++] = r * Math.cos(th);
    }
  }
  const id = (j, i) => 2 + (j - 1) * nu + (i % nu);
  const indices = new Uint32Array(3 * 2 * nu * (nv - 1));
  let t = 0;
  for (let i = 0; i < nu; i++) {
    indices.set([0, id(1, i), id(1, i + 1)], t);
    t += 3;
    indices.set([1, id(nv - 1, i + 1), id(nv - 1, i)], t);
    t += 3;
  }
  for (let j = 1; j + 1 < nv; j++) {
    for (let i = 0; i < nu; i++) {
      indices.set([id(j, i), id(j + 1, i), id(j + 1, i + 1)], t);
      t += 3;
      indices.set([id(j, i), id(j + 1, i + 1), id(j, i + 1)], t);
      t += 3;
    }
  }
  return { positions, indices };
}

if (import.meta.url === pathToFileURL(process.argv[1]).href) {
  const [out, nu = '1000', nv = '501'] = process.argv.slice(2);
  if (!out) {
    console.error('usage: node scripts/gen-big-mesh.mjs OUT.off [NU] [NV]');
    process.exit(2);
  }
  const { positions, indices } = bumpySphere(Number(nu), Number(nv));
  const fd = fs.openSync(out, 'w');
  fs.writeSync(fd, `OFF\n${positions.length / 3} ${indices.length / 3} 0\n`);
  let buf = [];
  const flush = () => {
    fs.writeSync(fd, buf.join(''));
    buf = [];
  };
  for (let v = 0; v < positions.length; v += 3) {
    buf.push(`${positions[v]} ${positions[v + 1]} ${positions[v + 2]}\n`);
    if (buf.length > 65536) flush();
  }
  for (let f = 0; f < indices.length; f += 3) {
    buf.push(`3 ${indices[f]} ${indices[f + 1]} ${indices[f + 2]}\n`);
    if (buf.length > 65536) flush();
  }
  flush();
  fs.closeSync(fd);
  console.log(`${out}: ${positions.length / 3} vertices, ${indices.length / 3} faces`);
}
