// Exact predicates on input points, planes and vertices: each evaluates one templated formula
// with Approx (a double plus a rigorous error bound) and, only when the sign is not certain, the
// same formula with exact expansions. Kernel vertices at input points take a cheaper route:
// their side of a plane is orient3d on input points, and incidence known from the mesh is 0 for
// free.
#pragma once

#include <cmath>
#include <cstdint>

#include "exact/determinants.h"
#include "exact/plane_store.h"
#include "exact/vertex.h"

namespace kergen {

// ---- predicates (exact signs) ----------------------------------------------------------------
// sign of det3(n_a, n_b, n_c)
int sign_det3_normals(const PlaneSet& ps, uint32_t a, uint32_t b, uint32_t c);
// whether n_a x n_b == 0 exactly
bool normals_parallel(const PlaneSet& ps, uint32_t a, uint32_t b);
// sign of det3(v, n_a, n_b) for an exact double vector v (objective directions)
int sign_det3_vector(const PlaneSet& ps, const double v[3], uint32_t a, uint32_t b);
// The line of planes p and q with its direction n_p x n_q precomputed (filtered): rate_sign(m)
// is the exact sign of n_m . (n_p x n_q) = det3(n_m, n_p, n_q), the rate of change of f_m along it.
struct LineDirection {
  LineDirection(const PlaneSet& ps, uint32_t p, uint32_t q);
  int rate_sign(const PlaneSet& ps, uint32_t m) const;
  uint32_t p, q;
  Approx u[3];
};
// sign of f_l at the vertex: > 0 outside plane l, 0 on it, < 0 inside.
int side(const PlaneSet& ps, uint32_t l, const VertexGeom& v);
// The same sign when the vertex lies on a line through an input point that plane l holds (the
// line of two basis planes through their shared input points), from signs of degree 3; 2 when
// there is no such point. side() uses it before exact expansions.
int side_through_anchor(const PlaneSet& ps, uint32_t l, const VertexGeom& v);
// The same sign when the vertex lies on the line of two triangles' planes through their common
// corner (kind 1 anchor), from eight orient3d values of input points, each of degree 3 (in
// double from relatively accurate factors, then double-double, then exactly); 2 for other
// vertices and planes (polygon planes not cornered at the point, explicit planes). side() uses it
// where the double-double filter cannot decide. `stage`, when given, gets the stage that decided
// (0 double, 1 double-double, 2 exact expansions), for tests.
int side_on_point_line(const PlaneSet& ps, uint32_t l, const VertexGeom& v, int* stage = nullptr);
// orient(a,b,c,p)'s value as a double v with a rigorous bound e, |v - exact| <= e, and e at most
// 2^-30 |v| (e = 0 for an exact zero): the double formula where its own bound is that small,
// else double-double, else the exact expansion rounded. Points as the exact stages take them
// (scaled by 2^exact_shift: no underflow).
Approx orient3d_value(const double* a, const double* b, const double* c, const double* p);
// sign of orient(a,b,c,p) = ((b-a) x (c-a)) . (p-a) for input points; exact stages use the points
// times 2^shift (same sign, no underflow).
int orient3d(const double* a, const double* b, const double* c, const double* p, int shift = 0);
// collinear()'s static filter alone (inline for the per-face loops): true when some component of
// the cross product (b - a) x (c - a) of the rounded differences is certainly non-zero, each
// within 5 eps (|u_i v_j| + |u_j v_i|) of the exact one; false when the exact test has to decide.
inline bool certainly_not_collinear(const double* a, const double* b, const double* c) {
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  bool certain = false;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const double x = u[i] * v[j], y = u[j] * v[i];
    certain |= std::fabs(x - y) > 5 * exact::kEps * (std::fabs(x) + std::fabs(y)) + exact::kUnderflowFloor;
  }
  return certain;
}
// sign of the orientation of the input points a, b, c projected along coordinate `axis` (the
// triangle's turn seen from +axis): for coplanar points, in-plane tests on a plane that is not
// parallel to that axis. Exact: orient3d of the projections lifted by (0, 0, 1).
int orient2d(const double* a, const double* b, const double* c, int axis, int shift = 0);
// Whether the input triangle (a,b,c) has exactly collinear vertices.
bool collinear(const double* a, const double* b, const double* c, int shift = 0);
// sign of dir . (n_h x n_s) where dir = n_p x n_q (edge orientation in facet h).
int sign_edge_in_facet(const PlaneSet& ps, uint32_t p, uint32_t q, uint32_t h, uint32_t s);
// Whether the inner half-spaces n_i . x + d_i <= 0 of k planes (exact coefficients, 2 <= k <= 4)
// have no common point and every one of them is needed for that. The proof is Farkas weights
// w_i > 0 with sum w_i n_i = 0 and sum w_i d_i > 0: at any point x, sum w_i (n_i . x + d_i) =
// sum w_i d_i > 0, so some plane has x outside. With all k weights positive and the normals of
// rank k - 1 (the only case where k normals have a null combination, unique up to scale), no
// proper subset has such weights, so no proper subset is disjoint (Farkas' converse).
bool halfspaces_disjoint(const PlaneCoef<Expansion>* planes, size_t k);

}  // namespace kergen
