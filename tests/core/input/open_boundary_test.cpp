// Options::open_boundary = OpenBoundary::Perpendicular: the kernel of a surface with a boundary,
// bounded by a wall at each boundary edge. References: the closed solid the walls close a surface
// into (an open cube, a bowl with a vertical lip: exactly), the prism behind a flat patch
// (analytic), and invariants (every kernel vertex behind every face and inside every wall).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "exact/predicates.h"
#include "fixtures.h"
#include "kergen/io.h"
#include "kergen/kergen.h"
#include "open_surfaces.h"

namespace {

using kergen::KernelType;
using kergen::Mesh;
using kergen::OpenBoundary;

kergen::Options perpendicular() {
  kergen::Options o;
  o.open_boundary = OpenBoundary::Perpendicular;
  return o;
}

// How far outside plane (a, b, c) (inside: orient3d <= 0) point p is, 0 when exactly inside or on it.
double outside_by(const std::array<double, 3>& a, const std::array<double, 3>& b, const std::array<double, 3>& c,
                  const double* p) {
  if (kergen::orient3d(a.data(), b.data(), c.data(), p) <= 0) return 0;
  double u[3], v[3], w[3], n[3];
  for (int k = 0; k < 3; ++k) u[k] = b[k] - a[k], v[k] = c[k] - a[k], w[k] = p[k] - a[k];
  n[0] = u[1] * v[2] - u[2] * v[1];
  n[1] = u[2] * v[0] - u[0] * v[2];
  n[2] = u[0] * v[1] - u[1] * v[0];
  return (n[0] * w[0] + n[1] * w[1] + n[2] * w[2]) / std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

// Every kernel vertex lies behind every face (its representative triangle: the first three
// corners) and inside every wall: exactly, or by no more than the rounding of its coordinates.
// Returns the number of walls.
size_t expect_inside_faces_and_walls(const Mesh& m, const kergen::Kernel& k) {
  const auto walls = kergen_test::boundary_walls(m);
  double worst = 0;
  for (size_t v = 0; v < k.num_vertices(); ++v) {
    const double* p = &k.vertices[3 * v];
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
      std::array<std::array<double, 3>, 3> tri;
      for (int c = 0; c < 3; ++c)
        for (int q = 0; q < 3; ++q) tri[c][q] = m.positions[3 * size_t(m.indices[t + c]) + q];
      worst = std::max(worst, outside_by(tri[0], tri[1], tri[2], p));
    }
    for (const auto& w : walls) worst = std::max(worst, outside_by(w[0], w[1], w[2], p));
  }
  EXPECT_LE(worst, 1e-14) << "a kernel vertex lies outside a face or a wall";
  return walls.size();
}

// Each wall holds a boundary edge of `m` and stands within 2e-14 radians of perpendicular to
// that edge's face (kergen.h, OpenBoundary). Returns the number of walls.
size_t expect_walls_perpendicular(const Mesh& m) {
  using V = std::array<long double, 3>;
  auto cross = [](const V& u, const V& v) {
    return V{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  };
  auto sub = [](const std::array<double, 3>& a, const std::array<double, 3>& b) {
    return V{(long double)a[0] - b[0], (long double)a[1] - b[1], (long double)a[2] - b[2]};
  };
  auto corner = [&](uint32_t v) {
    return std::array<double, 3>{m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]};
  };
  const auto walls = kergen_test::boundary_walls(m);
  for (const auto& w : walls) {
    bool found = false;
    for (size_t t = 0; t + 2 < m.indices.size() && !found; t += 3)
      for (int e = 0; e < 3 && !found; ++e) {
        if (corner(m.indices[t + e]) != w[0] || corner(m.indices[t + (e + 1) % 3]) != w[1]) continue;
        found = true;
        const V nf = cross(sub(corner(m.indices[t + 1]), corner(m.indices[t])),
                           sub(corner(m.indices[t + 2]), corner(m.indices[t])));
        const V nw = cross(sub(w[1], w[0]), sub(w[2], w[0]));
        const long double dot = nf[0] * nw[0] + nf[1] * nw[1] + nf[2] * nw[2];
        const long double len = std::sqrt((nf[0] * nf[0] + nf[1] * nf[1] + nf[2] * nf[2]) *
                                          (nw[0] * nw[0] + nw[1] * nw[1] + nw[2] * nw[2]));
        EXPECT_LE(double(std::fabs(dot) / len), 2e-14);
      }
    EXPECT_TRUE(found) << "a wall is not on a boundary edge as its face runs";
  }
  return walls.size();
}

std::vector<std::array<double, 3>> sorted_vertices(const kergen::Kernel& k) {
  std::vector<std::array<double, 3>> v(k.num_vertices());
  for (size_t i = 0; i < v.size(); ++i) v[i] = {k.vertices[3 * i], k.vertices[3 * i + 1], k.vertices[3 * i + 2]};
  std::sort(v.begin(), v.end());
  return v;
}

TEST(OpenBoundary, OpenCubeIsWalledIntoTheCube) {
  const Mesh m = kergen_test::open_cube();
  const kergen::Kernel clipped = kergen::compute_kernel(m.view(), [] {
    kergen::Options o;
    o.allow_open = true;
    return o;
  }());
  ASSERT_TRUE(clipped.ok()) << clipped.message;
  EXPECT_EQ(clipped.type, KernelType::Unbounded);

  const kergen::Kernel k = kergen::compute_kernel(m.view(), perpendicular());
  ASSERT_TRUE(k.ok()) << k.message;
  EXPECT_EQ(k.type, KernelType::Polyhedron);
  EXPECT_NEAR(k.volume, 1.0, 1e-14);
  EXPECT_EQ(sorted_vertices(k), sorted_vertices(kergen::compute_kernel(kergen_test::unit_cube().view())));
  EXPECT_EQ(expect_inside_faces_and_walls(m, k), 4u);  // the four top edges
}

TEST(OpenBoundary, NotNeededForClosedMeshes) {
  const Mesh m = kergen_test::l_prism();
  const kergen::Kernel a = kergen::compute_kernel(m.view()), b = kergen::compute_kernel(m.view(), perpendicular());
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.volume, b.volume);
}

