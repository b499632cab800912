#!/usr/bin/env node
// The package README's size table (wasm/README.md), measured on dist/. scripts/build-wasm.sh prints
// it after every build; the build never edits a tracked file, and tests/node/readme-examples.test.mjs
// checks that the README's numbers are within 5% of the current build's.
//   node scripts/size-table.mjs          prints the table
//   node scripts/size-table.mjs --write  also rewrites it in wasm/README.md (between the markers)
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import { fileURLToPath } from 'node:url';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const BEGIN = '<!-- size-table:begin (written by scripts/size-table.mjs) -->';
const END = '<!-- size-table:end -->';
const FILES = [
  ['dist/kergen.wasm', '`dist/kergen.wasm`'],
  ['dist/kergen.mjs', '`dist/kergen.mjs` (glue)'],
];

const bytes = (n) => `${n.toLocaleString('en-US')} B`;

function table() {
  const rows = ['| file | raw | gzip -9 | brotli -11 |', '|---|---|---|---|'];
  for (const [file, label] of FILES) {
    const data = fs.readFileSync(path.join(root, file));
    const gzip = zlib.gzipSync(data, { level: 9 }).length;
    const brotli = zlib.brotliCompressSync(data, { params: { [zlib.constants.BROTLI_PARAM_QUALITY]: 11 } }).length;
    rows.push(`| ${label} | ${bytes(data.length)} | ${bytes(gzip)} | ${bytes(brotli)} |`);
  }
  return rows.join('\n');
}

const readme = path.join(root, 'wasm', 'README.md');
const text = table();
console.log(text);
if (process.argv.includes('--write')) {
  const old = fs.readFileSync(readme, 'utf8');
  const start = old.indexOf(BEGIN);
  const end = old.indexOf(END);
  if (start < 0 || end < start) {
    console.error(`size-table: wasm/README.md has no ${BEGIN} ... ${END} section`);
    process.exit(1);
  }
  const updated = `${old.slice(0, start + BEGIN.length)}\n${text}\n${old.slice(end)}`;
  if (updated !== old) fs.writeFileSync(readme, updated);
}
