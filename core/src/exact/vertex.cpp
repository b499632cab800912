// Vertex construction: the input point on three planes, Cramer's rule or an anchor line through
// input points, homogeneous coordinates in double-double and exactly, and coordinates rounded to
// nearest for the output.
#include "exact/vertex.h"

#include <algorithm>
#include <cassert>

#include "exact/formulas.h"

namespace kergen {

using namespace formula;

namespace {
// Rigorous bounds on |x| from an expansion's components (the triangle inequality; the sums'
// roundings are covered by the factors 1 +- 2 (n + 1) eps).
double magnitude_above(const Expansion& x) {
  double s = 0;
  for (size_t i = 0; i < x.size(); ++i) s += std::fabs(x.data()[i]);
  return s * (1 + 2 * double(x.size() + 1) * exact::kEps);
}
double magnitude_below(const Expansion& x) {
  const size_t n = x.size();
  if (n == 0) return 0;
  double rest = 0;  // the components below the largest
  for (size_t i = 0; i + 1 < n; ++i) rest += std::fabs(x.data()[i]);
  return (std::fabs(x.data()[n - 1]) - rest * (1 + 2 * double(n + 1) * exact::kEps)) * (1 - 2 * exact::kEps);
}
}  // namespace

bool dd_coordinates(const ExactHomogeneous& h, int shift, exact::ApproxDD out[3]) {
  // x = num / den = q + r + (num - (q + r) den) / den exactly, for any doubles q and r: q is the
  // quotient of the estimates, r that of the remainder num - q den, and the last term is
  // bounded by the components of the second remainder and of den.
  const double den_below = magnitude_below(h.den);
  if (!(den_below > 0)) return false;
  const double den = h.den.estimate();
  for (int k = 0; k < 3; ++k) {
    const double q = h.num[k].estimate() / den;
    const Expansion rest = h.num[k] - Expansion(q) * h.den;
    const double r = rest.estimate() / den;
    const Expansion rest2 = rest - Expansion(r) * h.den;
    double hi, lo;
    exact::eft::two_sum(q, r, hi, lo);
    const double e = magnitude_above(rest2) / den_below * exact::kBoundScale;
    if (!std::isfinite(hi) || !std::isfinite(e)) return false;
    // Back from 2^shift units: exact unless a part becomes subnormal (the floor covers that).
    out[k] =
        exact::ApproxDD(std::ldexp(hi, -shift), std::ldexp(lo, -shift), std::ldexp(e, -shift) + exact::kUnderflowFloor);
  }
  return true;
}

const exact::ApproxDD* exact_dd_point(const PlaneSet& ps, const VertexGeom& v) {
  const ExactHomogeneous& h = exact_homogeneous(ps, v);
  if (h.point_state == 0) h.point_state = dd_coordinates(h, ps.exact_shift(), h.point) ? 1 : -1;
  return h.point_state > 0 ? h.point : nullptr;
}

bool dd_point(const PlaneSet& ps, const VertexGeom& v, exact::ApproxDD out[3]) {
  if (v.mesh_point != kNoPoint) {
    const double* p = ps.point(uint32_t(v.mesh_point));
    for (int k = 0; k < 3; ++k) out[k] = exact::ApproxDD(p[k]);
    return true;
  }
  if (v.exact && v.exact->point_state > 0) {
    for (int k = 0; k < 3; ++k) out[k] = v.exact->point[k];
    return true;
  }
  const DDHomogeneous& h = dd_homogeneous(ps, v);
  if (!(std::fabs(h.den.hi) - std::fabs(h.den.lo) > 4 * h.den.e)) return false;
  for (int k = 0; k < 3; ++k) out[k] = h.num[k] / h.den;
  return true;
}

const ExactHomogeneous& exact_homogeneous(const PlaneSet& ps, const VertexGeom& v) {
  if (!v.exact) {
    ExactHomogeneous* h = &ps.new_exact_homogeneous();
    const VertexAnchor l = vertex_anchor(ps, v);
    if (l.kind == 2) {
      Scaled x(ps.point(l.x), ps.exact_shift()), y(ps.point(l.y), ps.exact_shift());
      on_line(ps.exact(l.c), x.v, y.v, h->num, h->den);
    } else if (l.kind == 1) {
      Scaled x(ps.point(l.x), ps.exact_shift());
      on_point_line(ps.exact(l.a), ps.exact(l.b), ps.exact(l.c), x.v, h->num, h->den);
    } else {
      cramer(ps.exact(v.basis[0]), ps.exact(v.basis[1]), ps.exact(v.basis[2]), h->num, h->den);
    }
    for (auto& c : h->num) c.compress();
    h->den.compress();
    v.exact = h;
  }
  return *v.exact;
}

// Double-double homogeneous coordinates of a plane-triple vertex, computed once and shared by
// copies of the vertex.
const DDHomogeneous& dd_homogeneous(const PlaneSet& ps, const VertexGeom& v) {
  if (!v.dd) {
    DDHomogeneous* h = &ps.new_dd_homogeneous();
    const VertexAnchor l = vertex_anchor(ps, v);
    if (l.kind == 2) {
      on_line(ps.dd(l.c), ps.point(l.x), ps.point(l.y), h->num, h->den);
      // a - b = n_c . (x - y) is not 0 (the line crosses plane c) and rarely tiny.
      h->den_sign = h->den.sign();
      if (h->den_sign == 2) h->den_sign = exact_homogeneous(ps, v).den.sign();
    } else if (l.kind == 1) {
      on_point_line(ps.dd(l.a), ps.dd(l.b), ps.dd(l.c), ps.point(l.x), h->num, h->den);
      h->den_sign = v.det_sign;  // det3(n_a, n_b, n_c) is a cyclic shift of the basis order
    } else {
      cramer(ps.dd(v.basis[0]), ps.dd(v.basis[1]), ps.dd(v.basis[2]), h->num, h->den);
      h->den_sign = v.det_sign;
    }
    v.dd = h;
  }
  return *v.dd;
}

// The input point on planes a, b and c (three planes with independent normals meet in one
// point), or kNoPoint. `near`, when given, holds the point's coordinates with rigorous bounds:
// a candidate outside them cannot be the point and is skipped before any incidence lookup or
// orient3d (in double: rounding is monotonic, so |q - x| <= e computes as at most e).
int32_t input_point_on(const PlaneSet& ps, uint32_t a, uint32_t b, uint32_t c, const Approx* near) {
  if (ps.explicit_plane(a) || ps.explicit_plane(b) || ps.explicit_plane(c)) return kNoPoint;
  auto may_be_it = [&](uint32_t p) {
    if (!near) return true;
    const double* q = ps.point(p);
    for (int k = 0; k < 3; ++k)
      if (!(std::fabs(q[k] - near[k].v) <= near[k].e)) return false;
    return true;
  };
  // An input vertex on all three planes by construction is the vertex itself.
  const uint32_t planes[3] = {a, b, c};
  int smallest = 0;
  for (int i = 1; i < 3; ++i)
    if (ps.points_on(planes[i]).size() < ps.points_on(planes[smallest]).size()) smallest = i;
  for (uint32_t p : ps.points_on(planes[smallest])) {
    if (!may_be_it(p)) continue;
    bool on_all = true;
    for (int i = 0; i < 3 && on_all; ++i)
      if (i != smallest && !ps.point_on_plane(p, planes[i])) on_all = false;
    if (on_all) return int32_t(p);
  }
  // An input vertex on two of the planes by construction may lie on the third geometrically
  // (structured meshes): one exact orient3d per such vertex decides it.
  for (int i = 0; i < 3; ++i) {
    uint32_t p1 = planes[(i + 1) % 3], p2 = planes[(i + 2) % 3], third = planes[i];
    if (ps.points_on(p1).size() > ps.points_on(p2).size()) std::swap(p1, p2);
    if (ps.points_on(p1).size() > 64) continue;
    const auto& r = ps.rep(third);
    for (uint32_t p : ps.points_on(p1)) {
      if (!may_be_it(p) || !ps.point_on_plane(p, p2)) continue;
      if (orient3d(ps.point(r[0]), ps.point(r[1]), ps.point(r[2]), ps.point(p), ps.exact_shift()) == 0)
        return int32_t(p);
    }
  }
  return kNoPoint;
}

VertexGeom make_vertex(const PlaneSet& ps, uint32_t a, uint32_t b, uint32_t c, bool find_input_point,
                       int known_det_sign) {
  VertexGeom v;
  v.basis[0] = a;
  v.basis[1] = b;
  v.basis[2] = c;
  // Cramer's denominator is the normals' determinant: when its filter is certain it gives the
  // exact sign too (sign_det3_normals would evaluate it again first).
  const PlaneCoef<Approx> pa = ps.approx(a), pb = ps.approx(b), pc = ps.approx(c);
  const Approx den = det3_normals(pa, pb, pc);
  v.det_sign = den.certain() ? den.sign() : known_det_sign != 0 ? known_det_sign : sign_det3_normals(ps, a, b, c);
  assert(v.det_sign != 0 && "make_vertex: planes with dependent normals");

  Approx num[3];
  cramer_numerators(pa, pb, pc, num);
  bool good = den.certain();
  if (good)
    for (int k = 0; k < 3; ++k) v.x[k] = num[k] / den;  // rigorous bounds (den is certain)

  if (find_input_point) {
    v.mesh_point = input_point_on(ps, a, b, c, good ? v.x : nullptr);
    if (v.mesh_point != kNoPoint) {
      const double* x = ps.point(uint32_t(v.mesh_point));
      for (int k = 0; k < 3; ++k) v.x[k] = Approx(x[k]);
      return v;
    }
  } else {
    v.late_point = kPointNotSearched;
  }

  if (good) {
    for (int k = 0; k < 3; ++k)
      // Coordinates feed the side filter; poorly conditioned ones are recomputed exactly.
      if (v.x[k].e > ps.coordinate_tolerance(v.x[k].v)) good = false;
  }
  if (!good) {
    // Double-double Cramer: x = num / den with |num - exact| <= e_num, |den - exact| <= e_den.
    const DDHomogeneous& dh = dd_homogeneous(ps, v);  // cached: side() reuses it
    const exact::ApproxDD* dnum = dh.num;
    const exact::ApproxDD& dden = dh.den;
    double den = dden.hi + dden.lo;
    double eden = dden.e + exact::kEps * std::fabs(den);
    if (std::fabs(den) > 2 * eden) {
      good = true;
      for (int k = 0; k < 3; ++k) {
        double num = dnum[k].hi + dnum[k].lo;
        double x = num / den;
        double enm = dnum[k].e + exact::kEps * std::fabs(num);
        double e = ((enm + std::fabs(x) * eden) / (std::fabs(den) - eden) + 2 * exact::kEps * std::fabs(x)) *
                       exact::kBoundScale +
                   exact::kUnderflowFloor;
        v.x[k] = Approx(x, e);
        if (e > ps.coordinate_tolerance(x)) good = false;
      }
    }
  }
  if (!good) {
    ++ps.exact_fallbacks;
    const ExactHomogeneous& h = exact_homogeneous(ps, v);
    double dd = h.den.estimate();
    for (int k = 0; k < 3; ++k) {
      double x = std::ldexp(h.num[k].estimate() / dd, -ps.exact_shift());  // back from 2^shift units
      v.x[k] = Approx(x, 8 * exact::kEps * std::fabs(x) + exact::kUnderflowFloor);
    }
  }
  return v;
}

void precise_coordinates(const PlaneSet& ps, const VertexGeom& v, double hi[3], double lo[3]) {
  if (v.mesh_point != kNoPoint) {
    const double* p = ps.point(uint32_t(v.mesh_point));
    for (int k = 0; k < 3; ++k) {
      hi[k] = p[k];
      lo[k] = 0;
    }
    return;
  }
  const DDHomogeneous& h = dd_homogeneous(ps, v);
  if (std::fabs(h.den.hi) - std::fabs(h.den.lo) > 4 * h.den.e) {
    bool accurate = true;
    for (int k = 0; k < 3 && accurate; ++k) {
      exact::ApproxDD x = h.num[k] / h.den;
      hi[k] = x.hi;
      lo[k] = x.lo;
      // hi is the correctly rounded coordinate when both ends of the error interval round to it
      // (round-to-nearest is monotonic; the bound is doubled to cover the rounding of lo +- e).
      // A cancelled numerator, whose value has no correct digit, fails this and goes exact.
      const double e = 2 * x.e + exact::kUnderflowFloor;
      accurate = std::isfinite(x.hi) && x.hi + (x.lo - e) == x.hi && x.hi + (x.lo + e) == x.hi;
    }
    if (accurate) return;
  }
  // Too ill-conditioned for double-double: the exact quotient, with the exact remainder for the
  // low part (dd_coordinates, cached per vertex; without the low part, the local coordinates of
  // volume and area would lose every digit below the rounding of hi: a kernel far from the origin
  // would get a volume that depends on which vertex went this way).
  if (const exact::ApproxDD* x = exact_dd_point(ps, v)) {
    for (int k = 0; k < 3; ++k) {
      hi[k] = x[k].hi;
      lo[k] = x[k].lo;
    }
    return;
  }
  // (Not met with a valid vertex: dd_coordinates fails only for a zero or non-finite quotient.)
  const ExactHomogeneous& e = exact_homogeneous(ps, v);
  for (int k = 0; k < 3; ++k) {
    hi[k] = std::ldexp(e.num[k].estimate() / e.den.estimate(), -ps.exact_shift());
    lo[k] = 0;
  }
}

}  // namespace kergen
