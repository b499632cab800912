// Exact arithmetic and predicates against integer arithmetic (__int128) as the independent truth.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <random>
#include <vector>

#include "exact/expansion.h"
#include "exact/predicates.h"
#include "exact/wide_product.h"

namespace {

using kergen::exact::Approx;
using kergen::exact::Expansion;

// orient3d on small integer coordinates is exact in __int128.
int orient_int(const int64_t* a, const int64_t* b, const int64_t* c, const int64_t* p) {
  __int128 u[3], v[3], w[3];
  for (int k = 0; k < 3; ++k) {
    u[k] = b[k] - a[k];
    v[k] = c[k] - a[k];
    w[k] = p[k] - a[k];
  }
  __int128 d =
      u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
  return d > 0 ? 1 : (d < 0 ? -1 : 0);
}

TEST(Exact, ExpansionCancellation) {
  Expansion big(1e100), one(1.0);
  Expansion s = (big + one) - big;
  EXPECT_EQ(s.sign(), 1);
  EXPECT_EQ(s.estimate(), 1.0);
  Expansion z = (big + one) - one - big;
  EXPECT_EQ(z.sign(), 0);
  // (1 + 2^-60)^2 - 1 - 2^-59 = 2^-120 > 0 exactly, invisible in double.
  double e = std::ldexp(1.0, -60);
  Expansion x = Expansion(1.0) + Expansion(e);
  Expansion r = x * x - Expansion(1.0) - Expansion(2 * e);
  EXPECT_EQ(r.sign(), 1);
  EXPECT_EQ(r.estimate(), std::ldexp(1.0, -120));
}

TEST(Exact, ApproxBoundsContainTheExactValue) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int i = 0; i < 2000; ++i) {
    double a = U(rng), b = U(rng), c = U(rng), d = U(rng);
    Approx v = Approx(a) * Approx(b) - Approx(c) * Approx(d);
    Expansion e = Expansion(a) * Expansion(b) - Expansion(c) * Expansion(d);
    Expansion diff = e - Expansion(v.v);
    EXPECT_LE(std::fabs(diff.estimate()), v.e);
  }
}

// The filtered det3 (permanent bound) on entries known only to +- e: the exact determinant of
// the exact entries lies within the bound, including nearly singular matrices.
TEST(Exact, FilteredDet3BoundContainsTheExactDeterminant) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int i = 0; i < 20000; ++i) {
    double x[9];
    for (double& v : x) v = U(rng);
    if (i % 2)
      for (int k = 0; k < 3; ++k) x[6 + k] = x[k] + x[3 + k] * 0.5 + U(rng) * 1e-12;  // nearly singular
    Approx a[9];
    for (int k = 0; k < 9; ++k) {
      const double e = (i % 3) ? std::fabs(x[k]) * 1e-14 * (1 + k) : 0;  // known entries or uncertain ones
      const double shown = x[k] + (U(rng) * e);                          // any value within +- e
      a[k] = Approx(shown, e + kergen::exact::kEps * std::fabs(shown) * 2);
    }
    const Approx d = kergen::det3(a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7], a[8]);
    Expansion ex[9];
    for (int k = 0; k < 9; ++k) ex[k] = Expansion(x[k]);
    const Expansion exact = kergen::det3(ex[0], ex[1], ex[2], ex[3], ex[4], ex[5], ex[6], ex[7], ex[8]);
    const Expansion diff = exact - Expansion(d.v);
    ASSERT_LE(std::fabs(diff.estimate()), d.e) << "case " << i;
    if (d.sign() != 2) ASSERT_EQ(d.sign(), exact.sign()) << "case " << i;
  }
}

