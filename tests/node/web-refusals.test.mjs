// The demo's words for a refused mesh and what bounds its kernel (web/alternatives.js,
// web/face-sources.js), in Node: the package's real messages and warnings (computed here) are
// said without its option names, alternatives are ranked by what they give, and the face-source
// marks and witness edges are read as documented.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import * as K from '../../wasm/index.js';
import { T_JUNCTION_CUBE, tJunctionCube } from './lib/geometry.mjs';
import { candidatesFor, rankTrials, messageInWords, warningInWords, trialInWords } from '../../web/alternatives.js';
import { boxFaceIds, faceSourceInWords, edgeLines, FACE_SOURCE_BOX, FACE_SOURCE_WALL } from '../../web/face-sources.js';

const repo = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
await K.init({ wasmBinary: fs.readFileSync(path.join(repo, 'dist/kergen.wasm')) });

const OPTION_NAMES = /weld: true|allowOpen|repair: true|open: 'perpendicular'|Options::/;

// A unit cube whose top is two rectangles split at x = 0.5 (T-junctions on the y sides' top edges).
const Q = T_JUNCTION_CUBE.quads;
const tj = tJunctionCube();

test('the package messages of OPEN_MESH, NON_MANIFOLD_EDGE, MULTIPLE_COMPONENTS read without option names', () => {
  const messages = [];
  try {
    K.computeKernelSync(tj.positions, tj.indices, { faceSizes: tj.faceSizes });
  } catch (e) {
    messages.push([e.code, e.message]);
  }
  // A repeated face: an edge of three faces.
  const dup = Uint32Array.from([...Q.flat(), ...Q[3]]);
  try {
    K.computeKernelSync(tj.positions, dup, { faceSizes: Uint32Array.from([...Q.map((q) => q.length), 4]) });
  } catch (e) {
    messages.push([e.code, e.message]);
  }
  assert.deepEqual(
    messages.map(([c]) => c),
    ['OPEN_MESH', 'NON_MANIFOLD_EDGE'],
  );
  for (const [code, m] of messages) {
    assert.match(m, OPTION_NAMES, `${code}: the package's message names options`);
    const words = messageInWords(m);
    assert.doesNotMatch(words, OPTION_NAMES, words);
    assert.doesNotMatch(words, /\(s\)/, words);
  }
  assert.equal(messageInWords(messages[0][1]), 'the mesh is open: 6 edges belong to one face only, e.g. edge (4, 5)');
});

test('repair warnings in words: T-junctions with their count, a weld at tolerance 0 without "within 0"', () => {
  const r = K.computeKernelSync(tj.positions, tj.indices, { faceSizes: tj.faceSizes, repair: true });
  const t = r.warnings.find((w) => w.kind === 'T_JUNCTIONS_SPLIT');
  assert.equal(t.count, 2);
  assert.match(
    warningInWords(t),
    /^2 vertices lie inside another face's edge \(T-junctions\).*repair splits the edges/,
  );
  // Six separate quads of a cube (24 vertices): repair merges the 16 at an equal position.
  const C = [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1];
  const faces = [
    [0, 3, 2, 1],
    [4, 5, 6, 7],
    [0, 1, 5, 4],
    [1, 2, 6, 5],
    [2, 3, 7, 6],
    [3, 0, 4, 7],
  ];
  const soup = Float64Array.from(faces.flatMap((f) => f.flatMap((v) => C.slice(3 * v, 3 * v + 3))));
  const w = K.computeKernelSync(
    soup,
    Uint32Array.from(faces.flatMap((_, i) => [4 * i, 4 * i + 1, 4 * i + 2, 4 * i + 3])),
    {
      faceSizes: Uint32Array.from([4, 4, 4, 4, 4, 4]),
      repair: true,
    },
  ).warnings.find((x) => x.kind === 'VERTICES_WELDED');
  assert.match(w.message, /within 0\b/, 'the package says "within 0"');
  assert.equal(warningInWords(w), '16 vertices at the same position as another vertex were merged with it.');
  const relative = {
    ...w,
    count: 3,
    message: '3 vertices were merged into others within 1e-09, and 1 face that collapsed was dropped',
  };
  assert.equal(
    warningInWords(relative),
    '3 vertices closer than 1e-9 to another vertex were merged with it; 1 face that collapsed was dropped.',
  );
});

test('alternatives: what each refusal proposes, ranked by the kernel each gives', () => {
  const none = { allowOpen: false, walls: false, repair: false, weld: false };
  assert.deepEqual(candidatesFor('OPEN_MESH', none), ['repair', 'weldRepair', 'walls', 'allowOpen']);
  assert.deepEqual(candidatesFor('NON_MANIFOLD_EDGE', none), ['repair', 'weldRepair']);
  assert.deepEqual(candidatesFor('MULTIPLE_COMPONENTS', none), ['repair', 'weld']);
  assert.deepEqual(candidatesFor('OPEN_MESH', { ...none, repair: true, weld: true }), ['walls', 'allowOpen']);
  assert.deepEqual(candidatesFor('PARSE_ERROR', none), []);
  // The open ball: the open surface a polyhedron, walls empty, repair refused.
  const ball = {
    repair: { error: 'OPEN_MESH' },
    weldRepair: { error: 'OPEN_MESH' },
    walls: { status: 'EMPTY' },
    allowOpen: { status: 'POLYHEDRON', volume: 3.5 },
  };
  assert.deepEqual(rankTrials(ball), ['allowOpen', 'walls']);
  assert.match(trialInWords('walls', ball.walls), /the walls make the kernel empty/);
  // The open box: walls close it, the open surface is unbounded.
  assert.deepEqual(
    rankTrials({ repair: { error: 'OPEN_MESH' }, walls: { status: 'POLYHEDRON' }, allowOpen: { status: 'UNBOUNDED' } }),
    ['walls', 'allowOpen'],
  );
  // T-junctions: everything works; repair (the mesh as meant) first.
  assert.deepEqual(
    rankTrials({ repair: { status: 'POLYHEDRON' }, walls: { status: 'POLYGON' }, allowOpen: { status: 'POLYHEDRON' } }),
    ['repair', 'allowOpen', 'walls'],
  );
});

test('face sources: box faces from the marks, words for each mark, witness edges as segments', () => {
  const result = {
    faceSources: Int32Array.from([3, FACE_SOURCE_BOX, 0, FACE_SOURCE_WALL, FACE_SOURCE_BOX]),
    faces: [],
    vertices: new Float64Array(0),
  };
  assert.deepEqual(boxFaceIds(result, 1), [1, 4]);
  assert.equal(faceSourceInWords(result, 0).input, 3);
  assert.match(faceSourceInWords(result, 0).text, /bounded by input face 3\b/);
  assert.match(faceSourceInWords(result, 1).text, /clipping box/);
  assert.match(faceSourceInWords(result, 3).text, /wall at a boundary edge/);
  assert.equal(faceSourceInWords({ faces: [] }, 0), null);
  const { lines, mids } = edgeLines([0, 0, 0, 2, 0, 0, 2, 2, 0], Uint32Array.from([0, 1, 1, 2]), [1, 1, 0]);
  assert.deepEqual(Array.from(lines), [-1, -1, 0, 1, -1, 0, 1, -1, 0, 1, 1, 0]);
  assert.deepEqual(Array.from(mids), [0, -1, 0, 1, 0, 0]);
});
