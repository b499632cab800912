// Vertices: the point of three planes (or an input point), with coordinates as doubles with
// error bounds, and homogeneous coordinates in double-double and exactly, computed on demand.
#pragma once

#include <cstdint>

#include "exact/determinants.h"
#include "exact/plane_store.h"

namespace kergen {

// A point defined by three planes (Cramer's rule), or an input point (exact coordinates).
struct VertexGeom {
  uint32_t basis[3] = {kNoPlane, kNoPlane, kNoPlane};
  int32_t mesh_point = kNoPoint;  // when the three planes meet at an input vertex
  int det_sign = 0;               // sign of det3 of the basis normals
  // For a vertex built without the input-point search: the search's answer, found on the first
  // side test the filter cannot decide (kPointNotSearched until then). (Here, not last: the
  // record packs into 88 bytes.)
  mutable int32_t late_point = kNoPoint;
  Approx x[3];  // coordinates with error bounds (exact when mesh_point)
  // Computed on the first undecided side test and shared by copies: every further exact test
  // at this vertex is one 4-term dot product instead of a 4x4 determinant. They live in the
  // PlaneSet's arenas (PlaneSet::new_dd_homogeneous): a vertex is only used with the plane set
  // it was made from, and never outlives it.
  mutable const DDHomogeneous* dd = nullptr;
  mutable const ExactHomogeneous* exact = nullptr;
};

// Coordinates of a vertex as unevaluated double-double sums hi + lo, accurate to ~1e-30
// relative (exact for input points); hi is then the coordinate rounded to nearest (certified on the
// double-double path; the rare exact path rounds the exact quotient twice).
void precise_coordinates(const PlaneSet& ps, const VertexGeom& v, double hi[3], double lo[3]);
// A vertex's homogeneous coordinates (see DDHomogeneous), computed on first use and cached in
// the vertex (shared by its copies).
const DDHomogeneous& dd_homogeneous(const PlaneSet& ps, const VertexGeom& v);
const ExactHomogeneous& exact_homogeneous(const PlaneSet& ps, const VertexGeom& v);

// The coordinates of exact homogeneous ones (num / den in 2^shift units) as double-doubles in
// input units, each within its error bound e of the exact quotient. False when den's components
// do not bound it away from 0 or a value is not finite.
bool dd_coordinates(const ExactHomogeneous& h, int shift, exact::ApproxDD out[3]);
// A vertex's coordinates as double-doubles with rigorous error bounds, input units. dd_point:
// exact for an input point, else from the exact homogeneous coordinates when they are known,
// else the double-double quotient num / den (false when den is not certainly away from 0; the
// bounds are loose where den is tiny). exact_dd_point: from the exact homogeneous coordinates
// (computed if needed, cached), accurate to ~2^-100; nullptr when dd_coordinates fails.
bool dd_point(const PlaneSet& ps, const VertexGeom& v, exact::ApproxDD out[3]);
const exact::ApproxDD* exact_dd_point(const PlaneSet& ps, const VertexGeom& v);

// The input point on planes a, b and c (three planes with independent normals meet in one
// point), or kNoPoint. `near`, when given, holds the point's coordinates with rigorous bounds: a
// candidate outside them is skipped before any incidence lookup or orient3d.
int32_t input_point_on(const PlaneSet& ps, uint32_t a, uint32_t b, uint32_t c, const Approx* near = nullptr);
// Builds the vertex of three planes with independent normals (caller checked the sign != 0).
// With find_input_point it also recognises an input point on the three planes (exact
// coordinates, cheap exact side tests later): worth it for vertices that are kept, not for the
// LP's transient candidates.
// `known_det_sign`, when not 0, is the exact sign of det3(n_a, n_b, n_c) as the caller knows it
// (the cuts do, from the edge's orientation): it replaces the exact evaluation where the filter
// is uncertain.
VertexGeom make_vertex(const PlaneSet& ps, uint32_t a, uint32_t b, uint32_t c, bool find_input_point = true,
                       int known_det_sign = 0);

}  // namespace kergen
