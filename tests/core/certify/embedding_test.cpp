// The embedding certificate (embedding.h): a surface wound twice around a point, every face seen
// from its inner side there, is refused with SELF_INTERSECTION (its half-space intersection would
// otherwise be reported as its kernel); every full-dimensional kernel of the shared meshes is
// certified with degree 1.
#include "certify/embedding.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <vector>

#include "fixtures.h"
#include "kergen/io.h"
#include "kergen/kergen.h"
#include "planes/plane_classes.h"
#include "solve/lp.h"
#include "solve/plane_culling.h"

namespace {

namespace fs = std::filesystem;
using kergen::Mesh;

// The certificate of a mesh's kernel, through the same pipeline as compute_kernel (without face
// culling, which does not change the kernel).
kergen::EmbeddingCheck certificate(const Mesh& m, kergen::KernelType& type) {
  using namespace kergen;
  EmbeddingCheck none;
  const PreparedMesh mesh = prepare_mesh(m.view(), Options{});
  if (mesh.error != Error::Ok) return none;
  PlaneSet ps(&mesh.points, mesh.exact_shift);
  ps.set_extent(mesh.extent());
  std::vector<uint32_t> face_plane, planes, box;
  build_planes(mesh, ps, face_plane);
  for (uint32_t i = 0; i < ps.size(); ++i) planes.push_back(i);
  add_bounding_box(ps, box);
  std::vector<uint32_t> lp_planes = planes;
  lp_planes.insert(lp_planes.end(), box.begin(), box.end());
  const LpResult lp = solve_lp(ps, lp_planes, kDefaultDirection, kLpBound, 1);
  if (lp.outcome != LpResult::Outcome::Optimal) return none;
  const CulledTrace ct = trace_with_culling(ps, planes, box, lp.vertex, TraceOptions(), 1);
  type = kergen::compute_kernel(m.view()).type;
  return check_embedding(mesh, ps, ct.trace);
}

TEST(Embedding, SurfaceWoundTwiceIsRefused) {
  for (int n : {5, 7, 9, 31}) {
    const kergen::Kernel once = kergen::compute_kernel(kergen_test::wound_bipyramid(n, 1).view());
    ASSERT_TRUE(once.ok()) << once.message;
    EXPECT_EQ(once.type, kergen::KernelType::Polyhedron);
    const kergen::Kernel twice = kergen::compute_kernel(kergen_test::wound_bipyramid(n, 2).view());
    EXPECT_EQ(twice.error, kergen::Error::SelfIntersection) << n << ": " << twice.message;
    EXPECT_NE(twice.message.find("crosses it 2 times"), std::string::npos) << twice.message;
    kergen::KernelType type;
    const kergen::EmbeddingCheck c = certificate(kergen_test::wound_bipyramid(n, 2), type);
    EXPECT_EQ(c.outcome, kergen::EmbeddingCheck::Outcome::CrossesItself);
    EXPECT_EQ(c.crossings, 2);
  }
  // Three turns of a polygon of 7 corners (a {7/3} star), likewise.
  EXPECT_EQ(kergen::compute_kernel(kergen_test::wound_bipyramid(7, 3).view()).error, kergen::Error::SelfIntersection);
}

TEST(Embedding, EveryFullDimensionalKernelOfTheSharedMeshesIsCertified) {
  size_t certified = 0, meshes = 0;
  const bool found = kergen_test::for_each_shared_mesh([&](const fs::path& path, const Mesh& mesh) {
    kergen::KernelType type = kergen::KernelType::Empty;
    const kergen::EmbeddingCheck c = certificate(mesh, type);
    if (type != kergen::KernelType::Polyhedron) return;
    ++meshes;
    EXPECT_EQ(c.outcome, kergen::EmbeddingCheck::Outcome::Embedded) << path << ": degree " << c.crossings;
    certified += c.outcome == kergen::EmbeddingCheck::Outcome::Embedded;
  });
  if (!found) GTEST_SKIP() << "shared meshes not found at " << KERGEN_SHARED_MESHES;
  std::printf("%zu of %zu full-dimensional kernels certified with degree 1\n", certified, meshes);
  EXPECT_GT(meshes, 3000u);
}

}  // namespace
