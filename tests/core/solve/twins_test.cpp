// Scalar and vectorized twins that must decide alike (architecture: where two versions of one
// test exist for speed, a test proves they agree): the cube-map cell of a normal (cube_cell for
// the cuts, cube_position for culling's vectorized passes), the tight sets the tracer's
// vectorized certification (certify_over) recorded against certify_vertex's scalar pass, and
// the support test's scalar may_reach against its batched may_reach_all on one cube map.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "fixtures.h"
#include "input/mesh_prep.h"
#include "planes/plane_classes.h"
#include "solve/climb.h"
#include "solve/lp.h"
#include "solve/plane_culling.h"
#include "solve/tracer.h"

namespace {

using namespace kergen;

TEST(Twins, CubePositionGivesCubeCellsCell) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> N(0, 1);
  const double inf = std::numeric_limits<double>::infinity(), nan = std::nan("");
  std::vector<double> special = {0.0,    -0.0,    1.0,      -1.0,        0.5,      -0.5,
                                 1e-300, -1e-300, 4.9e-324, 1e300,       -1e300,   std::numeric_limits<double>::max(),
                                 inf,    -inf,    nan,      1.0 + 1e-16, 1 - 1e-16};
  std::vector<std::array<double, 3>> normals;
  for (double a : special)
    for (double b : special)
      for (double c : special) normals.push_back({a, b, c});
  for (int i = 0; i < 200000; ++i) {
    std::array<double, 3> n = {N(rng), N(rng), N(rng)};
    if (i % 4 == 1) n[1] = n[0];  // ties between axes
    if (i % 4 == 2) n[2] = -n[0];
    if (i % 8 == 3) n[rng() % 3] *= 1e-200;
    normals.push_back(n);
  }
  size_t usable_normals = 0;
  for (int k : {1, 2, 3, 7, 24}) {
    for (const auto& n : normals) {
      const size_t cell = cube_cell(size_t(k), n[0], n[1], n[2]);
      const CubePosition q = cube_position(k, n[0], n[1], n[2]);
      const bool finite = std::isfinite(n[0]) && std::isfinite(n[1]) && std::isfinite(n[2]);
      if (!usable(q.m)) {
        // (cube_cell ignores a NaN beside a finite maximum; culling never meets one: it is
        // refused as non-finite input long before.)
        if (finite) EXPECT_EQ(cell, kNoCell) << n[0] << " " << n[1] << " " << n[2];
        continue;
      }
      if (!finite) continue;
      ++usable_normals;
      ASSERT_EQ(size_t(q.cell), cell) << k << ": " << n[0] << " " << n[1] << " " << n[2];
      ASSERT_LT(size_t(q.corner), size_t(6 * (k + 1) * (k + 1)));
    }
  }
  EXPECT_GT(usable_normals, 900000u);
}

// The tracer certifies each vertex with its vectorized scan over structure-of-arrays planes;
// certify_vertex, one scalar pass over the plane store, must find the same tight set.
TEST(Twins, TracerTightSetsEqualCertifyVertex) {
  size_t vertices = 0;
  for (const Mesh& m : {kergen_test::dented_cube(), kergen_test::bumpy_sphere(24, 12, 0.05), kergen_test::l_prism(),
                        kergen_test::random_convex(3, 300).mesh, kergen_test::tessellated_cube(6)}) {
    const PreparedMesh mesh = prepare_mesh(m.view(), Options{});
    ASSERT_EQ(mesh.error, Error::Ok) << mesh.message;
    PlaneSet ps(&mesh.points, mesh.exact_shift);
    std::vector<uint32_t> face_plane, planes;
    build_planes(mesh, ps, face_plane);
    for (uint32_t i = 0; i < ps.size(); ++i) planes.push_back(i);
    const double dir[3] = {0.3, -0.5, 0.8};
    const LpResult lp = solve_lp(ps, planes, dir, kLpBound, 1);
    ASSERT_EQ(lp.outcome, LpResult::Outcome::Optimal);
    const TraceResult tr = trace_kernel_edges(ps, planes, lp.vertex, TraceOptions());
    ASSERT_FALSE(tr.internal_error);
    for (const TracedVertex& v : tr.vertices) {
      std::vector<uint32_t> tight;
      ASSERT_EQ(certify_vertex(ps, planes, v.geom, std::vector<char>(), tight), kNoPlane);
      ASSERT_TRUE(std::equal(tight.begin(), tight.end(), v.tight.begin(), v.tight.end()));
      ++vertices;
    }
  }
  EXPECT_GT(vertices, 100u);
}

