// Independent truth for real meshes: ../shared/meshes/labels.tsv records, per file, whether it is
// closed and star-shaped (from a Chebyshev-centre LP computed outside this project) and its signed
// volume. The wasm package must agree on every .off file of fixtures/ and princeton/, and its
// kernels must satisfy every input half-space.
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { assertBuilt, sharedMeshes, sharedMeshesMissing } from './lib/env.mjs';
import { readOff } from './lib/off.mjs';
import { checkKernel, relClose } from './lib/checks.mjs';

let K;
before(async () => {
  assertBuilt();
  K = await import('../../wasm/index.js');
  await K.init();
});

function labels() {
  const [header, ...rows] = fs.readFileSync(path.join(sharedMeshes, 'labels.tsv'), 'utf8').trim().split('\n');
  const cols = header.split('\t');
  return rows
    .map((r) => Object.fromEntries(r.split('\t').map((v, i) => [cols[i], v])))
    .filter((r) => /^(fixtures|princeton)\/[^/]+\.off$/.test(r.file));
}

test(
  'star-shapedness, status, shape volume and kernel validity agree with labels.tsv',
  { timeout: 600000 },
  async (t) => {
    const missing = sharedMeshesMissing();
    if (missing) return t.skip(missing);
    let checked = 0;
    for (const row of labels()) {
      const mesh = readOff(path.join(sharedMeshes, row.file));
      const opts = { faceSizes: mesh.faceSizes ?? undefined };
      if (row.star_shaped === 'yes' || row.star_shaped === 'no') {
        const star = row.star_shaped === 'yes';
        assert.equal(await K.isStarShaped(mesh.positions, mesh.indices, opts), star, `${row.file}: isStarShaped`);
        const r = await K.computeKernel(mesh.positions, mesh.indices, opts);
        const labelledVolume = Number(row.mesh_volume);
        relClose(r.shapeVolume, Math.abs(labelledVolume), 1e-5, `${row.file}: shape volume`);
        if (labelledVolume < 0)
          assert.ok(
            r.warnings.some((w) => w.kind === 'ORIENTATION_FLIPPED'),
            `${row.file}: flip reported`,
          );
        if (!star) {
          assert.equal(r.status, 'EMPTY', `${row.file}: status`);
          assert.equal(r.vertices.length, 0);
        } else {
          // chebyshev_r_over_diag > 0: the kernel has an interior, so it is a polyhedron.
          assert.ok(Number(row.chebyshev_r_over_diag) > 0);
          assert.equal(r.status, 'POLYHEDRON', `${row.file}: status`);
          checkKernel(r, mesh, { orientation: labelledVolume < 0 ? -1 : 1 });
          assert.ok(r.volume <= r.shapeVolume * (1 + 1e-9), `${row.file}: kernel within the shape`);
        }
      } else if (row.closed === 'False' || row.components !== '1') {
        // Not closed / not one component: the core must refuse it with a topology error.
        await assert.rejects(K.computeKernel(mesh.positions, mesh.indices, opts), (err) => {
          assert.ok(err instanceof K.KergenError, `${row.file}: ${err}`);
          assert.ok(
            [
              'OPEN_MESH',
              'NON_MANIFOLD_EDGE',
              'MULTIPLE_COMPONENTS',
              'INCONSISTENT_ORIENTATION',
              'DEGENERATE_INPUT',
            ].includes(err.code),
            `${row.file}: ${err.code}`,
          );
          return true;
        });
      } else {
        continue;
      }
      checked++;
    }
    t.diagnostic(`${checked} labelled meshes checked`);
    assert.ok(checked >= 40, `most labelled meshes were checked (${checked})`);
  },
);
