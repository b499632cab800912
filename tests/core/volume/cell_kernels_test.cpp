// compute_cell_kernels: each record is compute_kernel on cell_surface (exactly), ranges give the
// same records as the whole run, the numbers derived from the kernel (diameter, rho / h, the
// witness in local and global face ids), the summary, and the VTU writer read back by read_vtu.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "kergen/volume.h"
#include "volume/volume_test_util.h"

namespace {

using namespace volume_test;

kergen::VolumeMesh linear_cells() { return kergen::read_vtu(vtu_ascii(LinearCells()), "c.vtu").mesh; }

// A U-shaped prism (not star-shaped) as one polyhedron, plus the linear cells.
kergen::VolumeMesh with_u_shape() {
  kergen::VolumeMesh m = linear_cells();
  const uint32_t base = uint32_t(m.num_vertices());
  // U in the xy-plane (x 0..3, y 0..2, notch x 1..2, y 1..2), extruded z 0..1, at y = 5.
  const double xy[8][2] = {{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  for (int z = 0; z < 2; ++z)
    for (auto& p : xy) m.positions.insert(m.positions.end(), {p[0], p[1] + 5, double(z)});
  auto face = [&](std::vector<uint32_t> f) {
    for (uint32_t& v : f) v += base;
    m.face_indices.insert(m.face_indices.end(), f.begin(), f.end());
    m.face_offsets.push_back(uint32_t(m.face_indices.size()));
    m.cell_faces.push_back(uint32_t(m.face_offsets.size() - 2));
  };
  face({7, 6, 5, 4, 3, 2, 1, 0});
  face({8, 9, 10, 11, 12, 13, 14, 15});
  for (uint32_t i = 0; i < 8; ++i) face({i, (i + 1) % 8, 8 + (i + 1) % 8, 8 + i});
  m.cell_offsets.push_back(uint32_t(m.cell_faces.size()));
  return m;
}

TEST(CellKernels, EachRecordIsTheCellAlone) {
  const kergen::VolumeMesh m = with_u_shape();
  kergen::CellOptions o;
  o.deepest_point = true;
  const kergen::CellKernels run = kergen::compute_cell_kernels(m, o);
  ASSERT_TRUE(run.ok());
  ASSERT_EQ(run.cells.size(), 6u);
  kergen::Options ko;
  ko.deepest_point = true;
  for (size_t c = 0; c < 6; ++c) {
    const kergen::Kernel k = kergen::compute_kernel(kergen::cell_surface(m, c).mesh.view(), ko);
    const kergen::CellKernel& r = run.cells[c];
    EXPECT_EQ(r.type, k.type);
    EXPECT_EQ(r.kernel_volume, k.volume);
    EXPECT_EQ(r.cell_volume, k.shape_volume);
    EXPECT_EQ(r.inscribed_radius, k.inscribed_radius);
    EXPECT_EQ(r.witness_faces, k.witness_faces);
  }
  // The U: empty, its witness the two inner walls (local faces 2 + 3 and 2 + 5: x = 2 facing -x,
  // x = 1 facing +x), named globally through the cell's face list.
  const kergen::CellKernel& u = run.cells[5];
  EXPECT_EQ(u.type, kergen::KernelType::Empty);
  EXPECT_EQ(u.witness_faces, (std::vector<uint32_t>{5, 7}));
  ASSERT_EQ(u.witness_global_faces.size(), 2u);
  for (size_t i = 0; i < 2; ++i)
    EXPECT_EQ(u.witness_global_faces[i], m.cell_faces[m.cell_offsets[5] + u.witness_faces[i]]);
  EXPECT_EQ(u.kernel_ratio, 0);
  EXPECT_EQ(u.rho_over_h, 0);
  // The hexahedron: h = sqrt(3), rho = 1/2 (bisection: within 1e-9).
  const kergen::CellKernel& hex = run.cells[1];
  EXPECT_EQ(hex.diameter, std::sqrt(3.0));
  EXPECT_NEAR(hex.inscribed_radius, 0.5, 1e-9);
  EXPECT_NEAR(hex.rho_over_h, 0.5 / std::sqrt(3.0), 1e-9);
  EXPECT_EQ(kergen::cell_status_code(hex), 4);
}

TEST(CellKernels, RangesAndProgress) {
  const kergen::VolumeMesh m = with_u_shape();
  const kergen::CellKernels all = kergen::compute_cell_kernels(m);
  std::vector<size_t> progress;
  kergen::CellOptions o;
  o.progress_every = 2;
  o.on_progress = [&](size_t done, size_t total) {
    EXPECT_EQ(total, 4u);
    progress.push_back(done);
  };
  const kergen::CellKernels part = kergen::compute_cell_kernels(m, o, 2, 4);
  ASSERT_EQ(part.cells.size(), 4u);
  for (size_t i = 0; i < 4; ++i) EXPECT_EQ(part.cells[i].kernel_volume, all.cells[2 + i].kernel_volume);
  EXPECT_EQ(progress, (std::vector<size_t>{2, 4}));
  EXPECT_EQ(kergen::compute_cell_kernels(m, {}, 4).cells.size(), 2u);  // clipped to the end
  EXPECT_EQ(kergen::compute_cell_kernels(m, {}, 7).error, kergen::Error::InvalidArgument);
  kergen::VolumeMesh bad = m;
  bad.cell_offsets[2] = 1000;
  EXPECT_EQ(kergen::compute_cell_kernels(bad).error, kergen::Error::InvalidArgument);
}

TEST(CellKernels, Summary) {
  const kergen::CellKernels run = kergen::compute_cell_kernels(with_u_shape());
  const kergen::CellSummary s = kergen::summarize_cells(run.cells, 2, 100);
  EXPECT_EQ(s.cells, 6u);
  EXPECT_EQ(s.ok_cells, 6u);
  EXPECT_EQ(s.by_type[size_t(kergen::KernelType::Polyhedron)], 5u);
  EXPECT_EQ(s.by_type[size_t(kergen::KernelType::Empty)], 1u);
  EXPECT_EQ(s.min_ratio, 0);
  EXPECT_EQ(s.median_ratio, 1);  // lower middle of 0 1 1 1 1 1
  EXPECT_FALSE(s.has_rho_over_h);
  EXPECT_EQ(s.worst_cells, (std::vector<size_t>{105, 100}));
}

TEST(CellKernels, VtuWriterReadsBack) {
  const kergen::VolumeMesh m = with_u_shape();
  const kergen::CellKernels run = kergen::compute_cell_kernels(m);
  const std::string vtu = kergen::write_vtu_with_cell_data(m, run.cells);
  const kergen::VolumeReadResult back = kergen::read_vtu(vtu, "out.vtu");
  ASSERT_TRUE(back.ok()) << back.message;
  EXPECT_EQ(back.mesh.positions, m.positions);
  ASSERT_EQ(back.mesh.num_cells(), m.num_cells());
  const kergen::CellKernels again = kergen::compute_cell_kernels(back.mesh);
  for (size_t c = 0; c < m.num_cells(); ++c) EXPECT_EQ(again.cells[c].kernel_volume, run.cells[c].kernel_volume);
  EXPECT_THROW(kergen::write_vtu_with_cell_data(m, {}), std::invalid_argument);
}

}  // namespace
