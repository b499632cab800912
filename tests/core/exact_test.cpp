// Exact arithmetic and predicates against integer arithmetic (__int128) as the independent truth.
#include <gtest/gtest.h>

#include <random>

#include "exact.h"
#include "planes.h"

namespace {

using kergen::exact::Approx;
using kergen::exact::Expansion;

// orient3d on small integer coordinates is exact in __int128.
int orient_int(const int64_t* a, const int64_t* b, const int64_t* c, const int64_t* p) {
  __int128 u[3], v[3], w[3];
  for (int k = 0; k < 3; ++k) { u[k] = b[k] - a[k]; v[k] = c[k] - a[k]; w[k] = p[k] - a[k]; }
  __int128 d = u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
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
    if (i % 2) for (int k = 0; k < 3; ++k) x[6 + k] = x[k] + x[3 + k] * 0.5 + U(rng) * 1e-12;  // nearly singular
    Approx a[9];
    for (int k = 0; k < 9; ++k) {
      const double e = (i % 3) ? std::fabs(x[k]) * 1e-14 * (1 + k) : 0;  // known entries or uncertain ones
      const double shown = x[k] + (U(rng) * e);                           // any value within +- e
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

TEST(Exact, CollinearIsExact) {
  double a[3] = {0.1, 0.2, 0.3}, b[3] = {0.1 + 1.0, 0.2 + 2.0, 0.3 + 3.0};
  double c[3] = {a[0] + 2 * (b[0] - a[0]), a[1] + 2 * (b[1] - a[1]), a[2] + 2 * (b[2] - a[2])};
  // c is computed in double: collinear only if the arithmetic was exact, which orient decides.
  bool truth = (Expansion::difference(c[0], a[0]) * Expansion::difference(b[1], a[1]) -
                Expansion::difference(c[1], a[1]) * Expansion::difference(b[0], a[0])).sign() == 0 &&
               (Expansion::difference(c[1], a[1]) * Expansion::difference(b[2], a[2]) -
                Expansion::difference(c[2], a[2]) * Expansion::difference(b[1], a[1])).sign() == 0;
  EXPECT_EQ(kergen::collinear(a, b, c), truth);
  double p[3] = {0, 0, 0}, q[3] = {1, 1, 1}, r[3] = {3, 3, 3}, s[3] = {3, 3, 3.0000000000000004};
  EXPECT_TRUE(kergen::collinear(p, q, r));
  EXPECT_FALSE(kergen::collinear(p, q, s));
}

}  // namespace
