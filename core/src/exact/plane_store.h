// Plane store. A plane is either defined by three input points (a, b, c) of a representative
// triangle — never by rounded coefficients, so incidences of the input survive — or by explicit
// double coefficients that are exact as given (bounding-box planes). Inside is f(x) = n.x + d <= 0
// with n = (b - a) x (c - a), d = -n.a (outward normal).
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

#include "exact/expansion.h"
#include "exact/homogeneous.h"
#include "util/raw_vector.h"
#include "util/sparse_cache.h"
#include "util/stable_arena.h"

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
  explicit PlaneSet(const std::vector<double>* points, int exact_shift = 0)
      : points_(points), exact_shift_(exact_shift) {}
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
  void put(size_t j, const PlaneCoef<Approx>& c) { store(size() + j, c); }
  void keep_staged(const std::array<uint32_t, 3>* tri, const uint32_t* which, size_t n);
  uint32_t add_explicit(double nx, double ny, double nz, double d);
  void pop_last();  // removes the most recently added plane

  size_t size() const { return rep_.size(); }
  bool explicit_plane(uint32_t i) const { return rep_[i][0] == kNoPlane; }
  const std::array<uint32_t, 3>& rep(uint32_t i) const { return rep_[i]; }

  // Opposite plane (same geometric plane, inner side reversed), or kNoPlane.
  uint32_t opposite(uint32_t i) const { return opposite_[i]; }
  void set_opposite(uint32_t i, uint32_t j) {
    opposite_[i] = j;
    opposite_[j] = i;
  }

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
  template <class T>
  PlaneCoef<T> coef(uint32_t i) const;

  const double* point(uint32_t p) const { return &(*points_)[3 * size_t(p)]; }
  size_t num_points() const { return points_->size() / 3; }

  // Structure-of-arrays doubles for scans.
  const double* nx() const { return nx_.data(); }
  const double* ny() const { return ny_.data(); }
  const double* nz() const { return nz_.data(); }
  const double* d() const { return d_.data(); }

  mutable size_t exact_fallbacks = 0;

  // Fresh per-vertex caches (dd_homogeneous, exact_homogeneous in exact/vertex.h), freed with
  // the plane set: the vertices of a computation point to them.
  DDHomogeneous& new_dd_homogeneous() const { return dd_vertices_.emplace(); }
  ExactHomogeneous& new_exact_homogeneous() const { return exact_vertices_.emplace(); }

  // Capacity for n planes in all (a mesh's planes are then added without regrowth).
  void reserve(size_t n);

 private:
  void resize(size_t n);  // new entries uninitialised
  // The filtered coefficients of plane slot i (staged or kept), structure of arrays.
  void store(size_t i, const PlaneCoef<Approx>& c) {
    nx_[i] = c.n[0].v;
    enx_[i] = c.n[0].e;
    ny_[i] = c.n[1].v;
    eny_[i] = c.n[1].e;
    nz_[i] = c.n[2].v;
    enz_[i] = c.n[2].e;
    d_[i] = c.d.v;
    ed_[i] = c.d.e;
  }

  const std::vector<double>* points_;
  int exact_shift_ = 0;
  double extent_ = HUGE_VAL;
  RawVector<std::array<uint32_t, 3>> rep_;
  RawVector<double> nx_, ny_, nz_, d_, enx_, eny_, enz_, ed_;
  RawVector<uint32_t> opposite_;
  RawVector<uint32_t> plane_offsets_, plane_points_;
  // Computed on demand for the planes that need them (util/sparse_cache.h).
  mutable SparseCache<PlaneCoef<Expansion>> exact_;
  mutable SparseCache<PlaneCoef<exact::ApproxDD>> dd_;
  mutable StableArena<DDHomogeneous> dd_vertices_;
  mutable StableArena<ExactHomogeneous> exact_vertices_;
};

template <>
inline PlaneCoef<Approx> PlaneSet::coef<Approx>(uint32_t i) const {
  return approx(i);
}
template <>
inline PlaneCoef<Expansion> PlaneSet::coef<Expansion>(uint32_t i) const {
  return exact(i);
}

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
    r.n[k] =
        Approx(n, (3 * kEps * (std::fabs(p) + std::fabs(q)) + kEps * std::fabs(n)) * kBoundScale + kUnderflowFloor);
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

// Appends to `ps` the six planes of a box twice the size of the data (scaled coordinates are
// below 1), their ids to `box`: it bounds what an open surface leaves unbounded, and the subset
// kernels of culling. A closed mesh's kernel never reaches it.
void add_bounding_box(PlaneSet& ps, std::vector<uint32_t>& box);

}  // namespace kergen
