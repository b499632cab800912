// Exact and filtered arithmetic for the predicates.
//
// Expansion: an exact real number as a sum of non-overlapping doubles, after Shewchuk,
// "Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric Predicates" (1997).
// Exact for +, -, * as long as no intermediate overflows or underflows; the kernel code scales
// its input by a power of two (exact) so coordinates are below 1 in magnitude.
//
// Approx: a double with a rigorous bound on its absolute error (running error analysis). Every
// predicate is written once as a template and evaluated first with Approx; only when the sign is
// not certain (|value| <= error) is it evaluated again with Expansion.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

namespace kergen {
namespace exact {

constexpr double kEps = 1.1102230246251565e-16;  // 2^-53, unit roundoff
constexpr double kU2 = kEps * kEps;  // 2^-106: double-double rounding scale
// Inflation applied to every bound so the bound's own rounding never makes it too small; the
// absolute floor covers underflow in products of tiny values.
constexpr double kBoundScale = 1.0 + 8 * kEps;
constexpr double kUnderflowFloor = 1e-290;

// Error-free transformations (Dekker, Knuth; as in Shewchuk 1997): x + y is exactly the sum or
// product of a and b, x its rounding.
namespace eft {
inline void fast_two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  double bv = x - a;
  y = b - bv;
}
inline void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  double bv = x - a;
  double av = x - bv;
  double br = b - bv;
  double ar = a - av;
  y = ar + br;
}
inline void split(double a, double& hi, double& lo) {
  constexpr double kSplitter = 134217729.0;  // 2^27 + 1
  double c = kSplitter * a;
  double abig = c - a;
  hi = c - abig;
  lo = a - hi;
}
inline void two_product(double a, double b, double& x, double& y) {
  x = a * b;
  double ahi, alo, bhi, blo;
  split(a, ahi, alo);
  split(b, bhi, blo);
  double err1 = x - ahi * bhi;
  double err2 = err1 - alo * bhi;
  double err3 = err2 - ahi * blo;
  y = alo * blo - err3;
}
}  // namespace eft

class Expansion {
 public:
  Expansion() = default;
  explicit Expansion(double x) { if (x != 0) { p_[0] = x; n_ = 1; } }
  Expansion(const Expansion& o) { assign(o.p_, o.n_); }
  Expansion(Expansion&& o) noexcept { take(std::move(o)); }
  Expansion& operator=(const Expansion& o) { if (this != &o) assign(o.p_, o.n_); return *this; }
  Expansion& operator=(Expansion&& o) noexcept { if (this != &o) take(std::move(o)); return *this; }

  int sign() const { return n_ == 0 ? 0 : (p_[n_ - 1] > 0 ? 1 : -1); }
  double estimate() const;  // the value rounded (nearly correctly) to a double
  size_t size() const { return n_; }
  const double* data() const { return p_; }

  friend Expansion operator+(const Expansion& a, const Expansion& b);
  friend Expansion operator-(const Expansion& a, const Expansion& b);
  friend Expansion operator*(const Expansion& a, const Expansion& b);
  Expansion operator-() const;

  static Expansion difference(double a, double b);  // a - b exactly
  static Expansion product(double a, double b);     // a * b exactly
  void compress();  // same value, fewest components (worth it for values used many times)
  void swap(Expansion& o) noexcept;

 private:
  // Components live inline up to kInline (no allocation for the common small predicates).
  static constexpr size_t kInline = 24;
  double* reserve(size_t cap) {
    if (cap <= kInline) { p_ = buf_; }
    else { if (heap_.size() < cap) heap_.resize(cap); p_ = heap_.data(); }
    return p_;
  }
  void assign(const double* src, size_t n) {
    double* dst = reserve(n);
    for (size_t i = 0; i < n; ++i) dst[i] = src[i];
    n_ = n;
  }
  void take(Expansion&& o) {
    if (o.p_ == o.buf_) { assign(o.p_, o.n_); }
    else { heap_ = std::move(o.heap_); p_ = heap_.data(); n_ = o.n_; o.p_ = o.buf_; o.n_ = 0; }
  }

  double buf_[kInline];
  double* p_ = buf_;
  size_t n_ = 0;
  std::vector<double> heap_;
};

struct Approx {
  double v = 0;  // value
  double e = 0;  // |v - exact| <= e
  Approx() = default;
  Approx(double value) : v(value), e(0) {}  // NOLINT: exact input
  Approx(double value, double err) : v(value), e(err) {}
  // Sign when certain, 2 when not.
  int sign() const { return v > e ? 1 : (v < -e ? -1 : 2); }
  bool certain() const { return std::fabs(v) > e; }
};

