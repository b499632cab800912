#!/usr/bin/env node
// The README's size table, measured on dist/ (run by scripts/build-wasm.sh after every build, so
// the table is always that of the last build; never edited by hand).
//   node scripts/size-table.mjs          prints the table
//   node scripts/size-table.mjs --write  also rewrites it in README.md (between the size-table markers)
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

const text = table();
console.log(text);
if (process.argv.includes('--write')) {
  const readme = path.join(root, 'README.md');
  const old = fs.readFileSync(readme, 'utf8');
  const start = old.indexOf(BEGIN);
  const end = old.indexOf(END);
  if (start < 0 || end < start) {
    console.error(`size-table: README.md has no ${BEGIN} ... ${END} section`);
    process.exit(1);
  }
  const updated = `${old.slice(0, start + BEGIN.length)}\n${text}\n${old.slice(end)}`;
  if (updated !== old) fs.writeFileSync(readme, updated);
}
