#!/usr/bin/env node
// dist/constants.js: the values of the core's constants that the package exports (kergen.h's
// kFaceSourceBox and kFaceSourceWall, as FACE_SOURCE_BOX and FACE_SOURCE_WALL), read from the
// freshly built module's wireFormat() — declared once, in the core — and written as a static ES
// module, so that they can be imported before init() and beside a KernelWorker (whose page never
// loads the module). Run by scripts/build-wasm.sh after every build; index.js checks at init()
// that the module it loads gives the same values (a wrapper and a .wasm from different builds).
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const dist = path.join(root, 'dist');
const { default: createKergenModule } = await import(pathToFileURL(path.join(dist, 'kergen.mjs')).href);
const module = await createKergenModule({
  wasmBinary: fs.readFileSync(path.join(dist, 'kergen.wasm')),
  print: () => {},
  printErr: () => {},
});
const { box, wall } = module.wireFormat().faceSource;
if (!Number.isInteger(box) || !Number.isInteger(wall)) {
  console.error("write-constants: the module's wireFormat() has no integer faceSource.box / faceSource.wall");
  process.exit(1);
}
const text = `// Written by scripts/write-constants.mjs from the module's wireFormat() (the core's kergen.h): do not edit.
// kernel.faceSources values that name no input face: a face of the clipping box of an UNBOUNDED
// kernel, and a face on a boundary wall (open: 'perpendicular').
export const FACE_SOURCE_BOX = ${box};
export const FACE_SOURCE_WALL = ${wall};
`;
fs.writeFileSync(path.join(dist, 'constants.js'), text);
console.log(`write-constants: dist/constants.js written (FACE_SOURCE_BOX ${box}, FACE_SOURCE_WALL ${wall})`);
