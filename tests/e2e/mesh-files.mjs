// Mesh files written by the e2e tests (from the project's own generators), the package's and the
// native CLI's reading of them.
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import { assert, nativeCli } from './harness.mjs';

export function writeOFF(file, { positions, indices }, faceSize = 3) {
  const lines = ['OFF', `${positions.length / 3} ${indices.length / faceSize} 0`];
  for (let i = 0; i < positions.length; i += 3) lines.push(`${positions[i]} ${positions[i + 1]} ${positions[i + 2]}`);
  for (let i = 0; i < indices.length; i += faceSize)
    lines.push(`${faceSize} ${Array.from(indices.subarray(i, i + faceSize)).join(' ')}`);
  fs.writeFileSync(file, lines.join('\n') + '\n');
}

export function writeOBJ(file, { positions, indices }) {
  const lines = ['# written by tests/e2e/run.mjs', 'o sample'];
  for (let i = 0; i < positions.length; i += 3) lines.push(`v ${positions[i]} ${positions[i + 1]} ${positions[i + 2]}`);
  for (let i = 0; i < indices.length; i += 3)
    lines.push(`f ${indices[i] + 1} ${indices[i + 1] + 1} ${indices[i + 2] + 1}`);
  fs.writeFileSync(file, lines.join('\n') + '\n');
}

export function writePLY(file, { positions, indices }) {
  const nv = positions.length / 3,
    nf = indices.length / 3;
  const lines = [
    'ply',
    'format ascii 1.0',
    'comment written by tests/e2e/run.mjs',
    `element vertex ${nv}`,
    'property double x',
    'property double y',
    'property double z',
    `element face ${nf}`,
    'property list uchar int vertex_indices',
    'end_header',
  ];
  for (let i = 0; i < positions.length; i += 3) lines.push(`${positions[i]} ${positions[i + 1]} ${positions[i + 2]}`);
  for (let i = 0; i < indices.length; i += 3) lines.push(`3 ${indices[i]} ${indices[i + 1]} ${indices[i + 2]}`);
  fs.writeFileSync(file, lines.join('\n') + '\n');
}

export function writeAsciiSTL(file, { positions, indices }) {
  const lines = ['solid sample'];
  for (let t = 0; t < indices.length; t += 3) {
    lines.push('  facet normal 0 0 0', '    outer loop');
    for (let k = 0; k < 3; k++) {
      const v = indices[t + k];
      lines.push(`      vertex ${positions[3 * v]} ${positions[3 * v + 1]} ${positions[3 * v + 2]}`);
    }
    lines.push('    endloop', '  endfacet');
  }
  lines.push('endsolid sample');
  fs.writeFileSync(file, lines.join('\n') + '\n');
}

export const CUBE_V = [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1];
export const CUBE_Q = [
  [0, 3, 2, 1],
  [4, 5, 6, 7],
  [0, 1, 5, 4],
  [1, 2, 6, 5],
  [2, 3, 7, 6],
  [3, 0, 4, 7],
];

export function writeQuadOFF(file, verts, quads) {
  const lines = ['OFF', `${verts.length / 3} ${quads.length} 0`];
  for (let i = 0; i < verts.length; i += 3) lines.push(verts.slice(i, i + 3).join(' '));
  for (const q of quads) lines.push(`${q.length} ${q.join(' ')}`);
  fs.writeFileSync(file, lines.join('\n') + '\n');
}

// Two unit cubes touching along the edge x = y = 1 (the edge's two vertices are shared).
export function writeEdgeSharingCubes(file) {
  const verts = [...CUBE_V];
  const id = new Map();
  for (let i = 0; i < 8; i++) id.set(CUBE_V.slice(3 * i, 3 * i + 3).join(','), i);
  const map = [];
  for (let i = 0; i < 8; i++) {
    const p = [CUBE_V[3 * i] + 1, CUBE_V[3 * i + 1] + 1, CUBE_V[3 * i + 2]];
    const key = p.join(',');
    if (!id.has(key)) {
      id.set(key, verts.length / 3);
      verts.push(...p);
    }
    map.push(id.get(key));
  }
  writeQuadOFF(file, verts, [...CUBE_Q, ...CUBE_Q.map((q) => q.map((v) => map[v]))]);
}

// '' when the package (in Node) reads `file`, else why not.
export async function packageReadsFile(file) {
  const K = await import('../../wasm/index.js');
  if (typeof K.readMeshSync !== 'function') return 'this package build has no readMeshSync';
  await K.init();
  try {
    K.readMeshSync(new Uint8Array(fs.readFileSync(file)), { name: path.basename(file) });
    return '';
  } catch (err) {
    return `${err.code}: ${err.message}`;
  }
}

export function nativeKernel(file) {
  if (!fs.existsSync(nativeCli)) return null;
  const r = spawnSync(nativeCli, ['--json', file], { encoding: 'utf8' });
  const line = (r.stdout || '').split('\n').find((l) => l.trim().startsWith('{'));
  assert(line, `build/kergen --json ${file} printed no JSON (exit ${r.status}): ${r.stderr?.slice(0, 300)}`);
  return JSON.parse(line);
}
