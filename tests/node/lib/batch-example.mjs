// The computeKernels example of docs/js-api.md (run by tests/node/batch.test.mjs): the kernels of
// the mesh files named on the command line, in one call; one line per file on stdout.
import fs from 'node:fs';
import { readMesh, computeKernels, KergenError } from 'kergen-wasm';

const files = process.argv.slice(2);
const meshes = await Promise.all(files.map((file) => readMesh(fs.readFileSync(file), { name: file })));
const results = await computeKernels(meshes, {
  deepestPoint: true, // one options object for every mesh
  onProgress: ({ count, total }) => console.error(`${count} of ${total} meshes`),
});
results.forEach((r, i) => {
  if (r instanceof KergenError) console.log(`${files[i]}: ${r.code} (${r.message})`);
  else console.log(`${files[i]}: ${r.status}, volume ${r.volume}, inscribed radius ${r.inscribedRadius}`);
});
