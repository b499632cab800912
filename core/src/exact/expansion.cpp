// Expansion arithmetic after Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast
// Robust Geometric Predicates", Discrete & Computational Geometry 18 (1997): two_sum /
// two_product error-free transformations, zero-eliminating expansion sum and scaling, compression.
#include "exact/expansion.h"

#include <algorithm>
#include <cassert>
#include <cstdint>
#include <cstring>
#include <utility>

#include "exact/wide_product.h"

namespace kergen {
namespace exact {
using namespace eft;
namespace {

// h = e + f (zero-eliminating), Shewchuk's fast_expansion_sum_zeroelim; h has room for
// elen + flen components and may not alias e or f. Returns the length of h.
size_t expansion_sum(const double* e, size_t elen, const double* f, size_t flen, double* h) {
  if (elen == 0) {
    for (size_t i = 0; i < flen; ++i) h[i] = f[i];
    return flen;
  }
  if (flen == 0) {
    for (size_t i = 0; i < elen; ++i) h[i] = e[i];
    return elen;
  }
  size_t hlen = 0;
  double Q, Qnew, hh;
  size_t ei = 0, fi = 0;
  double enow = e[0], fnow = f[0];
  if ((fnow > enow) == (fnow > -enow)) {
    Q = enow;
    enow = (++ei < elen) ? e[ei] : 0;
  } else {
    Q = fnow;
    fnow = (++fi < flen) ? f[fi] : 0;
  }
  if (ei < elen && fi < flen) {
    if ((fnow > enow) == (fnow > -enow)) {
      fast_two_sum(enow, Q, Qnew, hh);
      enow = (++ei < elen) ? e[ei] : 0;
    } else {
      fast_two_sum(fnow, Q, Qnew, hh);
      fnow = (++fi < flen) ? f[fi] : 0;
    }
    Q = Qnew;
    if (hh != 0) h[hlen++] = hh;
    while (ei < elen && fi < flen) {
      if ((fnow > enow) == (fnow > -enow)) {
        two_sum(Q, enow, Qnew, hh);
        enow = (++ei < elen) ? e[ei] : 0;
      } else {
        two_sum(Q, fnow, Qnew, hh);
        fnow = (++fi < flen) ? f[fi] : 0;
      }
      Q = Qnew;
      if (hh != 0) h[hlen++] = hh;
    }
  }
  while (ei < elen) {
    two_sum(Q, enow, Qnew, hh);
    enow = (++ei < elen) ? e[ei] : 0;
    Q = Qnew;
    if (hh != 0) h[hlen++] = hh;
  }
  while (fi < flen) {
    two_sum(Q, fnow, Qnew, hh);
    fnow = (++fi < flen) ? f[fi] : 0;
    Q = Qnew;
    if (hh != 0) h[hlen++] = hh;
  }
  if (Q != 0) h[hlen++] = Q;
  return hlen;
}

// h = e * b (zero-eliminating), Shewchuk's scale_expansion_zeroelim; h has room for 2 * elen.
size_t scale_expansion(const double* e, size_t elen, double b, double* h) {
  if (elen == 0 || b == 0) return 0;
  size_t hlen = 0;
  double Q, sum, hh, product1, product0;
  two_product(e[0], b, Q, hh);
  if (hh != 0) h[hlen++] = hh;
  for (size_t i = 1; i < elen; ++i) {
    two_product(e[i], b, product1, product0);
    two_sum(Q, product0, sum, hh);
    if (hh != 0) h[hlen++] = hh;
    fast_two_sum(product1, sum, Q, hh);
    if (hh != 0) h[hlen++] = hh;
  }
  if (Q != 0) h[hlen++] = Q;
  return hlen;
}

}  // namespace

// Double-double division (the other operations are inline in expansion.h).
ApproxDD operator/(const ApproxDD& a, const ApproxDD& b) {
  // q1 = a / b in double, then one correction step: q = q1 + (a - q1 b) / b.
  double q1 = a.hi / b.hi;
  ApproxDD r = a - ApproxDD(q1) * ApproxDD(b.hi, b.lo, 0);
  double q2 = (r.hi + r.lo) / b.hi;
  double hi, lo;
  two_sum(q1, q2, hi, lo);
  double mb = std::fabs(b.hi) - std::fabs(b.lo) - b.e;
  double q = std::fabs(hi);
  // |a/b - (hi+lo)|: the input bounds (a.e + q b.e) / |b|, plus the correction step's own error
  // (second-order in the double quotient's relative error, ~1e-32 q).
  double e = ((a.e + q * b.e) / mb + 64 * kU2 * q + std::fabs(r.e) / mb) * kBoundScale + kUnderflowFloor;
  return {hi, lo, e};
}

ApproxDD dd_difference(double a, double b) {
  double x, y;
  two_sum(a, -b, x, y);
  return {x, y, 0};
}

#if defined(__SIZEOF_INT128__)
// Integer stage of orient3d: the points' coordinates (or their differences) are usually integer
// multiples of one power of two spanning at most ~60 bits, because nearby mesh coordinates share
// a binary grid. Then the determinant is exact in fixed-width integers, several times cheaper
// than expansions, and decides exact zeros (coplanar faces) as well as nonzero values.
namespace {

// Writes x[i] = q[i] 2^L with L = highest - max_bits, where |x[i]| < 2^highest for all i < n,
// when every q[i] is an integer (then |q[i]| < 2^max_bits); returns false otherwise (values on
// a finer grid, non-finite values, or |x[i]| >= 2^max_bits, which does not occur for the
// kernel's scaled points and differences, below 2).
template <int n>
bool to_common_grid(const double (&x)[n], int max_bits, int64_t (&q)[n]) {
  // The largest magnitude by the bit patterns (ordered like the magnitudes they encode).
  uint64_t max_magnitude = 0;
  for (int i = 0; i < n; ++i) {
    uint64_t bits;
    std::memcpy(&bits, &x[i], sizeof bits);
    max_magnitude = std::max(max_magnitude, bits & ~(uint64_t(1) << 63));
  }
  const int highest = int(max_magnitude >> 52) - 1022;  // |x[i]| < 2^highest
  // unit = 2^(max_bits - highest) must be a normal double >= 1: then x[i] unit is exact (a
  // power-of-two scaling up never rounds, and |x[i] unit| < 2^max_bits cannot overflow).
  // Also excludes inf and NaN (highest 1025) and all-zero input (highest -1022, handled below).
  const int unit_exponent = max_bits - highest;
  if (unit_exponent < 0 || unit_exponent > 1023) {
    if (max_magnitude != 0) return false;
    for (int i = 0; i < n; ++i) q[i] = 0;
    return true;
  }
  const uint64_t unit_bits = uint64_t(1023 + unit_exponent) << 52;
  double unit;
  std::memcpy(&unit, &unit_bits, sizeof unit);
  // scaled - q[i] is the fractional part, exactly (q[i] is scaled truncated, itself a double);
  // any nonzero one leaves bits other than the sign in the union of their bit patterns.
  uint64_t fractions = 0;
  for (int i = 0; i < n; ++i) {
    const double scaled = x[i] * unit;
    q[i] = int64_t(scaled);  // |scaled| < 2^max_bits <= 2^62 fits
    const double fraction = scaled - double(q[i]);
    uint64_t bits;
    std::memcpy(&bits, &fraction, sizeof bits);
    fractions |= bits;
  }
  return (fractions << 1) == 0;
}

// Sign of det3(u, v, w) for integer rows with every |entry| < 2^62, exactly.
// Bounds: each 2x2 minor is a difference of two products below 2^124, so below 2^125 in
// magnitude (Int128 holds 2^127). Each term z * minor is below 2^187 and the sum below 2^189,
// which is accumulated in 192 bits as high 2^64 + low: the minor m splits exactly into
// m_high 2^64 + m_low with m_high = floor(m / 2^64) (|m_high| <= 2^61) and m_low in [0, 2^64);
// z m_high is below 2^123, t = z m_low below 2^126, and t again splits into floor(t / 2^64)
// (below 2^62) and t's low 64 bits, whose sum over three terms stays below 3 2^64 in UInt128.
int det3_sign(const int64_t* u, const int64_t* v, const int64_t* w) {
  auto minor = [](int64_t p1, int64_t q1, int64_t p2, int64_t q2) {  // p1 q1 - p2 q2
    return wide_product(p1, q1) - wide_product(p2, q2);
  };
  // Expansion by the z column, as in stage B below.
  const Int128 minors[3] = {minor(v[0], w[1], w[0], v[1]), minor(w[0], u[1], u[0], w[1]),
                            minor(u[0], v[1], v[0], u[1])};
  const int64_t z[3] = {u[2], v[2], w[2]};
  Int128 high = 0;  // the determinant is high 2^64 + low
  UInt128 low = 0;
  for (int k = 0; k < 3; ++k) {
    // >> on a negative Int128 is an arithmetic shift (floor) in GCC and Clang, as in C++20.
    const int64_t m_high = int64_t(minors[k] >> 64);
    const uint64_t m_low = uint64_t(minors[k]);
    const Int128 t = wide_product(z[k], m_low);
    high += wide_product(z[k], m_high) + (t >> 64);
    low += uint64_t(t);
  }
  high += Int128(low >> 64);
  if (high != 0) return high > 0 ? 1 : -1;
  return uint64_t(low) != 0 ? 1 : 0;  // high == 0: the determinant is low's 64 bits, >= 0
}

}  // namespace
#endif

int orient3d_integer(const double* a, const double* b, const double* c, const double* p) {
#if defined(__SIZEOF_INT128__)
  // First the coordinates, when they share a grid of at most 61 bits (their differences then
  // stay below 2^62): nearly all calls on meshes, as the kernel's coordinates are below 1 and
  // not much finer than the input's. Else a grid of 62 bits, when the differences happen to stay
  // below 2^62 (they are below 2^63, no overflow). Else the differences, when they are exact in
  // double and share a grid of at most 62 bits (nearby points far from the origin).
  const double x[12] = {a[0], a[1], a[2], b[0], b[1], b[2], c[0], c[1], c[2], p[0], p[1], p[2]};
  int64_t q[12], u[3], v[3], w[3];
  auto differences = [&] {
    for (int k = 0; k < 3; ++k) {
      u[k] = q[3 + k] - q[k];
      v[k] = q[6 + k] - q[k];
      w[k] = q[9 + k] - q[k];
    }
  };
  if (to_common_grid(x, 61, q)) {
    differences();
    return det3_sign(u, v, w);
  }
  if (to_common_grid(x, 62, q)) {
    differences();
    constexpr int64_t kLimit = int64_t(1) << 62;
    bool small = true;
    for (int k = 0; k < 3; ++k) {
      small &= u[k] > -kLimit && u[k] < kLimit && v[k] > -kLimit && v[k] < kLimit;
      small &= w[k] > -kLimit && w[k] < kLimit;
    }
    if (small) return det3_sign(u, v, w);
  }
  double d[9];
  bool exact_differences = true;
  for (int k = 0; k < 3; ++k) {
    double tail_u, tail_v, tail_w;
    two_sum(b[k], -a[k], d[k], tail_u);
    two_sum(c[k], -a[k], d[3 + k], tail_v);
    two_sum(p[k], -a[k], d[6 + k], tail_w);
    exact_differences &= tail_u == 0 && tail_v == 0 && tail_w == 0;
  }
  int64_t e[9];
  if (exact_differences && to_common_grid(d, 62, e)) return det3_sign(e, e + 3, e + 6);
#else
  (void)a, (void)b, (void)c, (void)p;
#endif
  return 2;
}

// Where the integer stage goes: natively first, as it costs less than half of stage B (x86-64
// callgrind, princeton/325.off: ~375 instructions per call against ~810). In WebAssembly the
// 128-bit products are emulated (four 64-bit multiplies each) and the integer stage costs more
// than stage B on exact differences (V8 x86-64 code: ~1250 instructions against ~950 per call
// on 325.off), so there it only replaces stages B and C for inexact differences (~1300-1700,
// and often the caller's full expansion formula after them).
#if defined(__wasm__) || defined(KERGEN_INTEGER_STAGE_AFTER_EXACT_DIFFERENCES)
constexpr bool kIntegerStageFirst = false;
#else
constexpr bool kIntegerStageFirst = true;
#endif

int orient3d_adaptive(const double* a, const double* b, const double* c, const double* p) {
  if (kIntegerStageFirst) {
    const int integer_sign = orient3d_integer(a, b, c, p);
    if (integer_sign != 2) return integer_sign;
  }
  // Shewchuk's orient3dadapt (1997, section 4.3), stages B and C, with his variables: the rows
  // u = b - a, v = c - a, w = p - a are his (ad, bd, cd), so det3(u, v, w) is his determinant.
  double u[3], v[3], w[3], ut[3], vt[3], wt[3];
  bool exact_differences = true;
  for (int k = 0; k < 3; ++k) {
    two_sum(b[k], -a[k], u[k], ut[k]);
    two_sum(c[k], -a[k], v[k], vt[k]);
    two_sum(p[k], -a[k], w[k], wt[k]);
    exact_differences &= ut[k] == 0 && vt[k] == 0 && wt[k] == 0;
  }
  if (!kIntegerStageFirst && !exact_differences) {
    const int integer_sign = orient3d_integer(a, b, c, p);
    if (integer_sign != 2) return integer_sign;
  }
  // Stage B: the determinant of the rounded differences, exactly, by the z column:
  // u_z (v_x w_y - w_x v_y) + v_z (w_x u_y - u_x w_y) + w_z (u_x v_y - v_x u_y), each minor an
  // exact 4-component expansion, each term at most 8 components, the sum at most 24.
  auto minor = [](double p1, double q1, double p2, double q2, double* out) {  // p1 q1 - p2 q2
    double x[2], y[2];
    two_product(p1, q1, x[1], x[0]);
    two_product(-p2, q2, y[1], y[0]);
    return expansion_sum(x, 2, y, 2, out);
  };
  double bc[4], ca[4], ab[4], t0[8], t1[8], t2[8], s01[16], fin[24];
  const size_t nbc = minor(v[0], w[1], w[0], v[1], bc);
  const size_t nca = minor(w[0], u[1], u[0], w[1], ca);
  const size_t nab = minor(u[0], v[1], v[0], u[1], ab);
  const size_t k0 = scale_expansion(bc, nbc, u[2], t0);
  const size_t k1 = scale_expansion(ca, nca, v[2], t1);
  const size_t k2 = scale_expansion(ab, nab, w[2], t2);
  const size_t k01 = expansion_sum(t0, k0, t1, k1, s01);
  const size_t n = expansion_sum(s01, k01, t2, k2, fin);
  if (exact_differences) return n == 0 ? 0 : (fin[n - 1] > 0 ? 1 : -1);
  double det = 0;
  for (size_t i = 0; i < n; ++i) det += fin[i];
  const double permanent = (std::fabs(v[0] * w[1]) + std::fabs(w[0] * v[1])) * std::fabs(u[2]) +
                           (std::fabs(w[0] * u[1]) + std::fabs(u[0] * w[1])) * std::fabs(v[2]) +
                           (std::fabs(u[0] * v[1]) + std::fabs(v[0] * u[1])) * std::fabs(w[2]);
  const double bound_b = (3.0 + 28.0 * kEps) * kEps * permanent;
  if (det >= bound_b || -det >= bound_b) return det > 0 ? 1 : (det < 0 ? -1 : 0);  // bound 0: det exact
  // Stage C: the first-order terms of the difference tails, in floating point.
  const double bound_c = (26.0 + 288.0 * kEps) * kEps * kEps * permanent + (3.0 + 8.0 * kEps) * kEps * std::fabs(det);
  det +=
      (u[2] * ((v[0] * wt[1] + w[1] * vt[0]) - (v[1] * wt[0] + w[0] * vt[1])) + ut[2] * (v[0] * w[1] - v[1] * w[0])) +
      (v[2] * ((w[0] * ut[1] + u[1] * wt[0]) - (w[1] * ut[0] + u[0] * wt[1])) + vt[2] * (w[0] * u[1] - w[1] * u[0])) +
      (w[2] * ((u[0] * vt[1] + v[1] * ut[0]) - (u[1] * vt[0] + v[0] * ut[1])) + wt[2] * (u[0] * v[1] - u[1] * v[0]));
  if (det >= bound_c || -det >= bound_c) return det > 0 ? 1 : (det < 0 ? -1 : 0);
  return 2;
}

void Expansion::compress() {
  // Shewchuk's compress: shortens the expansion without changing its value.
  size_t n = n_;
  if (n < 2) return;
  double small[kInline * 2];
  std::vector<double> big;
  double* g = n <= kInline * 2 ? small : (big.resize(n), big.data());
  double Q = p_[n - 1], q, Qnew;
  size_t bottom = n - 1;
  for (size_t i = n - 1; i-- > 0;) {
    fast_two_sum(Q, p_[i], Qnew, q);
    if (q != 0) {
      g[bottom--] = Qnew;
      Q = q;
    } else
      Q = Qnew;
  }
  size_t top = 0;
  for (size_t i = bottom + 1; i < n; ++i) {
    fast_two_sum(g[i], Q, Qnew, q);
    Q = Qnew;
    if (q != 0) p_[top++] = q;
  }
  p_[top++] = Q;
  n_ = (top == 1 && p_[0] == 0) ? 0 : top;
}

double Expansion::estimate() const {
  double s = 0;
  for (size_t i = 0; i < n_; ++i) s += p_[i];
  return s;
}

// Results longer than this are compressed: sums and products of uncompressed expansions grow
// with every operation (a product costs the product of the lengths), while their values rarely
// need more than a few components.
constexpr size_t kCompressAbove = 4;

Expansion operator+(const Expansion& a, const Expansion& b) {
  Expansion r;
  r.n_ = expansion_sum(a.p_, a.n_, b.p_, b.n_, r.reserve(a.n_ + b.n_));
  if (r.n_ > kCompressAbove) r.compress();
  return r;
}
void Expansion::swap(Expansion& o) noexcept {
  const bool inline_a = p_ == buf_, inline_b = o.p_ == o.buf_;
  if (inline_a && inline_b) {
    for (size_t i = 0, m = std::max(n_, o.n_); i < m; ++i) std::swap(buf_[i], o.buf_[i]);
  } else if (!inline_a && !inline_b) {
    heap_.swap(o.heap_);
    p_ = heap_.data();
    o.p_ = o.heap_.data();
  } else {  // the inline one's components move to the other's buffer, the heap block the other way
    Expansion& in = inline_a ? *this : o;
    Expansion& out = inline_a ? o : *this;
    for (size_t i = 0; i < in.n_; ++i) out.buf_[i] = in.buf_[i];
    in.heap_.swap(out.heap_);
    in.p_ = in.heap_.data();
    out.p_ = out.buf_;
  }
  std::swap(n_, o.n_);
}

Expansion Expansion::operator-() const {
  Expansion r;
  double* h = r.reserve(n_);
  for (size_t i = 0; i < n_; ++i) h[i] = -p_[i];
  r.n_ = n_;
  return r;
}
Expansion operator-(const Expansion& a, const Expansion& b) {
  // a + (-b) with -b negated on the stack when it fits (no temporary Expansion).
  if (b.n_ <= Expansion::kInline) {
    double nb[Expansion::kInline];
    for (size_t i = 0; i < b.n_; ++i) nb[i] = -b.p_[i];
    Expansion r;
    r.n_ = expansion_sum(a.p_, a.n_, nb, b.n_, r.reserve(a.n_ + b.n_));
    if (r.n_ > kCompressAbove) r.compress();
    return r;
  }
  return a + (-b);
}

Expansion operator*(const Expansion& a, const Expansion& b) {
  const Expansion& small = a.size() <= b.size() ? a : b;
  const Expansion& large = a.size() <= b.size() ? b : a;
  if (small.n_ <= 1) {  // a double times an expansion: one scaling
    Expansion r;
    if (small.n_ == 1) r.n_ = scale_expansion(large.p_, large.n_, small.p_[0], r.reserve(2 * large.n_));
    if (r.n_ > kCompressAbove) r.compress();
    return r;
  }
  // The partial sums alternate between two stack buffers when they fit (the usual case): the
  // same scalings and sums as below, so the same components, without swapping and resizing
  // Expansion objects on every step.
  constexpr size_t kStack = 192;
  if (2 * large.n_ * small.n_ <= kStack) {  // (the accumulated length is at most this)
    double bufs[2][kStack], term[kStack];
    double *acc = bufs[0], *next = bufs[1];
    size_t n = 0;
    for (size_t i = 0; i < small.n_; ++i) {
      const size_t tn = scale_expansion(large.p_, large.n_, small.p_[i], term);
      const size_t m = expansion_sum(acc, n, term, tn, next);
      std::swap(acc, next);
      n = m;
    }
    Expansion r;
    r.assign(acc, n);
    if (r.n_ > kCompressAbove) r.compress();
    return r;
  }
  Expansion acc, next, term;
  double* t = term.reserve(2 * large.n_);
  for (size_t i = 0; i < small.n_; ++i) {
    term.n_ = scale_expansion(large.p_, large.n_, small.p_[i], t);
    next.n_ = expansion_sum(acc.p_, acc.n_, term.p_, term.n_, next.reserve(acc.n_ + term.n_));
    acc.swap(next);
  }
  if (acc.n_ > kCompressAbove) acc.compress();
  return acc;
}

Expansion Expansion::difference(double a, double b) {
  Expansion r;
  double x, y;
  two_sum(a, -b, x, y);
  if (y != 0) r.p_[r.n_++] = y;
  if (x != 0) r.p_[r.n_++] = x;
  return r;
}
Expansion Expansion::product(double a, double b) {
  Expansion r;
  double x, y;
  two_product(a, b, x, y);
  if (y != 0) r.p_[r.n_++] = y;
  if (x != 0) r.p_[r.n_++] = x;
  return r;
}

}  // namespace exact
}  // namespace kergen