// A bowl with a vertical lip: its rim faces are exactly vertical, so every wall is exactly the
// plane z = 0, and the kernel is exactly that of the bowl closed by a flat lid.
TEST(OpenBoundary, LippedBowlHasTheKernelOfTheClosedBowl) {
  const Mesh open = kergen_test::bowl(24, 8, 0.25), closed = kergen_test::bowl(24, 8, 0.25, true);
  const kergen::Kernel k = kergen::compute_kernel(open.view(), perpendicular());
  const kergen::Kernel ref = kergen::compute_kernel(closed.view());
  ASSERT_TRUE(k.ok()) << k.message;
  ASSERT_TRUE(ref.ok()) << ref.message;
  EXPECT_EQ(k.type, KernelType::Polyhedron);
  EXPECT_EQ(ref.type, KernelType::Polyhedron);
  EXPECT_EQ(sorted_vertices(k), sorted_vertices(ref));
  EXPECT_NEAR(k.volume, ref.volume, 1e-14 * ref.volume);
  EXPECT_EQ(k.num_faces(), ref.num_faces());
  for (const auto& w : kergen_test::boundary_walls(open))
    for (const auto& p : w) EXPECT_EQ(p[2], 0.0);
  EXPECT_EQ(expect_inside_faces_and_walls(open, k), 24u);
  // Without walls the bowl is open upwards.
  kergen::Options clip;
  clip.allow_open = true;
  EXPECT_EQ(kergen::compute_kernel(open.view(), clip).type, KernelType::Unbounded);
}