// det3 in double-double (the running bound of each operation): entries hi + lo +- e around exact
// values hi + lo + delta (|delta| <= e, e = 0 for known entries), general, nearly singular (a row
// a combination of the others up to 1e-12 or up to 1e-31) and singular matrices (two equal rows):
// the bound must contain the exact determinant, a decided sign must be exact, and the bound must
// stay near double-double accuracy.
TEST(Exact, DoubleDoubleDet3BoundContainsTheExactDeterminant) {
  using kergen::exact::ApproxDD;
  std::mt19937_64 rng(37);
  std::uniform_real_distribution<double> U(-1, 1);
  size_t decided = 0, undecided = 0;
  for (int i = 0; i < 20000; ++i) {
    double h[9], l[9], delta[9], e[9];
    const double scale = std::ldexp(1.0, int(rng() % 60) - 30);
    for (int k = 0; k < 9; ++k) h[k] = U(rng) * scale;
    if (i % 3 != 0)  // nearly singular: row 3 = row 1 + row 2 / 2 + a perturbation
      for (int k = 0; k < 3; ++k) h[6 + k] = h[k] + h[3 + k] * 0.5 + U(rng) * scale * (i % 3 == 1 ? 1e-12 : 1e-31);
    for (int k = 0; k < 9; ++k) {
      double lo = U(rng) * std::fabs(h[k]) * 1e-16, hi;
      kergen::exact::eft::two_sum(h[k], lo, hi, lo);
      h[k] = hi;
      l[k] = lo;
      e[k] = (i % 2) ? std::fabs(hi) * 1e-30 * (1 + k) : 0;
      delta[k] = U(rng) * e[k];
    }
    if (i % 6 == 5)  // two equal rows, errors included: an exact zero
      for (int k = 0; k < 3; ++k) {
        h[6 + k] = h[k];
        l[6 + k] = l[k];
        e[6 + k] = e[k];
        delta[6 + k] = delta[k];
      }
    ApproxDD a[9];
    Expansion x[9];
    for (int k = 0; k < 9; ++k) {
      a[k] = ApproxDD(h[k], l[k], e[k]);
      x[k] = Expansion(h[k]) + Expansion(l[k]) + Expansion(delta[k]);
    }
    const ApproxDD d = kergen::det3(a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7], a[8]);
    const Expansion exact = kergen::det3(x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7], x[8]);
    const Expansion shown = Expansion(d.hi) + Expansion(d.lo);
    ASSERT_LE((exact - shown - Expansion(d.e)).sign(), 0) << "case " << i;
    ASSERT_GE((exact - shown + Expansion(d.e)).sign(), 0) << "case " << i;
    double perm = 0;
    for (double v : h) perm = std::max(perm, std::fabs(v));
    perm = 6 * perm * perm * perm;
    ASSERT_LE(d.e, 1e-28 * perm + 1e-20 * perm * (i % 2)) << "case " << i;
    if (d.sign() != 2) {
      ASSERT_EQ(d.sign(), exact.sign()) << "case " << i;
      ++decided;
    } else {
      ++undecided;
    }
  }
  EXPECT_GT(decided, 10000u);
  EXPECT_GT(undecided, 100u) << "no case near the bound";
}

TEST(Exact, Orient3dMatchesIntegerArithmetic) {
  std::mt19937_64 rng(11);
  std::uniform_int_distribution<int64_t> I(-(int64_t(1) << 25), int64_t(1) << 25);
  int zeros = 0;
  for (int i = 0; i < 20000; ++i) {
    int64_t q[4][3];
    for (auto& p : q)
      for (auto& c : p) c = I(rng);
    if (i % 2 == 0) {  // force coplanarity: p = a + s (b - a) + t (c - a) with small integers
      int64_t s = I(rng) % 5, t = I(rng) % 5;
      for (int k = 0; k < 3; ++k) q[3][k] = q[0][k] + s * (q[1][k] - q[0][k]) + t * (q[2][k] - q[0][k]);
    }
    double d[4][3];
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 3; ++k) d[j][k] = double(q[j][k]) * std::ldexp(1.0, -30);  // exact scaling
    int expect = orient_int(q[0], q[1], q[2], q[3]);
    zeros += expect == 0;
    ASSERT_EQ(kergen::orient3d(d[0], d[1], d[2], d[3]), expect) << i;
  }
  EXPECT_GT(zeros, 5000);
}

