// Seidel LP: the optimum in random directions equals the best vertex of the traced kernel,
// and infeasibility matches an empty kernel.
#include <gtest/gtest.h>

#include <random>

#include "fixtures.h"
#include "lp.h"
#include "mesh_prep.h"
#include "plane_classes.h"

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
      if (i < 6) { c[0] = c[1] = c[2] = 0; c[i / 2] = i % 2 ? 1 : -1; }  // axis directions: ties
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

}  // namespace