inline Approx operator+(Approx a, Approx b) {
  double v = a.v + b.v;
  return {v, (a.e + b.e + kEps * std::fabs(v)) * kBoundScale};
}
inline Approx operator-(Approx a, Approx b) {
  double v = a.v - b.v;
  return {v, (a.e + b.e + kEps * std::fabs(v)) * kBoundScale};
}
inline Approx operator-(Approx a) { return {-a.v, a.e}; }
inline Approx operator*(Approx a, Approx b) {
  double v = a.v * b.v;
  double e = std::fabs(a.v) * b.e + std::fabs(b.v) * a.e + a.e * b.e + kEps * std::fabs(v);
  e += kUnderflowFloor;  // a product may underflow (cheaper than testing when it cannot)
  return {v, e * kBoundScale};
}
// Division; the caller guarantees b.certain().
inline Approx operator/(Approx a, Approx b) {
  double x = a.v / b.v;
  double denom = std::fabs(b.v) - b.e;
  double e = (a.e + std::fabs(x) * b.e) / denom + kEps * std::fabs(x);
  return {x, e * kBoundScale * kBoundScale + kUnderflowFloor};
}

// Sign of det3(b - a, c - a, p - a) exactly in 64/128-bit integers, when the coordinates (or
// else the differences, exact in double) are integer multiples of 2^-61 or 2^-62 times the
// power of two just above the largest of them (the latter with differences of the integers
// below 2^62), and below 2^62 in magnitude: nearly always on meshes. 2 when they are not (or
// without __int128).
int orient3d_integer(const double* a, const double* b, const double* c, const double* p);

// Sign of det3(b - a, c - a, p - a): orient3d_integer (in WebAssembly only for inexact
// differences, see exact.cpp), else Shewchuk's adaptive stages B and C:
// exact when every coordinate difference is exact in double (nearby points), else certified by
// the two error bounds; 2 when neither decides (use the full exact formula). Inputs are the
// scaled points (no underflow in the products, see PreparedMesh::exact_shift).
int orient3d_adaptive(const double* a, const double* b, const double* c, const double* p);

// Double-double with a rigorous error bound: |(hi + lo) - exact| <= e. A second filter stage
// (about 106 bits) for values too close to zero for Approx; exact zeros still fall through.
struct ApproxDD {
  double hi = 0, lo = 0, e = 0;
  ApproxDD() = default;
  ApproxDD(double x) : hi(x) {}  // NOLINT: exact input
  ApproxDD(double h, double l, double err) : hi(h), lo(l), e(err) {}
  int sign() const {
    double v = hi + lo;  // |v - (hi + lo)| <= eps |v|
    double a = std::fabs(v);
    if (a * (1 - 2 * kEps) > e) return v > 0 ? 1 : -1;
    return 2;
  }
};
// Double-double arithmetic (Dekker; Hida, Li & Bailey), inline: the filters' hot loops. Each
// operation's own rounding error is below 8 u^2 times the magnitude of its operands
// (u = 2^-53), which also covers cancellation; the input bounds are propagated on top.
namespace dd_detail {
inline ApproxDD normalize(double s, double t, double err, double magnitude) {
  double hi, lo;
  eft::two_sum(s, t, hi, lo);
  return {hi, lo, (err + 8 * kU2 * magnitude) * kBoundScale + kUnderflowFloor};
}
}  // namespace dd_detail
inline ApproxDD operator+(const ApproxDD& a, const ApproxDD& b) {
  double s, t;
  eft::two_sum(a.hi, b.hi, s, t);
  t += a.lo + b.lo;
  return dd_detail::normalize(s, t, a.e + b.e, std::fabs(a.hi) + std::fabs(b.hi));
}
inline ApproxDD operator-(const ApproxDD& a) { return {-a.hi, -a.lo, a.e}; }
inline ApproxDD operator-(const ApproxDD& a, const ApproxDD& b) { return a + (-b); }
inline ApproxDD operator*(const ApproxDD& a, const ApproxDD& b) {
  double p, q;
  eft::two_product(a.hi, b.hi, p, q);
  q += a.hi * b.lo + a.lo * b.hi;
  const double ma = std::fabs(a.hi) + std::fabs(a.lo), mb = std::fabs(b.hi) + std::fabs(b.lo);
  const double prop = ma * b.e + mb * a.e + a.e * b.e + std::fabs(a.lo * b.lo);
  return dd_detail::normalize(p, q, prop, ma * mb);
}
ApproxDD dd_difference(double a, double b);  // exact
// a / b with a rigorous bound; the caller guarantees |b| > b.e.
ApproxDD operator/(const ApproxDD& a, const ApproxDD& b);

inline int sign_of(const Approx& a) { return a.sign(); }
inline int sign_of(const Expansion& a) { return a.sign(); }

}  // namespace exact
}  // namespace kergen
