// The wasm build gives the same answers as the native CLI (`build/kergen --json FILE`) on the
// shared real meshes: same status (or the same error code), the same volume within 1e-9
// relative, the same face sources (kernel face by kernel face) and the same witness faces of an
// empty kernel. The OFF files are read here by a separate test-only JS parser.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { assertBuilt, nativeCli, offFiles, sharedMeshesMissing, repoRoot } from './lib/env.mjs';
import { readOff } from './lib/off.mjs';
import { runCli } from './lib/cli-compare.mjs';

let K;
before(async () => {
  assertBuilt();
  K = await import('../../wasm/index.js');
  await K.init();
});

function nativeError(obj) {
  const e = obj.error ?? obj.error_code ?? obj.code;
  return typeof e === 'string' && e !== '' && e !== 'OK' ? e : null;
}

function runWasm(file) {
  let mesh;
  try {
    mesh = readOff(file);
  } catch (err) {
    return { parseError: err.message };
  }
  try {
    const r = K.computeKernelSync(mesh.positions, mesh.indices, { faceSizes: mesh.faceSizes ?? undefined });
    return {
      status: r.status,
      volume: r.volume,
      faceSources: Array.from(r.faceSources),
      witnessFaces: Array.from(r.witnessFaces),
    };
  } catch (err) {
    if (!(err instanceof K.KergenError)) throw err;
    return { error: err.code, message: err.message };
  }
}

function compareFolder(folder) {
  return async (t) => {
    const missing = sharedMeshesMissing();
    if (missing) return t.skip(missing);
    if (!fs.existsSync(nativeCli)) {
      return t.skip(
        `native CLI ${path.relative(repoRoot, nativeCli)} not built (npm run build:native): skipping the comparison`,
      );
    }
    const files = offFiles(folder);
    assert.ok(files.length > 0, `${folder} has .off files`);
    let agree = 0;
    let errorsAgree = 0;
    const problems = [];
    for (const file of files) {
      const name = path.relative(path.dirname(path.dirname(file)), file);
      const n = runCli(file);
      const w = runWasm(file);
      const nErr = nativeError(n);
      if (w.parseError) {
        problems.push(`${name}: the test's OFF parser failed (${w.parseError}); native says ${nErr ?? n.status}`);
        continue;
      }
      if (nErr || w.error) {
        if (nErr === w.error) errorsAgree++;
        else problems.push(`${name}: native ${nErr ?? n.status} vs wasm ${w.error ?? w.status} (${w.message ?? ''})`);
        continue;
      }
      if (n.status !== w.status) {
        problems.push(`${name}: status native ${n.status} vs wasm ${w.status}`);
        continue;
      }
      const scale = Math.max(Math.abs(n.volume), Math.abs(w.volume));
      if (Math.abs(n.volume - w.volume) > 1e-9 * scale) {
        problems.push(`${name}: volume native ${n.volume} vs wasm ${w.volume}`);
        continue;
      }
      if (JSON.stringify(n.face_sources) !== JSON.stringify(w.faceSources)) {
        problems.push(
          `${name}: face sources native ${JSON.stringify(n.face_sources)} vs wasm ${JSON.stringify(w.faceSources)}`,
        );
        continue;
      }
      if (JSON.stringify(n.witness_faces) !== JSON.stringify(w.witnessFaces)) {
        problems.push(
          `${name}: witness faces native ${JSON.stringify(n.witness_faces)} vs wasm ${JSON.stringify(w.witnessFaces)}`,
        );
        continue;
      }
      agree++;
    }
    t.diagnostic(
      `${folder}: ${agree} kernels and ${errorsAgree} error codes agree, ${problems.length} differ, of ${files.length}`,
    );
    assert.deepEqual(problems, [], problems.join('\n'));
    assert.ok(agree > 0, 'at least one kernel was compared');
  };
}

test('fixtures/*.off: wasm agrees with the native CLI', { timeout: 600000 }, compareFolder('fixtures'));
test('princeton/*.off: wasm agrees with the native CLI', { timeout: 600000 }, compareFolder('princeton'));
