// The witness of an empty kernel with boundary walls (OpenBoundary::Perpendicular): the faces of
// Kernel::witness_faces and the walls at Kernel::witness_boundary_edges, each wall rebuilt here
// from its edge and its face as kergen.h describes it (and compared with the library's), have no
// common point (exact Farkas weights, halfspaces_disjoint), and every proper subset has one
// (an exact LP finds it). Shapes: a flat frustum open at the top and bumpy balls with a hole of
// four faces (clipped, their kernels are not empty; walled, the walls leave nothing), and a bowl
// whose faces face its centre (empty only within the clipping box: no witness).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "exact/predicates.h"
#include "fixtures.h"
#include "input/mesh_prep.h"
#include "kergen/kergen.h"
#include "open_surfaces.h"
#include "solve/lp.h"

namespace {

using kergen::KernelType;
using kergen::Mesh;

kergen::Options walls() {
  kergen::Options o;
  o.open_boundary = kergen::OpenBoundary::Perpendicular;
  return o;
}

// The bumpy sphere (fixtures.h) without faces first .. first + 3: an open ball. Its kernel is a
// small region near the centre, which the walls at the hole, leaning with the bumps, may cut off.
Mesh open_bumpy_ball(size_t first) {
  const Mesh sphere = kergen_test::bumpy_sphere(16, 8);
  Mesh m;
  m.positions = sphere.positions;
  for (size_t f = 0; f < sphere.num_faces(); ++f)
    if (f < first || f >= first + 4)
      m.indices.insert(m.indices.end(), sphere.indices.begin() + long(3 * f), sphere.indices.begin() + long(3 * f + 3));
  return m;
}

// The walls' half-spaces and faces' half-spaces of a witness, rebuilt from the input (triangles):
// points in the prepared (scaled) units, one triangle per half-space.
struct Rebuilt {
  std::vector<double> points;
  int shift = 0;
  std::vector<std::array<uint32_t, 3>> triangles;
};

// The wall on boundary edge a -> b (kergen.h, OpenBoundary::Perpendicular): through a, b and
// c = a + n, n the exact normal of the face whose loop runs from a to b, rounded, scaled by a power
// of two to a largest component in [1/32, 1/16), rounded to a multiple of 2^-60 (scaled units).
// False when no face runs a -> b, or one runs b -> a (not a boundary edge).
bool add_wall(const Mesh& m, uint32_t a, uint32_t b, Rebuilt& r) {
  int runs = 0, back = 0;
  size_t face = 0;
  for (size_t f = 0; f < m.num_faces(); ++f)
    for (int e = 0; e < 3; ++e) {
      const uint32_t u = m.indices[3 * f + e], v = m.indices[3 * f + (e + 1) % 3];
      if (u == a && v == b) ++runs, face = f;
      if (u == b && v == a) ++back;
    }
  if (runs != 1 || back != 0) return false;
  const double* P = r.points.data();
  const uint32_t* t = &m.indices[3 * face];
  const auto plane = kergen::exact_plane(P + 3 * t[0], P + 3 * t[1], P + 3 * t[2], r.shift);
  double n[3], largest = 0;
  for (int k = 0; k < 3; ++k) largest = std::max(largest, std::fabs(n[k] = plane.n[k].estimate()));
  int e = 0;
  std::frexp(largest, &e);
  double c[3];
  for (int k = 0; k < 3; ++k)
    c[k] = r.points[3 * a + k] + std::ldexp(std::nearbyint(std::ldexp(n[k], 60 - e - 4)), -60);
  const uint32_t id = uint32_t(r.points.size() / 3);
  r.points.insert(r.points.end(), c, c + 3);
  r.triangles.push_back({a, b, id});
  return true;
}

// Checks the witness of empty kernel `k` of walled triangle mesh `m`; returns the number of walls.
size_t check_wall_witness(const Mesh& m, const kergen::Kernel& k, const std::string& name) {
  EXPECT_EQ(k.type, KernelType::Empty) << name;
  EXPECT_EQ(k.witness_boundary_edges.size() % 2, 0u) << name;
  const size_t faces = k.witness_faces.size(), num_walls = k.witness_boundary_edges.size() / 2;
  EXPECT_GE(faces + num_walls, 2u) << name;
  EXPECT_LE(faces + num_walls, 4u) << name;
  EXPECT_TRUE(std::is_sorted(k.witness_faces.begin(), k.witness_faces.end())) << name;
  kergen::Options o;
  o.allow_open = true;
  const kergen::PreparedMesh pm = kergen::prepare_mesh(m.view(), o);
  EXPECT_EQ(pm.error, kergen::Error::Ok) << name;
  Rebuilt r{pm.points, pm.exact_shift, {}};
  r.points.resize(3 * m.num_vertices());  // (the input's points, scaled exactly)
  for (uint32_t f : k.witness_faces) {
    EXPECT_LT(f, m.num_faces()) << name;
    if (f >= m.num_faces()) return num_walls;
    r.triangles.push_back({m.indices[3 * f], m.indices[3 * f + 1], m.indices[3 * f + 2]});
  }
  // Each wall rebuilt, and found among the library's walls (open_surfaces.h) point for point.
  const auto library_walls = kergen_test::boundary_walls(m);
  for (size_t w = 0; w < num_walls; ++w) {
    const uint32_t a = k.witness_boundary_edges[2 * w], b = k.witness_boundary_edges[2 * w + 1];
    EXPECT_TRUE(add_wall(m, a, b, r)) << name << ": " << a << " -> " << b << " is not a boundary edge as its face runs";
    if (r.triangles.size() != faces + w + 1) return num_walls;
    std::array<std::array<double, 3>, 3> mine;
    for (int c = 0; c < 3; ++c)
      for (int q = 0; q < 3; ++q) mine[c][q] = pm.to_input(r.points[3 * size_t(r.triangles.back()[c]) + q]);
    EXPECT_NE(std::find(library_walls.begin(), library_walls.end(), mine), library_walls.end())
        << name << ": the wall at " << a << " -> " << b << " is not built as kergen.h says";
  }
  // No common point: exact Farkas weights over the rebuilt planes (all needed, says the test too).
  std::vector<kergen::PlaneCoef<kergen::Expansion>> planes;
  for (const auto& t : r.triangles)
    planes.push_back(kergen::exact_plane(&r.points[3 * t[0]], &r.points[3 * t[1]], &r.points[3 * t[2]], r.shift));
  EXPECT_TRUE(kergen::halfspaces_disjoint(planes.data(), planes.size())) << name << ": the witness has a common point";
  // Every proper subset (dropping one) has a common point: the exact LP finds one, within bounds
  // far wider than the mesh (the subset's point may lie far away: the whole set's planes meet at
  // a small angle).
  for (size_t drop = 0; drop < r.triangles.size(); ++drop) {
    kergen::PlaneSet ps(&r.points, r.shift);
    std::vector<uint32_t> ids;
    for (size_t i = 0; i < r.triangles.size(); ++i)
      if (i != drop) ids.push_back(ps.add_from_points(r.triangles[i][0], r.triangles[i][1], r.triangles[i][2]));
    const kergen::LpResult lp = kergen::solve_lp(ps, ids, kergen::kDefaultDirection, 0x1p40, 1);
    EXPECT_NE(lp.outcome, kergen::LpResult::Outcome::Infeasible)
        << name << ": the witness without its half-space " << drop << " is still empty (not minimal)";
  }
  return num_walls;
}

TEST(WallWitness, OpenFrustumNeedsTheBottomAndWalls) {
  const Mesh m = kergen_test::open_frustum();
  kergen::Options clip;
  clip.allow_open = true;
  const kergen::Kernel clipped = kergen::compute_kernel(m.view(), clip);
  ASSERT_TRUE(clipped.ok()) << clipped.message;
  EXPECT_NE(clipped.type, KernelType::Empty);
  const kergen::Kernel walled = kergen::compute_kernel(m.view(), walls());
  ASSERT_TRUE(walled.ok()) << walled.message;
  ASSERT_EQ(walled.type, KernelType::Empty);
  // Walls alone leave room below the bottom, so the bottom's plane is in every witness, named by
  // its first face; two walls of opposite sides at least.
  EXPECT_GE(check_wall_witness(m, walled, "open frustum"), 2u);
  EXPECT_EQ(walled.witness_faces, std::vector<uint32_t>{0});
  for (size_t i = 0; i < walled.witness_boundary_edges.size(); ++i)
    EXPECT_GE(walled.witness_boundary_edges[i], 4u) << "a rim vertex";
  const kergen::KernelPoint p = kergen::find_kernel_point(m.view(), walls());
  ASSERT_EQ(p.error, kergen::Error::Ok) << p.message;
  EXPECT_FALSE(p.star_shaped);
  EXPECT_EQ(p.witness_faces, walled.witness_faces);
  EXPECT_EQ(p.witness_boundary_edges, walled.witness_boundary_edges);
}

// Open balls: wherever the walls make the kernel empty (clipped, it is a polyhedron), the witness
// names them, with faces or alone.
TEST(WallWitness, OpenBumpyBallsEmptiedByTheirWalls) {
  kergen::Options clip;
  clip.allow_open = true;
  size_t emptied = 0, walls_only = 0, with_faces = 0, most_walls = 0;
  for (size_t first = 0; first + 4 < kergen_test::bumpy_sphere(16, 8).num_faces(); first += 7) {
    const Mesh m = open_bumpy_ball(first);
    const kergen::Kernel clipped = kergen::compute_kernel(m.view(), clip);
    const kergen::Kernel walled = kergen::compute_kernel(m.view(), walls());
    ASSERT_TRUE(clipped.ok() && walled.ok()) << first << ": " << clipped.message << walled.message;
    if (clipped.type != KernelType::Polyhedron || walled.type != KernelType::Empty) continue;
    ++emptied;
    const std::string name = "open bumpy ball without faces " + std::to_string(first) + "..";
    const size_t n = check_wall_witness(m, walled, name);
    EXPECT_GE(n, 1u) << name << ": the walls made it empty, so the witness needs one";
    most_walls = std::max(most_walls, n);
    (walled.witness_faces.empty() ? walls_only : with_faces) += 1;
    const kergen::KernelPoint p = kergen::find_kernel_point(m.view(), walls());
    EXPECT_EQ(p.witness_faces, walled.witness_faces) << name;
    EXPECT_EQ(p.witness_boundary_edges, walled.witness_boundary_edges) << name;
  }
  std::printf("%zu open balls emptied by their walls: %zu witnesses of walls only, %zu with faces, up to %zu walls\n",
              emptied, walls_only, with_faces, most_walls);
  EXPECT_GT(emptied, 0u);
}

// A bowl whose faces face its centre: its faces' and walls' half-spaces meet only far below it,
// beyond the box the kernel is clipped to, so the kernel is empty without a witness (an exact LP
// over all of them, rebuilt here, finds their common point).
TEST(WallWitness, BowlFacingItsCentreMeetsOnlyBeyondTheBox) {
  const Mesh m = kergen_test::flipped(kergen_test::bowl(16, 6));
  const kergen::Kernel k = kergen::compute_kernel(m.view(), walls());
  ASSERT_TRUE(k.ok()) << k.message;
  ASSERT_EQ(k.type, KernelType::Empty);
  EXPECT_TRUE(k.witness_faces.empty());
  EXPECT_TRUE(k.witness_boundary_edges.empty());
  kergen::Options o;
  o.allow_open = true;
  const kergen::PreparedMesh pm = kergen::prepare_mesh(m.view(), o);
  Rebuilt r{pm.points, pm.exact_shift, {}};
  size_t num_walls = 0;
  for (size_t f = 0; f < m.num_faces(); ++f) {
    r.triangles.push_back({m.indices[3 * f], m.indices[3 * f + 1], m.indices[3 * f + 2]});
    for (int e = 0; e < 3; ++e) num_walls += add_wall(m, m.indices[3 * f + e], m.indices[3 * f + (e + 1) % 3], r);
  }
  EXPECT_EQ(num_walls, 16u);
  kergen::PlaneSet ps(&r.points, r.shift);
  std::vector<uint32_t> ids;
  for (const auto& t : r.triangles) ids.push_back(ps.add_from_points(t[0], t[1], t[2]));
  const double down[3] = {0, 0, -1};
  const kergen::LpResult lp = kergen::solve_lp(ps, ids, down, 64, 1);
  EXPECT_NE(lp.outcome, kergen::LpResult::Outcome::Infeasible);
}

// Without walls, no wall is named; a closed mesh's witness has none either.
TEST(WallWitness, NoWallsWithoutThem) {
  kergen::Options clip;
  clip.allow_open = true;
  const kergen::Kernel k = kergen::compute_kernel(kergen_test::flipped(kergen_test::bowl(16, 6)).view(), clip);
  ASSERT_TRUE(k.ok());
  EXPECT_TRUE(k.witness_boundary_edges.empty());
  const kergen::Kernel u = kergen::compute_kernel(kergen_test::u_prism().view());
  ASSERT_EQ(u.type, KernelType::Empty);
  EXPECT_FALSE(u.witness_faces.empty());
  EXPECT_TRUE(u.witness_boundary_edges.empty());
}

}  // namespace
