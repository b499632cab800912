// The READMEs' code blocks that show example files are those files' lines, so they cannot drift:
//   <!-- example: FILE -->        the next fenced block is a run of FILE's consecutive lines
//                                 (indentation removed evenly, as an excerpt of an indented part)
//   <!-- example-lines: FILE -->  each line of the next fenced block is a line of FILE (trimmed),
//                                 in FILE's order (a few lines picked out of it)
// and the package README's size table is within 5% of the current build's (scripts/size-table.mjs).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import zlib from 'node:zlib';
import { distWasm, distGlue, repoRoot } from './lib/env.mjs';

const READMES = ['wasm/README.md', 'README.md', 'docs/js-api.md'];

function blocks(readme) {
  const text = fs.readFileSync(path.join(repoRoot, readme), 'utf8');
  const re = /<!-- (example|example-lines): (\S+) -->\n```\w*\n([\s\S]*?)\n```/g;
  return [...text.matchAll(re)].map((m) => ({ mode: m[1], file: m[2], code: m[3] }));
}

const indentOf = (l) => l.length - l.trimStart().length;

function containsRun(fileLines, code) {
  const lines = code.split('\n');
  for (let at = 0; at + lines.length <= fileLines.length; at++) {
    const first = fileLines[at];
    const cut = indentOf(first) - indentOf(lines[0]);
    if (cut < 0) continue;
    if (lines.every((l, i) => (l === '' ? fileLines[at + i].trim() === '' : fileLines[at + i] === ' '.repeat(cut) + l)))
      return true;
  }
  return false;
}

function containsInOrder(fileLines, code) {
  let at = 0;
  for (const line of code.split('\n')) {
    while (at < fileLines.length && fileLines[at].trim() !== line.trim()) at++;
    if (at === fileLines.length) return line;
    at++;
  }
  return null;
}

for (const readme of READMES) {
  test(`${readme}: every example block is the example file's lines`, (t) => {
    const found = blocks(readme);
    t.diagnostic(found.map((b) => `${b.mode} ${b.file} (${b.code.split('\n').length} lines)`).join('; '));
    assert.ok(found.length > 0, `${readme} shows at least one example file`);
    for (const { mode, file, code } of found) {
      const fileLines = fs.readFileSync(path.join(repoRoot, file), 'utf8').split('\n');
      if (mode === 'example')
        assert.ok(containsRun(fileLines, code), `${readme}: the block marked ${file} is not a run of its lines`);
      else {
        const missing = containsInOrder(fileLines, code);
        assert.equal(missing, null, `${readme}: "${missing}" is not (in this order) a line of ${file}`);
      }
    }
  });
}

test('the package README shows the whole Vite + three.js example app', (t) => {
  const app = blocks('wasm/README.md').find((b) => b.mode === 'example' && b.file === 'examples/vite-three/main.js');
  const file = fs.readFileSync(path.join(repoRoot, 'examples/vite-three/main.js'), 'utf8');
  assert.ok(app, 'the block is there');
  assert.equal(`${app.code}\n`, file, 'all of it');
  t.diagnostic(`examples/vite-three/main.js: ${file.split('\n').length - 1} lines`);
});

test("the package README's size table is within 5% of the current build (else: node scripts/size-table.mjs --write)", (t) => {
  const text = fs.readFileSync(path.join(repoRoot, 'wasm/README.md'), 'utf8');
  const table = /<!-- size-table:begin[^>]*-->\n([\s\S]*?)<!-- size-table:end -->/.exec(text);
  assert.ok(table, 'the README has the size table');
  for (const [file, name] of [
    [distWasm, 'dist/kergen.wasm'],
    [distGlue, 'dist/kergen.mjs'],
  ]) {
    const row = table[1].split('\n').find((l) => l.includes(`\`${name}\``));
    assert.ok(row, `a row for ${name}`);
    const [raw, gzip, brotli] = [...row.matchAll(/([\d,]+) B/g)].map((m) => Number(m[1].replace(/,/g, '')));
    const data = fs.readFileSync(file);
    const now = [
      data.length,
      zlib.gzipSync(data, { level: 9 }).length,
      zlib.brotliCompressSync(data, { params: { [zlib.constants.BROTLI_PARAM_QUALITY]: 11 } }).length,
    ];
    t.diagnostic(`${name}: README ${[raw, gzip, brotli].join(' / ')} B, build ${now.join(' / ')} B`);
    [raw, gzip, brotli].forEach((v, i) =>
      assert.ok(Math.abs(v - now[i]) <= 0.05 * now[i], `${name}: README says ${v} B, the build is ${now[i]} B`),
    );
  }
});
