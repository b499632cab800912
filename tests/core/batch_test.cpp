// KernelBatch and compute_kernels (batch.h) against compute_kernel: the same answer, field by
// field, for every kind of input, whatever ran in the batch before.
#include "kergen/batch.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "fixtures.h"
#include "kergen/io.h"

#ifndef KERGEN_SHARED_MESHES
#define KERGEN_SHARED_MESHES "../shared/meshes"
#endif

namespace {

using namespace kergen;
using namespace kergen_test;

// Every result field but Stats' times, exactly (bit for bit for the doubles).
void expect_same(const Kernel& a, const Kernel& b, const std::string& what) {
  SCOPED_TRACE(what);
  EXPECT_EQ(a.error, b.error);
  EXPECT_EQ(a.message, b.message);
  EXPECT_EQ(a.type, b.type);
  EXPECT_EQ(a.complete, b.complete);
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.edges, b.edges);
  EXPECT_EQ(a.face_indices, b.face_indices);
  EXPECT_EQ(a.face_sizes, b.face_sizes);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.face_sources, b.face_sources);
  EXPECT_EQ(a.witness_faces, b.witness_faces);
  EXPECT_EQ(a.witness_boundary_edges, b.witness_boundary_edges);
  EXPECT_EQ(a.volume, b.volume);
  EXPECT_EQ(a.area, b.area);
  EXPECT_EQ(a.shape_volume, b.shape_volume);
  EXPECT_EQ(a.volume_ratio, b.volume_ratio);
  EXPECT_EQ(a.has_kernel_point, b.has_kernel_point);
  EXPECT_EQ(a.kernel_point, b.kernel_point);
  EXPECT_EQ(a.has_deepest_point, b.has_deepest_point);
  EXPECT_EQ(a.deepest_point, b.deepest_point);
  EXPECT_EQ(a.inscribed_radius, b.inscribed_radius);
  ASSERT_EQ(a.warnings.size(), b.warnings.size());
  for (size_t i = 0; i < a.warnings.size(); ++i) {
    EXPECT_EQ(a.warnings[i].kind, b.warnings[i].kind);
    EXPECT_EQ(a.warnings[i].count, b.warnings[i].count);
    EXPECT_EQ(a.warnings[i].message, b.warnings[i].message);
  }
  EXPECT_EQ(a.stats.input_vertices, b.stats.input_vertices);
  EXPECT_EQ(a.stats.input_faces, b.stats.input_faces);
  EXPECT_EQ(a.stats.dropped_faces, b.stats.dropped_faces);
  EXPECT_EQ(a.stats.distinct_planes, b.stats.distinct_planes);
  EXPECT_EQ(a.stats.active_planes, b.stats.active_planes);
}

struct Case {
  std::string name;
  Mesh mesh;
  Options options;
};

// Small and larger meshes, star and not, open, flipped, refused, with options that change the
// path (steps, from, deepest point, walls), in an order that sends large inputs before small ones.
std::vector<Case> cases() {
  std::vector<Case> c;
  c.push_back({"cube", unit_cube(), {}});
  c.push_back({"tessellated cube 12", tessellated_cube(12), {}});
  c.push_back({"l prism", l_prism(), {}});
  c.push_back({"s prism", s_prism(), {}});
  c.push_back({"u prism (not star)", u_prism(), {}});
  c.push_back({"torus (not star)", torus(), {}});
  c.push_back({"flipped dented cube", flipped(dented_cube()), {}});
  c.push_back({"bumpy sphere", bumpy_sphere(40, 21, 0.05), {}});
  c.push_back({"pyramid 7", pyramid(7), {}});
  for (uint32_t seed = 1; seed <= 6; ++seed)
    c.push_back({"random convex", random_convex(seed, 5 + int(seed) * 3).mesh, {}});
  c.push_back({"open cube (refused)", open_cube(), {}});
  Options open;
  open.allow_open = true;
  c.push_back({"open cube (allowed)", open_cube(), open});
  Options walls;
  walls.open_boundary = OpenBoundary::Perpendicular;
  c.push_back({"open cube (walls)", open_cube(), walls});
  Options steps;
  steps.max_steps = 7;
  c.push_back({"plus prism, 7 steps", plus_prism(0.5), steps});
  Options from;
  from.has_from = true;
  from.from = {3, -2, 1};
  from.deepest_point = true;
  c.push_back({"pinwheel from, deepest", pinwheel_prism(), from});
  Mesh bad = unit_cube();
  bad.indices[4] = 99;
  c.push_back({"index out of range", bad, {}});
  c.push_back({"cubes sharing an edge", cubes_sharing_edge(), {}});
  Options repair;
  repair.repair = true;
  c.push_back({"t junction, repaired", t_junction_box(), repair});
  c.push_back({"empty", Mesh{}, {}});
  return c;
}

TEST(KernelBatch, SameAsComputeKernelInAnyOrder) {
  const std::vector<Case> all = cases();
  KernelBatch batch;
  Kernel reused;  // one result object for every call: nothing of an earlier result may remain
  for (int round = 0; round < 2; ++round) {
    for (size_t j = 0; j < all.size(); ++j) {
      const Case& c = all[round == 0 ? j : all.size() - 1 - j];
      const Kernel expected = compute_kernel(c.mesh.view(), c.options);
      expect_same(batch.compute(c.mesh.view(), c.options), expected, c.name);
      batch.compute(c.mesh.view(), c.options, reused);
      expect_same(reused, expected, c.name + " (into a reused Kernel)");
    }
    if (round == 0) batch.release();
  }
}

TEST(KernelBatch, MovedFromBatchIsUsable) {
  KernelBatch a;
  const Mesh cube = unit_cube();
  KernelBatch b = std::move(a);
  expect_same(b.compute(cube.view()), compute_kernel(cube.view()), "moved to");
  expect_same(a.compute(cube.view()), compute_kernel(cube.view()), "moved from");  // NOLINT(bugprone-use-after-move)
}

TEST(KernelBatch, ComputeKernelsOverManyMeshes) {
  const std::vector<Case> all = cases();
  std::vector<MeshView> views;
  for (const Case& c : all) views.push_back(c.mesh.view());
  std::vector<Kernel> results(views.size());
  compute_kernels(views.data(), views.size(), Options{}, results.data());
  for (size_t i = 0; i < all.size(); ++i) expect_same(results[i], compute_kernel(views[i]), all[i].name);
  compute_kernels(nullptr, 0, Options{}, nullptr);  // nothing to do
}

// The polyhedral cells of a volume mesh, the batch's use: one shared set of cells, each cell's
// result as compute_kernel gives it.
TEST(KernelBatch, SharedPolyhedraCells) {
  for (const char* set : {"tet10", "tet30", "voro"}) {
    std::vector<Mesh> cells;
    for (int i = 0; i < 40; ++i) {
      ReadResult r =
          read_mesh_file(std::string(KERGEN_SHARED_MESHES) + "/polyhedra/" + set + "/" + std::to_string(i) + ".off");
      if (!r.ok()) GTEST_SKIP() << "shared meshes not found: " << r.message;
      cells.push_back(std::move(r.mesh));
    }
    KernelBatch batch;
    for (size_t i = 0; i < cells.size(); ++i)
      expect_same(batch.compute(cells[i].view()), compute_kernel(cells[i].view()),
                  std::string(set) + "/" + std::to_string(i));
  }
}

}  // namespace
