// glTF 2.0 test files written from scratch (no exporter): a triangle mesh split over two scene
// nodes whose transforms put the pieces back together in world space, as .glb (binary) and as
// .gltf (JSON with the buffer embedded as a data URI), and a .gltf whose buffer is a separate
// file (which a single dropped file cannot bring along).
import fs from 'node:fs';

// Two meshes from one triangle mesh: the first `split` triangles and the rest. Every vertex is
// written per triangle (a soup: the page welds it). Node 0 scales by 2 (its positions halved),
// node 1 translates by (shift, 0, 0) (its positions moved by -shift): both exact in binary for
// coordinates like the dented cube's (a shift of general float32 coordinates rounds: use 0).
function gltfParts({ positions, indices }, split, shift = 3) {
  const pieces = [
    [0, split],
    [split, indices.length / 3],
  ];
  const chunks = [];
  const accessors = [],
    bufferViews = [],
    meshes = [];
  let offset = 0;
  pieces.forEach(([t0, t1], k) => {
    const out = new Float32Array(9 * (t1 - t0));
    for (let t = t0; t < t1; t++) {
      for (let c = 0; c < 3; c++) {
        const v = indices[3 * t + c];
        const p = [positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]];
        const q = k === 0 ? p.map((x) => x / 2) : [p[0] - shift, p[1], p[2]];
        out.set(q, 9 * (t - t0) + 3 * c);
      }
    }
    const min = [0, 1, 2].map((c) => Math.min(...out.filter((_, i) => i % 3 === c)));
    const max = [0, 1, 2].map((c) => Math.max(...out.filter((_, i) => i % 3 === c)));
    bufferViews.push({ buffer: 0, byteOffset: offset, byteLength: out.byteLength });
    accessors.push({ bufferView: k, componentType: 5126, count: out.length / 3, type: 'VEC3', min, max });
    meshes.push({ primitives: [{ attributes: { POSITION: k }, mode: 4 }] });
    chunks.push(Buffer.from(out.buffer));
    offset += out.byteLength;
  });
  const bin = Buffer.concat(chunks);
  const json = {
    asset: { version: '2.0', generator: 'kergen-wasm tests/e2e/gltf-files.mjs' },
    scene: 0,
    scenes: [{ nodes: [0, 1] }],
    nodes: [
      { mesh: 0, scale: [2, 2, 2] },
      { mesh: 1, translation: [shift, 0, 0] },
    ],
    meshes,
    accessors,
    bufferViews,
    buffers: [{ byteLength: bin.length }],
  };
  return { json, bin };
}

const pad4 = (buf, fill) => Buffer.concat([buf, Buffer.alloc((4 - (buf.length % 4)) % 4, fill)]);

/** Writes `mesh` (split after `split` triangles) as a GLB file. */
export function writeGlb(file, mesh, split, { shift = 3 } = {}) {
  const { json, bin } = gltfParts(mesh, split, shift);
  const jsonChunk = pad4(Buffer.from(JSON.stringify(json)), 0x20);
  const binChunk = pad4(bin, 0);
  const header = Buffer.alloc(12);
  header.write('glTF', 0);
  header.writeUInt32LE(2, 4);
  header.writeUInt32LE(12 + 8 + jsonChunk.length + 8 + binChunk.length, 8);
  const chunkHeader = (length, type) => {
    const h = Buffer.alloc(8);
    h.writeUInt32LE(length, 0);
    h.write(type, 4);
    return h;
  };
  fs.writeFileSync(
    file,
    Buffer.concat([
      header,
      chunkHeader(jsonChunk.length, 'JSON'),
      jsonChunk,
      chunkHeader(binChunk.length, 'BIN\0'),
      binChunk,
    ]),
  );
}

/** Writes `mesh` as a .gltf with its buffer embedded (data URI), or, with `external`, beside it. */
export function writeGltf(file, mesh, split, { external = false } = {}) {
  const { json, bin } = gltfParts(mesh, split);
  json.buffers[0].uri = external ? 'buffer.bin' : `data:application/octet-stream;base64,${bin.toString('base64')}`;
  fs.writeFileSync(file, JSON.stringify(json));
}
