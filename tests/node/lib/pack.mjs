// `npm pack` of the repository for the tests. node --test runs test files in parallel, and a pack
// swaps README.md for the package README between its prepack and postpack steps
// (scripts/pack-readme.mjs): two packs at once would see each other's swap. So packs take a lock
// (a directory: mkdir is atomic) and run one at a time.
import fs from 'node:fs';
import path from 'node:path';
import { execFileSync } from 'node:child_process';
import { repoRoot } from './env.mjs';

export const npmEnv = {
  ...process.env,
  npm_config_audit: 'false',
  npm_config_fund: 'false',
  npm_config_update_notifier: 'false',
  npm_config_loglevel: 'error',
};

const lock = path.join(repoRoot, 'build', 'pack.lock');
const sleep = (ms) => Atomics.wait(new Int32Array(new SharedArrayBuffer(4)), 0, 0, ms);

function withLock(fn) {
  fs.mkdirSync(path.dirname(lock), { recursive: true });
  const deadline = Date.now() + 300000;
  for (;;) {
    try {
      fs.mkdirSync(lock);
      break;
    } catch (err) {
      if (err.code !== 'EEXIST') throw err;
      // A lock older than 5 minutes belongs to a killed run.
      if (Date.now() - fs.statSync(lock, { throwIfNoEntry: false })?.mtimeMs > 300000)
        fs.rmSync(lock, { force: true, recursive: true });
      if (Date.now() > deadline) throw new Error(`pack: ${lock} held for 5 minutes`);
      sleep(200);
    }
  }
  try {
    return fn();
  } finally {
    fs.rmSync(lock, { recursive: true, force: true });
  }
}

/** Packs the repository into `dest`; returns npm's JSON record ({ filename, size, files, ... }) and the tarball path. */
export function packTarball(dest) {
  return withLock(() => {
    const out = execFileSync('npm', ['pack', '--json', '--pack-destination', dest], {
      cwd: repoRoot,
      encoding: 'utf8',
      env: npmEnv,
      stdio: ['ignore', 'pipe', 'pipe'],
    });
    const info = JSON.parse(out.slice(out.indexOf('[')))[0];
    return { ...info, tarball: path.join(dest, info.filename) };
  });
}

/** Extracts a packed tarball into `<app>/node_modules/<name>` (what npm install puts there; offline). */
export function extractTarball(tarball, app, name = 'kergen-wasm') {
  const into = path.join(app, 'node_modules', name);
  fs.mkdirSync(into, { recursive: true });
  execFileSync('tar', ['-xzf', tarball, '-C', into, '--strip-components=1']);
  return into;
}
