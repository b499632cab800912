#!/usr/bin/env node
// Writes an agglomerated box grid (web/cells-sample.js: L-, U- and single-box cells, kernels known
// by hand) as a VTK XML .vtu volume mesh of VTK_POLYHEDRON cells (never committed):
//   node scripts/gen-volume-mesh.mjs OUT.vtu [CELLS]     about CELLS cells (default 100000)
//   node scripts/gen-volume-mesh.mjs OUT.vtu NX NY NZ    a grid of NX × NY × NZ boxes
// Prints the grid, the number of cells by kind and the file's size.
import fs from 'node:fs';
import { agglomeratedGrid, gridForCells, volumeMeshToVtu } from '../web/cells-sample.js';

const [out, ...sizes] = process.argv.slice(2);
if (!out || !(sizes.length === 0 || sizes.length === 1 || sizes.length === 3) || sizes.some((s) => !(Number(s) >= 1))) {
  console.error('usage: gen-volume-mesh.mjs OUT.vtu [CELLS | NX NY NZ]');
  process.exit(2);
}
const grid = sizes.length === 3 ? sizes.map(Number) : gridForCells(Number(sizes[0] ?? 100000));
const mesh = agglomeratedGrid(...grid);
fs.writeFileSync(out, volumeMeshToVtu(mesh));
const count = (k) => mesh.kinds.filter((x) => x === k).length;
console.log(
  `${out}: ${grid.join(' x ')} boxes, ${mesh.cells.length} cells (${count('S')} single, ${count('L')} L, ${count('U')} U), ` +
    `${(fs.statSync(out).size / 1e6).toFixed(1)} MB`,
);
