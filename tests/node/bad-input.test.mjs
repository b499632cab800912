// The bad-input table (tests/bad_inputs.json, shared with tests/core/bad_input_test.cpp) through
// the npm package: every 'mesh' row goes to computeKernel, every file row marked "npm" goes
// through the package's reader (readMeshSync, what the demo page's worker does) and then
// computeKernel. Errors must be KergenError instances with the row's code
// and message fragment; successes must match the row's status / volume / warning. (Rows the
// native readers reject as malformed files have no npm counterpart: the package takes arrays.)
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { assertBuilt, repoRoot, sharedMeshes, sharedMeshesMissing } from './lib/env.mjs';

const table = JSON.parse(fs.readFileSync(path.join(repoRoot, 'tests', 'bad_inputs.json'), 'utf8'));

let K;
before(async () => {
  assertBuilt();
  K = await import('../../wasm/index.js');
  await K.init();
});

const num = (v) => (v === 'NaN' ? NaN : v === 'Infinity' ? Infinity : v === '-Infinity' ? -Infinity : v);

async function outcome(positions, indices, options) {
  try {
    return { result: await K.computeKernel(positions, indices, options) };
  } catch (error) {
    return { error };
  }
}

function check(row, expect, { result, error }) {
  if (expect.code === 'OK') {
    assert.equal(error, undefined, `${row.name}: unexpected error ${error && error.code}: ${error && error.message}`);
    if (expect.status) assert.equal(result.status, expect.status, row.name);
    if (expect.volume !== undefined) {
      assert.ok(
        Math.abs(result.volume - expect.volume) <= 1e-12 * expect.volume,
        `${row.name}: volume ${result.volume} vs ${expect.volume}`,
      );
    }
    if (expect.warning) {
      assert.ok(
        result.warnings.some((w) => w.kind === expect.warning),
        `${row.name}: warning ${expect.warning} missing`,
      );
    }
    return;
  }
  assert.ok(error, `${row.name}: expected ${expect.code}, got a result (${result && result.status})`);
  assert.ok(error instanceof K.KergenError, `${row.name}: not a KergenError: ${error}`);
  assert.equal(error.code, expect.code, `${row.name}: ${error.message}`);
  assert.notEqual(error.code, 'INTERNAL_ERROR', `${row.name}: ${error.message}`);
  assert.ok(
    error.message.includes(expect.message),
    `${row.name}: message "${error.message}" lacks "${expect.message}"`,
  );
}

for (const row of table.rows.filter((r) => r.mesh)) {
  test(`mesh row ${row.name}: ${row.what}`, async () => {
    const m = row.mesh;
    const positions = Float64Array.from(m.positions.map(num));
    const indices = m.indices; // plain numbers: the package accepts arrays
    const options = m.faceSizes ? { faceSizes: m.faceSizes } : {};
    if (row.options && row.options.maxFaces !== undefined) options.maxFaces = row.options.maxFaces;
    if (row.options && row.options.repair !== undefined) options.repair = row.options.repair;
    if (row.options && row.options.allowOpen !== undefined) options.allowOpen = row.options.allowOpen;
    if (row.options && row.options.open !== undefined) options.open = row.options.open;
    check(row, row.expect, await outcome(positions, indices, options));
    // The same verdict for the cheaper entry point.
    if (row.expect.code !== 'OK' && !row.compute_kernel_only) {
      let err = null;
      try {
        await K.findKernelPoint(positions, indices, options);
      } catch (e) {
        err = e;
      }
      assert.ok(
        err instanceof K.KergenError && err.code === row.expect.code,
        `${row.name}: findKernelPoint ${err && err.code}`,
      );
    }
  });
}

for (const row of table.rows.filter((r) => r.file && r.npm)) {
  test(`file row ${row.name} via readMeshSync: ${row.what}`, async (t) => {
    const missing = row.file.shared ? sharedMeshesMissing() : '';
    if (missing) {
      t.skip(missing);
      return;
    }
    if (typeof K.readMeshSync !== 'function') {
      t.skip('this package build has no readMeshSync');
      return;
    }
    const bytes = new Uint8Array(fs.readFileSync(path.join(sharedMeshes, row.file.shared)));
    assert.equal(row.file.format, 'stl');
    const mesh = K.readMeshSync(bytes, { format: 'stl', name: row.file.shared });
    check(row, row.native, await outcome(mesh.positions, mesh.indices));
  });
}

test('the table has mesh rows and npm file rows', () => {
  assert.ok(table.rows.filter((r) => r.mesh).length >= 20);
  assert.ok(table.rows.filter((r) => r.file && r.npm).length >= 3);
});
