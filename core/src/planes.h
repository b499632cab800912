// Plane store and the exact predicates on planes.
//
// A plane is either defined by three input points (a, b, c) of a representative triangle —
// never by rounded coefficients, so incidences of the input survive — or by explicit double
// coefficients that are exact as given (bounding-box planes). Inside is f(x) = n.x + d <= 0 with
// n = (b - a) x (c - a), d = -n.a (outward normal).
//
// Coefficients are kept twice: as doubles with a rigorous error bound (structure of arrays, for
// the filters and the float scans) and, lazily, as exact expansions (for the rare undecided sign).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "exact.h"
#include "flat_set.h"

namespace kergen {

using exact::Approx;
using exact::Expansion;

template <class T>
struct PlaneCoef {
  T n[3];
  T d;
};

constexpr uint32_t kNoPlane = 0xffffffffu;
constexpr int32_t kNoPoint = -1;
constexpr int32_t kPointNotSearched = -2;

class PlaneSet {
 public:
  // Input points (already scaled), referenced by index.
  explicit PlaneSet(const std::vector<double>* points, int exact_shift = 0) : points_(points), exact_shift_(exact_shift) {}
  // Exact evaluations work on the points times 2^exact_shift (see PreparedMesh::exact_shift).
  int exact_shift() const { return exact_shift_; }
  // The extent of the shape (its bounding box's largest side, scaled units). Vertex coordinates
  // whose error bound is not far below it are refined (make_vertex): every double filter, scan
  // and climb works at the shape's scale, which for a shape far smaller than its distance from
  // the origin is far below the rounding of its coordinates' magnitude. Infinite by default.
  void set_extent(double extent) { extent_ = extent; }
  // Largest error bound accepted for a filtered vertex coordinate of magnitude |x| (at least a
  // few roundings of x: a double-double coordinate rounded to a double meets it).
  double coordinate_tolerance(double x) const {
    return std::max(1e-10 * std::min(std::fabs(x) + 1e-3, extent_), 16 * exact::kEps * std::fabs(x));
  }

  uint32_t add_from_points(uint32_t a, uint32_t b, uint32_t c);
  // Adds the planes of triangles tri[which[0]], ..., tri[which[n - 1]] (ids size(), size() + 1,
  // ...), with room for `spare` more planes afterwards: one resize and one pass per batch.
  void add_from_triangles(const std::array<uint32_t, 3>* tri, const uint32_t* which, size_t n, size_t spare);
  // The same in two steps, for callers that compute the planes of all triangles anyway:
  // stage(n) makes room for n candidate planes after the current ones, put(j, c) stores
  // candidate j's filtered plane (as plane_from_points computes it), and
  // keep_staged(tri, which, n) keeps candidates which[0] < which[1] < ... as planes size(),
  // size() + 1, ... of triangles tri[which[k]].
  void stage(size_t n);
  void put(size_t j, const PlaneCoef<Approx>& c) {
    const size_t i = size() + j;
    nx_[i] = c.n[0].v; enx_[i] = c.n[0].e;
    ny_[i] = c.n[1].v; eny_[i] = c.n[1].e;
    nz_[i] = c.n[2].v; enz_[i] = c.n[2].e;
    d_[i] = c.d.v; ed_[i] = c.d.e;
  }
  void keep_staged(const std::array<uint32_t, 3>* tri, const uint32_t* which, size_t n);
  uint32_t add_explicit(double nx, double ny, double nz, double d);
  void pop_last();  // removes the most recently added plane

  size_t size() const { return rep_.size(); }
  bool explicit_plane(uint32_t i) const { return rep_[i][0] == kNoPlane; }
  const std::array<uint32_t, 3>& rep(uint32_t i) const { return rep_[i]; }

  // Opposite plane (same geometric plane, inner side reversed), or kNoPlane.
  uint32_t opposite(uint32_t i) const { return opposite_[i]; }
  void set_opposite(uint32_t i, uint32_t j) { opposite_[i] = j; opposite_[j] = i; }

