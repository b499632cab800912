// Plane store: adding planes (from input triangles, batched, or explicit), their coefficients in
// double with bounds, double-double and exact, and the incidence rows.
#include "exact/plane_store.h"

#include <algorithm>
#include <cassert>

#include "exact/formulas.h"

namespace kergen {

using namespace formula;

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
    store(i, p);
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
    nx_[i] = nx_[j];
    enx_[i] = enx_[j];
    ny_[i] = ny_[j];
    eny_[i] = eny_[j];
    nz_[i] = nz_[j];
    enz_[i] = enz_[j];
    d_[i] = d_[j];
    ed_[i] = ed_[j];
    opposite_[i] = kNoPlane;
  }
  for (auto* v : {&nx_, &ny_, &nz_, &d_, &enx_, &eny_, &enz_, &ed_}) v->resize(first + n);
}

uint32_t PlaneSet::add_explicit(double nx, double ny, double nz, double d) {
  rep_.push_back({kNoPlane, kNoPlane, kNoPlane});
  nx_.push_back(nx);
  enx_.push_back(0);
  ny_.push_back(ny);
  eny_.push_back(0);
  nz_.push_back(nz);
  enz_.push_back(0);
  d_.push_back(d);
  ed_.push_back(0);
  opposite_.push_back(kNoPlane);
  return uint32_t(size() - 1);
}

void PlaneSet::pop_last() {
  const uint32_t i = uint32_t(size() - 1);
  rep_.pop_back();
  nx_.pop_back();
  ny_.pop_back();
  nz_.pop_back();
  d_.pop_back();
  enx_.pop_back();
  eny_.pop_back();
  enz_.pop_back();
  ed_.pop_back();
  opposite_.pop_back();
  exact_.erase(i);
  dd_.erase(i);
}

const PlaneCoef<Expansion>& PlaneSet::exact(uint32_t i) const {
  if (const PlaneCoef<Expansion>* cached = exact_.find(i)) return *cached;
  {
    PlaneCoef<Expansion> p;
    if (explicit_plane(i)) {
      // n . x + d = 0 in coordinates times 2^shift: n . x' + 2^shift d = 0.
      p.n[0] = Expansion(nx_[i]);
      p.n[1] = Expansion(ny_[i]);
      p.n[2] = Expansion(nz_[i]);
      p.d = Expansion(std::ldexp(d_[i], exact_shift_));
    } else {
      Scaled a(point(rep_[i][0]), exact_shift_), b(point(rep_[i][1]), exact_shift_), c(point(rep_[i][2]), exact_shift_);
      p = plane_from_points<Expansion>(a.v, b.v, c.v);
      for (auto& c : p.n) c.compress();
      p.d.compress();
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
    PlaneCoef<exact::ApproxDD> p;
    if (explicit_plane(i)) {
      p = {{nx_[i], ny_[i], nz_[i]}, d_[i]};  // exact doubles
    } else {
      p = plane_from_points<exact::ApproxDD>(point(rep_[i][0]), point(rep_[i][1]), point(rep_[i][2]));
    }
    return dd_.insert(i, std::move(p));
  }
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
