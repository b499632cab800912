// A fresh, uninitialized copy of the package's JS wrapper, with module state of its own: the
// wrapper's state (the loaded module, its wire format) lives in wasm/load.js, which every import
// of wasm/index.js shares, so a test of what happens before init() needs other module URLs.
// wasm/*.js are copied into a temporary folder beside a link to the built dist/ (errors.js is
// re-exported from the original: one KergenError class).
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../../..');
const made = [];
process.on('exit', () => {
  for (const dir of made) fs.rmSync(dir, { recursive: true, force: true });
});

/** Imports a fresh copy of wasm/index.js (nothing loaded yet). */
export async function freshWrapper() {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'kergen-fresh-'));
  made.push(dir);
  fs.mkdirSync(path.join(dir, 'wasm'));
  // ES modules as in the package (Node 18 does not detect module syntax in .js files).
  fs.writeFileSync(path.join(dir, 'package.json'), '{ "type": "module" }\n');
  for (const f of fs.readdirSync(path.join(repo, 'wasm'))) {
    if (f.endsWith('.js') && f !== 'errors.js') fs.copyFileSync(path.join(repo, 'wasm', f), path.join(dir, 'wasm', f));
  }
  // One KergenError class for both copies, so that `instanceof` holds across them.
  const errors = pathToFileURL(path.join(repo, 'wasm', 'errors.js')).href;
  fs.writeFileSync(path.join(dir, 'wasm', 'errors.js'), `export * from ${JSON.stringify(errors)};\n`);
  fs.symlinkSync(path.join(repo, 'dist'), path.join(dir, 'dist'));
  return import(pathToFileURL(path.join(dir, 'wasm', 'index.js')).href);
}