// On one SupportTest (one cube map), may_reach_all keeps every plane may_reach keeps, and the
// same planes where both climb (a sample kernel above the scan limit of 128 vertices); below it
// the batched test scans every vertex, which keeps what the climb keeps and possibly more.
TEST(Twins, MayReachAllAgreesWithMayReach) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> N(0, 1);
  size_t compared = 0, climbed = 0;
  for (const Mesh& m : {kergen_test::random_convex(1, 60).mesh, kergen_test::random_convex(2, 2000).mesh,
                        kergen_test::bumpy_sphere(40, 20, 0.05)}) {
    const PreparedMesh mesh = prepare_mesh(m.view(), Options{});
    ASSERT_EQ(mesh.error, Error::Ok);
    PlaneSet ps(&mesh.points, mesh.exact_shift);
    std::vector<uint32_t> face_plane, planes;
    build_planes(mesh, ps, face_plane);
    for (uint32_t i = 0; i < ps.size(); ++i) planes.push_back(i);
    const double dir[3] = {0.2, 0.7, -0.4};
    const LpResult lp = solve_lp(ps, planes, dir, kLpBound, 1);
    ASSERT_EQ(lp.outcome, LpResult::Outcome::Optimal);
    const TraceResult k = trace_kernel_edges(ps, planes, lp.vertex, TraceOptions());
    ASSERT_FALSE(k.internal_error);
    std::vector<double> nx, ny, nz, d, enx, eny, enz, ed;
    for (int i = 0; i < 3000; ++i) {
      // Planes through points near kernel vertices (a hair either side) and random ones.
      const auto& v = k.vertices[rng() % k.vertices.size()].geom;
      const double a = N(rng), b = N(rng), c = N(rng);
      const double off = i % 2 ? std::pow(10.0, -16.0 + double(rng() % 14)) * (rng() % 2 ? 1 : -1) : 0.3 * N(rng);
      nx.push_back(a);
      ny.push_back(b);
      nz.push_back(c);
      d.push_back(-(a * v.x[0].v + b * v.x[1].v + c * v.x[2].v) + off);
      enx.push_back(0);
      eny.push_back(0);
      enz.push_back(0);
      ed.push_back(0);
    }
    const PlaneArrays arrays{nx.data(), ny.data(), nz.data(), d.data(), enx.data(), eny.data(), enz.data(), ed.data()};
    const SupportTest test(k, nx.size(), true);
    SupportTest::Scratch scratch;
    std::vector<char> all(nx.size());
    test.may_reach_all(arrays, nx.size(), scratch, all.data());
    const bool climbs = k.vertices.size() > 128;
    climbed += climbs;
    for (size_t i = 0; i < nx.size(); ++i) {
      PlaneCoef<Approx> p{{Approx(nx[i], 0), Approx(ny[i], 0), Approx(nz[i], 0)}, Approx(d[i], 0)};
      uint32_t hint = 0;
      const bool one = test.may_reach(p, scratch, hint);
      if (one) ASSERT_TRUE(all[i]) << "plane " << i;
      if (climbs) ASSERT_EQ(bool(all[i]), one) << "plane " << i;
      ++compared;
    }
  }
  EXPECT_EQ(compared, 9000u);
  EXPECT_GE(climbed, 1u);
}

}  // namespace
