// Shared body of the volume reader fuzz targets (fuzz_vtu, fuzz_vtk_legacy, fuzz_node_ele): parse
// the bytes; a refusal must be a reader error with a message; whatever parses must be a
// well-formed VolumeMesh (offsets, ids in range, finite coordinates), must survive the VTU writer
// and read_vtu bit for bit, and its cells (when few) go through compute_cell_kernels, which must
// give a record per cell and never Error::Internal.
#pragma once

#include <cmath>
#include <cstring>
#include <string>

#include "invariants.h"
#include "kergen/volume.h"

namespace kfuzz {

inline void check_offsets(const std::vector<uint32_t>& offsets, size_t target, const char* what) {
  if (offsets.empty()) return;
  KFUZZ_CHECK(offsets[0] == 0, std::string(what) + " do not start at 0");
  for (size_t i = 1; i < offsets.size(); ++i)
    KFUZZ_CHECK(offsets[i] >= offsets[i - 1], std::string(what) + " decrease");
  KFUZZ_CHECK(offsets.back() == target, std::string(what) + " do not end at the array's size");
}

inline void fuzz_volume(const kergen::VolumeReadResult& r) {
  using kergen::Error;
  if (!r.ok()) {
    KFUZZ_CHECK(r.error == Error::ParseError || r.error == Error::EmptyInput || r.error == Error::TooLarge,
                std::string("volume reader returned ") + kergen::error_name(r.error));
    KFUZZ_CHECK(!r.message.empty() && r.message.size() < 4096, "volume reader message empty or huge");
    return;
  }
  const kergen::VolumeMesh& m = r.mesh;
  KFUZZ_CHECK(m.positions.size() % 3 == 0, "positions not xyz triples");
  for (double c : m.positions) KFUZZ_CHECK(std::isfinite(c), "reader accepted a non-finite coordinate");
  check_offsets(m.face_offsets, m.face_indices.size(), "face_offsets");
  check_offsets(m.cell_offsets, m.cell_faces.size(), "cell_offsets");
  for (uint32_t v : m.face_indices) KFUZZ_CHECK(v < m.num_vertices(), "reader accepted an out-of-range vertex");
  for (uint32_t f : m.cell_faces) KFUZZ_CHECK(f < m.num_faces(), "reader accepted an out-of-range face");
  if (m.face_indices.size() > 4000) return;  // keep one run fast
  const kergen::CellKernels run = kergen::compute_cell_kernels(m);
  KFUZZ_CHECK(run.ok() && run.cells.size() == m.num_cells(), "compute_cell_kernels: " + run.message);
  for (const kergen::CellKernel& c : run.cells) {
    KFUZZ_CHECK(c.error != Error::Internal, c.message);
    if (c.ok()) KFUZZ_CHECK(c.kernel_volume >= 0 && c.kernel_ratio >= 0, "negative kernel volume or ratio");
  }
  const kergen::VolumeReadResult back = kergen::read_vtu(kergen::write_vtu_with_cell_data(m, run.cells), "back.vtu");
  KFUZZ_CHECK(back.ok(), "the VTU writer's file does not read back: " + back.message);
  KFUZZ_CHECK(
      back.mesh.positions.size() == m.positions.size() &&
          (m.positions.empty() ||  // memcmp must not see the null data() of empty vectors
           std::memcmp(back.mesh.positions.data(), m.positions.data(), m.positions.size() * sizeof(double)) == 0),
      "VTU round trip changed the coordinates");
  KFUZZ_CHECK(back.mesh.face_indices == m.face_indices || m.cell_faces.size() != m.num_faces(),
              "VTU round trip changed the faces");
  KFUZZ_CHECK(back.mesh.num_cells() == m.num_cells(), "VTU round trip changed the cell count");
}

}  // namespace kfuzz
