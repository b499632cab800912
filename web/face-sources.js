// What bounds the kernel: `result.faceSources` (one entry per kernel face: the lowest input face
// index whose plane the face lies on, or FACE_SOURCE_BOX for a face of the clipping box of an
// UNBOUNDED kernel, or FACE_SOURCE_WALL for a wall at a boundary edge) and
// `result.witnessBoundaryEdges` (input vertex-id pairs of the boundary edges whose walls take part
// in an empty kernel's witness). Results of a package without them leave both undefined: the page
// then keeps its older behaviour (box facets found geometrically, unbounded.js; no face info).

// The package's marks, the core's values (kergen::kFaceSourceBox, kFaceSourceWall): from the
// worker entry, as importing the main one would load the wasm glue on this thread.
import { FACE_SOURCE_BOX, FACE_SOURCE_WALL } from 'kergen-wasm/worker';
import { boxFacets } from './unbounded.js';

export { FACE_SOURCE_BOX, FACE_SOURCE_WALL };

/** The kernel faces that are the clip box's: from the marks when the result has them. */
export function boxFaceIds(result, maxAbs) {
  const src = result.faceSources;
  if (!src) return boxFacets(result, maxAbs);
  const out = [];
  for (let f = 0; f < src.length; f++) if (src[f] === FACE_SOURCE_BOX) out.push(f);
  return out;
}

/** What bounds kernel face `f`, in words, and the input face to highlight (or -1). */
export function faceSourceInWords(result, f) {
  const s = result.faceSources?.[f];
  if (s === undefined) return null;
  if (s === FACE_SOURCE_BOX)
    return { input: -1, text: `Kernel face ${f}: the clipping box (the kernel goes on beyond it).` };
  if (s === FACE_SOURCE_WALL) return { input: -1, text: `Kernel face ${f}: a wall at a boundary edge.` };
  return { input: s, text: `Kernel face ${f}: bounded by input face ${s} (highlighted in cyan).` };
}

/**
 * Segments (float32 xyz pairs) and midpoints of the input edges `pairs` (vertex-id pairs into
 * `positions`), relative to `center`: the witness's boundary edges as drawn.
 */
export function edgeLines(positions, pairs, center) {
  const n = pairs.length / 2;
  const lines = new Float32Array(6 * n),
    mids = new Float32Array(3 * n);
  for (let i = 0; i < n; i++) {
    const a = pairs[2 * i],
      b = pairs[2 * i + 1];
    for (let c = 0; c < 3; c++) {
      const pa = positions[3 * a + c] - center[c],
        pb = positions[3 * b + c] - center[c];
      lines[6 * i + c] = pa;
      lines[6 * i + 3 + c] = pb;
      mids[3 * i + c] = (pa + pb) / 2;
    }
  }
  return { lines, mids };
}
