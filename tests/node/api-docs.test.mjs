// The API reference (scripts/build-api-docs.sh: TypeDoc on the package's .d.ts files) builds
// without warnings and documents the main entry points of the three modules.
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { execFileSync } from 'node:child_process';
import { repoRoot } from './lib/env.mjs';

let out;
before(() => {
  out = fs.mkdtempSync(path.join(os.tmpdir(), 'kergen-api-docs-'));
});
after(() => {
  if (out) fs.rmSync(out, { recursive: true, force: true });
});

test(
  'scripts/build-api-docs.sh writes the reference of kergen-wasm, kergen-wasm/worker and kergen-wasm/three',
  { timeout: 300000 },
  (t) => {
    execFileSync('bash', [path.join(repoRoot, 'scripts/build-api-docs.sh'), out], {
      cwd: repoRoot,
      stdio: ['ignore', 'pipe', 'pipe'],
    });
    const read = (f) => fs.readFileSync(path.join(out, f), 'utf8');
    const index = read('index.html');
    assert.match(index, /kergen-wasm/);
    const modules = read('modules.html');
    for (const m of ['kergen-wasm', 'kergen-wasm/worker', 'kergen-wasm/three'])
      assert.ok(modules.includes(`>${m}<`), `module ${m}`);
    const pages = [
      ['functions/kergen-wasm.computeKernel.html', 'computeKernel'],
      ['classes/kergen-wasm_worker.KernelWorker.html', 'computeFile'],
      ['classes/kergen-wasm_three.KernelWorker.html', 'computeObject'],
      ['functions/kergen-wasm_three.computeKernelOfObject.html', 'world transforms'],
      ['classes/kergen-wasm.KergenError.html', 'code'],
    ];
    for (const [file, text] of pages) {
      assert.ok(fs.existsSync(path.join(out, file)), `${file} exists`);
      assert.ok(read(file).includes(text), `${file} mentions ${text}`);
    }
    t.diagnostic(
      `${fs.readdirSync(path.join(out, 'functions')).length} function pages, ${fs.readdirSync(path.join(out, 'classes')).length} class pages`,
    );
  },
);
