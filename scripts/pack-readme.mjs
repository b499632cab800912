#!/usr/bin/env node
// npm takes a package's README from the package root, always, whatever `files` says; the root
// README.md of this repository is the C++/CLI story, and the JS users' README is wasm/README.md.
// So `npm pack` / `npm publish` run this around packing (package.json prepack / postpack):
//   node scripts/pack-readme.mjs swap      checks dist/, saves README.md to build/pack-readme/,
//                                          moves wasm/README.md in its place (npm packs a README
//                                          found in any packed folder: left in wasm/, the package
//                                          README would be in the tarball twice)
//   node scripts/pack-readme.mjs restore   puts both back where they were (postpack)
// If a pack was interrupted between the two (postpack never ran), the next `swap` (or `restore`)
// first puts the saved README.md back, so the work tree is never left with the swapped file:
// `git status` is clean after every pack. The saved copy lives in build/ (gitignored).
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const readme = path.join(root, 'README.md');
const packageReadme = path.join(root, 'wasm', 'README.md');
const saved = path.join(root, 'build', 'pack-readme', 'README.md');

function restore() {
  if (!fs.existsSync(saved)) return false;
  // (README.md holds the package README while packing: it goes back to wasm/ first.)
  if (!fs.existsSync(packageReadme)) fs.copyFileSync(readme, packageReadme);
  fs.copyFileSync(saved, readme);
  fs.rmSync(saved);
  return true;
}

const mode = process.argv[2];
if (mode === 'restore') {
  restore();
} else if (mode === 'swap') {
  for (const f of ['dist/kergen.mjs', 'dist/kergen.wasm', 'dist/constants.js']) {
    if (!fs.existsSync(path.join(root, f))) {
      console.error(`pack: ${f} is missing: run npm run build:wasm first`);
      process.exit(1);
    }
  }
  if (restore()) console.error('pack: README.md restored from an interrupted pack');
  fs.mkdirSync(path.dirname(saved), { recursive: true });
  fs.copyFileSync(readme, saved);
  fs.renameSync(packageReadme, readme);
} else {
  console.error('usage: node scripts/pack-readme.mjs swap|restore');
  process.exit(2);
}
