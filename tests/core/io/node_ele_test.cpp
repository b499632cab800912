// The .node/.ele reader (read_node_ele, and read_volume_mesh_file finding the sibling file):
// comments, 1-based ids, TetGen-style attributes and markers in .node, faces across lines; refusals.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "kergen/volume.h"
#include "volume/volume_test_util.h"

namespace {

// A unit cube and a tetra on top of it (sharing the cube's top face, listed once per cell).
const char* kNode =
    "# a cube and a tetrahedron\n9 3 1 1\n"
    "1 0 0 0 7.5 1\n2 1 0 0 7.5 1\n3 1 1 0 7.5 1\n4 0 1 0 7.5 1\n"
    "5 0 0 1 7.5 1\n6 1 0 1 7.5 1\n7 1 1 1 7.5 1\n8 0 1 1 7.5 1\n"
    "9 0.5 0.5 2 0 0  # apex\n";
const char* kEle =
    "2 0\n"
    "1 6\n1 4 1 4 3 2\n2 4 5 6 7 8\n3 4 1 2 6 5\n4 4 2 3 7 6\n5 4 3 4 8 7\n6 4 4 1 5 8\n"
    "\n# the pyramid: the cube's top face again, inward here\n2 5\n2 4 5 6 7 8\n"
    "7 3 5 9 6\n8 3 6 9 7\n9 3\n 7 9 8\n10 3 8 9 5\n";

TEST(NodeEle, ReadsCellsWithSharedFaces) {
  const kergen::VolumeReadResult r = kergen::read_node_ele(kNode, kEle, "a.node", "a.ele");
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.mesh.num_vertices(), 9u);
  EXPECT_EQ(r.mesh.num_cells(), 2u);
  EXPECT_EQ(r.mesh.num_faces(), 11u);
  const kergen::CellKernels k = kergen::compute_cell_kernels(r.mesh);
  EXPECT_DOUBLE_EQ(k.cells[0].kernel_volume, 1);
  EXPECT_NEAR(k.cells[1].kernel_volume, 1.0 / 3, 1e-15);
  // The pyramid lists the shared face as the cube does: turned outward for it alone.
  EXPECT_FALSE(k.cells[0].reoriented);
  EXPECT_TRUE(k.cells[1].reoriented);
}

TEST(NodeEle, FileFormFindsTheSibling) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "kergen_node_ele_test";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "m.node") << kNode;
  std::ofstream(dir / "m.ele") << kEle;
  for (const char* name : {"m.node", "m.ele"}) {
    const kergen::VolumeReadResult r = kergen::read_volume_mesh_file((dir / name).string());
    ASSERT_TRUE(r.ok()) << r.message;
    EXPECT_EQ(r.mesh.num_cells(), 2u);
  }
  std::filesystem::remove(dir / "m.ele");
  const kergen::VolumeReadResult r = kergen::read_volume_mesh_file((dir / "m.node").string());
  EXPECT_EQ(r.error, kergen::Error::IoError);
  EXPECT_NE(r.message.find("m.ele"), std::string::npos) << r.message;
  std::filesystem::remove_all(dir);
}

TEST(NodeEle, Refusals) {
  auto expect = [](const std::string& node, const std::string& ele, const std::string& fragment) {
    const kergen::VolumeReadResult r = kergen::read_node_ele(node, ele, "x.node", "x.ele");
    EXPECT_EQ(r.error, kergen::Error::ParseError) << r.message;
    EXPECT_NE(r.message.find(fragment), std::string::npos) << r.message;
  };
  expect("2 3 0 0\n0 0 0 0\n2 1 1 1\n", "1 0\n", "ids are consecutive");
  expect("1 2 0 0\n0 0 0\n", "1 0\n", "dimension 2");
  expect("1 3 0 0\n0 0 0 nan\n", "1 0\n", "non-finite");
  expect(kNode, std::string(kEle) + "3\n", "content after the 2 cells");
  expect(kNode, "1 0\n0 1\n0 3 1 2 10\n", "vertex id 10 out of range");
}

}  // namespace
