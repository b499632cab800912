// The support test of face culling must never drop a plane that touches the sample kernel K_S:
// every plane some vertex of K_S lies on or outside (decided exactly by side()) must be kept by
// the scalar test (may_reach, with its climb) and by the batched one (may_reach_all, with its
// vectorized passes and, on a small K_S, the scan of every vertex). Planes a hair away from a
// vertex on either side, the mesh's own planes and random planes; the tests must also drop most
// of the planes that hold K_S strictly (a test that keeps everything is sound but useless).
#include "solve/plane_culling.h"

#include <gtest/gtest.h>

#include <random>

#include "fixtures.h"
#include "input/mesh_prep.h"
#include "planes/plane_classes.h"
#include "solve/lp.h"
#include "solve/tracer.h"

namespace {

using namespace kergen;

struct Tally {
  size_t planes = 0, touching = 0, dropped_scalar = 0, dropped_batched = 0;
  size_t largest_sample_kernel = 0, smallest_sample_kernel = SIZE_MAX;  // vertices
};

// K_S: the kernel of a random third of the mesh planes (with the LP vertex's planes and a box).
void check_support_test(const Mesh& m, const char* name, uint64_t seed, Tally& t) {
  SCOPED_TRACE(name);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> N(0, 1);
  const PreparedMesh mesh = prepare_mesh(m.view(), Options{});
  ASSERT_EQ(mesh.error, Error::Ok) << mesh.message;
  PlaneSet ps(&mesh.points, mesh.exact_shift);
  std::vector<uint32_t> face_plane, mesh_planes, box;
  build_planes(mesh, ps, face_plane);
  for (uint32_t i = 0; i < ps.size(); ++i) mesh_planes.push_back(i);
  for (int k = 0; k < 3; ++k)
    for (double s : {-1.0, 1.0}) {
      double n[3] = {0, 0, 0};
      n[k] = s;
      box.push_back(ps.add_explicit(n[0], n[1], n[2], -2));
    }
  const double dir[3] = {N(rng), N(rng), N(rng)};
  const LpResult lp = solve_lp(ps, mesh_planes, dir, 8, seed);
  ASSERT_EQ(lp.outcome, LpResult::Outcome::Optimal);
  std::vector<uint32_t> all = mesh_planes, tight;
  all.insert(all.end(), box.begin(), box.end());
  ASSERT_EQ(certify_vertex(ps, all, lp.vertex, std::vector<char>(), tight), kNoPlane);
  std::vector<char> in_s(ps.size(), 0);
  for (uint32_t l : tight) in_s[l] = 1;
  for (uint32_t l : box) in_s[l] = 1;
  for (uint32_t l : mesh_planes)
    if (rng() % 3 == 0) in_s[l] = 1;
  std::vector<uint32_t> S;
  for (uint32_t l = 0; l < ps.size(); ++l)
    if (in_s[l]) S.push_back(l);
  const TraceResult ks = trace_kernel_edges(ps, S, lp.vertex, TraceOptions());
  ASSERT_FALSE(ks.internal_error);
  ASSERT_TRUE(ks.complete);
  ASSERT_GE(ks.vertices.size(), 4u);
  t.largest_sample_kernel = std::max(t.largest_sample_kernel, ks.vertices.size());
  t.smallest_sample_kernel = std::min(t.smallest_sample_kernel, ks.vertices.size());

  // The planes tested: the mesh planes outside S, then explicit planes through points a hair
  // from vertices of K_S (both sides, relative offsets 1e-15 .. 1e-6) and random ones.
  std::vector<uint32_t> tested;
  for (uint32_t l : mesh_planes)
    if (!in_s[l]) tested.push_back(l);
  for (int i = 0; i < 400; ++i) {
    const auto& v = ks.vertices[rng() % ks.vertices.size()].geom;
    double n[3] = {N(rng), N(rng), N(rng)};
    const double sign = rng() % 2 ? 1 : -1;  // (one draw per statement: the same numbers under every compiler)
    const double offset = sign * std::pow(10.0, -15.0 + double(rng() % 10));
    const double d = -(n[0] * v.x[0].v + n[1] * v.x[1].v + n[2] * v.x[2].v) + offset;
    tested.push_back(ps.add_explicit(n[0], n[1], n[2], d));
  }
  for (int i = 0; i < 200; ++i) {
    const double a = N(rng), b = N(rng), c = N(rng), d = 0.5 * N(rng);
    tested.push_back(ps.add_explicit(a, b, c, d));
  }

  std::vector<double> nx, ny, nz, d, enx, eny, enz, ed;
  for (uint32_t l : tested) {
    const PlaneCoef<Approx> c = ps.approx(l);
    nx.push_back(c.n[0].v);
    ny.push_back(c.n[1].v);
    nz.push_back(c.n[2].v);
    d.push_back(c.d.v);
    enx.push_back(c.n[0].e);
    eny.push_back(c.n[1].e);
    enz.push_back(c.n[2].e);
    ed.push_back(c.d.e);
  }
  const PlaneArrays arrays{nx.data(), ny.data(), nz.data(), d.data(), enx.data(), eny.data(), enz.data(), ed.data()};
  const SupportTest scalar(ks, tested.size()), batched(ks, tested.size(), true);
  SupportTest::Scratch scratch;
  std::vector<char> reaching(tested.size());
  batched.may_reach_all(arrays, tested.size(), scratch, reaching.data());
  for (size_t i = 0; i < tested.size(); ++i) {
    const uint32_t l = tested[i];
    bool touches = false;
    for (const auto& v : ks.vertices) touches |= side(ps, l, v.geom) >= 0;
    uint32_t hint = 0;
    const bool kept = scalar.may_reach(ps.approx(l), scratch, hint);
    ++t.planes;
    t.touching += touches;
    t.dropped_scalar += !kept;
    t.dropped_batched += !reaching[i];
    if (touches) {
      ASSERT_TRUE(kept) << "may_reach dropped plane " << l << ", which touches K_S";
      ASSERT_TRUE(reaching[i]) << "may_reach_all dropped plane " << l << ", which touches K_S";
    }
  }
}

TEST(Culling, SupportTestsNeverDropAPlaneTouchingTheSampleKernel) {
  Tally t;
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    check_support_test(kergen_test::bumpy_sphere(24, 12, 0.15), "bumpy_sphere", seed, t);
    check_support_test(kergen_test::uv_sphere(20, 10, 0.3), "twisted uv_sphere", seed, t);
    check_support_test(kergen_test::random_convex(uint32_t(seed), 60).mesh, "random_convex", seed, t);
    check_support_test(kergen_test::dented_cube(), "dented_cube", seed, t);
    check_support_test(kergen_test::random_convex(uint32_t(seed), 600).mesh, "large random_convex", seed, t);
  }
  // Both paths of the batched test: the scan of every vertex (small K_S) and the climb.
  std::printf("sample kernels of %zu to %zu vertices\n", t.smallest_sample_kernel, t.largest_sample_kernel);
  EXPECT_LE(t.smallest_sample_kernel, 128u);
  EXPECT_GT(t.largest_sample_kernel, 128u);
  std::printf("%zu planes, %zu touching K_S; dropped: %zu by may_reach, %zu by may_reach_all\n", t.planes, t.touching,
              t.dropped_scalar, t.dropped_batched);
  EXPECT_GT(t.touching, 0u);
  // Most planes that hold K_S strictly are dropped (the rest come within the margins).
  EXPECT_GT(t.dropped_scalar, (t.planes - t.touching) / 2);
  EXPECT_GT(t.dropped_batched, (t.planes - t.touching) / 2);
}

}  // namespace
