// The double filters' error bounds, in one place. Each bound is rigorous for doubles with the
// library's rounding (no FMA contraction, no fast-math): a filter that decides by comparing a
// computed value with it gives the exact sign. Scalar and vectorized callers use these same
// functions (the vectorized loops repeat the operations lane by lane in the same order, so the
// same bits and decisions).
#pragma once

#include <cmath>

#include "exact/expansion.h"

namespace kergen {

// ---- a plane's sign at a vertex (VertexFilter, the tracer's certification scan) -------------
// For a vertex with coordinates x_k +- dx (|x_k| <= xm) and a plane n.x + d with coefficient
// errors e(n_k), e(d): |f(exact) - f(computed)| <= (sum e(n_k)) c1 + |n|_1 c2 + (e(d) + 4 eps
// |d| + floor), times kBoundScale, with the vertex terms c1, c2 below (the plane's errors over
// the coordinates' reach, the coordinates' errors and the evaluation's rounding over |n|).
struct VertexFilterTerms {
  double c1, c2;
};
inline VertexFilterTerms vertex_filter_terms(const exact::Approx x[3]) {
  double xm = 0, dx = 0;
  for (int k = 0; k < 3; ++k) {
    xm = std::max(xm, std::fabs(x[k].v));
    dx = std::max(dx, x[k].e);
  }
  return {(xm + 2 * dx) * exact::kBoundScale, (dx + 4 * exact::kEps * xm) * exact::kBoundScale};
}
// The plane's own terms: |n|_1, sum e(n_k), and e(d) + rounding (kept per plane by scans).
struct PlaneFilterTerms {
  double n1, en, e0;
};
inline PlaneFilterTerms plane_filter_terms(double nx, double ny, double nz, double d, double enx, double eny,
                                           double enz, double ed) {
  return {std::fabs(nx) + std::fabs(ny) + std::fabs(nz), enx + eny + enz,
          ed + 4 * exact::kEps * std::fabs(d) + exact::kUnderflowFloor};
}
// The bound before the final kBoundScale (callers compare f against -bound * kBoundScale or
// bound * kBoundScale; the vectorized scan multiplies by -kBoundScale, which gives the same bits
// negated).
inline double vertex_filter_bound(const PlaneFilterTerms& p, const VertexFilterTerms& v) {
  return p.en * v.c1 + p.n1 * v.c2 + p.e0;
}

// ---- a plane's value at a vertex of a traced polytope (climbs, culling, cuts) ----------------
// How far a computed f(v) = a x + b y + c z + d at a vertex of a traced polytope can be from the
// exact plane's value at the exact vertex: the rounding of the evaluation (below 8 eps of the sum
// of the terms' magnitudes), the vertices' coordinate errors (at most coord_error; coordinates at
// most max_abs in magnitude) and the plane's coefficient errors (ea, eb, ec, ed). It scales with
// the coordinates' magnitudes, not with 1: a polytope far smaller than its distance from the
// origin (a tiny shape placed far out) keeps margins below its own size, so the climbs and
// searches built on it stay local. climb_to_max needs a tie of at least twice it.
inline double value_error_bound(double a, double b, double c, double d, double ea, double eb, double ec, double ed,
                                double max_abs, double coord_error) {
  const double n1 = std::fabs(a) + std::fabs(b) + std::fabs(c), reach = max_abs + coord_error;
  return 8 * exact::kEps * (n1 * reach + std::fabs(d)) + n1 * coord_error + (ea + eb + ec) * reach + ed +
         exact::kUnderflowFloor;
}
// Multiples of value_error_bound (delta) used by the support test of culling and by the cuts:
// a plane may reach a polytope when its computed maximum is above -kReachMargin delta (far above
// what a value can be off by, so a reaching plane is never missed), and the climbs' tie is
// kClimbTie delta (above the 2 delta their plateau search needs to reach every higher vertex).
constexpr double kReachMargin = 16;
constexpr double kClimbTie = 4;

}  // namespace kergen
