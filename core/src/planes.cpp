// Plane store and exact predicates. Each predicate evaluates one templated formula with Approx
// (a double plus a rigorous error bound); when the sign is not certain it evaluates the same
// formula with exact expansions. Kernel vertices at input points take a cheaper route: their
// side of a plane is orient3d on input points, and incidence known from the mesh is 0 for free.
#include "planes.h"

#include <algorithm>
#include <cassert>

namespace kergen {

namespace {

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

// The filtered plane: approx_plane (planes.h, inline for the per-face loops).
template <>
PlaneCoef<Approx> plane_from_points<Approx>(const double* a, const double* b, const double* c) {
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

}  // namespace

namespace {
struct Scaled {
  double v[3];
  Scaled(const double* p, int shift) {
    for (int k = 0; k < 3; ++k) v[k] = shift == 0 ? p[k] : std::ldexp(p[k], shift);
  }
};
}  // namespace

uint32_t PlaneSet::add_from_points(uint32_t a, uint32_t b, uint32_t c) {
  const std::array<uint32_t, 3> t = {a, b, c};
  const uint32_t which = 0;
  add_from_triangles(&t, &which, 1, 0);
  return uint32_t(size() - 1);
}

void PlaneSet::add_from_triangles(const std::array<uint32_t, 3>* tri, const uint32_t* which, size_t n, size_t spare) {
  const size_t first = size();
  if (first + n + spare > rep_.capacity()) reserve(std::max(first + n + spare, 2 * rep_.capacity()));
  resize(first + n);
  for (size_t k = 0; k < n; ++k) {
    const std::array<uint32_t, 3>& t = tri[which[k]];
    const PlaneCoef<Approx> p = plane_from_points<Approx>(point(t[0]), point(t[1]), point(t[2]));
    const size_t i = first + k;
    rep_[i] = t;
    nx_[i] = p.n[0].v; enx_[i] = p.n[0].e;
    ny_[i] = p.n[1].v; eny_[i] = p.n[1].e;
    nz_[i] = p.n[2].v; enz_[i] = p.n[2].e;
    d_[i] = p.d.v; ed_[i] = p.d.e;
    opposite_[i] = kNoPlane;
  }
}

void PlaneSet::stage(size_t n) {
  const size_t first = size();
  if (first + n > nx_.capacity()) reserve(first + n);
  for (auto* v : {&nx_, &ny_, &nz_, &d_, &enx_, &eny_, &enz_, &ed_}) v->resize(first + n);
}

void PlaneSet::keep_staged(const std::array<uint32_t, 3>* tri, const uint32_t* which, size_t n) {
  const size_t first = size();
  rep_.resize(first + n);
  opposite_.resize(first + n);
  // In place: which[k] >= k, increasing, so a candidate is read before its slot is written.
  for (size_t k = 0; k < n; ++k) {
    const size_t i = first + k, j = first + which[k];
    rep_[i] = tri[which[k]];
    nx_[i] = nx_[j]; enx_[i] = enx_[j];
    ny_[i] = ny_[j]; eny_[i] = eny_[j];
    nz_[i] = nz_[j]; enz_[i] = enz_[j];
    d_[i] = d_[j]; ed_[i] = ed_[j];
    opposite_[i] = kNoPlane;
  }
  for (auto* v : {&nx_, &ny_, &nz_, &d_, &enx_, &eny_, &enz_, &ed_}) v->resize(first + n);
}

uint32_t PlaneSet::add_explicit(double nx, double ny, double nz, double d) {
  rep_.push_back({kNoPlane, kNoPlane, kNoPlane});
  nx_.push_back(nx); enx_.push_back(0);
  ny_.push_back(ny); eny_.push_back(0);
  nz_.push_back(nz); enz_.push_back(0);
  d_.push_back(d); ed_.push_back(0);
  opposite_.push_back(kNoPlane);
  return uint32_t(size() - 1);
}

void PlaneSet::pop_last() {
  const uint32_t i = uint32_t(size() - 1);
  rep_.pop_back();
  nx_.pop_back(); ny_.pop_back(); nz_.pop_back(); d_.pop_back();
  enx_.pop_back(); eny_.pop_back(); enz_.pop_back(); ed_.pop_back();
  opposite_.pop_back();
  exact_.erase(i);
  dd_.erase(i);
}

const PlaneCoef<Expansion>& PlaneSet::exact(uint32_t i) const {
  if (const PlaneCoef<Expansion>* cached = exact_.find(i)) return *cached;
  {
    auto p = std::make_unique<PlaneCoef<Expansion>>();
    if (explicit_plane(i)) {
      // n . x + d = 0 in coordinates times 2^shift: n . x' + 2^shift d = 0.
      p->n[0] = Expansion(nx_[i]); p->n[1] = Expansion(ny_[i]); p->n[2] = Expansion(nz_[i]);
      p->d = Expansion(std::ldexp(d_[i], exact_shift_));
    } else {
      Scaled a(point(rep_[i][0]), exact_shift_), b(point(rep_[i][1]), exact_shift_), c(point(rep_[i][2]), exact_shift_);
      *p = plane_from_points<Expansion>(a.v, b.v, c.v);
      for (auto& c : p->n) c.compress();
      p->d.compress();
    }
    return exact_.insert(i, std::move(p));
  }
}

void PlaneSet::set_incidence(RawVector<uint32_t> plane_offsets, RawVector<uint32_t> plane_points) {
  plane_offsets_ = std::move(plane_offsets);
  plane_points_ = std::move(plane_points);
}

PlaneCoef<Expansion> exact_plane(const double* a, const double* b, const double* c, int shift) {
  Scaled sa(a, shift), sb(b, shift), sc(c, shift);
  return plane_from_points<Expansion>(sa.v, sb.v, sc.v);
}


PlaneCoef<exact::ApproxDD> dd_plane(const double* a, const double* b, const double* c) {
  return plane_from_points<exact::ApproxDD>(a, b, c);
}

const PlaneCoef<exact::ApproxDD>& PlaneSet::dd(uint32_t i) const {
  if (const PlaneCoef<exact::ApproxDD>* cached = dd_.find(i)) return *cached;
  {
    auto p = std::make_unique<PlaneCoef<exact::ApproxDD>>();
    if (explicit_plane(i)) {
      *p = {{nx_[i], ny_[i], nz_[i]}, d_[i]};  // exact doubles
    } else {
      *p = plane_from_points<exact::ApproxDD>(point(rep_[i][0]), point(rep_[i][1]), point(rep_[i][2]));
    }
    return dd_.insert(i, std::move(p));
  }
}

namespace {
// How many input points (0, 1 or 2, stopping at 2) lie on both planes p and q by construction,
// in x then y, searched from the plane with fewer points; 0 when the search would be long. Two
// make the line of p and q the line through them.
int shared_input_points(const PlaneSet& ps, uint32_t p, uint32_t q, uint32_t& x, uint32_t& y) {
  if (ps.explicit_plane(p) || ps.explicit_plane(q)) return 0;
  if (ps.points_on(p).size() > ps.points_on(q).size()) std::swap(p, q);
  if (ps.points_on(p).size() > 256) return 0;
  int found = 0;
  for (uint32_t pt : ps.points_on(p)) {
    if (!ps.point_on_plane(pt, q)) continue;
    (found == 0 ? x : y) = pt;
    if (++found == 2) break;
  }
  return found;
}

// Exact sign of n_c . (Y - X) = f_c(Y) - f_c(X) for input points X, Y.
int sign_rate_between(const PlaneSet& ps, uint32_t c, uint32_t x, uint32_t y) {
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
int sign_det3_on_line(const PlaneSet& ps, uint32_t a, uint32_t b, uint32_t c, uint32_t x, uint32_t y) {
  const int shift = ps.exact_shift();
  const double *X = ps.point(x), *Y = ps.point(y);
  uint32_t w = kNoPlane;
  for (uint32_t r : ps.rep(b))
    if (r != x && r != y && !collinear(X, Y, ps.point(r), shift)) { w = r; break; }
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
}  // namespace

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
  return det3(Expansion(v[0]), Expansion(v[1]), Expansion(v[2]), ea.n[0], ea.n[1], ea.n[2], eb.n[0], eb.n[1], eb.n[2]).sign();
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
// The vertex through input points: on the line xy of two basis planes (kind 2), or on their
// line through the input point x (kind 1); c is the third basis plane.
struct VertexAnchor {
  int kind = 0;
  uint32_t x = 0, y = 0, c = kNoPlane, a = kNoPlane, b = kNoPlane;
};
VertexAnchor vertex_anchor(const PlaneSet& ps, const VertexGeom& v) {
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
void on_point_line(const PlaneCoef<T>& a, const PlaneCoef<T>& b, const PlaneCoef<T>& c, const double* X, T num[3], T& den) {
  const std::array<T, 3> u = cross_normals(a, b);
  den = c.n[0] * u[0] + c.n[1] * u[1] + c.n[2] * u[2];
  const T fx = plane_value(c, X);
  for (int k = 0; k < 3; ++k) num[k] = T(X[k]) * den - fx * u[k];
}
}  // namespace

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
    out[k] = exact::ApproxDD(std::ldexp(hi, -shift), std::ldexp(lo, -shift), std::ldexp(e, -shift) + exact::kUnderflowFloor);
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
    auto h = std::make_shared<ExactHomogeneous>();
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
    v.exact = std::move(h);
  }
  return *v.exact;
}

// Double-double homogeneous coordinates of a plane-triple vertex, computed once and shared by
// copies of the vertex.
const DDHomogeneous& dd_homogeneous(const PlaneSet& ps, const VertexGeom& v) {
  if (!v.dd) {
    auto h = std::make_shared<DDHomogeneous>();
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
    v.dd = std::move(h);
  }
  return *v.dd;
}

// The input point on planes a, b and c (three planes with independent normals meet in one
// point), or kNoPoint. `near`, when given, holds the point's coordinates with rigorous bounds:
// a candidate outside them cannot be the point and is skipped before any incidence lookup or
// orient3d (in double: rounding is monotonic, so |q - x| <= e computes as at most e).
int32_t input_point_on(const PlaneSet& ps, uint32_t a, uint32_t b, uint32_t c, const Approx* near = nullptr) {
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
      if (orient3d(ps.point(r[0]), ps.point(r[1]), ps.point(r[2]), ps.point(p), ps.exact_shift()) == 0) return int32_t(p);
    }
  }
  return kNoPoint;
}