// A hemisphere bowl: its rim faces lean outwards at the bottom, so their walls rise towards the
// middle: the kernel is bounded, reaches a little above the rim (under the low cone of the
// walls), lies inside the unit ball, and (checked against CGAL in tests/oracle) is the
// intersection of the faces' and walls' half-spaces.
TEST(OpenBoundary, HemisphereBowlIsBounded) {
  const Mesh m = kergen_test::bowl(32, 12);
  const kergen::Kernel k = kergen::compute_kernel(m.view(), perpendicular());
  ASSERT_TRUE(k.ok()) << k.message;
  EXPECT_EQ(k.type, KernelType::Polyhedron);
  double top = -1;
  for (size_t v = 0; v < k.num_vertices(); ++v) {
    const double* p = &k.vertices[3 * v];
    EXPECT_LE(p[0] * p[0] + p[1] * p[1] + p[2] * p[2], 1 + 1e-12);
    top = std::max(top, p[2]);
  }
  // The walls lean by the rim faces' tilt, half a ring's angle (pi / 48): their cone over the
  // rim's circle (inscribed radius cos(pi / 32)) peaks at about tan(pi / 48).
  EXPECT_NEAR(top, std::tan(3.14159265358979323846 / 48), 2e-3);
  EXPECT_EQ(expect_inside_faces_and_walls(m, k), 32u);
  EXPECT_EQ(expect_walls_perpendicular(m), 32u);
}

TEST(OpenBoundary, HillIsBoundedValleyIsNot) {
  const Mesh h = kergen_test::hill(12);
  const kergen::Kernel k = kergen::compute_kernel(h.view(), perpendicular());
  ASSERT_TRUE(k.ok()) << k.message;
  EXPECT_EQ(k.type, KernelType::Polyhedron);
  EXPECT_GT(k.volume, 0);
  EXPECT_EQ(expect_inside_faces_and_walls(h, k), 48u);
  EXPECT_EQ(expect_walls_perpendicular(h), 48u);

  // The valley's walls spread apart below it: every point far enough below is behind every face.
  const Mesh v = kergen_test::valley(12);
  const kergen::Kernel u = kergen::compute_kernel(v.view(), perpendicular());
  ASSERT_TRUE(u.ok()) << u.message;
  EXPECT_EQ(u.type, KernelType::Unbounded);
  expect_inside_faces_and_walls(v, u);
}

// A flat patch: the points behind it and inside its walls are the prism below it, unbounded; the
// result is that prism clipped to the box: the patch's boundary corners (vertices `first` and up)
// at z = 0 and the same corners on the box's bottom.
void expect_prism_below(const Mesh& m, size_t first, double area) {
  const size_t corners = m.num_vertices() - first;
  const kergen::Kernel k = kergen::compute_kernel(m.view(), perpendicular());
  ASSERT_TRUE(k.ok()) << k.message;
  EXPECT_EQ(k.type, KernelType::Unbounded);
  ASSERT_EQ(k.num_vertices(), 2 * corners);
  double bottom = 0;
  for (size_t v = 0; v < k.num_vertices(); ++v) bottom = std::min(bottom, k.vertices[3 * v + 2]);
  EXPECT_LT(bottom, -1);
  for (size_t v = 0; v < k.num_vertices(); ++v) {
    const double* p = &k.vertices[3 * v];
    EXPECT_TRUE(p[2] == 0 || p[2] == bottom) << p[2];
    bool above_a_corner = false;  // the boundary vertex with the same x and y
    for (size_t c = first; c < m.num_vertices(); ++c)
      above_a_corner |= m.positions[3 * c] == p[0] && m.positions[3 * c + 1] == p[1];
    EXPECT_TRUE(above_a_corner) << p[0] << " " << p[1];
  }
  EXPECT_NEAR(k.volume, area * -bottom, 1e-12 * area * -bottom);
  expect_inside_faces_and_walls(m, k);
}

TEST(OpenBoundary, FlatDiscIsThePrismBelowIt) {
  const int n = 16;
  const double area = 0.5 * n * std::sin(2 * 3.14159265358979323846 / n);
  expect_prism_below(kergen_test::disc(n), 1, area);
}

