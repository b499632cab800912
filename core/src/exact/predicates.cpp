// Exact predicates (see predicates.h): signs of normal determinants, side of a plane at a vertex
// (a cascade of filters, anchor shortcuts and exact expansions), orient3d, collinearity and the
// orientation of an edge in a facet.
#include "exact/predicates.h"

#include <algorithm>
#include <cassert>

#include "exact/formulas.h"

namespace kergen {

using namespace formula;

int sign_det3_normals(const PlaneSet& ps, uint32_t a, uint32_t b, uint32_t c) {
  int s = det3_normals(ps.approx(a), ps.approx(b), ps.approx(c)).sign();
  if (s != 2) return s;
  s = det3_normals(ps.dd(a), ps.dd(b), ps.dd(c)).sign();
  if (s != 2) return s;
  // Two of the planes through one input edge (nearly coplanar triangles of a fine tessellation
  // or of a split polygon): the signs of the line's formula. det3 is cyclic, so the pair goes
  // first.
  const uint32_t t[3] = {a, b, c};
  for (int i = 0; i < 3; ++i) {
    uint32_t x, y;
    if (shared_input_points(ps, t[(i + 1) % 3], t[(i + 2) % 3], x, y) < 2) continue;
    s = sign_det3_on_line(ps, t[(i + 1) % 3], t[(i + 2) % 3], t[i], x, y);
    if (s != 2) return s;
  }
  ++ps.exact_fallbacks;
  return det3_normals(ps.exact(a), ps.exact(b), ps.exact(c)).sign();
}

bool normals_parallel(const PlaneSet& ps, uint32_t a, uint32_t b) {
  auto x = cross_normals(ps.approx(a), ps.approx(b));
  if (x[0].certain() || x[1].certain() || x[2].certain()) return false;
  ++ps.exact_fallbacks;
  auto e = cross_normals(ps.exact(a), ps.exact(b));
  return e[0].sign() == 0 && e[1].sign() == 0 && e[2].sign() == 0;
}

int sign_det3_vector(const PlaneSet& ps, const double v[3], uint32_t a, uint32_t b) {
  auto pa = ps.approx(a), pb = ps.approx(b);
  int s = det3(Approx(v[0]), Approx(v[1]), Approx(v[2]), pa.n[0], pa.n[1], pa.n[2], pb.n[0], pb.n[1], pb.n[2]).sign();
  if (s != 2) return s;
  ++ps.exact_fallbacks;
  const auto &ea = ps.exact(a), &eb = ps.exact(b);
  return det3(Expansion(v[0]), Expansion(v[1]), Expansion(v[2]), ea.n[0], ea.n[1], ea.n[2], eb.n[0], eb.n[1], eb.n[2])
      .sign();
}

LineDirection::LineDirection(const PlaneSet& ps, uint32_t p, uint32_t q) : p(p), q(q) {
  auto cp = cross_normals(ps.approx(p), ps.approx(q));
  for (int k = 0; k < 3; ++k) u[k] = cp[k];
}

int LineDirection::rate_sign(const PlaneSet& ps, uint32_t m) const {
  auto pm = ps.approx(m);
  int s = (pm.n[0] * u[0] + pm.n[1] * u[1] + pm.n[2] * u[2]).sign();
  if (s != 2) return s;
  return sign_det3_normals(ps, m, p, q);
}

namespace {
// Exact sign of f_plane at input point pt (orient3d of the plane's representative triangle).
int sign_at_point(const PlaneSet& ps, uint32_t plane, uint32_t pt) {
  if (ps.point_on_plane(pt, plane)) return 0;
  if (ps.explicit_plane(plane)) {
    Scaled x(ps.point(pt), ps.exact_shift());
    return plane_value(ps.exact(plane), x.v).sign();
  }
  const auto& r = ps.rep(plane);
  return orient3d(ps.point(r[0]), ps.point(r[1]), ps.point(r[2]), ps.point(pt), ps.exact_shift());
}
}  // namespace

// Sign of f_l at a vertex whose anchor line (vertex_anchor) passes through an input point that
// plane l holds; 2 when l holds none. f_l is affine along the line and 0 at that point, so its
// value at the vertex factors into signs of degree 3 in the input (orient3d and normal
// determinants) where the general formula has degree 6 and, at the nearly coincident vertices of
// nearly coplanar planes (split polygons), needs exact expansions of every coefficient.
//  - Line through x with direction u = n_a x n_b: v = x + t u, t = -f_c(x) / det3(n_a, n_b, n_c);
//    if f_l(x) = 0 then f_l(v) = t det3(n_a, n_b, n_l).
//  - Line xy: v = (a y - b x) / (a - b) with a = f_c(x), b = f_c(y); f_l(v) = (a f_l(y) - b f_l(x)) / (a - b).
int side_through_anchor(const PlaneSet& ps, uint32_t l, const VertexGeom& v) {
  const VertexAnchor an = vertex_anchor(ps, v);
  if (an.kind == 0) return 2;
  const int lx = sign_at_point(ps, l, an.x);
  if (an.kind == 1) {
    if (lx != 0) return 2;
    const int cx = sign_at_point(ps, an.c, an.x);
    if (cx == 0) return 0;  // the vertex is x
    // det3(n_a, n_b, n_c) is a cyclic shift of the basis order: its sign is det_sign.
    return -cx * v.det_sign * sign_det3_normals(ps, an.a, an.b, l);
  }
  const int ly = sign_at_point(ps, l, an.y);
  if (lx != 0 && ly != 0) return 2;
  // a - b = f_c(x) - f_c(y) = -n_c . (y - x), not 0: the line crosses plane c.
  const int den = -sign_rate_between(ps, an.c, an.x, an.y);
  if (lx == 0) return sign_at_point(ps, an.c, an.x) * ly * den;
  return -sign_at_point(ps, an.c, an.y) * lx * den;
}

namespace {
// Exact sign of f_l at a vertex whose anchor is a line through one input point x (vertex_anchor
// kind 1), 2 for other vertices: f_l(v) det3(n_a, n_b, n_c) = f_l(x) det3(n_a, n_b, n_c) -
// f_c(x) det3(n_a, n_b, n_l) (see side_through_anchor), in expansions: the two determinants
// share the cross product n_a x n_b, and the plane values are at an input point.
int side_exact_on_point_line(const PlaneSet& ps, uint32_t l, const VertexGeom& v) {
  const VertexAnchor an = vertex_anchor(ps, v);
  if (an.kind != 1) return 2;
  const Scaled x(ps.point(an.x), ps.exact_shift());  // the exact planes' units (positive multiples)
  const PlaneCoef<Expansion>&pa = ps.exact(an.a), &pb = ps.exact(an.b), &pc = ps.exact(an.c), &pl = ps.exact(l);
  const std::array<Expansion, 3> u = cross_normals(pa, pb);
  const Expansion det_c = pc.n[0] * u[0] + pc.n[1] * u[1] + pc.n[2] * u[2];
  const Expansion det_l = pl.n[0] * u[0] + pl.n[1] * u[1] + pl.n[2] * u[2];
  const Expansion value = plane_value(pl, x.v) * det_c - plane_value(pc, x.v) * det_l;
  // det3(n_a, n_b, n_c) is a cyclic shift of the basis order: its sign is det_sign.
  return value.sign() * v.det_sign;
}
}  // namespace

namespace {
// The input points of side_on_point_line's factorisation, times 2^exact_shift: the anchor point
// x, the other two corners of planes a and b in their cyclic order from x (so (a1 - x) x (a2 - x)
// is a's normal as its representative triangle gives it, a positive multiple of n_a), and the
// representative triangles of planes c and l.
struct PointLineCorners {
  double x[3], a1[3], a2[3], b1[3], b2[3], c[3][3], l[3][3];
  // The factors below known to be 0 by construction (a point of the plane's own faces).
  bool zero[8] = {false, false, false, false, false, false, false, false};
};
// Whether plane i is a triangle's plane through input point x as a corner; then the two other
// corners in cyclic order from x.
bool corners_from(const PlaneSet& ps, uint32_t i, uint32_t x, uint32_t& first, uint32_t& second) {
  if (ps.explicit_plane(i)) return false;
  const auto& r = ps.rep(i);
  for (int k = 0; k < 3; ++k)
    if (r[k] == x) {
      first = r[(k + 1) % 3];
      second = r[(k + 2) % 3];
      return true;
    }
  return false;
}
void scaled_point(const PlaneSet& ps, uint32_t p, double out[3]) {
  const Scaled s(ps.point(p), ps.exact_shift());
  std::copy(s.v, s.v + 3, out);
}
// f_l(v) det3(n_a, n_b, n_c) for a vertex v on the line of planes a and b through their common
// corner x (times a positive constant), from eight orient3d values of input points, each of
// degree 3. With A_i = a_i - x, B_i = b_i - x, n_a = A1 x A2 and n_b = B1 x B2, the line's
// direction is u = n_a x n_b = D1 B1 - D2 B2 (D1 = det3(A1, A2, B2), D2 = det3(A1, A2, B1)),
// and n_m . B_i = f_m(b_i) - f_m(x) for any plane m. Put into f_l(x) (n_c . u) - f_c(x) (n_l . u)
// (see side_through_anchor), the terms f_l(x) f_c(x) cancel:
//   D1 (f_l(x) f_c(b1) - f_c(x) f_l(b1)) - D2 (f_l(x) f_c(b2) - f_c(x) f_l(b2)).
// Every factor is a plane's value at an input point, accurate to its last bits in each number
// type even where it is tiny (a plane through a point up to rounding, which is what makes the
// vertex nearly incident to l), so the combination is decided with far less cancellation than
// the plane coefficients' expansions had.
template <class T, class Factor>
T point_line_value(const PointLineCorners& k, Factor f) {
  auto factor = [&](int i, const double* p, const double* q, const double* r, const double* s) {
    return k.zero[i] ? T(0.0) : f(p, q, r, s);
  };
  const T d1 = factor(0, k.x, k.a1, k.a2, k.b2), d2 = factor(1, k.x, k.a1, k.a2, k.b1);
  const T lx = factor(2, k.l[0], k.l[1], k.l[2], k.x), cx = factor(3, k.c[0], k.c[1], k.c[2], k.x);
  const T lb1 = factor(4, k.l[0], k.l[1], k.l[2], k.b1), cb1 = factor(5, k.c[0], k.c[1], k.c[2], k.b1);
  const T lb2 = factor(6, k.l[0], k.l[1], k.l[2], k.b2), cb2 = factor(7, k.c[0], k.c[1], k.c[2], k.b2);
  return d1 * (lx * cb1 - cx * lb1) - d2 * (lx * cb2 - cx * lb2);
}
}  // namespace

Approx orient3d_value(const double* a, const double* b, const double* c, const double* p) {
  constexpr double kRelative = 0x1p-30;
  const Approx d = orient3d_formula<Approx>(a, b, c, p);
  if (d.e <= kRelative * std::fabs(d.v)) return d;
  // |exact - v| <= e_dd + |(hi + lo) - v|, the latter below eps |v| (scaled up for its roundings).
  const exact::ApproxDD dd = orient3d_formula<exact::ApproxDD>(a, b, c, p);
  const double v = dd.hi + dd.lo, e = (dd.e + exact::kEps * std::fabs(v)) * exact::kBoundScale;
  if (e <= kRelative * std::fabs(v)) return {v, e};
  Expansion x = orient3d_formula<Expansion>(a, b, c, p);
  x.compress();
  const double rounded = x.estimate();
  const Expansion rest = x - Expansion(rounded);
  double r = 0;  // sum of |rest|'s components, rounded up by the factor
  for (size_t i = 0; i < rest.size(); ++i) r += std::fabs(rest.data()[i]);
  return {rounded, r * (1 + 2 * double(rest.size() + 1) * exact::kEps) * exact::kBoundScale};
}

int side_on_point_line(const PlaneSet& ps, uint32_t l, const VertexGeom& v, int* stage) {
  const VertexAnchor an = vertex_anchor(ps, v);
  if (an.kind != 1 || ps.explicit_plane(an.c) || ps.explicit_plane(l)) return 2;
  uint32_t a1, a2, b1, b2;
  if (!corners_from(ps, an.a, an.x, a1, a2) || !corners_from(ps, an.b, an.x, b1, b2)) return 2;
  PointLineCorners k;
  scaled_point(ps, an.x, k.x);
  scaled_point(ps, a1, k.a1);
  scaled_point(ps, a2, k.a2);
  scaled_point(ps, b1, k.b1);
  scaled_point(ps, b2, k.b2);
  for (int i = 0; i < 3; ++i) {
    scaled_point(ps, ps.rep(an.c)[i], k.c[i]);
    scaled_point(ps, ps.rep(l)[i], k.l[i]);
  }
  // Factors of points on the plane by construction (neighbouring faces share corners) are 0.
  const uint32_t plane_of[8] = {an.a, an.a, l, an.c, l, an.c, l, an.c},
                 point_of[8] = {b2, b1, an.x, an.x, b1, b1, b2, b2};
  for (int i = 0; i < 8; ++i) k.zero[i] = ps.point_on_plane(point_of[i], plane_of[i]);
  // Factors accurate to 2^-30 of themselves: the combination decides in double unless it cancels
  // itself; then in double-double, then exactly.
  int s = point_line_value<Approx>(k, orient3d_value).sign(), decided_by = 0;
  if (s == 2) {
    s = point_line_value<exact::ApproxDD>(k, orient3d_formula<exact::ApproxDD>).sign();
    decided_by = 1;
  }
  if (s == 2) {
    s = point_line_value<Expansion>(k, orient3d_formula<Expansion>).sign();
    decided_by = 2;
  }
  if (stage) *stage = decided_by;
  // det3(n_a, n_b, n_c) is a cyclic shift of the basis order: its sign is det_sign.
  return s * v.det_sign;
}

int side(const PlaneSet& ps, uint32_t l, const VertexGeom& v) {
  // The defining planes hold the vertex by construction (their filtered value is a rounding
  // residue the filter cannot decide, and deciding it exactly costs a full Cramer solve).
  if (l == v.basis[0] || l == v.basis[1] || l == v.basis[2]) return 0;
  // At an input point, a face plane's sign is orient3d's (filtered inside); an explicit plane
  // (no incident points) tries the double filter below first.
  if (v.mesh_point != kNoPoint && !ps.explicit_plane(l)) return sign_at_point(ps, l, uint32_t(v.mesh_point));
  auto pl = ps.approx(l);
  Approx f = pl.n[0] * v.x[0] + pl.n[1] * v.x[1] + pl.n[2] * v.x[2] + pl.d;
  int s = f.sign();
  if (s != 2) return s;
  ++ps.exact_fallbacks;
  int32_t point = v.mesh_point;
  if (point == kNoPoint) {
    // A vertex built without the search (an LP candidate) that the filter cannot place is
    // usually an input point where four or more planes meet: worth a search before the exact
    // Cramer solve. The coordinates' bounds (rigorous, as the filter above relies on) skip the
    // candidates that cannot be the point before their incidence lookups and orient3d.
    if (v.late_point == kPointNotSearched) v.late_point = input_point_on(ps, v.basis[0], v.basis[1], v.basis[2], v.x);
    point = v.late_point;
  }
  if (point != kNoPoint) return sign_at_point(ps, l, uint32_t(point));  // exact input coordinates
  // f_l(v) = (n_l . num + d_l den) / den: first in double-double, then exactly (both cached
  // per vertex).
  const PlaneCoef<exact::ApproxDD> pl_dd = ps.dd(l);
  {
    const DDHomogeneous& h = dd_homogeneous(ps, v);
    const auto& pl = pl_dd;
    int sf = (pl.n[0] * h.num[0] + pl.n[1] * h.num[1] + pl.n[2] * h.num[2] + pl.d * h.den).sign();
    if (sf != 2) return sf * h.den_sign;
  }
  {
    const int sa = side_through_anchor(ps, l, v);
    if (sa != 2) return sa;
  }
  {
    const int sp = side_on_point_line(ps, l, v);
    if (sp != 2) return sp;
  }
  if (!v.exact) {
    // A vertex whose exact homogeneous coordinates are not known yet (the usual case: most
    // vertices reach this stage once, if at all): a direct exact formula is cheaper than
    // computing them.
    const int se = side_exact_on_point_line(ps, l, v);
    if (se != 2) return se;
  }
  if (const exact::ApproxDD* x = exact_dd_point(ps, v)) {
    // The plane at the vertex's double-double coordinates (see ExactHomogeneous::point): decides
    // all but values within ~2^-100 of the magnitudes, at a small part of the exact dot product.
    const auto& pl = pl_dd;
    const int sf = (pl.n[0] * x[0] + pl.n[1] * x[1] + pl.n[2] * x[2] + pl.d).sign();
    if (sf != 2) return sf;
  }
  const ExactHomogeneous& h = exact_homogeneous(ps, v);
  const auto& e = ps.exact(l);
  int sf = (e.n[0] * h.num[0] + e.n[1] * h.num[1] + e.n[2] * h.num[2] + e.d * h.den).sign();
  return sf * h.den.sign();
}

int orient3d(const double* a, const double* b, const double* c, const double* p, int shift) {
  // Shewchuk's static filter: |det - exact| <= (7 eps + 56 eps^2) * permanent, differences
  // included (Shewchuk 1997, orient3d error bound A).
  const double ux = b[0] - a[0], uy = b[1] - a[1], uz = b[2] - a[2];
  const double vx = c[0] - a[0], vy = c[1] - a[1], vz = c[2] - a[2];
  const double wx = p[0] - a[0], wy = p[1] - a[1], wz = p[2] - a[2];
  const double m0 = vy * wz - vz * wy, m1 = vx * wz - vz * wx, m2 = vx * wy - vy * wx;
  const double det = ux * m0 - uy * m1 + uz * m2;
  const double perm = std::fabs(ux) * (std::fabs(vy * wz) + std::fabs(vz * wy)) +
                      std::fabs(uy) * (std::fabs(vx * wz) + std::fabs(vz * wx)) +
                      std::fabs(uz) * (std::fabs(vx * wy) + std::fabs(vy * wx));
  const double bound = (7.0 * exact::kEps + 56.0 * exact::kEps * exact::kEps) * perm;
  if (det > bound) return 1;
  if (det < -bound) return -1;
  // Undecided here: exact zeros (coplanar faces, points on planes) and nearly coplanar points
  // (polygons non-planar by rounding). Shewchuk's adaptive stages decide the latter; the full
  // exact formula is left for the zeros.
  Scaled sa(a, shift), sb(b, shift), sc(c, shift), sp(p, shift);
  int s = exact::orient3d_adaptive(sa.v, sb.v, sc.v, sp.v);
  if (s != 2) return s;
  return orient3d_formula<Expansion>(sa.v, sb.v, sc.v, sp.v).sign();
}

int orient2d(const double* a, const double* b, const double* c, int axis, int shift) {
  // orient3d(a', b', c', d') with x' = (x_i, x_j, 0) and d' = (0, 0, 1) is the 2x2 determinant of
  // (b - a, c - a) in the (i, j) plane: every lifted coordinate is an input double, so the sign
  // is exact. (i, j) follows the axis cyclically, so the sign is the turn seen from +axis.
  const int i = (axis + 1) % 3, j = (axis + 2) % 3;
  const double pa[3] = {a[i], a[j], 0}, pb[3] = {b[i], b[j], 0}, pc[3] = {c[i], c[j], 0}, up[3] = {0, 0, 1};
  return orient3d(pa, pb, pc, up, shift);
}

bool collinear(const double* a, const double* b, const double* c, int shift) {
  if (certainly_not_collinear(a, b, c)) return false;
  auto pa = plane_from_points<Approx>(a, b, c);
  if (pa.n[0].certain() || pa.n[1].certain() || pa.n[2].certain()) return false;
  auto pe = exact_plane(a, b, c, shift);
  return pe.n[0].sign() == 0 && pe.n[1].sign() == 0 && pe.n[2].sign() == 0;
}

namespace {
template <class T>
T edge_in_facet_formula(const PlaneCoef<T>& p, const PlaneCoef<T>& q, const PlaneCoef<T>& h, const PlaneCoef<T>& s) {
  auto dir = cross_normals(p, q);
  auto w = cross_normals(h, s);
  return dir[0] * w[0] + dir[1] * w[1] + dir[2] * w[2];
}
}  // namespace

int sign_edge_in_facet(const PlaneSet& ps, uint32_t p, uint32_t q, uint32_t h, uint32_t s) {
  // (n_p x n_q) . (n_p x n_q) = |n_p x n_q|^2 > 0 for the independent normals of an edge.
  if (h == p && s == q) return 1;
  if (h == q && s == p) return -1;
  int r = edge_in_facet_formula(ps.approx(p), ps.approx(q), ps.approx(h), ps.approx(s)).sign();
  if (r != 2) return r;
  ++ps.exact_fallbacks;
  return edge_in_facet_formula(ps.exact(p), ps.exact(q), ps.exact(h), ps.exact(s)).sign();
}

namespace {
// Farkas weights w (all of one strict sign, made positive) for planes 0..k-1, from the normals'
// null combination: true when they exist and sum w_i d_i > 0.
bool weights_prove_disjoint(const PlaneCoef<Expansion>* pl, const Expansion* w, size_t k) {
  const int s = w[0].sign();
  if (s == 0) return false;
  for (size_t i = 1; i < k; ++i)
    if (w[i].sign() != s) return false;
  Expansion sum;
  for (size_t i = 0; i < k; ++i) sum = sum + w[i] * pl[i].d;
  return sum.sign() == s;
}
}  // namespace

bool halfspaces_disjoint(const PlaneCoef<Expansion>* pl, size_t k) {
  if (k == 4) {
    // sum_i (-1)^i det3(the other three normals, in order) n_i = 0 for any four vectors of R^3
    // (a 4x4 determinant with a repeated column, expanded).
    Expansion w[4];
    for (size_t i = 0; i < 4; ++i) {
      const PlaneCoef<Expansion>* o[3];
      for (size_t j = 0, m = 0; j < 4; ++j)
        if (j != i) o[m++] = &pl[j];
      w[i] = det3_normals(*o[0], *o[1], *o[2]);
      if (i % 2) w[i] = -w[i];
    }
    return weights_prove_disjoint(pl, w, 4);
  }
  if (k == 3) {
    // Three normals in a plane with normal u: n_a x n_b = c_ab u, and c_12 n_0 + c_20 n_1 +
    // c_01 n_2 = 0 (Cramer's rule in that plane); one coordinate of the cross products gives
    // c times u_j, a common factor, on an axis where u_j != 0.
    if (det3_normals(pl[0], pl[1], pl[2]).sign() != 0) return false;
    const auto c12 = cross_normals(pl[1], pl[2]), c20 = cross_normals(pl[2], pl[0]), c01 = cross_normals(pl[0], pl[1]);
    for (int j = 0; j < 3; ++j) {
      const Expansion w[3] = {c12[j], c20[j], c01[j]};
      if (w[0].sign() != 0 || w[1].sign() != 0 || w[2].sign() != 0) return weights_prove_disjoint(pl, w, 3);
    }
    return false;  // all normals parallel: rank 1, not 2
  }
  if (k == 2) {
    // Parallel normals: w = (-n_1j, n_0j) on an axis where n_0j != 0 is a null combination.
    const auto c = cross_normals(pl[0], pl[1]);
    if (c[0].sign() != 0 || c[1].sign() != 0 || c[2].sign() != 0) return false;
    for (int j = 0; j < 3; ++j)
      if (pl[0].n[j].sign() != 0) {
        const Expansion w[2] = {-pl[1].n[j], pl[0].n[j]};
        return weights_prove_disjoint(pl, w, 2);
      }
  }
  return false;
}

}  // namespace kergen
