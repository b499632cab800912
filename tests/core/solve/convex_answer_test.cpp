// The convex answer: a certified convex solid is answered without LP and trace, and the answer
// must be the traced one (the same vertices, edges, faces with their sources, type, volume);
// surfaces that are almost convex, or locally convex but not embedded, must not take it.
#include "solve/convex_answer.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "fixtures.h"
#include "input/mesh_prep.h"

namespace {

using namespace kergen;
using namespace kergen_test;

using Point = std::array<double, 3>;

// A kernel independent of the order it was built in: vertices sorted, edges as sorted pairs of
// points, faces as loops of points from their smallest point, each with its source face.
struct Canonical {
  KernelType type = KernelType::Empty;
  std::vector<Point> vertices;
  std::set<std::pair<Point, Point>> edges;
  std::set<std::pair<std::vector<Point>, int32_t>> faces;
  bool operator==(const Canonical& o) const {
    return type == o.type && vertices == o.vertices && edges == o.edges && faces == o.faces;
  }
};

Canonical canonical(const Kernel& k) {
  Canonical c;
  c.type = k.type;
  auto at = [&](uint32_t v) { return Point{k.vertices[3 * v], k.vertices[3 * v + 1], k.vertices[3 * v + 2]}; };
  for (uint32_t v = 0; v < k.num_vertices(); ++v) c.vertices.push_back(at(v));
  std::sort(c.vertices.begin(), c.vertices.end());
  for (size_t e = 0; e < k.num_edges(); ++e) {
    const Point a = at(k.edges[2 * e]), b = at(k.edges[2 * e + 1]);
    c.edges.insert({std::min(a, b), std::max(a, b)});
  }
  size_t off = 0;
  for (size_t f = 0; f < k.num_faces(); ++f) {
    std::vector<Point> loop;
    for (uint32_t i = 0; i < k.face_sizes[f]; ++i) loop.push_back(at(k.face_indices[off + i]));
    off += k.face_sizes[f];
    std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
    c.faces.insert({loop, k.face_sources[f]});
  }
  return c;
}

bool takes_convex_answer(const Mesh& m) {
  const PreparedMesh p = prepare_mesh(m.view(), Options());
  return p.error == Error::Ok && convex_solid(p);
}

// Step events need a trace: with max_steps set (never reached) compute_kernel traces.
Options traced_options() {
  Options o;
  o.max_steps = std::numeric_limits<uint64_t>::max();
  return o;
}

void expect_same_as_traced(const Mesh& m, const char* name) {
  SCOPED_TRACE(name);
  const Kernel fast = compute_kernel(m.view()), traced = compute_kernel(m.view(), traced_options());
  ASSERT_TRUE(fast.ok()) << fast.message;
  ASSERT_TRUE(traced.ok()) << traced.message;
  EXPECT_TRUE(canonical(fast) == canonical(traced));
  EXPECT_EQ(fast.num_vertices(), traced.num_vertices());
  EXPECT_EQ(fast.num_faces(), traced.num_faces());
  EXPECT_NEAR(fast.volume, traced.volume, 1e-12 * std::fabs(traced.volume));
  EXPECT_NEAR(fast.area, traced.area, 1e-12 * std::fabs(traced.area));
  EXPECT_EQ(fast.kernel_point, traced.kernel_point);
  EXPECT_EQ(fast.has_kernel_point, traced.has_kernel_point);
  EXPECT_EQ(fast.warnings.size(), traced.warnings.size());
}

TEST(ConvexAnswer, ConvexSolidsAreTheirOwnKernel) {
  struct Case {
    const char* name;
    Mesh mesh;
    size_t vertices, faces;
  };
  // Coplanar triangles merged into faces (the tessellated cube: face-interior and edge-interior
  // corners are no kernel vertices), polygons, strictly convex solids.
  const Case cases[] = {
      {"unit cube", unit_cube(), 8, 6},
      {"tessellated cube 7", tessellated_cube(7), 8, 6},
      {"moved cube", transformed(tessellated_cube(3), 1e3, 1e5, -3e4, 7), 8, 6},
      {"random convex 5", random_convex(5, 40).mesh, 42, 80},
      {"geodesic sphere 6", geodesic_sphere(6).mesh, 362, 720},
      {"pyramid 40", pyramid(40), 41, 41},
      {"flipped cube", flipped(tessellated_cube(2)), 8, 6},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    EXPECT_TRUE(takes_convex_answer(c.mesh));
    const Kernel k = compute_kernel(c.mesh.view());
    ASSERT_TRUE(k.ok()) << k.message;
    EXPECT_EQ(k.type, KernelType::Polyhedron);
    EXPECT_EQ(k.num_vertices(), c.vertices);
    EXPECT_EQ(k.num_faces(), c.faces);
    EXPECT_EQ(k.stats.traced_lines, 0u);
    expect_same_as_traced(c.mesh, c.name);
  }
}

TEST(ConvexAnswer, CubeVolumeAndSources) {
  const Mesh m = tessellated_cube(4);
  const Kernel k = compute_kernel(m.view());
  ASSERT_TRUE(k.ok());
  EXPECT_DOUBLE_EQ(k.volume, 1.0);
  EXPECT_DOUBLE_EQ(k.area, 6.0);
  // Each face's source is the lowest input face on its plane: the first triangle of each side.
  std::set<int32_t> sources(k.face_sources.begin(), k.face_sources.end());
  EXPECT_EQ(sources, (std::set<int32_t>{0, 32, 64, 96, 128, 160}));
}

// One corner in the middle of a side moved inward by one ulp: the triangles around it are no
// longer coplanar and their planes cut the cube, so the kernel is not the solid. (Outward, the
// flat triangles' planes cut the bump.)
TEST(ConvexAnswer, OneUlpDentIsNotConvex) {
  Mesh m = tessellated_cube(4);
  size_t centre = 0;
  for (size_t v = 0; v < m.num_vertices(); ++v)
    if (m.positions[3 * v] == 0.5 && m.positions[3 * v + 1] == 0.5 && m.positions[3 * v + 2] == 1) centre = v;
  ASSERT_NE(centre, 0u);
  EXPECT_TRUE(takes_convex_answer(m));
  m.positions[3 * centre + 2] = std::nextafter(1.0, 0.0);
  EXPECT_FALSE(takes_convex_answer(m));
  const Kernel k = compute_kernel(m.view());
  ASSERT_TRUE(k.ok()) << k.message;
  EXPECT_GT(k.num_vertices(), 8u);  // the dent's planes cut the top
  expect_same_as_traced(m, "dented");
  // Moved outward by one ulp instead: a low pyramid on the side, whose base edges are reflex.
  m.positions[3 * centre + 2] = std::nextafter(1.0, 2.0);
  EXPECT_FALSE(takes_convex_answer(m));
  expect_same_as_traced(m, "bump");
}

// A face of a polyhedron with polygon faces nudged by one ulp: the quad is no longer planar and
// is split; the mesh no longer lists all its edges as face pairs and goes the traced way.
TEST(ConvexAnswer, NonPlanarQuadGoesTheTracedWay) {
  Mesh m = prism({{0, 0}, {1, 0}, {1, 1}, {0, 1}});  // quads; vertices 4-7 on top
  EXPECT_TRUE(takes_convex_answer(m));
  expect_same_as_traced(m, "box of quads");
  m.positions[3 * 6 + 2] = std::nextafter(1.0, 0.0);
  EXPECT_FALSE(takes_convex_answer(m));
  expect_same_as_traced(m, "nudged box");
}

// Every edge convex, every face seen from inside at the centre, but the surface winds twice
// around it: the degree certificate refuses it, and the traced way reports the crossing.
TEST(ConvexAnswer, LocallyConvexDoubleCoverIsRefused) {
  const Mesh m = wound_bipyramid(5, 2);
  EXPECT_FALSE(takes_convex_answer(m));
  const Kernel k = compute_kernel(m.view());
  EXPECT_EQ(k.error, Error::SelfIntersection) << k.message;
}

TEST(ConvexAnswer, NonConvexMeshesGoTheTracedWay) {
  EXPECT_FALSE(takes_convex_answer(dented_cube()));
  EXPECT_FALSE(takes_convex_answer(l_prism()));
  EXPECT_FALSE(takes_convex_answer(bumpy_sphere(20, 11, 0.05)));
  EXPECT_FALSE(takes_convex_answer(torus()));
  EXPECT_FALSE(takes_convex_answer(open_cube()));
  EXPECT_FALSE(takes_convex_answer(cubes_sharing_edge()));
  // Float UV spheres: the two triangles of a quad are not exactly coplanar, and half the
  // diagonals are reflex.
  EXPECT_FALSE(takes_convex_answer(uv_sphere(24, 12, 0)));
}

#ifdef KERGEN_SHARED_MESHES
// Every shared mesh the certificate accepts: the same kernel as the trace gives.
TEST(ConvexAnswer, SharedConvexMeshesMatchTheTrace) {
  // (Most shared polyhedra are convex only up to rounding: their float polygons are split.)
  size_t convex = 0, total = 0;
  std::set<std::string> names;
  const bool found = for_each_shared_mesh([&](const std::filesystem::path& path, const Mesh& m) {
    ++total;
    if (!takes_convex_answer(m)) return;
    ++convex;
    names.insert(path.filename().string());
    expect_same_as_traced(m, path.string().c_str());
  });
  if (!found) GTEST_SKIP() << "shared meshes not found";
  for (const char* name : {"cube.off", "cube-meshed.off", "icosahedron.off", "octahedron.off", "tetrahedron.off"})
    EXPECT_EQ(names.count(name), 1u) << name;
  std::printf("convex answer on %zu of %zu shared meshes:", convex, total);
  for (const auto& n : names) std::printf(" %s", n.c_str());
  std::printf("\n");
}
#endif

}  // namespace