// Points with arbitrary doubles (inexact differences) that are coplanar up to rounding, or
// exactly (repeated points), or off by a relative 1e-17..1e-12: the adaptive stages must agree
// with the plain expansion determinant of the exact differences.
TEST(Exact, Orient3dNearlyCoplanarMatchesExpansions) {
  std::mt19937_64 rng(13);
  std::uniform_real_distribution<double> U(-1, 1);
  int zeros = 0, nonzero_near = 0;
  for (int i = 0; i < 40000; ++i) {
    double d[4][3];
    const double scale = std::ldexp(1.0, int(rng() % 40) - 20);  // differences of unlike magnitudes
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) d[j][k] = U(rng) * (j == 0 ? 1 : scale) + (j == 0 ? 0 : d[0][k]);
    const double s = U(rng), t = U(rng);
    const double off = (i % 4 == 0) ? 0 : std::ldexp(U(rng), -int(rng() % 30) - 50);
    for (int k = 0; k < 3; ++k) d[3][k] = d[0][k] + s * (d[1][k] - d[0][k]) + t * (d[2][k] - d[0][k]) + off;
    if (i % 7 == 0) {  // exactly coplanar: a repeated point
      const int j = int(rng() % 3);
      for (int k = 0; k < 3; ++k) d[3][k] = d[j][k];
    }
    Expansion u[3], v[3], w[3];
    for (int k = 0; k < 3; ++k) {
      u[k] = Expansion::difference(d[1][k], d[0][k]);
      v[k] = Expansion::difference(d[2][k], d[0][k]);
      w[k] = Expansion::difference(d[3][k], d[0][k]);
    }
    const int expect = kergen::det3(u[0], u[1], u[2], v[0], v[1], v[2], w[0], w[1], w[2]).sign();
    zeros += expect == 0;
    // nearly coplanar: the double determinant's own bound cannot decide it
    const Approx a = kergen::det3(Approx(u[0].estimate()), Approx(u[1].estimate()), Approx(u[2].estimate()),
                                  Approx(v[0].estimate()), Approx(v[1].estimate()), Approx(v[2].estimate()),
                                  Approx(w[0].estimate()), Approx(w[1].estimate()), Approx(w[2].estimate()));
    nonzero_near += expect != 0 && a.sign() == 2;
    ASSERT_EQ(kergen::orient3d(d[0], d[1], d[2], d[3]), expect) << i;
  }
  EXPECT_GT(zeros, 4000);
  EXPECT_GT(nonzero_near, 10000);
}

// Sign of det3(b - a, c - a, p - a) by expansions only (the reference for the integer stage).
int orient_expansion(const double* a, const double* b, const double* c, const double* p) {
  Expansion u[3], v[3], w[3];
  for (int k = 0; k < 3; ++k) {
    u[k] = Expansion::difference(b[k], a[k]);
    v[k] = Expansion::difference(c[k], a[k]);
    w[k] = Expansion::difference(p[k], a[k]);
  }
  return kergen::det3(u[0], u[1], u[2], v[0], v[1], v[2], w[0], w[1], w[2]).sign();
}

