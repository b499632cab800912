// The small-input path (core/src/small): the clipping itself on planes with known answers
// (cubes, a pyramid's four-plane apex, planes touching a vertex, through an edge, disjoint and
// opposite half-spaces), and compute_kernel's answer on it against the general path's (plane
// culling and tracing), field by field, on analytic meshes and on every small shared input.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "exact/plane_store.h"
#include "exact/vertex.h"
#include "fixtures.h"
#include "kergen/io.h"
#include "kergen/kergen.h"
#include "small/clip_polytope.h"
#include "small/extreme_vertex.h"
#include "small/kernel_path.h"
#include "small/small_kernel.h"

namespace {

using kergen::Kernel;
using kergen::KernelPath;
using kergen::Mesh;

// Explicit planes n . x + d <= 0 in a plane set of their own, clipped from the box.
struct Clipped {
  std::vector<double> no_points;
  kergen::PlaneSet ps{&no_points};
  std::vector<uint32_t> box, planes;
  kergen::ClipPolytope clip;
  kergen::TraceResult tr;
  bool ok = false;

  explicit Clipped(const std::vector<std::array<double, 4>>& halfspaces) {
    for (const auto& h : halfspaces) planes.push_back(ps.add_explicit(h[0], h[1], h[2], h[3]));
    kergen::add_bounding_box(ps, box);
    ok = kergen::small_kernel_trace(ps, planes, box, clip, tr);
  }
  size_t tight_count(double x, double y, double z) const {
    for (const auto& v : tr.vertices) {
      double hi[3], lo[3];
      kergen::precise_coordinates(ps, v.geom, hi, lo);
      if (hi[0] == x && hi[1] == y && hi[2] == z) return v.tight.size();
    }
    return 0;
  }
};

// The unit cube's six half-spaces.
std::vector<std::array<double, 4>> unit_cube_planes() {
  return {{-1, 0, 0, 0}, {1, 0, 0, -1}, {0, -1, 0, 0}, {0, 1, 0, -1}, {0, 0, -1, 0}, {0, 0, 1, -1}};
}

TEST(SmallClip, UnitCube) {
  const Clipped c(unit_cube_planes());
  ASSERT_TRUE(c.ok);
  EXPECT_EQ(c.tr.vertices.size(), 8u);
  EXPECT_EQ(c.tr.edges.size(), 12u);
  for (double x : {0.0, 1.0})
    for (double y : {0.0, 1.0})
      for (double z : {0.0, 1.0}) EXPECT_EQ(c.tight_count(x, y, z), 3u) << x << " " << y << " " << z;
  for (const auto& e : c.tr.edges) EXPECT_EQ(e.planes.size(), 2u);
}

// A square pyramid: its apex lies on four planes (a degenerate vertex), each base corner on three.
TEST(SmallClip, PyramidApexOnFourPlanes) {
  const Clipped c({{0, 0, -1, 0}, {1, 0, 1, -1}, {-1, 0, 1, -1}, {0, 1, 1, -1}, {0, -1, 1, -1}});
  ASSERT_TRUE(c.ok);
  EXPECT_EQ(c.tr.vertices.size(), 5u);
  EXPECT_EQ(c.tr.edges.size(), 8u);
  EXPECT_EQ(c.tight_count(0, 0, 1), 4u);
  EXPECT_EQ(c.tight_count(1, 1, 0), 3u);
  EXPECT_EQ(c.tight_count(-1, 1, 0), 3u);
}

// A plane touching one corner changes nothing but that corner's tight set.
TEST(SmallClip, PlaneTouchingAVertex) {
  auto planes = unit_cube_planes();
  planes.push_back({1, 1, 1, -3});
  const Clipped c(planes);
  ASSERT_TRUE(c.ok);
  EXPECT_EQ(c.tr.vertices.size(), 8u);
  EXPECT_EQ(c.tr.edges.size(), 12u);
  EXPECT_EQ(c.tight_count(1, 1, 1), 4u);
}

// A plane through two opposite edges (x <= y) halves the cube into a triangular prism; the
// vertices on it keep their edges, and the new face joins them.
TEST(SmallClip, PlaneThroughEdges) {
  auto planes = unit_cube_planes();
  planes.push_back({1, -1, 0, 0});
  const Clipped c(planes);
  ASSERT_TRUE(c.ok);
  EXPECT_EQ(c.tr.vertices.size(), 6u);
  EXPECT_EQ(c.tr.edges.size(), 9u);
  EXPECT_EQ(c.tight_count(0, 0, 0), 4u);
  EXPECT_EQ(c.tight_count(1, 1, 1), 4u);
  EXPECT_EQ(c.tight_count(0, 1, 0), 3u);
}

// The cube cut by x + y + z <= 1.5 (a hexagonal section through six edges).
TEST(SmallClip, HexagonalCut) {
  auto planes = unit_cube_planes();
  planes.push_back({1, 1, 1, -1.5});
  const Clipped c(planes);
  ASSERT_TRUE(c.ok);
  EXPECT_EQ(c.tr.vertices.size(), 10u);  // 4 corners below, 6 cut points
  EXPECT_EQ(c.tr.edges.size(), 15u);
  EXPECT_EQ(c.tight_count(1, 0.5, 0), 3u);
}

// Half-spaces with no common point, and two that meet in a plane only: the clip hands over.
TEST(SmallClip, EmptyAndFlatHandOver) {
  EXPECT_FALSE(Clipped({{1, 0, 0, 1}, {-1, 0, 0, 1}}).ok);  // x <= -1 and x >= 1
  EXPECT_FALSE(Clipped({{1, 0, 0, 0}, {-1, 0, 0, 0}}).ok);  // x <= 0 and x >= 0: flat
}

// The certainly extreme vertex: the cube's (1, 1, 1) for a positive direction, none for a tie.
TEST(SmallClip, ExtremeVertex) {
  const Clipped c(unit_cube_planes());
  ASSERT_TRUE(c.ok);
  const double up[3] = {0.5773502691896258, 0.5773502691896257, 0.5773502691896256};
  const uint32_t top = kergen::certainly_extreme_vertex(c.tr, up);
  ASSERT_NE(top, kergen::kNoVertex);
  double hi[3], lo[3];
  kergen::precise_coordinates(c.ps, c.tr.vertices[top].geom, hi, lo);
  EXPECT_EQ(hi[0] + hi[1] + hi[2], 3.0);
  const double tie[3] = {1, 0, 0};  // four corners at x = 1
  EXPECT_EQ(kergen::certainly_extreme_vertex(c.tr, tie), kergen::kNoVertex);
}

// The first field in which the two answers differ ("" when none): everything but Stats.
std::string first_difference(const Kernel& a, const Kernel& b) {
  if (a.error != b.error || a.message != b.message) return "error";
  if (a.type != b.type || a.complete != b.complete) return "type";
  if (a.vertices != b.vertices) return "vertices";
  if (a.edges != b.edges) return "edges";
  if (a.face_indices != b.face_indices || a.face_sizes != b.face_sizes || a.triangles != b.triangles) return "faces";
  if (a.face_sources != b.face_sources) return "face sources";
  if (a.witness_faces != b.witness_faces || a.witness_boundary_edges != b.witness_boundary_edges) return "witness";
  if (a.volume != b.volume || a.area != b.area || a.shape_volume != b.shape_volume || a.volume_ratio != b.volume_ratio)
    return "volume or area";
  if (a.has_kernel_point != b.has_kernel_point || a.kernel_point != b.kernel_point) return "kernel point";
  if (a.has_deepest_point != b.has_deepest_point || a.deepest_point != b.deepest_point) return "deepest point";
  if (a.warnings.size() != b.warnings.size()) return "warnings";
  return "";
}

// Both paths on `mesh` (the small one forced); returns the small path's answer.
Kernel both_paths(const Mesh& mesh, const std::string& name, kergen::Options options = {}) {
  const Kernel small = kergen::compute_kernel_on_path(mesh.view(), options, KernelPath::Small);
  const Kernel general = kergen::compute_kernel_on_path(mesh.view(), options, KernelPath::General);
  EXPECT_EQ(first_difference(small, general), "") << name;
  EXPECT_EQ(first_difference(kergen::compute_kernel(mesh.view(), options), general), "") << name;
  return small;
}

TEST(SmallPath, AnalyticKernels) {
  using namespace kergen_test;
  // The L prism's kernel is the unit cube where its arms overlap.
  const Kernel l = both_paths(l_prism(), "L prism");
  ASSERT_TRUE(l.ok());
  EXPECT_EQ(l.type, kergen::KernelType::Polyhedron);
  EXPECT_EQ(l.num_vertices(), 8u);
  EXPECT_DOUBLE_EQ(l.volume, 1.0);
  for (double c : l.vertices) EXPECT_TRUE(c == 0.0 || c == 1.0);
  // The U prism is not star-shaped: the LP's witness, the same on both paths.
  const Kernel u = both_paths(u_prism(), "U prism");
  ASSERT_TRUE(u.ok());
  EXPECT_EQ(u.type, kergen::KernelType::Empty);
  EXPECT_FALSE(u.witness_faces.empty());
  // The plus prism's kernel is its centre square (volume 4 w^2), the S prism's a rectangle
  // (flat: handed over to the general path).
  const Kernel plus = both_paths(plus_prism(0.25), "plus prism");
  ASSERT_TRUE(plus.ok());
  EXPECT_EQ(plus.num_vertices(), 8u);
  EXPECT_DOUBLE_EQ(plus.volume, 0.25);
  both_paths(s_prism(), "S prism");
  both_paths(dented_cube(), "dented cube");
  both_paths(pinwheel_prism(), "pinwheel prism");
  // Coplanar faces (a tessellated cube: many triangles per plane), and a bumpy sphere's
  // kernel, whose vertices are cut points of many planes.
  both_paths(tessellated_cube(4), "tessellated cube");
  both_paths(bumpy_sphere(12, 8), "bumpy sphere");
  kergen::Options from;
  from.has_from = true;
  from.from = {0.3, 0.2, 0.1};
  both_paths(l_prism(), "L prism from a point", from);
  kergen::Options deepest;
  deepest.deepest_point = true;
  both_paths(l_prism(), "L prism with its deepest point", deepest);
  kergen::Options open;
  open.allow_open = true;
  both_paths(open_cube(), "open cube", open);
}

// A kernel far from the origin (x near -1e6, the rest of size 1) with pairs of vertices whose
// coordinates round to the same doubles: their order is their exact coordinates' (found by the
// differential fuzzer: the low parts of the coordinates, which follow the planes a vertex was
// found on, had ordered them differently on the two paths).
TEST(SmallPath, VerticesRoundingAlikeInExactOrder) {
  const kergen::ReadResult r = kergen::read_off(R"(OFF
17 30 0
-1000000 0 1
-1000000 0 -1
-999999.16789321881 0 0.83210678118654768
-999999.81274198776 0.57632090142723058 0.60597965688967914
-1000000.6033114028 0.43833139177762104 0.745733905483416
-1000000.6033114028 -0.43833139177762087 0.745733905483416
-999999.81274198776 -0.57632090142723058 0.60597965688967903
-999999.25 0 4.5924254968025742e-17
-999999.62848300568 1.1434117373686068 7.3616840865081302e-17
-1000000.7465169943 0.54237634429213821 5.6501881544324978e-17
-1000000.7465169943 -0.54237634429213788 5.6501881544324965e-17
-999999.62848300568 -1.143411737368607 7.3616840865081302e-17
-999999.16789321881 0 -0.83210678118654735
-999999.81274198776 0.57632090142723069 -0.60597965688967903
-1000000.6033114028 0.43833139177762109 -0.74573390548341589
-1000000.6033114028 -0.43833139177762093 -0.74573390548341589
-999999.81274198776 -0.57632090142723069 -0.60597965688967903
3 0 2 3
3 1 13 12
3 0 3 4
3 1 14 13
3 0 4 5
3 1 15 14
3 0 5 6
3 1 16 15
3 0 6 2
3 1 12 16
3 2 7 8
3 2 8 3
3 3 8 9
3 3 9 4
3 4 9 10
3 4 10 5
3 5 10 11
3 5 11 6
3 6 11 7
3 6 7 2
3 7 12 13
3 7 13 8
3 8 13 14
3 8 14 9
3 9 14 15
3 9 15 10
3 10 15 16
3 10 16 11
3 11 16 12
3 11 12 7
)");
  ASSERT_TRUE(r.ok()) << r.message;
  const Kernel k = both_paths(r.mesh, "far kernel with ties");
  ASSERT_TRUE(k.ok());
  size_t ties = 0;
  for (size_t i = 1; i < k.num_vertices(); ++i)
    ties += std::equal(&k.vertices[3 * i - 3], &k.vertices[3 * i], &k.vertices[3 * i]);
  EXPECT_GT(ties, 0u);
}

#ifdef KERGEN_SHARED_MESHES
// Every shared input of at most 1024 faces (the four polyhedra sets, the small fixtures,
// Princeton and refinement meshes), on both paths.
TEST(SmallPath, SharedSmallInputs) {
  size_t checked = 0, polyhedra = 0;
  const bool found = kergen_test::for_each_shared_mesh([&](const std::filesystem::path& path, const Mesh& mesh) {
    if (mesh.num_faces() > 1024) return;
    both_paths(mesh, path.string());
    ++checked;
    polyhedra += path.string().find("polyhedra") != std::string::npos;
  });
  if (!found) GTEST_SKIP() << "../shared/meshes not found";
  EXPECT_GE(polyhedra, 4000u);
  EXPECT_GT(checked, polyhedra);
}
#endif

}  // namespace
