// The package against the native CLI on the same file: the CLI's JSON outcome, the package's
// (readMeshSync + computeKernelSync, given the loaded wrapper K) in the same terms, and their
// differences with each front end's option words set aside.
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { execFileSync } from 'node:child_process';
import { nativeCli, repoRoot } from './env.mjs';

export const cliMissing = () =>
  fs.existsSync(nativeCli)
    ? ''
    : `native CLI ${path.relative(repoRoot, nativeCli)} not built (npm run build:native): skipping`;

// `kergen --json FILE [args]`: the one JSON object it prints (exit code 1 for rejected input).
export function runCli(file, args = []) {
  let stdout;
  try {
    stdout = execFileSync(nativeCli, ['--json', ...args, file], {
      encoding: 'utf8',
      stdio: ['ignore', 'pipe', 'pipe'],
      timeout: 120000,
    });
  } catch (err) {
    stdout = err.stdout || '';
    if (!stdout.trim())
      throw new Error(`native CLI failed on ${file} without JSON output: ${err.stderr || err.message}`);
  }
  const lines = stdout.split('\n').filter((l) => l.startsWith('{'));
  assert.equal(lines.length, 1, `one JSON object from the CLI for ${file}`);
  return JSON.parse(lines[0]);
}

// The package's outcome for a file, in the CLI's JSON terms: read with readMesh (named as the CLI
// names it: the path), then computeKernel, welded when the CLI welds (a name ending in .stl: its
// default weld is the package's weld: true).
export function runPackage(K, file) {
  try {
    const mesh = K.readMeshSync(fs.readFileSync(file), { name: file });
    const weld = /\.stl$/i.test(file) ? { weld: true } : {};
    const k = K.computeKernelSync(mesh.positions, mesh.indices, { faceSizes: mesh.faceSizes ?? undefined, ...weld });
    return { ok: true, error: null, message: '', status: k.status, volume: k.volume };
  } catch (err) {
    if (!(err instanceof K.KergenError)) throw err;
    return { ok: false, error: err.code, message: err.message, status: null, volume: null };
  }
}

// Each front end names the options a message suggests in its own words (CLI flags, JS option
// names); the rest of the message is the core's and must be the same.
const cliWords = (m) =>
  m
    .replaceAll('--weld', '<weld>')
    .replaceAll('--allow-open', '<allowOpen>')
    .replaceAll('--repair', '<repair>')
    .replaceAll('--open perpendicular', '<open>')
    .replaceAll('--flip-faces', '<flipFaces>');
const jsWords = (m) =>
  m
    .replaceAll('weld: true', '<weld>')
    .replaceAll('allowOpen: true', '<allowOpen>')
    .replaceAll('repair: true', '<repair>')
    .replaceAll("open: 'perpendicular'", '<open>')
    .replaceAll('flipFaces: true', '<flipFaces>');

// Differences between the CLI's and the package's outcome for one file ('' when they agree).
export function compareOutcome(K, file) {
  const n = runCli(file);
  const w = runPackage(K, file);
  const expected = { ok: n.ok, error: n.error, message: cliWords(n.message), status: n.status };
  const actual = { ok: w.ok, error: w.error, message: jsWords(w.message), status: w.status };
  try {
    assert.deepEqual(actual, expected);
  } catch {
    return `${file}: CLI ${JSON.stringify(expected)} vs package ${JSON.stringify(actual)}`;
  }
  if (n.ok && Math.abs(n.volume - w.volume) > 1e-9 * Math.max(Math.abs(n.volume), Math.abs(w.volume))) {
    return `${file}: volume CLI ${n.volume} vs package ${w.volume}`;
  }
  return '';
}

export function filesUnder(dir) {
  const out = [];
  for (const entry of fs.readdirSync(dir, { withFileTypes: true })) {
    const full = path.join(dir, entry.name);
    if (entry.isDirectory()) out.push(...filesUnder(full));
    else if (entry.isFile()) out.push(full);
  }
  return out.sort();
}

export function countBy(values) {
  const counts = {};
  for (const v of values) counts[v] = (counts[v] ?? 0) + 1;
  return counts;
}
