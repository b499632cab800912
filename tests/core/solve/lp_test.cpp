// Seidel LP: the optimum in random directions equals the best vertex of the traced kernel,
// and infeasibility matches an empty kernel. The double-precision guess that orders its
// constraints (lp_hint): on well-conditioned input its planes are the exact optimum's (each
// passes through the vertex the exact LP returns), and its conflicts are real conflicts (the
// exact LP on those planes alone is infeasible); its misses cost time, never answers.
#include "solve/lp.h"

#include <gtest/gtest.h>

#include <random>

#include "fixtures.h"
#include "input/mesh_prep.h"
#include "planes/plane_classes.h"
#include "solve/lp_hint.h"

namespace {

using namespace kergen;

struct Planes {
  PreparedMesh mesh;
  std::unique_ptr<PlaneSet> ps;
  std::vector<uint32_t> all;
  explicit Planes(const Mesh& m) {
    mesh = prepare_mesh(m.view(), Options{});
    EXPECT_EQ(mesh.error, Error::Ok) << mesh.message;
    ps = std::make_unique<PlaneSet>(&mesh.points);
    std::vector<uint32_t> fp;
    build_planes(mesh, *ps, fp);
    for (uint32_t i = 0; i < ps->size(); ++i) all.push_back(i);
  }
};

TEST(Lp, RandomDirectionsHitTheExtremeKernelVertex) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> N(0, 1);
  for (const Mesh& m : {kergen_test::dented_cube(), kergen_test::plus_prism(0.3), kergen_test::l_prism(),
                        kergen_test::random_convex(9).mesh, kergen_test::pyramid(40)}) {
    Kernel k = compute_kernel(m.view());
    ASSERT_EQ(k.type, KernelType::Polyhedron);
    Planes p(m);
    for (int i = 0; i < 40; ++i) {
      double c[3] = {N(rng), N(rng), N(rng)};
      if (i < 6) {
        c[0] = c[1] = c[2] = 0;
        c[i / 2] = i % 2 ? 1 : -1;
      }  // axis directions: ties
      LpResult r = solve_lp(*p.ps, p.all, c, 8, uint64_t(i));
      ASSERT_EQ(r.outcome, LpResult::Outcome::Optimal);
      double best = -INFINITY;
      for (size_t v = 0; v < k.num_vertices(); ++v)
        best = std::max(best, c[0] * k.vertices[3 * v] + c[1] * k.vertices[3 * v + 1] + c[2] * k.vertices[3 * v + 2]);
      double got = 0;
      for (int j = 0; j < 3; ++j) got += c[j] * p.mesh.to_input(r.vertex.x[j].v);
      EXPECT_NEAR(got, best, 1e-12 * (1 + std::fabs(best)));
    }
  }
}

TEST(Lp, ResultDoesNotDependOnTheOrder) {
  Planes p(kergen_test::dented_cube());
  double c[3] = {0.3, -0.2, 0.9};
  LpResult a = solve_lp(*p.ps, p.all, c, 8, 1), b = solve_lp(*p.ps, p.all, c, 8, 99);
  for (int j = 0; j < 3; ++j) EXPECT_EQ(a.vertex.x[j].v, b.vertex.x[j].v);
}

TEST(Lp, InfeasibleWhenNotStarShaped) {
  Planes p(kergen_test::u_prism());
  double c[3] = {1, 1, 1};
  for (uint64_t seed = 0; seed < 10; ++seed)
    EXPECT_EQ(solve_lp(*p.ps, p.all, c, 8, seed).outcome, LpResult::Outcome::Infeasible);
}

// The conflict of an infeasible LP: two to four face planes, proven disjoint and each needed by
// exact Farkas weights. The U's inner walls (x <= 1 inside the left prong, x >= 2 inside the
// right one) are the only pair of planes with no common point, whatever the order; so on the
// U prism every conflict is that pair.
TEST(Lp, ConflictIsAMinimalDisjointSet) {
  const Mesh shapes[] = {kergen_test::u_prism(), kergen_test::torus(), kergen_test::s_prism(),
                         kergen_test::pinwheel_prism()};
  double c[3] = {1, 1, 1};
  int conflicts = 0;
  for (const Mesh& m : shapes) {
    Planes p(m);
    for (uint64_t seed = 0; seed < 10; ++seed) {
      const LpResult r = solve_lp(*p.ps, p.all, c, 8, seed);
      if (r.outcome != LpResult::Outcome::Infeasible) continue;
      ASSERT_GE(r.conflict.size(), 2u);
      ASSERT_LE(r.conflict.size(), 4u);
      std::vector<PlaneCoef<Expansion>> planes;
      for (const auto& t : r.conflict)
        planes.push_back(exact_plane(p.mesh.point(t[0]), p.mesh.point(t[1]), p.mesh.point(t[2]), p.mesh.exact_shift));
      EXPECT_TRUE(halfspaces_disjoint(planes.data(), planes.size())) << "seed " << seed;
      if (&m == &shapes[0]) {
        ASSERT_EQ(r.conflict.size(), 2u);
        for (const auto& t : r.conflict) {  // both walls are vertical planes at x = 1 or x = 2
          const double x = p.mesh.to_input(p.mesh.point(t[0])[0]);
          EXPECT_TRUE(x == 1 || x == 2);
          for (int k = 1; k < 3; ++k) EXPECT_EQ(p.mesh.point(t[k])[0], p.mesh.point(t[0])[0]);
        }
      }
      ++conflicts;
    }
  }
  EXPECT_GE(conflicts, 20);
}

