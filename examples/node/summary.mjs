#!/usr/bin/env node
// node summary.mjs MESH   (OFF, OBJ, STL or PLY) → a JSON summary of its kernel on stdout.
// A rejected mesh prints {"file", "error", "message"} and exits with status 1.
import { readFile } from 'node:fs/promises';
import { readMesh, computeKernel, KergenError } from 'kergen-wasm';

const file = process.argv[2];
if (!file) {
  console.error('usage: node summary.mjs MESH');
  process.exit(2);
}
try {
  const mesh = await readMesh(await readFile(file), { name: file });
  const kernel = await computeKernel(mesh.positions, mesh.indices, { faceSizes: mesh.faceSizes, weld: true });
  const { status, volume, shapeVolume, kernelPoint, warnings } = kernel;
  const counts = { vertices: kernel.vertices.length / 3, edges: kernel.edges.length / 2, faces: kernel.faces.length };
  console.log(JSON.stringify({ file, status, volume, shapeVolume, kernelPoint, ...counts, warnings }, null, 2));
} catch (err) {
  if (!(err instanceof KergenError)) throw err;
  console.log(JSON.stringify({ file, error: err.code, message: err.message }, null, 2));
  process.exitCode = 1;
}