// Differential test of orient3d's integer stage against expansions: exactly coplanar points on
// binary lattices of many scales and offsets, mesh-like decimal coordinates on lattice planes,
// one-ulp perturbations, zeros and sign mixes, entries at the 2^62 limit, and exponent spreads
// that must fall back. Whenever the integer stage answers (not 2) it must equal the reference,
// and orient3d_adaptive / orient3d must agree with the reference always.
TEST(Exact, Orient3dIntegerStageMatchesExpansions) {
  std::mt19937_64 rng(17);
  std::uniform_int_distribution<int64_t> small(-9, 9);
  std::uniform_real_distribution<double> U(-1, 1);
  auto pick = [&](int n) { return int(rng() % unsigned(n)); };
  enum Kind { kLattice, kDecimal, kLimit, kGrid62, kSpread, kRandom, kKinds };
  int answered[kKinds] = {}, cases[kKinds] = {}, zeros[kKinds] = {};
  for (int i = 0; i < 200000; ++i) {
    const Kind kind = Kind(i % kKinds);
    double d[4][3];
    if (kind == kLattice) {
      // p = a + s (b - a) + t (c - a) on the grid 2^e with coordinates up to 2^bits grid units
      // and a common offset (a multiple of the grid): exactly coplanar unless perturbed.
      const int e = pick(150) - 151, bits = 1 + pick(50);  // below 2^55 2^e <= 2^54
      std::uniform_int_distribution<int64_t> I(-(int64_t(1) << bits), int64_t(1) << bits);
      const int64_t offset[3] = {I(rng) * pick(4), I(rng) * pick(4), I(rng) * pick(4)};
      int64_t q[4][3];
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) q[j][k] = I(rng) * (pick(8) != 0);  // some zero coordinates
      const int64_t s = small(rng), t = small(rng);
      for (int k = 0; k < 3; ++k) q[3][k] = q[0][k] + s * (q[1][k] - q[0][k]) + t * (q[2][k] - q[0][k]);
      for (int j = 0; j < 4; ++j)
        for (int k = 0; k < 3; ++k) d[j][k] = std::ldexp(double(q[j][k] + offset[k]), e);  // < 2^55 units: exact
    } else if (kind == kDecimal) {
      // Decimal coordinates as in refinements/*.off (5 digits, rounded to double) on planes
      // with small integer coefficients: z = const and x = z are coplanar after rounding, and
      // z = x + y or z = 2 x - y usually not (the reference decides).
      const double scale = std::ldexp(1.0, pick(20) - 10);
      auto decimal = [&]() { return double(int64_t(rng() % 10000000) - 5000000) / 1e5 * scale; };
      const int plane = pick(4);
      const double z0 = decimal();
      for (auto& pt : d) {
        pt[0] = decimal();
        pt[1] = decimal();
        pt[2] = plane == 0 ? z0 : plane == 1 ? pt[0] : plane == 2 ? pt[0] + pt[1] : 2 * pt[0] - pt[1];
      }
    } else if (kind == kLimit) {
      // Differences (a = 0) of up to 62 bits: 53-bit significands shifted by up to 9 bits next to
      // small integers, the widest spread the integer stage takes; then scaled by 2^e <= 2^-1
      // (the integer stage takes magnitudes below 2^62 only). (Not perturbed: one ulp of a small
      // significand would widen the spread.)
      const int e = pick(200) - 201;
      for (auto& c : d[0]) c = 0;
      for (int j = 1; j < 4; ++j)
        for (int k = 0; k < 3; ++k) {
          const int64_t m = int64_t(rng() >> 11) * (pick(2) ? 1 : -1);  // up to 53 bits
          d[j][k] = pick(3) ? std::ldexp(double(m), pick(10)) : double(small(rng));
        }
      if (pick(2)) {  // coplanar: p = +-b or +-c
        const int j = 1 + pick(2);
        const double sign = pick(2) ? 1 : -1;
        for (int k = 0; k < 3; ++k) d[3][k] = sign * d[j][k];
      }
      for (auto& pt : d)
        for (auto& c : pt) c = std::ldexp(c, e);
    } else if (kind == kGrid62) {
      // Coordinates on a grid of 62 bits, not 61: near +-2^61 (multiples of 2^9) on some axes,
      // 40-bit integers on the others; their differences stay below 2^62, and so does
      // p = a +- (b - a) +- (c - a), exactly. Then scaled by 2^e.
      const int e = pick(300) - 300;
      std::uniform_int_distribution<int64_t> near(-(int64_t(1) << 40), int64_t(1) << 40);
      const int64_t s = small(rng) % 2, t = small(rng) % 2;
      for (int k = 0; k < 3; ++k) {
        const bool big_axis = k == 0 || (k == 2 && pick(2));
        const int64_t sign = pick(2) ? 1 : -1;
        int64_t q[4];
        for (int j = 0; j < 3; ++j) q[j] = big_axis ? sign * ((int64_t(1) << 61) + near(rng) * 512) : near(rng);
        q[3] = q[0] + s * (q[1] - q[0]) + t * (q[2] - q[0]);
        for (int j = 0; j < 4; ++j) d[j][k] = std::ldexp(double(q[j]), e);
      }
    } else if (kind == kSpread) {
      // Coordinates of unlike magnitudes (2^-40 next to 1, or exact tiny values): wide grids.
      for (auto& pt : d)
        for (auto& c : pt) c = U(rng) * std::ldexp(1.0, -pick(3) * 30);
      if (pick(2))
        for (int k = 0; k < 3; ++k) d[3][k] = d[pick(3)][k];
    } else {
      // Arbitrary doubles of similar magnitude, nearly coplanar (inexact differences): the
      // coordinates' own grid.
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) d[j][k] = U(rng);
      const double s = U(rng), t = U(rng);
      for (int k = 0; k < 3; ++k) d[3][k] = d[0][k] + s * (d[1][k] - d[0][k]) + t * (d[2][k] - d[0][k]);
    }
    double& moved = d[pick(4)][pick(3)];
    const bool perturbed = kind != kLimit && moved != 0 && pick(3) == 0;
    if (perturbed)  // one ulp off (zeros are not: that would be a subnormal)
      moved = std::nextafter(moved, pick(2) ? INFINITY : -INFINITY);
    if (pick(4) == 0) {  // mirrored
      const int axis = pick(3);
      for (auto& pt : d) pt[axis] = -pt[axis];
    }
    const int expect = orient_expansion(d[0], d[1], d[2], d[3]);
    const int integer = kergen::exact::orient3d_integer(d[0], d[1], d[2], d[3]);
    ++cases[kind];
    zeros[kind] += expect == 0;
    // Lattice points span at most 55 bits: one common grid unless a small value was perturbed.
    if ((kind == kLattice || kind == kGrid62) && !perturbed) ASSERT_NE(integer, 2) << "case " << i;
    if (kind == kLimit) ASSERT_NE(integer, 2) << "case " << i;
    if (integer != 2) {
      ++answered[kind];
      ASSERT_EQ(integer, expect) << "case " << i;
    }
    const int adaptive = kergen::exact::orient3d_adaptive(d[0], d[1], d[2], d[3]);
    if (adaptive != 2) ASSERT_EQ(adaptive, expect) << "case " << i;
    ASSERT_EQ(kergen::orient3d(d[0], d[1], d[2], d[3]), expect) << "case " << i;
  }
  // The integer stage must be the common path where it applies, and exact zeros common.
  EXPECT_GT(answered[kLattice], cases[kLattice] * 99 / 100);
  EXPECT_GT(answered[kDecimal], cases[kDecimal] * 95 / 100);
  EXPECT_GT(answered[kRandom], cases[kRandom] * 95 / 100);
  EXPECT_LT(answered[kSpread], cases[kSpread] / 2);
  EXPECT_GT(zeros[kLattice], cases[kLattice] / 2);
  EXPECT_GT(zeros[kDecimal], cases[kDecimal] / 3);
  EXPECT_GT(zeros[kLimit], cases[kLimit] / 4);
  EXPECT_GT(zeros[kGrid62], cases[kGrid62] / 2);
}

