// Per-vertex caches of homogeneous coordinates (see exact/vertex.h), declared here so that the
// PlaneSet can own their arenas.
#pragma once

#include "exact/expansion.h"

namespace kergen {

// Homogeneous coordinates of a plane-triple vertex, x_k = num[k] / den, in double-double with
// error bounds and exactly: Cramer's rule in general; when two of the planes share two input
// points x and y (the vertex is on the line xy), num = a y - b x and den = a - b with a, b the
// third plane's values at x and y (lower degree, and well conditioned where the two planes are
// nearly coplanar, as the triangles of a finely tessellated or a rounding-split flat face are);
// when they share one input point x, from x and the line's direction (fewer products).
struct DDHomogeneous {
  exact::ApproxDD num[3], den;
  int den_sign = 0;  // exact sign of den
};
struct ExactHomogeneous {
  exact::Expansion num[3], den;
  // The coordinates num[k] / den as double-doubles with rigorous error bounds, in input units
  // (dd_coordinates, on first need through exact_dd_point; point_state 1 = valid, -1 = not
  // available, 0 = not computed yet): side() evaluates a plane there before the exact dot
  // product, the cuts' edge rates and the output coordinates use them too. Where den is
  // tiny (the vertex of nearly coplanar planes), the double-double homogeneous values leave no
  // correct digit of a plane's value while these coordinates are still accurate to ~2^-100.
  mutable exact::ApproxDD point[3];
  mutable int point_state = 0;
};

}  // namespace kergen