  // Incidence known by construction, as compressed rows (sorted, unique): the mesh vertices on
  // each plane (vertices of its faces). Planes added after set_incidence (bounding planes) have
  // no incident points.
  struct Span {
    const uint32_t* b = nullptr;
    const uint32_t* e = nullptr;
    const uint32_t* begin() const { return b; }
    const uint32_t* end() const { return e; }
    size_t size() const { return size_t(e - b); }
  };
  void set_incidence(RawVector<uint32_t> plane_offsets, RawVector<uint32_t> plane_points);
  Span points_on(uint32_t plane) const {
    if (size_t(plane) + 1 >= plane_offsets_.size()) return {};
    return {plane_points_.data() + plane_offsets_[plane], plane_points_.data() + plane_offsets_[plane + 1]};
  }
  // (A plane of a few faces holds a handful of points, scanned; a merged flat region's long row
  // is searched.)
  bool point_on_plane(uint32_t point, uint32_t plane) const {
    const Span row = points_on(plane);
    if (row.size() <= 8) return std::find(row.b, row.e, point) != row.e;
    return std::binary_search(row.b, row.e, point);
  }

  PlaneCoef<Approx> approx(uint32_t i) const {
    return {{Approx(nx_[i], enx_[i]), Approx(ny_[i], eny_[i]), Approx(nz_[i], enz_[i])}, Approx(d_[i], ed_[i])};
  }
  const PlaneCoef<Expansion>& exact(uint32_t i) const;
  // Double-double coefficients (exact for explicit planes), computed on first use.
  const PlaneCoef<exact::ApproxDD>& dd(uint32_t i) const;
  template <class T> PlaneCoef<T> coef(uint32_t i) const;

  const double* point(uint32_t p) const { return &(*points_)[3 * size_t(p)]; }
  size_t num_points() const { return points_->size() / 3; }

  // Structure-of-arrays doubles for scans.
  const double* nx() const { return nx_.data(); }
  const double* ny() const { return ny_.data(); }
  const double* nz() const { return nz_.data(); }
  const double* d() const { return d_.data(); }

  mutable size_t exact_fallbacks = 0;

  // Capacity for n planes in all (a mesh's planes are then added without regrowth).
  void reserve(size_t n);

 private:
  void resize(size_t n);  // new entries uninitialised

