// The hand-written declarations (wasm/index.d.ts, wasm/worker.d.ts, wasm/three.d.ts) type-check a
// consumer's usage examples (tests/types/usage.ts, three-usage.ts with @types/three) under `tsc --strict`, resolved through the package's "exports" map; the example
// also contains @ts-expect-error lines, so declarations that are too loose fail too.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import fs from 'node:fs';
import os from 'node:os';
import { execFileSync } from 'node:child_process';
import { repoRoot } from './lib/env.mjs';

// tsc --noEmit --strict on tests/types with the compiler at `tsc`; its output is the failure message.
function assertTypesCheck(tsc) {
  let out = '';
  let status = 0;
  try {
    out = execFileSync(process.execPath, [tsc, '-p', path.join(repoRoot, 'tests', 'types'), '--noEmit', '--strict'], {
      encoding: 'utf8',
      stdio: ['ignore', 'pipe', 'pipe'],
    });
  } catch (err) {
    status = err.status;
    out = `${err.stdout}${err.stderr}`;
  }
  assert.equal(status, 0, out);
}

test('tsc --noEmit --strict on tests/types/usage.ts', { timeout: 120000 }, (t) => {
  const tsc = path.join(repoRoot, 'node_modules', 'typescript', 'bin', 'tsc');
  if (!fs.existsSync(tsc)) return t.skip('typescript is not installed (npm ci)');
  assertTypesCheck(tsc);
});

// The same check with the current TypeScript from the npm registry (skipped with a message when
// the registry is out of reach): the declarations must not depend on one compiler version.
test('tsc --strict with typescript@latest on tests/types', { timeout: 300000 }, (t) => {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), 'kergen-ts-latest-'));
  try {
    fs.writeFileSync(path.join(dir, 'package.json'), JSON.stringify({ name: 'ts-latest', private: true }));
    try {
      execFileSync('npm', ['install', '--no-audit', '--no-fund', 'typescript@latest'], {
        cwd: dir,
        stdio: ['ignore', 'pipe', 'pipe'],
        timeout: 240000,
      });
    } catch (err) {
      return t.skip(
        `the npm registry could not provide typescript@latest: ${String(err.stderr || err.message).split('\n')[0]}`,
      );
    }
    const tsc = path.join(dir, 'node_modules', 'typescript', 'bin', 'tsc');
    t.diagnostic(execFileSync(process.execPath, [tsc, '--version'], { encoding: 'utf8' }).trim());
    assertTypesCheck(tsc);
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
});