TEST(LpHint, PlanesOfTheGuessPassThroughTheExactOptimum) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> N(0, 1);
  int guesses = 0;
  for (uint32_t seed = 0; seed < 12; ++seed) {
    Planes p(kergen_test::random_convex(seed, 40).mesh);
    for (int i = 0; i < 20; ++i) {
      const double c[3] = {N(rng), N(rng), N(rng)};
      const LpResult exact = solve_lp(*p.ps, p.all, c, 8, uint64_t(i));
      ASSERT_EQ(exact.outcome, LpResult::Outcome::Optimal);
      const LpHint hint = float_lp_hint(*p.ps, p.all.data(), p.all.size(), c, 8);
      EXPECT_FALSE(hint.infeasible);
      // A generic direction on a random polytope: a simple vertex, three planes.
      ASSERT_EQ(hint.count, 3) << "seed " << seed << " direction " << i;
      for (int k = 0; k < hint.count; ++k) {
        ASSERT_LT(hint.position[k], p.all.size());
        EXPECT_EQ(side(*p.ps, p.all[hint.position[k]], exact.vertex), 0) << "seed " << seed << " direction " << i;
      }
      ++guesses;
    }
  }
  EXPECT_EQ(guesses, 240);
}

TEST(LpHint, ConflictIsInfeasibleOnItsOwn) {
  for (const Mesh& m : {kergen_test::u_prism(), kergen_test::torus()}) {
    Planes p(m);
    const double c[3] = {1, 1, 1};
    ASSERT_EQ(solve_lp(*p.ps, p.all, c, 8, 3).outcome, LpResult::Outcome::Infeasible);
    const LpHint hint = float_lp_hint(*p.ps, p.all.data(), p.all.size(), c, 8);
    ASSERT_TRUE(hint.infeasible);
    ASSERT_GE(hint.count, 2);
    ASSERT_LE(hint.count, 4);
    std::vector<uint32_t> conflict;
    for (int k = 0; k < hint.count; ++k) conflict.push_back(p.all[hint.position[k]]);
    EXPECT_EQ(solve_lp(*p.ps, conflict, c, 8, 1).outcome, LpResult::Outcome::Infeasible);
  }
}

TEST(LpHint, UnusablePlanesGiveNoGuess) {
  std::vector<double> no_points;
  PlaneSet ps(&no_points);
  std::vector<uint32_t> ids = {ps.add_explicit(1, 0, 0, -1), ps.add_explicit(0, 0, 0, 1), ps.add_explicit(0, 1, 0, -1)};
  const double c[3] = {1, 1, 1};
  LpHint hint = float_lp_hint(ps, ids.data(), ids.size(), c, 8);
  EXPECT_EQ(hint.count, 0);
  EXPECT_FALSE(hint.infeasible);
  ids = {ps.add_explicit(1, 0, 0, std::nan("")), ps.add_explicit(HUGE_VAL, 0, 0, 0)};
  hint = float_lp_hint(ps, ids.data(), ids.size(), c, 8);
  EXPECT_EQ(hint.count, 0);
}

TEST(LpHint, ParallelAndRepeatedPlanes) {
  // x <= 1 three times, y <= 1, z <= 1, and x >= 2 parallel to them: infeasible, and the guess
  // names a pair of parallel planes that conflict.
  std::vector<double> no_points;
  PlaneSet ps(&no_points);
  std::vector<uint32_t> ids;
  for (int k = 0; k < 3; ++k) ids.push_back(ps.add_explicit(1, 0, 0, -1));
  ids.push_back(ps.add_explicit(0, 1, 0, -1));
  ids.push_back(ps.add_explicit(0, 0, 1, -1));
  const double c[3] = {1, 0.5, 0.25};
  LpHint hint = float_lp_hint(ps, ids.data(), ids.size(), c, 8);
  ASSERT_FALSE(hint.infeasible);
  ASSERT_EQ(hint.count, 3);
  // The optimum (1, 1, 1): one of the three copies of x <= 1, y <= 1 and z <= 1.
  int x_planes = 0;
  for (int k = 0; k < 3; ++k) x_planes += hint.position[k] < 3;
  EXPECT_EQ(x_planes, 1);
  ids.push_back(ps.add_explicit(-1, 0, 0, 2));
  hint = float_lp_hint(ps, ids.data(), ids.size(), c, 8);
  ASSERT_TRUE(hint.infeasible);
  bool has_far_side = false;
  for (int k = 0; k < hint.count; ++k) has_far_side |= hint.position[k] == 5;
  EXPECT_TRUE(has_far_side);
  std::vector<uint32_t> conflict;
  for (int k = 0; k < hint.count; ++k) conflict.push_back(ids[hint.position[k]]);
  EXPECT_EQ(solve_lp(ps, conflict, c, 8, 1).outcome, LpResult::Outcome::Infeasible);
}

}  // namespace
