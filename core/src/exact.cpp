// Expansion arithmetic after Shewchuk, "Adaptive Precision Floating-Point Arithmetic and Fast
// Robust Geometric Predicates", Discrete & Computational Geometry 18 (1997): two_sum /
// two_product error-free transformations, zero-eliminating expansion sum and scaling, compression.
#include "exact.h"

#include <cassert>

namespace kergen {
namespace exact {
namespace {

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

// h = e + f (zero-eliminating), Shewchuk's fast_expansion_sum_zeroelim.
void expansion_sum(const std::vector<double>& e, const std::vector<double>& f, std::vector<double>& h) {
  h.clear();
  size_t elen = e.size(), flen = f.size();
  if (elen == 0) { h = f; return; }
  if (flen == 0) { h = e; return; }
  h.reserve(elen + flen);
  double Q, Qnew, hh;
  size_t ei = 0, fi = 0;
  double enow = e[0], fnow = f[0];
  if ((fnow > enow) == (fnow > -enow)) { Q = enow; enow = (++ei < elen) ? e[ei] : 0; }
  else { Q = fnow; fnow = (++fi < flen) ? f[fi] : 0; }
  if (ei < elen && fi < flen) {
    if ((fnow > enow) == (fnow > -enow)) { fast_two_sum(enow, Q, Qnew, hh); enow = (++ei < elen) ? e[ei] : 0; }
    else { fast_two_sum(fnow, Q, Qnew, hh); fnow = (++fi < flen) ? f[fi] : 0; }
    Q = Qnew;
    if (hh != 0) h.push_back(hh);
    while (ei < elen && fi < flen) {
      if ((fnow > enow) == (fnow > -enow)) { two_sum(Q, enow, Qnew, hh); enow = (++ei < elen) ? e[ei] : 0; }
      else { two_sum(Q, fnow, Qnew, hh); fnow = (++fi < flen) ? f[fi] : 0; }
      Q = Qnew;
      if (hh != 0) h.push_back(hh);
    }
  }
  while (ei < elen) {
    two_sum(Q, enow, Qnew, hh);
    enow = (++ei < elen) ? e[ei] : 0;
    Q = Qnew;
    if (hh != 0) h.push_back(hh);
  }
  while (fi < flen) {
    two_sum(Q, fnow, Qnew, hh);
    fnow = (++fi < flen) ? f[fi] : 0;
    Q = Qnew;
    if (hh != 0) h.push_back(hh);
  }
  if (Q != 0 || h.empty()) h.push_back(Q);
  if (h.size() == 1 && h[0] == 0) h.clear();
}

// h = e * b (zero-eliminating), Shewchuk's scale_expansion_zeroelim.
void scale_expansion(const std::vector<double>& e, double b, std::vector<double>& h) {
  h.clear();
  if (e.empty() || b == 0) return;
  h.reserve(2 * e.size());
  double Q, sum, hh, product1, product0;
  two_product(e[0], b, Q, hh);
  if (hh != 0) h.push_back(hh);
  for (size_t i = 1; i < e.size(); ++i) {
    two_product(e[i], b, product1, product0);
    two_sum(Q, product0, sum, hh);
    if (hh != 0) h.push_back(hh);
    fast_two_sum(product1, sum, Q, hh);
    if (hh != 0) h.push_back(hh);
  }
  if (Q != 0 || h.empty()) h.push_back(Q);
  if (h.size() == 1 && h[0] == 0) h.clear();
}

}  // namespace

void Expansion::compress() {
  // Shewchuk's compress: shortens the expansion without changing its value.
  size_t n = c_.size();
  if (n < 2) return;
  std::vector<double> g(n);
  double Q = c_[n - 1], q, Qnew;
  size_t bottom = n - 1;
  for (size_t i = n - 1; i-- > 0;) {
    fast_two_sum(Q, c_[i], Qnew, q);
    if (q != 0) { g[bottom--] = Qnew; Q = q; }
    else Q = Qnew;
  }
  g[bottom] = Q;
  size_t top = 0;
  std::vector<double> h;
  h.reserve(n);
  for (size_t i = bottom + 1; i < n; ++i) {
    fast_two_sum(g[i], Q, Qnew, q);
    Q = Qnew;
    if (q != 0) h.push_back(q);
  }
  (void)top;
  h.push_back(Q);
  if (h.size() == 1 && h[0] == 0) h.clear();
  c_.swap(h);
}

double Expansion::estimate() const {
  double s = 0;
  for (double x : c_) s += x;
  return s;
}

Expansion operator+(const Expansion& a, const Expansion& b) {
  Expansion r;
  expansion_sum(a.c_, b.c_, r.c_);
  return r;
}
Expansion Expansion::operator-() const {
  Expansion r = *this;
  for (double& x : r.c_) x = -x;
  return r;
}
Expansion operator-(const Expansion& a, const Expansion& b) { return a + (-b); }

Expansion operator*(const Expansion& a, const Expansion& b) {
  const Expansion& small = a.size() <= b.size() ? a : b;
  const Expansion& large = a.size() <= b.size() ? b : a;
  Expansion acc, term, next;
  for (double s : small.c_) {
    scale_expansion(large.c_, s, term.c_);
    expansion_sum(acc.c_, term.c_, next.c_);
    acc.c_.swap(next.c_);
  }
  if (acc.c_.size() > 4) acc.compress();
  return acc;
}

Expansion Expansion::difference(double a, double b) {
  Expansion r;
  double x, y;
  two_sum(a, -b, x, y);
  if (y != 0) r.c_.push_back(y);
  if (x != 0) r.c_.push_back(x);
  return r;
}
Expansion Expansion::product(double a, double b) {
  Expansion r;
  double x, y;
  two_product(a, b, x, y);
  if (y != 0) r.c_.push_back(y);
  if (x != 0) r.c_.push_back(x);
  return r;
}

}  // namespace exact
}  // namespace kergen