TEST(OpenBoundary, SingleTriangleIsThePrismBelowIt) {
  Mesh t;
  kergen_test::add_point(t, 0, 0, 0);
  kergen_test::add_point(t, 2, 0, 0);
  kergen_test::add_point(t, 0, 1, 0);
  kergen_test::add_face(t, {0, 1, 2});
  expect_prism_below(t, 0, 1.0);
}

// Walls facing the faces' fronts: a bowl turned inside out (faces towards the centre) has its
// kernel outside the sphere, behind the faces, where the walls (now facing outward too) leave
// nothing that is behind every face.
TEST(OpenBoundary, InvertedBowlIsEmpty) {
  const Mesh m = kergen_test::flipped(kergen_test::bowl(16, 6));
  const kergen::Kernel k = kergen::compute_kernel(m.view(), perpendicular());
  ASSERT_TRUE(k.ok()) << k.message;
  EXPECT_EQ(k.type, KernelType::Empty);
}

TEST(OpenBoundary, OpenMeshMessageNamesTheOption) {
  const kergen::Kernel k = kergen::compute_kernel(kergen_test::open_cube().view());
  EXPECT_EQ(k.error, kergen::Error::OpenMesh);
  EXPECT_NE(k.message.find("Options::open_boundary"), std::string::npos) << k.message;
  EXPECT_STREQ(kergen::open_boundary_name(OpenBoundary::Perpendicular), "perpendicular");
  EXPECT_STREQ(kergen::open_boundary_name(OpenBoundary::Clip), "clip");
}

TEST(OpenBoundary, FindKernelPointAgrees) {
  for (const Mesh& m :
       {kergen_test::bowl(16, 6), kergen_test::hill(6), kergen_test::flipped(kergen_test::bowl(16, 6))}) {
    const kergen::Kernel k = kergen::compute_kernel(m.view(), perpendicular());
    const kergen::KernelPoint p = kergen::find_kernel_point(m.view(), perpendicular());
    ASSERT_TRUE(k.ok() && p.error == kergen::Error::Ok);
    EXPECT_EQ(p.star_shaped, k.type != KernelType::Empty);
  }
}

}  // namespace

namespace {

// Powers of two scale every step exactly (the mesh is scaled to below 1 first): the walls, and so
// the kernel's vertices, scale bit for bit, down to 2^-900 and up to 2^900.
TEST(OpenBoundary, PowerOfTwoScalesGiveTheSameKernelScaled) {
  const Mesh base = kergen_test::hill(6);
  const kergen::Kernel k = kergen::compute_kernel(base.view(), perpendicular());
  ASSERT_TRUE(k.ok()) << k.message;
  for (int e : {-900, -40, 40, 900}) {
    Mesh m = base;
    for (double& x : m.positions) x = std::ldexp(x, e);
    const kergen::Kernel s = kergen::compute_kernel(m.view(), perpendicular());
    ASSERT_TRUE(s.ok()) << e << ": " << s.message;
    EXPECT_EQ(s.type, k.type) << e;
    auto scaled = sorted_vertices(k);
    for (auto& v : scaled)
      for (double& x : v) x = std::ldexp(x, e);
    EXPECT_EQ(sorted_vertices(s), scaled) << e;
  }
}

// Moved far from the origin (1e6, where the coordinates keep ~1e-10 of the hill's size), the hill's
// kernel keeps its volume to the rounding of the moved coordinates.
TEST(OpenBoundary, TranslationKeepsTheKernel) {
  const Mesh base = kergen_test::hill(6);
  const kergen::Kernel k = kergen::compute_kernel(base.view(), perpendicular());
  const kergen::Kernel t =
      kergen::compute_kernel(kergen_test::transformed(base, 1, 1e6, -1e6, 1e6).view(), perpendicular());
  ASSERT_TRUE(k.ok() && t.ok()) << t.message;
  EXPECT_EQ(t.type, KernelType::Polyhedron);
  EXPECT_NEAR(t.volume, k.volume, 1e-6 * k.volume);
}

}  // namespace