// The grid's bounds: 62 bits of differences are taken, 63 fall back; 61 bits of coordinates
// with inexact differences are taken, 62 only when the differences stay below 2^62.
TEST(Exact, Orient3dIntegerStageBounds) {
  const double top = std::ldexp(double((int64_t(1) << 53) - 1), 9);  // 2^62 - 2^9: below 2^62
  const double o[3] = {0, 0, 0};
  double b[3] = {top, 1, 0}, c[3] = {0, top, 1}, p[3] = {1, 0, top};
  for (int k = 0; k < 3; ++k) {  // magnitudes below 2^62 only
    b[k] = std::ldexp(b[k], -5);
    c[k] = std::ldexp(c[k], -5);
    p[k] = std::ldexp(p[k], -5);
  }
  EXPECT_EQ(kergen::exact::orient3d_integer(o, b, c, p), orient_expansion(o, b, c, p));
  EXPECT_NE(kergen::exact::orient3d_integer(o, b, c, p), 2);
  b[0] = std::ldexp(1.0, 62 - 5);  // 2^62 next to 1: 63 bits
  EXPECT_EQ(kergen::exact::orient3d_integer(o, b, c, p), 2);
  EXPECT_EQ(kergen::orient3d(o, b, c, p), orient_expansion(o, b, c, p));
  // Inexact differences: coordinates 2^-61 .. 1 (61 bits) are taken; 2^-62 .. 1 are not, as
  // the differences (up to 1.75) reach 2^62 units of 2^-62.
  const double x[3] = {1 - std::ldexp(1.0, -53), std::ldexp(1.0, -61), 0.5};
  const double y[3] = {-0.75, 0.25 + std::ldexp(1.0, -53), std::ldexp(3.0, -61)};
  const double z[3] = {std::ldexp(5.0, -61), -0.5, 0.125};
  double w[3] = {0.3, std::ldexp(7.0, -61), -0.9};
  EXPECT_NE(kergen::exact::orient3d_integer(x, y, z, w), 2);
  EXPECT_EQ(kergen::exact::orient3d_integer(x, y, z, w), orient_expansion(x, y, z, w));
  w[1] = std::ldexp(7.0, -62);
  EXPECT_EQ(kergen::exact::orient3d_integer(x, y, z, w), 2);
  // Coordinates on a 62-bit grid (2^-62 next to 1/2): taken when the differences stay below
  // 2^62 grid units (below 1 here), else not (they are inexact in double, too).
  const double g = std::ldexp(1.0, -62);
  const double ga[3] = {0.5, 3 * g, 0.25}, gb[3] = {0.25, 0.5, 5 * g}, gc[3] = {7 * g, 0.25, 0.5};
  double gp[3] = {0.5, 0.5, 0.5};
  EXPECT_NE(kergen::exact::orient3d_integer(ga, gb, gc, gp), 2);
  EXPECT_EQ(kergen::exact::orient3d_integer(ga, gb, gc, gp), orient_expansion(ga, gb, gc, gp));
  gp[0] = -0.75;  // gp - ga = -1.25 on x: over 2^62 grid units; gb - ga is inexact in double
  EXPECT_EQ(kergen::exact::orient3d_integer(ga, gb, gc, gp), 2);
  // All points equal (all differences 0), and a subnormal difference (falls back).
  EXPECT_EQ(kergen::exact::orient3d_integer(x, x, x, x), 0);
  const double tiny[3] = {std::ldexp(1.0, -1060), 0, 0};
  EXPECT_EQ(kergen::exact::orient3d_integer(o, tiny, c, p), 2);
}