VertexGeom make_vertex(const PlaneSet& ps, uint32_t a, uint32_t b, uint32_t c, bool find_input_point) {
  VertexGeom v;
  v.basis[0] = a; v.basis[1] = b; v.basis[2] = c;
  // Cramer's denominator is the normals' determinant: when its filter is certain it gives the
  // exact sign too (sign_det3_normals would evaluate it again first).
  const PlaneCoef<Approx> pa = ps.approx(a), pb = ps.approx(b), pc = ps.approx(c);
  const Approx den = det3_normals(pa, pb, pc);
  v.det_sign = den.certain() ? den.sign() : sign_det3_normals(ps, a, b, c);
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
                   exact::kBoundScale + exact::kUnderflowFloor;
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
    for (int k = 0; k < 3; ++k) { hi[k] = p[k]; lo[k] = 0; }
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
    // Cramer solve.
    if (v.late_point == kPointNotSearched) v.late_point = input_point_on(ps, v.basis[0], v.basis[1], v.basis[2]);
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

void PlaneSet::reserve(size_t n) {
  rep_.reserve(n);
  for (auto* v : {&nx_, &ny_, &nz_, &d_, &enx_, &eny_, &enz_, &ed_}) v->reserve(n);
  opposite_.reserve(n);
}

void PlaneSet::resize(size_t n) {
  rep_.resize(n);
  for (auto* v : {&nx_, &ny_, &nz_, &d_, &enx_, &eny_, &enz_, &ed_}) v->resize(n);
  opposite_.resize(n);
}

void add_bounding_box(PlaneSet& ps, std::vector<uint32_t>& box) {
  for (int k = 0; k < 3; ++k)
    for (int sgn = -1; sgn <= 1; sgn += 2) {
      double n[3] = {0, 0, 0};
      n[k] = sgn;
      box.push_back(ps.add_explicit(n[0], n[1], n[2], -2.0));
    }
}

}  // namespace kergen
