// The legacy VTK reader (read_vtk_legacy): CELLS in the version 4 and version 5 layouts, linear
// cells and polyhedra, METADATA and attribute sections; its refusals.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "kergen/volume.h"
#include "volume/volume_test_util.h"

namespace {

using namespace volume_test;

std::string legacy(const LinearCells& c, bool version5) {
  std::string s = std::string("# vtk DataFile Version ") + (version5 ? "5.1" : "4.2") +
                  "\ncells\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS " + std::to_string(c.points.size() / 3) +
                  " double\n";
  for (double p : c.points) s += std::to_string(p) + " ";
  s += "\nMETADATA\nINFORMATION 0\n\n";
  // Per cell: its values (point ids, or a polyhedron's face stream).
  std::vector<std::vector<long long>> values;
  long long begin = 0;
  for (size_t i = 0; i < c.types.size(); ++i) {
    if (c.types[i] == 42)
      values.push_back(c.faces);
    else
      values.emplace_back(c.connectivity.begin() + begin, c.connectivity.begin() + c.offsets[i]);
    begin = c.offsets[i];
  }
  if (version5) {
    std::vector<long long> offsets{0}, conn;
    for (auto& v : values) conn.insert(conn.end(), v.begin(), v.end()), offsets.push_back((long long)conn.size());
    s += "CELLS " + std::to_string(offsets.size()) + " " + std::to_string(conn.size()) + "\nOFFSETS vtktypeint64\n" +
         join(offsets) + "\nCONNECTIVITY vtktypeint64\n" + join(conn) + "\n";
  } else {
    size_t size = 0;
    for (auto& v : values) size += v.size() + 1;
    s += "CELLS " + std::to_string(values.size()) + " " + std::to_string(size) + "\n";
    for (auto& v : values) s += std::to_string(v.size()) + " " + join(v) + "\n";
  }
  s += "CELL_TYPES 5\n" + join(c.types) + "\nCELL_DATA 5\nSCALARS x int 1\nLOOKUP_TABLE default\n1 2 3 4 5\n";
  return s;
}

TEST(VtkLegacy, BothCellLayouts) {
  for (bool v5 : {false, true}) {
    const kergen::VolumeReadResult r = kergen::read_vtk_legacy(legacy(LinearCells(), v5), "a.vtk");
    ASSERT_TRUE(r.ok()) << r.message;
    const std::vector<double> want = LinearCells().volumes(), got = kernel_volumes(r.mesh);
    ASSERT_EQ(got.size(), want.size());
    for (size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(got[i], want[i], 1e-15) << "cell " << i;
  }
}

TEST(VtkLegacy, Refusals) {
  std::string s = legacy(LinearCells(), false);
  EXPECT_EQ(kergen::read_vtk_legacy(s.substr(0, s.find("CELL_TYPES")), "t.vtk").error, kergen::Error::ParseError);
  s.replace(s.find("UNSTRUCTURED_GRID"), 17, "POLYDATA");
  const kergen::VolumeReadResult r = kergen::read_vtk_legacy(s, "p.vtk");
  EXPECT_EQ(r.error, kergen::Error::ParseError);
  EXPECT_NE(r.message.find("not a volume mesh"), std::string::npos) << r.message;
}

}  // namespace