  const std::vector<double>* points_;
  int exact_shift_ = 0;
  double extent_ = HUGE_VAL;
  RawVector<std::array<uint32_t, 3>> rep_;
  RawVector<double> nx_, ny_, nz_, d_, enx_, eny_, enz_, ed_;
  RawVector<uint32_t> opposite_;
  RawVector<uint32_t> plane_offsets_, plane_points_;
  // Only a few planes ever need them: a map, not a pointer per plane.
  mutable SparseCache<PlaneCoef<Expansion>> exact_;
  mutable SparseCache<PlaneCoef<exact::ApproxDD>> dd_;
};

template <>
inline PlaneCoef<Approx> PlaneSet::coef<Approx>(uint32_t i) const { return approx(i); }
template <>
inline PlaneCoef<Expansion> PlaneSet::coef<Expansion>(uint32_t i) const { return exact(i); }

// ---- generic formulas (written once, evaluated with Approx then Expansion) -----------------
template <class T>
T det3(const T& a0, const T& a1, const T& a2, const T& b0, const T& b1, const T& b2, const T& c0,
       const T& c1, const T& c2) {
  return a0 * (b1 * c2 - b2 * c1) - a1 * (b0 * c2 - b2 * c0) + a2 * (b0 * c1 - b1 * c0);
}
// The filtered determinant, the hottest formula of the LP and of vertex construction, with one
// bound instead of a running error per operation: for entries v +- e,
//   |det(exact) - det(v)| <= perm(|v| + e) - perm(|v|)   (multilinear expansion, term by term),
// plus the rounding of the double evaluation, below 8 eps perm(|v|); the two permanents' own
// rounding (at most 7 eps each, positive terms) is covered by 24 eps perm(|v| + e).
template <>
inline Approx det3<Approx>(const Approx& a0, const Approx& a1, const Approx& a2, const Approx& b0, const Approx& b1,
                           const Approx& b2, const Approx& c0, const Approx& c1, const Approx& c2) {
  const double m0 = b1.v * c2.v - b2.v * c1.v, m1 = b0.v * c2.v - b2.v * c0.v, m2 = b0.v * c1.v - b1.v * c0.v;
  const double det = a0.v * m0 - a1.v * m1 + a2.v * m2;
  const double A0 = std::fabs(a0.v), A1 = std::fabs(a1.v), A2 = std::fabs(a2.v), B0 = std::fabs(b0.v),
               B1 = std::fabs(b1.v), B2 = std::fabs(b2.v), C0 = std::fabs(c0.v), C1 = std::fabs(c1.v),
               C2 = std::fabs(c2.v);
  const double perm = A0 * (B1 * C2 + B2 * C1) + A1 * (B0 * C2 + B2 * C0) + A2 * (B0 * C1 + B1 * C0);
  const double E0 = A0 + a0.e, E1 = A1 + a1.e, E2 = A2 + a2.e, F0 = B0 + b0.e, F1 = B1 + b1.e, F2 = B2 + b2.e,
               G0 = C0 + c0.e, G1 = C1 + c1.e, G2 = C2 + c2.e;
  const double perm_e = E0 * (F1 * G2 + F2 * G1) + E1 * (F0 * G2 + F2 * G0) + E2 * (F0 * G1 + F1 * G0);
  const double err = ((perm_e - perm) + 32 * exact::kEps * perm_e) * exact::kBoundScale + exact::kUnderflowFloor;
  return {det, err};
}

template <class T>
T det3_normals(const PlaneCoef<T>& p, const PlaneCoef<T>& q, const PlaneCoef<T>& r) {
  return det3(p.n[0], p.n[1], p.n[2], q.n[0], q.n[1], q.n[2], r.n[0], r.n[1], r.n[2]);
}
// n_p x n_q: the direction of the line of planes p and q.
template <class T>
std::array<T, 3> cross_normals(const PlaneCoef<T>& p, const PlaneCoef<T>& q) {
  return {p.n[1] * q.n[2] - p.n[2] * q.n[1], p.n[2] * q.n[0] - p.n[0] * q.n[2],
          p.n[0] * q.n[1] - p.n[1] * q.n[0]};
}

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
  Expansion num[3], den;
  // The coordinates num[k] / den as double-doubles with rigorous error bounds, in input units
  // (dd_coordinates, on first need through exact_dd_point; point_state 1 = valid, -1 = not
  // available, 0 = not computed yet): side() evaluates a plane there before the exact dot
  // product, the cuts' edge rates and the output coordinates use them too. Where den is
  // tiny (the vertex of nearly coplanar planes), the double-double homogeneous values leave no
  // correct digit of a plane's value while these coordinates are still accurate to ~2^-100.
  mutable exact::ApproxDD point[3];
  mutable int point_state = 0;
};

// A point defined by three planes (Cramer's rule), or an input point (exact coordinates).
struct VertexGeom {
  uint32_t basis[3] = {kNoPlane, kNoPlane, kNoPlane};
  int32_t mesh_point = kNoPoint;  // when the three planes meet at an input vertex
  int det_sign = 0;               // sign of det3 of the basis normals
  Approx x[3];                    // coordinates with error bounds (exact when mesh_point)
  // Computed on the first undecided side test and shared by copies: every further exact test
  // at this vertex is one 4-term dot product instead of a 4x4 determinant.
  mutable std::shared_ptr<const DDHomogeneous> dd;
  mutable std::shared_ptr<const ExactHomogeneous> exact;
  // For a vertex built without the input-point search: the search's answer, found on the first
  // side test the filter cannot decide (kPointNotSearched until then).
  mutable int32_t late_point = kNoPoint;
};

