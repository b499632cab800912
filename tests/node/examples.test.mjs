// examples/node from the packed tarball: a temporary copy of the example with the tarball
// installed (extracted into node_modules, as npm would: offline), run on mesh files with known
// kernels; its JSON on stdout checked against the analytic values. (The two browser examples are
// built and run in Chromium by tests/e2e/examples.mjs.)
import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { spawnSync } from 'node:child_process';
import { assertBuilt, repoRoot } from './lib/env.mjs';
import { extractTarball, packTarball } from './lib/pack.mjs';
import { lPrismFiles, plusPrismStl } from './lib/example-meshes.mjs';

let tmp;
let app;
before(() => {
  assertBuilt();
  tmp = fs.mkdtempSync(path.join(os.tmpdir(), 'kergen-examples-'));
  const { tarball } = packTarball(tmp);
  app = path.join(tmp, 'node-example');
  fs.cpSync(path.join(repoRoot, 'examples', 'node'), app, { recursive: true });
  extractTarball(tarball, app);
  const l = lPrismFiles();
  fs.writeFileSync(path.join(app, 'l-prism.off'), l.off);
  fs.writeFileSync(path.join(app, 'l-prism.obj'), l.obj);
  fs.writeFileSync(path.join(app, 'open.off'), l.openOff);
  fs.writeFileSync(path.join(app, 'plus.stl'), plusPrismStl());
  fs.writeFileSync(path.join(app, 'broken.off'), 'OFF\n3 1 0\n0 0 0\n1 0 0\n');
});
after(() => {
  if (tmp) fs.rmSync(tmp, { recursive: true, force: true });
});

function summary(file) {
  const r = spawnSync(process.execPath, ['summary.mjs', file], { cwd: app, encoding: 'utf8' });
  return { status: r.status, json: r.stdout ? JSON.parse(r.stdout) : null, stderr: r.stderr };
}

const close = (a, b, what) => assert.ok(Math.abs(a - b) <= 1e-12 * Math.abs(b), `${what}: ${a}, expected ${b}`);

test('examples/node: OFF and OBJ L prisms → the unit cube kernel (volume 1 of 3)', () => {
  for (const file of ['l-prism.off', 'l-prism.obj']) {
    const { status, json } = summary(file);
    assert.equal(status, 0, file);
    assert.equal(json.file, file);
    assert.equal(json.status, 'POLYHEDRON');
    close(json.volume, 1, `${file} volume`);
    close(json.shapeVolume, 3, `${file} shape volume`);
    assert.deepEqual([json.vertices, json.edges, json.faces], [8, 12, 6]);
    assert.ok(
      json.kernelPoint.every((x) => x >= 0 && x <= 1),
      `kernel point ${json.kernelPoint} in the cube`,
    );
  }
});

test('examples/node: a binary STL triangle soup (plus prism; readMesh welds STL) → the central cube (volume 1 of 5)', () => {
  const { status, json } = summary('plus.stl');
  assert.equal(status, 0);
  assert.equal(json.status, 'POLYHEDRON');
  close(json.volume, 1, 'volume');
  close(json.shapeVolume, 5, 'shape volume');
});

test('examples/node: an open mesh and a malformed file → {"error"} and exit status 1; no file → usage, 2', () => {
  const open = summary('open.off');
  assert.equal(open.status, 1);
  assert.equal(open.json.error, 'OPEN_MESH');
  const broken = summary('broken.off');
  assert.equal(broken.status, 1);
  assert.equal(broken.json.error, 'PARSE_ERROR');
  assert.match(broken.json.message, /broken\.off/);
  const usage = spawnSync(process.execPath, ['summary.mjs'], { cwd: app, encoding: 'utf8' });
  assert.equal(usage.status, 2);
  assert.match(usage.stderr, /usage/);
});
