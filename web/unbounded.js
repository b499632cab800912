// Which facets of an UNBOUNDED kernel are the clip box's rather than the mesh's.
//
// With allowOpen, a kernel that the mesh's face planes do not bound is clipped by the package to
// a box around the mesh: the planes ±B on each axis, with B = 2^(e+1) where the input's largest
// coordinate magnitude is m·2^e, m in [0.5, 1) (the core scales coordinates below 1 by a power of
// two and puts the box at ±2 in those units). The result does not say which facets lie in box
// planes, so the page finds them from the geometry: a box facet has every vertex at the same
// coordinate ±B on one axis, and B exceeds every input coordinate's magnitude. A facet of a mesh
// plane cannot do that: an axis-aligned mesh plane x = c contains an input face, so |c| is at
// most the largest input coordinate. (Box facet vertices lie exactly on ±B: B is a power of two
// and the kernel's vertices are the exact ones rounded, so the test is an equality.)

/**
 * The indices of `result.faces` that lie in the clip box's planes. `maxAbs`: the largest
 * magnitude of the input's coordinates (prepareDrawing's `maxAbs`).
 */
export function boxFacets(result, maxAbs) {
  const v = result.vertices;
  const out = [];
  for (let f = 0; f < result.faces.length; f++) {
    const loop = result.faces[f];
    for (let axis = 0; axis < 3; axis++) {
      const c = v[3 * loop[0] + axis];
      if (!(Math.abs(c) > maxAbs)) continue;
      let flat = true;
      for (let i = 1; i < loop.length && flat; i++) flat = v[3 * loop[i] + axis] === c;
      if (flat) {
        out.push(f);
        break;
      }
    }
  }
  return out;
}

/** The clip box's half-size B for an input whose largest coordinate magnitude is `maxAbs`. */
export function clipBoxHalfSize(maxAbs) {
  if (!(maxAbs > 0)) return 2;
  const e = Math.floor(Math.log2(maxAbs)) + 1; // maxAbs = m·2^e with m in [0.5, 1)
  return 2 ** (e + 1);
}