// Plane of an input triangle with error bounds, without adding it to a set (inline: the
// per-face loops of plane classes and face culling call it once per face). One pass of doubles
// with bounds of the same form as the running error of the generic formula: for u = b - a and
// v = c - a rounded (relative error eps each), a normal component n = p - q with p, q the
// rounded products is within 3 eps (|p| + |q|) + eps |n| of the exact one (two input errors and
// one rounding per product, one rounding of the difference; the second-order terms fit in
// kBoundScale's slack), and d = -(n . a) with exact a adds the normal errors times |a| and the
// roundings of the products and partial sums.
inline PlaneCoef<Approx> approx_plane(const double* a, const double* b, const double* c) {
  using exact::kBoundScale;
  using exact::kEps;
  using exact::kUnderflowFloor;
  const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  PlaneCoef<Approx> r;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const double p = u[i] * v[j], q = u[j] * v[i], n = p - q;
    r.n[k] = Approx(n, (3 * kEps * (std::fabs(p) + std::fabs(q)) + kEps * std::fabs(n)) * kBoundScale + kUnderflowFloor);
  }
  const double p0 = r.n[0].v * a[0], p1 = r.n[1].v * a[1], p2 = r.n[2].v * a[2];
  const double s01 = p0 + p1, s = s01 + p2;
  const double input = std::fabs(a[0]) * r.n[0].e + std::fabs(a[1]) * r.n[1].e + std::fabs(a[2]) * r.n[2].e;
  const double rounding = kEps * (std::fabs(p0) + std::fabs(p1) + std::fabs(p2) + std::fabs(s01) + std::fabs(s));
  r.d = Approx(-s, (input + rounding) * kBoundScale + kUnderflowFloor);
  return r;
}

// The plane of an input triangle in double-double with a rigorous bound (error ~1e-32 of its
// magnitude), as PlaneSet::dd computes it.
PlaneCoef<exact::ApproxDD> dd_plane(const double* a, const double* b, const double* c);
// Exact plane of the triangle with its points times 2^shift (a positive multiple of the plane).
PlaneCoef<Expansion> exact_plane(const double* a, const double* b, const double* c, int shift = 0);

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

// Builds the vertex of three planes with independent normals (caller checked the sign != 0).
// With find_input_point it also recognises an input point on the three planes (exact
// coordinates, cheap exact side tests later): worth it for vertices that are kept, not for the
// LP's transient candidates.
VertexGeom make_vertex(const PlaneSet& ps, uint32_t a, uint32_t b, uint32_t c, bool find_input_point = true);
// sign of f_l at the vertex: > 0 outside plane l, 0 on it, < 0 inside.
int side(const PlaneSet& ps, uint32_t l, const VertexGeom& v);
// The same sign when the vertex lies on a line through an input point that plane l holds (the
// line of two basis planes through their shared input points), from signs of degree 3; 2 when
// there is no such point. side() uses it before exact expansions.
int side_through_anchor(const PlaneSet& ps, uint32_t l, const VertexGeom& v);
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
// Whether the input triangle (a,b,c) has exactly collinear vertices.
bool collinear(const double* a, const double* b, const double* c, int shift = 0);
// sign of dir . (n_h x n_s) where dir = n_p x n_q (edge orientation in facet h).
int sign_edge_in_facet(const PlaneSet& ps, uint32_t p, uint32_t q, uint32_t h, uint32_t s);

// Appends to `ps` the six planes of a box twice the size of the data (scaled coordinates are
// below 1), their ids to `box`: it bounds what an open surface leaves unbounded, and the subset
// kernels of culling. A closed mesh's kernel never reaches it.
void add_bounding_box(PlaneSet& ps, std::vector<uint32_t>& box);

}  // namespace kergen
