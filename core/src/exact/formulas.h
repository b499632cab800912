// Formulas shared by the exact layer's files (internal to core/src/exact/): exact differences of
// input coordinates, the plane of three points, orient3d, Cramer's rule, the input points two
// planes share and the signs that follow from them, and a vertex's anchor line through input
// points. Each template is evaluated with Approx, ApproxDD or Expansion.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "exact/determinants.h"
#include "exact/plane_store.h"
#include "exact/predicates.h"
#include "exact/vertex.h"

namespace kergen {
namespace formula {

// Exact differences of input coordinates in each number type (one- or two-component in the
// exact types: the differences of nearby points are usually exact in double already).
inline Approx difference(Approx*, double x, double y) { return Approx(x) - Approx(y); }
inline exact::ApproxDD difference(exact::ApproxDD*, double x, double y) { return exact::dd_difference(x, y); }
inline Expansion difference(Expansion*, double x, double y) { return Expansion::difference(x, y); }

// n = (b - a) x (c - a), d = -n . a
template <class T>
PlaneCoef<T> plane_from_points(const double* a, const double* b, const double* c) {
  T u[3], v[3];
  for (int i = 0; i < 3; ++i) {
    u[i] = difference((T*)nullptr, b[i], a[i]);
    v[i] = difference((T*)nullptr, c[i], a[i]);
  }
  PlaneCoef<T> p;
  p.n[0] = u[1] * v[2] - u[2] * v[1];
  p.n[1] = u[2] * v[0] - u[0] * v[2];
  p.n[2] = u[0] * v[1] - u[1] * v[0];
  p.d = -(p.n[0] * T(a[0]) + p.n[1] * T(a[1]) + p.n[2] * T(a[2]));
  return p;
}

// The filtered plane: approx_plane (plane_store.h, inline for the per-face loops).
template <>
inline PlaneCoef<Approx> plane_from_points<Approx>(const double* a, const double* b, const double* c) {
  return approx_plane(a, b, c);
}

// det3(b - a, c - a, p - a).
template <class T>
T orient3d_formula(const double* a, const double* b, const double* c, const double* p) {
  T u[3], v[3], w[3];
  for (int k = 0; k < 3; ++k) {
    u[k] = difference((T*)nullptr, b[k], a[k]);
    v[k] = difference((T*)nullptr, c[k], a[k]);
    w[k] = difference((T*)nullptr, p[k], a[k]);
  }
  return det3(u[0], u[1], u[2], v[0], v[1], v[2], w[0], w[1], w[2]);
}

// Cramer's rule for the vertex of planes a, b, c: coordinate k = num_k / den.
template <class T>
void cramer_numerators(const PlaneCoef<T>& a, const PlaneCoef<T>& b, const PlaneCoef<T>& c, T num[3]) {
  T ma = -a.d, mb = -b.d, mc = -c.d;
  num[0] = det3(ma, a.n[1], a.n[2], mb, b.n[1], b.n[2], mc, c.n[1], c.n[2]);
  num[1] = det3(a.n[0], ma, a.n[2], b.n[0], mb, b.n[2], c.n[0], mc, c.n[2]);
  num[2] = det3(a.n[0], a.n[1], ma, b.n[0], b.n[1], mb, c.n[0], c.n[1], mc);
}
template <class T>
void cramer(const PlaneCoef<T>& a, const PlaneCoef<T>& b, const PlaneCoef<T>& c, T num[3], T& den) {
  den = det3_normals(a, b, c);
  cramer_numerators(a, b, c, num);
}

struct Scaled {
  double v[3];
  Scaled(const double* p, int shift) {
    for (int k = 0; k < 3; ++k) v[k] = shift == 0 ? p[k] : std::ldexp(p[k], shift);
  }
};

// How many input points (0, 1 or 2, stopping at 2) lie on both planes p and q by construction,
// in x then y, searched from the plane with fewer points; 0 when the search would be long. Two
// make the line of p and q the line through them.
inline int shared_input_points(const PlaneSet& ps, uint32_t p, uint32_t q, uint32_t& x, uint32_t& y) {
  if (ps.explicit_plane(p) || ps.explicit_plane(q)) return 0;
  if (ps.points_on(p).size() > ps.points_on(q).size()) std::swap(p, q);
  if (ps.points_on(p).size() > 256) return 0;
  int found = 0;
  const PlaneSet::Span rp = ps.points_on(p), rq = ps.points_on(q);
  if (rq.size() <= 16) {
    // Short rows (a triangle's plane holds 3 points): one merge of the sorted rows finds the
    // same points in the same order as the lookups below (called for most vertices).
    for (const uint32_t *i = rp.b, *j = rq.b; i != rp.e && j != rq.e;) {
      if (*i < *j) {
        ++i;
      } else if (*j < *i) {
        ++j;
      } else {
        (found == 0 ? x : y) = *i;
        if (++found == 2) break;
        ++i;
        ++j;
      }
    }
    return found;
  }
  for (uint32_t pt : rp) {
    if (!ps.point_on_plane(pt, q)) continue;
    (found == 0 ? x : y) = pt;
    if (++found == 2) break;
  }
  return found;
}

// Exact sign of n_c . (Y - X) = f_c(Y) - f_c(X) for input points X, Y.
inline int sign_rate_between(const PlaneSet& ps, uint32_t c, uint32_t x, uint32_t y) {
  const double *X = ps.point(x), *Y = ps.point(y);
  if (!ps.explicit_plane(c)) {
    const auto& r = ps.rep(c);
    const double *r0 = ps.point(r[0]), *r1 = ps.point(r[1]), *r2 = ps.point(r[2]);
    if (ps.point_on_plane(x, c)) return orient3d(r0, r1, r2, Y, ps.exact_shift());
    if (ps.point_on_plane(y, c)) return -orient3d(r0, r1, r2, X, ps.exact_shift());
  }
  auto pa = ps.approx(c);
  Approx dv[3];
  for (int k = 0; k < 3; ++k) dv[k] = Approx(Y[k]) - Approx(X[k]);
  int s = (pa.n[0] * dv[0] + pa.n[1] * dv[1] + pa.n[2] * dv[2]).sign();
  if (s != 2) return s;
  const auto& e = ps.exact(c);
  Scaled sx(X, ps.exact_shift()), sy(Y, ps.exact_shift());
  Expansion r;
  for (int k = 0; k < 3; ++k) r = r + e.n[k] * Expansion::difference(sy.v[k], sx.v[k]);
  return r.sign();
}

// n . ((Y - X) x (W - X)) = det3(n, Y - X, W - X), with the differences exact in T.
template <class T>
T normal_dot_cross(const PlaneCoef<T>& p, const double* X, const double* Y, const double* W) {
  T d[3], e[3];
  for (int k = 0; k < 3; ++k) {
    d[k] = difference((T*)nullptr, Y[k], X[k]);
    e[k] = difference((T*)nullptr, W[k], X[k]);
  }
  return det3(p.n[0], p.n[1], p.n[2], d[0], d[1], d[2], e[0], e[1], e[2]);
}

// Exact sign of det3(n_a, n_b, n_c) when planes a and b both hold input points x != y (2 when
// the shortcut does not apply). With d = y - x and e = w - x for an input point w of plane b off
// the line, n_b = s k (d x e) with k > 0 and s = sign(n_b . (d x e)), so
//   n_a x n_b = s k (n_a . e) d   and   det3 = n_c . (n_a x n_b) = s k f_a(w) (n_c . d),
// three signs of degree 3 in the input (two of them orient3d of input points) where Cramer-like
// evaluation needs degree 6 and, for nearly coplanar a and b, exact expansions.
inline int sign_det3_on_line(const PlaneSet& ps, uint32_t a, uint32_t b, uint32_t c, uint32_t x, uint32_t y) {
  const int shift = ps.exact_shift();
  const double *X = ps.point(x), *Y = ps.point(y);
  uint32_t w = kNoPlane;
  for (uint32_t r : ps.rep(b))
    if (r != x && r != y && !collinear(X, Y, ps.point(r), shift)) {
      w = r;
      break;
    }
  if (w == kNoPlane) return 2;
  const double* W = ps.point(w);
  // s: n_b is parallel to d x e, so n_b . (d x e) = +-|n_b||d x e| has no cancellation.
  int s;
  {
    s = normal_dot_cross(ps.approx(b), X, Y, W).sign();
    if (s == 2) {
      Scaled sx(X, shift), sy(Y, shift), sw(W, shift);
      s = normal_dot_cross(ps.exact(b), sx.v, sy.v, sw.v).sign();
    }
  }
  const auto& ra = ps.rep(a);
  const int fa = orient3d(ps.point(ra[0]), ps.point(ra[1]), ps.point(ra[2]), W, shift);
  if (s == 0 || fa == 0) return 0;
  return s * fa * sign_rate_between(ps, c, x, y);
}

// The vertex through input points: on the line xy of two basis planes (kind 2), or on their
// line through the input point x (kind 1); c is the third basis plane.
struct VertexAnchor {
  int kind = 0;
  uint32_t x = 0, y = 0, c = kNoPlane, a = kNoPlane, b = kNoPlane;
};
inline VertexAnchor vertex_anchor(const PlaneSet& ps, const VertexGeom& v) {
  VertexAnchor best;
  for (int i = 0; i < 3; ++i) {
    VertexAnchor t;
    t.a = v.basis[(i + 1) % 3];
    t.b = v.basis[(i + 2) % 3];
    t.c = v.basis[i];
    t.kind = shared_input_points(ps, t.a, t.b, t.x, t.y);
    if (t.kind == 2) return t;
    if (t.kind > best.kind) best = t;
  }
  return best;
}

// Homogeneous coordinates in T (X, Y: the points in T's units).
// Line xy: num = a y - b x, den = a - b with a = f_c(x), b = f_c(y).
template <class T>
T plane_value(const PlaneCoef<T>& c, const double* X) {
  return c.n[0] * T(X[0]) + c.n[1] * T(X[1]) + c.n[2] * T(X[2]) + c.d;
}
template <class T>
void on_line(const PlaneCoef<T>& c, const double* X, const double* Y, T num[3], T& den) {
  const T a = plane_value(c, X), b = plane_value(c, Y);
  for (int k = 0; k < 3; ++k) num[k] = a * T(Y[k]) - b * T(X[k]);
  den = a - b;
}
// Line of planes a and b through x, direction u = n_a x n_b: v = x + t u with f_c(v) = 0, so
// num = x den - f_c(x) u and den = n_c . u = det3(n_a, n_b, n_c) (Cramer's degrees, but about a
// third of its products, and f_c(x) stays accurate when the vertex is near x).
template <class T>
void on_point_line(const PlaneCoef<T>& a, const PlaneCoef<T>& b, const PlaneCoef<T>& c, const double* X, T num[3],
                   T& den) {
  const std::array<T, 3> u = cross_normals(a, b);
  den = c.n[0] * u[0] + c.n[1] * u[1] + c.n[2] * u[2];
  const T fx = plane_value(c, X);
  for (int k = 0; k < 3; ++k) num[k] = T(X[k]) * den - fx * u[k];
}

}  // namespace formula
}  // namespace kergen
