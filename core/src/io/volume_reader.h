// volume_reader.h — what the volume mesh readers (vtu.cpp, vtk_legacy.cpp, node_ele.cpp) share,
// private to io/: the run that turns a ReadFailure (reader.h) into a VolumeReadResult, the mesh
// being built (faces and cells appended with their offsets, sizes checked against 32-bit
// offsets), the faces of VTK's cell types, and base64.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "io/reader.h"
#include "kergen/volume.h"

namespace kergen::io {

// Runs one volume reader's body: a ReadFailure, or running out of memory, becomes the result's error.
VolumeReadResult run_volume_reader(const std::function<void(VolumeMesh&)>& body);

// Builds a VolumeMesh: faces appended one at a time, each added to the open cell.
class VolumeBuilder {
 public:
  explicit VolumeBuilder(VolumeMesh& mesh);
  // Appends a face (vertex ids already checked) to the mesh and to the current cell.
  void add_face(const uint32_t* loop, size_t size);
  void add_face(std::initializer_list<uint32_t> loop) { add_face(loop.begin(), loop.size()); }
  // Closes the current cell (its faces are those added since the previous end_cell).
  void end_cell();
  VolumeMesh& mesh() { return mesh_; }

 private:
  VolumeMesh& mesh_;
};

// VTK cell types read by both VTK readers.
constexpr int64_t kVtkTetra = 10, kVtkHexahedron = 12, kVtkWedge = 13, kVtkPyramid = 14, kVtkPolyhedron = 42;

// Appends one VTK cell as a closed cell of the builder: a linear cell (tetra, hexahedron, wedge,
// pyramid) from its point ids, or a polyhedron from its face stream
// [nfaces, (npts, id...) per face]. Ids are offset by `point_base` and must be below
// `num_points` (before the offset). Returns "" or why the cell is refused (the caller names
// where).
std::string append_vtk_cell(VolumeBuilder& builder, int64_t type, const int64_t* data, size_t size, uint64_t point_base,
                            uint64_t num_points);

// Standard base64 (RFC 4648, '+' '/' and '=' padding); whitespace is skipped. Appends the decoded
// bytes to `out`; returns false on a character outside the alphabet or misplaced padding, with
// `bad_at` its offset in `text`. Stops after the first padded quantum when `stop_at_padding`.
bool base64_decode(std::string_view text, std::string& out, size_t& bad_at, bool stop_at_padding = false,
                   size_t* consumed = nullptr);

}  // namespace kergen::io
