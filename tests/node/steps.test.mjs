// Streaming: the step events form a growing valid partial kernel, map 1:1 to the result, and can
// stop the trace (onStep returning false, maxSteps).
import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { assertBuilt, sharedMeshesMissing, sharedMeshes } from './lib/env.mjs';
import { readOff } from './lib/off.mjs';
import { bboxDiagonal, box, extrude, faceLoops, halfSpaces, lPrism, maxViolation, plusPrism } from './lib/geometry.mjs';
import { checkKernel } from './lib/checks.mjs';

let K;
before(async () => {
  assertBuilt();
  K = await import('../../wasm/index.js');
  await K.init();
});

function starPrism(n, inner) {
  const poly = [];
  for (let i = 0; i < 2 * n; i++) {
    const r = i % 2 ? inner : 1;
    poly.push([r * Math.cos((Math.PI * i) / n), r * Math.sin((Math.PI * i) / n)]);
  }
  return extrude(poly, 0, 1);
}

/** Runs computeKernel collecting events and checking each as it arrives against the input. */
async function traced(mesh, options = {}) {
  const planes = halfSpaces(mesh.positions, faceLoops(mesh.indices, mesh.faceSizes));
  const tol = 1e-9 * bboxDiagonal(mesh.positions);
  const events = [];
  const seen = { vertex: 0, edge: 0, face: 0 };
  const result = await K.computeKernel(mesh.positions, mesh.indices, {
    ...options,
    faceSizes: mesh.faceSizes ?? undefined,
    onStep(e) {
      events.push(e);
      assert.equal(e.id, seen[e.type], `${e.type} ids arrive in order`);
      seen[e.type]++;
      if (e.type === 'vertex') {
        assert.equal(e.position.length, 3);
        const worst = maxViolation(planes, e.position);
        assert.ok(worst <= tol, `vertex event ${e.id} lies outside a half-space by ${worst}`);
      } else if (e.type === 'edge') {
        assert.ok(
          e.a < seen.vertex && e.b < seen.vertex && e.a !== e.b,
          `edge ${e.id} joins vertices already reported`,
        );
      } else {
        assert.equal(e.type, 'face');
        assert.ok(Array.isArray(e.loop) && e.loop.length >= 3);
        for (const v of e.loop) assert.ok(v < seen.vertex, `face ${e.id} uses vertices already reported`);
      }
      return options.onStep ? options.onStep(e) : undefined;
    },
  });
  return { result, events, seen };
}

function meshes() {
  const list = [
    ['box', box([0, 0, 0], [2, 1, 3])],
    ['L prism', lPrism()],
    ['plus prism', plusPrism(0.3, 1.5)],
    ['star prism', starPrism(9, 0.55)],
  ];
  if (!sharedMeshesMissing()) {
    for (const f of [
      'fixtures/star.off',
      'fixtures/cross_quad.off',
      'fixtures/dodecahedron_pentagons.off',
      'princeton/350.off',
    ]) {
      list.push([f, readOff(path.join(sharedMeshes, f))]);
    }
  }
  return list;
}

test('every vertex event lies in the kernel; final counts and coordinates equal the result', async (t) => {
  if (sharedMeshesMissing()) t.diagnostic(sharedMeshesMissing());
  for (const [name, mesh] of meshes()) {
    const { result, events, seen } = await traced(mesh);
    assert.equal(result.complete, true, name);
    assert.equal(result.status, 'POLYHEDRON', name);
    checkKernel(result, mesh);
    assert.equal(seen.vertex, result.vertices.length / 3, `${name}: one event per vertex`);
    assert.equal(seen.edge, result.edges.length / 2, `${name}: one event per edge`);
    assert.equal(seen.face, result.faces.length, `${name}: one event per face`);
    for (const e of events) {
      if (e.type === 'vertex') {
        assert.deepEqual(
          e.position,
          Array.from(result.vertices.subarray(3 * e.id, 3 * e.id + 3)),
          `${name}: vertex ${e.id}`,
        );
      } else if (e.type === 'edge') {
        const a = result.edges[2 * e.id];
        const b = result.edges[2 * e.id + 1];
        assert.ok((a === e.a && b === e.b) || (a === e.b && b === e.a), `${name}: edge ${e.id}`);
      } else {
        assert.deepEqual(e.loop, Array.from(result.faces[e.id]), `${name}: face ${e.id}`);
      }
    }
  }
});

test('the stream is deterministic', async () => {
  const mesh = starPrism(7, 0.5);
  const a = await traced(mesh);
  const b = await traced(mesh);
  assert.deepEqual(b.events, a.events);
});

test('onStep returning false stops the trace with a valid partial kernel', async () => {
  const mesh = starPrism(12, 0.6);
  const full = await traced(mesh);
  const total = full.events.length;
  assert.ok(total > 20, `enough events to stop in the middle (${total})`);
  for (const stopAt of [1, 5, Math.floor(total / 2)]) {
    let n = 0;
    const { result, events, seen } = await traced(mesh, { onStep: () => ++n < stopAt });
    assert.equal(events.length, stopAt, 'no event after false');
    assert.equal(result.complete, false);
    // The partial result holds exactly the reported vertices, and every reported edge under its id;
    // it may also hold parts found but not yet reported (e.g. the edge that led to the last
    // vertex); everything in it must lie in the kernel.
    assert.equal(result.vertices.length / 3, seen.vertex, 'the partial result holds the reported vertices');
    for (const e of events) {
      if (e.type === 'vertex')
        assert.deepEqual(e.position, Array.from(result.vertices.subarray(3 * e.id, 3 * e.id + 3)));
      if (e.type === 'edge') {
        const pair = [result.edges[2 * e.id], result.edges[2 * e.id + 1]].sort();
        assert.deepEqual(pair, [e.a, e.b].sort(), `reported edge ${e.id} is in the partial result`);
      }
    }
    assert.ok(result.edges.length / 2 >= seen.edge && result.faces.length >= seen.face);
    checkKernel(result, mesh);
  }
});

test('maxSteps bounds the number of events', async () => {
  const mesh = starPrism(10, 0.5);
  const { result, events } = await traced(mesh, { maxSteps: 7 });
  assert.equal(events.length, 7);
  assert.equal(result.complete, false);
  const all = await traced(mesh, { maxSteps: 1e9 });
  assert.equal(all.result.complete, true);
});

test('from: the trace starts at the kernel vertex extreme towards the given point', async () => {
  const mesh = box([0, 0, 0], [1, 1, 1]);
  for (const corner of [
    [5, 5, 5],
    [-5, 5, -5],
    [5, -5, -5],
  ]) {
    const { events } = await traced(mesh, { from: corner });
    const first = events.find((e) => e.type === 'vertex').position;
    assert.deepEqual(
      first,
      corner.map((c) => (c > 0 ? 1 : 0)),
      `first vertex towards ${corner}`,
    );
  }
});
