// cell_surface: a cell's vertices renumbered in increasing global id, its faces in the cell's
// order, turned outward whatever the file says (per face, and as a whole), and its errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "kergen/volume.h"

namespace {

// Two unit cubes side by side sharing the face x = 1 (stored once: outward for the first cube).
kergen::VolumeMesh two_cubes() {
  kergen::VolumeMesh m;
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 2; ++y)
      for (int z = 0; z < 2; ++z) m.positions.insert(m.positions.end(), {double(x), double(y), double(z)});
  auto id = [](int x, int y, int z) { return uint32_t(4 * x + 2 * y + z); };
  auto quad = [&](std::vector<uint32_t> q) {
    m.face_indices.insert(m.face_indices.end(), q.begin(), q.end());
    m.face_offsets.push_back(uint32_t(m.face_indices.size()));
  };
  m.face_offsets = {0};
  for (int x = 0; x < 2; ++x) {  // per cube: x-min (not for the second), y-min, y-max, z-min, z-max
    if (x == 0) quad({id(0, 0, 0), id(0, 0, 1), id(0, 1, 1), id(0, 1, 0)});
    quad({id(x, 0, 0), id(x + 1, 0, 0), id(x + 1, 0, 1), id(x, 0, 1)});
    quad({id(x, 1, 0), id(x, 1, 1), id(x + 1, 1, 1), id(x + 1, 1, 0)});
    quad({id(x, 0, 0), id(x, 1, 0), id(x + 1, 1, 0), id(x + 1, 0, 0)});
    quad({id(x, 0, 1), id(x + 1, 0, 1), id(x + 1, 1, 1), id(x, 1, 1)});
  }
  quad({id(1, 0, 0), id(1, 1, 0), id(1, 1, 1), id(1, 0, 1)});  // face 9: x = 1, facing +x
  quad({id(2, 0, 0), id(2, 1, 0), id(2, 1, 1), id(2, 0, 1)});  // face 10: x = 2, facing +x
  m.cell_faces = {0, 1, 2, 3, 4, 9, /**/ 9, 5, 6, 7, 8, 10};
  m.cell_offsets = {0, 6, 12};
  return m;
}

TEST(CellSurface, NumbersVerticesAndKeepsFaceOrder) {
  const kergen::VolumeMesh m = two_cubes();
  const kergen::CellSurface s = kergen::cell_surface(m, 1);
  ASSERT_TRUE(s.ok()) << s.message;
  EXPECT_EQ(s.global_vertices, (std::vector<uint32_t>{4, 5, 6, 7, 8, 9, 10, 11}));
  EXPECT_EQ(s.mesh.face_sizes, std::vector<uint32_t>(6, 4));
  // The shared face comes first in cell 1, reversed (it faces +x, into cell 1).
  EXPECT_EQ(std::vector<uint32_t>(s.mesh.indices.begin(), s.mesh.indices.begin() + 4),
            (std::vector<uint32_t>{1, 3, 2, 0}));
  EXPECT_TRUE(s.reoriented);
  EXPECT_FALSE(kergen::cell_surface(m, 0).reoriented);
  // Every face outward: compute_kernel sees a closed, outward cube.
  const kergen::Kernel k = kergen::compute_kernel(s.mesh.view());
  ASSERT_TRUE(k.ok()) << k.message;
  EXPECT_EQ(k.volume, 1);
  for (const auto& w : k.warnings) EXPECT_NE(w.kind, kergen::Warning::Kind::OrientationFlipped);
}

TEST(CellSurface, TurnsAWhollyInwardCell) {
  kergen::VolumeMesh m = two_cubes();
  for (size_t f = 0; f + 1 < m.face_offsets.size(); ++f)
    std::reverse(m.face_indices.begin() + m.face_offsets[f], m.face_indices.begin() + m.face_offsets[f + 1]);
  const kergen::CellKernels k = kergen::compute_cell_kernels(m);
  ASSERT_TRUE(k.ok());
  for (const kergen::CellKernel& c : k.cells) {
    EXPECT_TRUE(c.reoriented);
    EXPECT_EQ(c.cell_volume, 1);
  }
  ASSERT_EQ(k.warnings.size(), 1u);
  EXPECT_EQ(k.warnings[0].count, 2u);
}

TEST(CellSurface, Errors) {
  kergen::VolumeMesh m = two_cubes();
  EXPECT_EQ(kergen::cell_surface(m, 2).error, kergen::Error::InvalidArgument);
  m.cell_faces[3] = 77;
  const kergen::CellSurface s = kergen::cell_surface(m, 0);
  EXPECT_EQ(s.error, kergen::Error::IndexOutOfRange);
  EXPECT_NE(s.message.find("cell 0: face 77"), std::string::npos) << s.message;
  m = two_cubes();
  m.face_indices[0] = 1000;
  EXPECT_EQ(kergen::cell_surface(m, 0).error, kergen::Error::IndexOutOfRange);
  EXPECT_TRUE(kergen::cell_surface(m, 1).ok());
}

}  // namespace
