// kergen::repair_mesh: the mesh compute_kernel works on, after Options::weld and Options::repair,
// for saving it. The repaired mesh of a T-junction solid is closed, its kernel (without repair) is
// the kernel computed with repair, and it survives the writers and readers unchanged.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

#include "fixtures.h"
#include "kergen/io.h"
#include "kergen/kergen.h"

namespace {

using kergen::Error;
using kergen::Mesh;

kergen::Options with_repair() {
  kergen::Options o;
  o.repair = true;
  return o;
}

std::vector<std::array<double, 3>> sorted_vertices(const kergen::Kernel& k) {
  std::vector<std::array<double, 3>> v(k.num_vertices());
  for (size_t i = 0; i < v.size(); ++i) v[i] = {k.vertices[3 * i], k.vertices[3 * i + 1], k.vertices[3 * i + 2]};
  std::sort(v.begin(), v.end());
  return v;
}

size_t count_of(const std::vector<kergen::Warning>& warnings, kergen::Warning::Kind kind) {
  for (const kergen::Warning& w : warnings)
    if (w.kind == kind) return w.count;
  return 0;
}

TEST(RepairMesh, TJunctionSolidBecomesClosedWithTheRepairedKernel) {
  const Mesh m = kergen_test::t_junction_box();
  const kergen::RepairedMesh r = kergen::repair_mesh(m.view(), with_repair());
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(count_of(r.warnings, kergen::Warning::Kind::TJunctionsSplit), 2u);
  EXPECT_EQ(r.mesh.positions, m.positions);  // every vertex is used; none moved
  EXPECT_EQ(r.mesh.num_faces(), m.num_faces());
  EXPECT_EQ(r.mesh.indices.size(), m.indices.size() + 2);  // the front and back quads gained a corner

  // Closed as it is: no repair needed any more, and the same kernel as with repair.
  const kergen::Kernel plain = kergen::compute_kernel(r.mesh.view());
  const kergen::Kernel repaired = kergen::compute_kernel(m.view(), with_repair());
  ASSERT_TRUE(plain.ok()) << plain.message;
  ASSERT_TRUE(repaired.ok()) << repaired.message;
  EXPECT_EQ(plain.type, kergen::KernelType::Polyhedron);
  EXPECT_EQ(sorted_vertices(plain), sorted_vertices(repaired));
  EXPECT_EQ(plain.volume, 2.0);  // the box [0,2]x[0,1]x[0,1], exactly
  EXPECT_EQ(repaired.volume, 2.0);
  EXPECT_TRUE(plain.warnings.empty());
}

TEST(RepairMesh, WithoutRepairTheInputComesBackWithValidationsVerdict) {
  const Mesh m = kergen_test::t_junction_box();
  const kergen::RepairedMesh r = kergen::repair_mesh(m.view(), kergen::Options{});
  EXPECT_EQ(r.error, Error::OpenMesh);
  EXPECT_EQ(r.message, kergen::compute_kernel(m.view()).message);
  EXPECT_EQ(r.mesh.positions, m.positions);
  EXPECT_EQ(r.mesh.indices, m.indices);
  EXPECT_EQ(r.mesh.face_sizes, m.face_sizes);
}

TEST(RepairMesh, RoundTripThroughTheWriters) {
  const kergen::RepairedMesh r = kergen::repair_mesh(kergen_test::t_junction_box().view(), with_repair());
  ASSERT_TRUE(r.ok());
  for (kergen::MeshFormat format : {kergen::MeshFormat::Off, kergen::MeshFormat::Obj}) {
    const kergen::ReadResult back = kergen::read_mesh(kergen::write_mesh(r.mesh, format), format);
    ASSERT_TRUE(back.ok()) << back.message;
    EXPECT_EQ(back.mesh.positions, r.mesh.positions);
    EXPECT_EQ(back.mesh.indices, r.mesh.indices);
    EXPECT_EQ(back.mesh.face_sizes, r.mesh.face_sizes);
  }
  // Binary STL triangulates and stores floats (exact here): the same solid.
  const kergen::ReadResult stl =
      kergen::read_mesh(kergen::write_mesh(r.mesh, kergen::MeshFormat::Stl), kergen::MeshFormat::Stl);
  ASSERT_TRUE(stl.ok()) << stl.message;
  const kergen::Kernel k = kergen::compute_kernel(stl.mesh.view());
  ASSERT_TRUE(k.ok()) << k.message;
  EXPECT_EQ(k.volume, 2.0);
}

// Welding merges vertices: the merged ones are left out, the others keep their order.
TEST(RepairMesh, WeldedSoupLosesItsMergedVertices) {
  const Mesh cube = kergen_test::unit_cube();
  Mesh soup;
  for (uint32_t v : cube.indices) {
    kergen_test::add_point(soup, cube.positions[3 * v], cube.positions[3 * v + 1], cube.positions[3 * v + 2]);
    soup.indices.push_back(uint32_t(soup.indices.size()));
  }
  kergen::Options o;
  o.weld = 0;  // equal positions only
  const kergen::RepairedMesh r = kergen::repair_mesh(soup.view(), o);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.mesh.num_vertices(), 8u);
  EXPECT_EQ(r.mesh.num_faces(), 12u);
  EXPECT_EQ(count_of(r.warnings, kergen::Warning::Kind::VerticesWelded), 36u - 8u);
  for (uint32_t v : r.mesh.indices) EXPECT_LT(v, 8u);
  const kergen::Kernel k = kergen::compute_kernel(r.mesh.view());
  ASSERT_TRUE(k.ok()) << k.message;
  EXPECT_EQ(k.volume, 1.0);
}

TEST(RepairMesh, MalformedInputLeavesNoMesh) {
  Mesh m = kergen_test::unit_cube();
  m.indices[4] = 99;
  const kergen::RepairedMesh r = kergen::repair_mesh(m.view(), with_repair());
  EXPECT_EQ(r.error, Error::IndexOutOfRange);
  EXPECT_EQ(r.mesh.num_faces(), 0u);
  EXPECT_EQ(r.mesh.num_vertices(), 0u);
}

}  // namespace
