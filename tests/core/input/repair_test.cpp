// Options::repair: a solid with T-junctions (an edge of one face split in two by its neighbours),
// repeated faces and face pairs that cancel gets the kernel of the solid it describes; without
// repair it is refused as before.
#include "input/repair.h"

#include <gtest/gtest.h>

#include "fixtures.h"
#include "kergen/kergen.h"

namespace {

using kergen::Error;
using kergen::Mesh;

using kergen_test::t_junction_box;

const kergen::Warning* find(const kergen::Kernel& k, kergen::Warning::Kind kind) {
  for (const auto& w : k.warnings)
    if (w.kind == kind) return &w;
  return nullptr;
}

TEST(Repair, TJunctionSolidGetsItsKernel) {
  const Mesh m = t_junction_box();
  EXPECT_EQ(kergen::compute_kernel(m.view()).error, Error::OpenMesh);
  kergen::Options o;
  o.repair = true;
  const kergen::Kernel k = kergen::compute_kernel(m.view(), o);
  ASSERT_TRUE(k.ok()) << k.message;
  EXPECT_EQ(k.type, kergen::KernelType::Polyhedron);
  EXPECT_EQ(k.volume, 2.0);  // the box, exactly
  EXPECT_EQ(k.num_vertices(), 8u);
  ASSERT_NE(find(k, kergen::Warning::Kind::TJunctionsSplit), nullptr);
  EXPECT_EQ(find(k, kergen::Warning::Kind::TJunctionsSplit)->count, 2u);
}

TEST(Repair, RepeatedAndCancellingFacesAreRemoved) {
  Mesh dup = kergen_test::unit_cube();
  dup.indices.insert(dup.indices.end(), dup.indices.begin() + 3, dup.indices.begin() + 6);  // a copy, rotated below
  std::rotate(dup.indices.end() - 3, dup.indices.end() - 2, dup.indices.end());
  EXPECT_NE(kergen::compute_kernel(dup.view()).error, Error::Ok);
  kergen::Options o;
  o.repair = true;
  kergen::Kernel k = kergen::compute_kernel(dup.view(), o);
  ASSERT_TRUE(k.ok()) << k.message;
  EXPECT_EQ(k.volume, 1.0);
  EXPECT_EQ(find(k, kergen::Warning::Kind::DuplicateFacesRemoved)->count, 1u);

  Mesh cancel = kergen_test::unit_cube();
  cancel.positions.insert(cancel.positions.end(), {0.5, 0.5, 0.5, 0.6, 0.5, 0.5, 0.5, 0.6, 0.5});
  cancel.indices.insert(cancel.indices.end(), {8, 9, 10, 8, 10, 9});  // a triangle inside, both ways
  EXPECT_NE(kergen::compute_kernel(cancel.view()).error, Error::Ok);
  k = kergen::compute_kernel(cancel.view(), o);
  ASSERT_TRUE(k.ok()) << k.message;
  EXPECT_EQ(k.volume, 1.0);
  EXPECT_EQ(find(k, kergen::Warning::Kind::CancellingFacesRemoved)->count, 2u);
}

TEST(Repair, WhatRepairCannotFixIsRefusedAsBefore) {
  kergen::Options o;
  o.repair = true;
  EXPECT_EQ(kergen::compute_kernel(kergen_test::open_cube().view(), o).error, Error::OpenMesh);
  EXPECT_EQ(kergen::compute_kernel(kergen_test::cubes_sharing_edge().view(), o).error, Error::NonManifoldEdge);
  // A vertex near, but not exactly on, the edge is not inserted.
  Mesh m = t_junction_box();
  m.positions[25] = 1e-12;  // vertex 8, (1, 1e-12, 0): off the front face's bottom edge
  EXPECT_EQ(kergen::compute_kernel(m.view(), o).error, Error::OpenMesh);
  // Without repair every result is unchanged: the table of shared meshes checks that elsewhere.
  const kergen::RepairCounts none = [] {
    Mesh cube = kergen_test::unit_cube();
    return kergen::repair_mesh(cube);
  }();
  EXPECT_EQ(none.duplicate_faces + none.cancelling_faces + none.t_junctions, 0u);
}

}  // namespace