TEST(Exact, CollinearIsExact) {
  double a[3] = {0.1, 0.2, 0.3}, b[3] = {0.1 + 1.0, 0.2 + 2.0, 0.3 + 3.0};
  double c[3] = {a[0] + 2 * (b[0] - a[0]), a[1] + 2 * (b[1] - a[1]), a[2] + 2 * (b[2] - a[2])};
  // c is computed in double: collinear only if the arithmetic was exact, which orient decides.
  bool truth = (Expansion::difference(c[0], a[0]) * Expansion::difference(b[1], a[1]) -
                Expansion::difference(c[1], a[1]) * Expansion::difference(b[0], a[0]))
                       .sign() == 0 &&
               (Expansion::difference(c[1], a[1]) * Expansion::difference(b[2], a[2]) -
                Expansion::difference(c[2], a[2]) * Expansion::difference(b[1], a[1]))
                       .sign() == 0;
  EXPECT_EQ(kergen::collinear(a, b, c), truth);
  double p[3] = {0, 0, 0}, q[3] = {1, 1, 1}, r[3] = {3, 3, 3}, s[3] = {3, 3, 3.0000000000000004};
  EXPECT_TRUE(kergen::collinear(p, q, r));
  EXPECT_FALSE(kergen::collinear(p, q, s));
}

}  // namespace

// The wasm build multiplies 64-bit integers in four 32-bit halves (no 64x64->128 instruction
// there); natively the same code is checked against the compiler's __int128 products, on the
// extremes and on random operands of every width.
TEST(WideProduct, PortableFormEqualsNativeProducts) {
  using kergen::exact::Int128;
  using kergen::exact::portable_wide_product;
  const int64_t edges[] = {0,
                           1,
                           -1,
                           2,
                           -2,
                           INT64_MAX,
                           INT64_MIN + 1,
                           int64_t(1) << 62,
                           -(int64_t(1) << 62),
                           0xffffffffll,
                           -0xffffffffll,
                           0x100000000ll,
                           0x7fffffff,
                           -0x80000000ll};
  std::mt19937_64 rng(7);
  std::vector<int64_t> values(std::begin(edges), std::end(edges));
  for (int bits = 1; bits <= 63; ++bits)
    for (int k = 0; k < 40; ++k) {
      const int64_t v = int64_t(rng() >> (64 - bits));
      values.push_back(k % 2 ? v : -v);
    }
  size_t checked = 0;
  for (int64_t a : values)
    for (int64_t b : values) {
      // |a b| < 2^127 always holds for int64 operands other than INT64_MIN (excluded above).
      ASSERT_TRUE(portable_wide_product(a, b) == Int128(a) * Int128(b)) << a << " * " << b;
      const uint64_t ub = uint64_t(b < 0 ? -(b + 1) : b) >> 1;  // (int64, uint64) form: |a ub| < 2^127
      ASSERT_TRUE(portable_wide_product(a, ub) == Int128(a) * Int128(ub)) << a << " * " << ub;
      ++checked;
    }
  EXPECT_GT(checked, 6000000u);
}
