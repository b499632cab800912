// The kernel of an open surface with boundary walls (Options::open_boundary = Perpendicular)
// against CGAL: the oracle gets the same half-spaces, the surface's faces and the walls the
// library builds (their exact input points), as triangles taken as half-spaces only
// (OracleOptions::half_spaces_only). The walls' construction itself is checked in
// tests/core/open_boundary_test.cpp (perpendicular within 2e-14 radians, exactly z = 0 for a
// lipped bowl).
#include <gtest/gtest.h>

#include <cmath>

#include "cgal_oracle.h"
#include "fixtures.h"
#include "kergen/kergen.h"
#include "open_surfaces.h"

namespace {

using kergen::Mesh;

Mesh faces_and_walls(const Mesh& m) {
  Mesh soup = m;
  for (const auto& w : kergen_test::boundary_walls(m)) {
    uint32_t ids[3];
    for (int c = 0; c < 3; ++c) ids[c] = kergen_test::add_point(soup, w[c][0], w[c][1], w[c][2]);
    kergen_test::add_face(soup, {ids[0], ids[1], ids[2]});
  }
  return soup;
}

void expect_oracle_agrees(const Mesh& m, const char* name) {
  kergen::Options o;
  o.open_boundary = kergen::OpenBoundary::Perpendicular;
  const kergen::Kernel k = kergen::compute_kernel(m.view(), o);
  ASSERT_TRUE(k.ok()) << name << ": " << k.message;
  ASSERT_EQ(k.type, kergen::KernelType::Polyhedron) << name;
  kergen_oracle::OracleOptions half_spaces;
  half_spaces.half_spaces_only = true;
  const kergen_oracle::OracleResult r = kergen_oracle::oracle_kernel(faces_and_walls(m), half_spaces);
  ASSERT_TRUE(r.ok) << name << ": " << r.message;
  EXPECT_FALSE(r.flipped) << name;
  ASSERT_EQ(r.verdict, kergen_oracle::Verdict::Full) << name;
  EXPECT_EQ(r.vertices, k.num_vertices()) << name;
  EXPECT_EQ(r.facets, k.num_faces()) << name;
  EXPECT_NEAR(k.volume, r.volume, 1e-12 * r.volume) << name;
  std::printf("%s: kergen V %zu F %zu volume %.15g; CGAL V %zu F %zu volume %.15g\n", name, k.num_vertices(),
              k.num_faces(), k.volume, r.vertices, r.facets, r.volume);
}

TEST(OracleOpenBoundary, HemisphereBowl) { expect_oracle_agrees(kergen_test::bowl(32, 12), "bowl 32x12"); }
TEST(OracleOpenBoundary, LippedBowl) { expect_oracle_agrees(kergen_test::bowl(24, 8, 0.25), "lipped bowl 24x8"); }
TEST(OracleOpenBoundary, Hill) { expect_oracle_agrees(kergen_test::hill(12), "hill 12x12"); }
TEST(OracleOpenBoundary, OpenCube) { expect_oracle_agrees(kergen_test::open_cube(), "open cube"); }

}  // namespace
