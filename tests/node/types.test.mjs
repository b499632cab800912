// The hand-written declarations (wasm/index.d.ts, wasm/worker.d.ts) type-check a consumer's
// usage example under `tsc --strict`, resolved through the package's "exports" map; the example
// also contains @ts-expect-error lines, so declarations that are too loose fail too.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import fs from 'node:fs';
import { execFileSync } from 'node:child_process';
import { repoRoot } from './lib/env.mjs';

test('tsc --noEmit --strict on tests/types/usage.ts', { timeout: 120000 }, (t) => {
  const tsc = path.join(repoRoot, 'node_modules', 'typescript', 'bin', 'tsc');
  if (!fs.existsSync(tsc)) return t.skip('typescript is not installed (npm ci)');
  let out = '';
  let status = 0;
  try {
    out = execFileSync(process.execPath, [tsc, '-p', path.join(repoRoot, 'tests', 'types'), '--noEmit', '--strict'], { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
  } catch (err) {
    status = err.status;
    out = `${err.stdout}${err.stderr}`;
  }
  assert.equal(status, 0, out);
});
