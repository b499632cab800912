// volume_reader.cpp — the volume mesh readers' shared parts (volume_reader.h).
#include "io/volume_reader.h"

#include <limits>
#include <new>
#include <stdexcept>

namespace kergen::io {

VolumeReadResult run_volume_reader(const std::function<void(VolumeMesh&)>& body) {
  VolumeReadResult result;
  try {
    body(result.mesh);
  } catch (const ReadFailure& failure) {
    result = VolumeReadResult{};
    result.error = failure.error;
    result.message = failure.message;
  } catch (const std::bad_alloc&) {
    result = VolumeReadResult{};
    result.error = Error::TooLarge;
    result.message = "out of memory while reading the volume mesh";
  } catch (const std::length_error&) {
    result = VolumeReadResult{};
    result.error = Error::TooLarge;
    result.message = "volume mesh too large to hold in memory";
  }
  return result;
}

VolumeBuilder::VolumeBuilder(VolumeMesh& mesh) : mesh_(mesh) {
  mesh_.face_offsets.assign(1, 0);
  mesh_.cell_offsets.assign(1, 0);
}

namespace {
// Offsets and ids are 32-bit: a mesh past that is refused rather than wrapped.
void check_fits(size_t size, const char* what) {
  if (size > std::numeric_limits<uint32_t>::max())
    fail(Error::TooLarge, std::string("more than 4294967295 ") + what + " (offsets are 32-bit)");
}
}  // namespace

void VolumeBuilder::add_face(const uint32_t* loop, size_t size) {
  check_fits(mesh_.face_indices.size() + size, "face corners");
  check_fits(mesh_.face_offsets.size(), "faces");
  check_fits(mesh_.cell_faces.size() + 1, "cell faces");
  mesh_.face_indices.insert(mesh_.face_indices.end(), loop, loop + size);
  mesh_.face_offsets.push_back(static_cast<uint32_t>(mesh_.face_indices.size()));
  mesh_.cell_faces.push_back(static_cast<uint32_t>(mesh_.face_offsets.size() - 2));
}

void VolumeBuilder::end_cell() {
  check_fits(mesh_.cell_offsets.size(), "cells");
  mesh_.cell_offsets.push_back(static_cast<uint32_t>(mesh_.cell_faces.size()));
}

namespace {

// The faces of VTK's linear cells by local point number (VTK file formats, "Linear cell types"),
// each counter-clockwise seen from outside for a cell of positive orientation. -1 ends a face.
struct CellShape {
  int64_t type;
  size_t points;
  const char* name;
  std::initializer_list<int> faces;
};
const CellShape kShapes[] = {
    {kVtkTetra, 4, "tetra", {0, 2, 1, -1, 0, 1, 3, -1, 1, 2, 3, -1, 0, 3, 2, -1}},
    {kVtkHexahedron, 8, "hexahedron", {0, 3, 2, 1, -1, 4, 5, 6, 7, -1, 0, 1, 5, 4, -1,
                                       1, 2, 6, 5, -1, 2, 3, 7, 6, -1, 3, 0, 4, 7, -1}},
    {kVtkWedge, 6, "wedge", {0, 1, 2, -1, 3, 5, 4, -1, 0, 3, 4, 1, -1, 1, 4, 5, 2, -1, 2, 5, 3, 0, -1}},
    {kVtkPyramid, 5, "pyramid", {0, 3, 2, 1, -1, 0, 1, 4, -1, 1, 2, 4, -1, 2, 3, 4, -1, 3, 0, 4, -1}},
};

bool point_id(int64_t id, uint64_t point_base, uint64_t num_points, uint32_t& out, std::string& why) {
  if (id < 0 || uint64_t(id) >= num_points) {
    why = "point id " + std::to_string(id) + " out of range (there are " + std::to_string(num_points) + " points)";
    return false;
  }
  const uint64_t global = point_base + uint64_t(id);
  if (global > std::numeric_limits<uint32_t>::max()) fail(Error::TooLarge, "more than 4294967295 points");
  out = static_cast<uint32_t>(global);
  return true;
}

std::string append_polyhedron(VolumeBuilder& builder, const int64_t* data, size_t size, uint64_t point_base,
                              uint64_t num_points) {
  if (size == 0) return "polyhedron without its face count";
  const int64_t faces = data[0];
  if (faces < 0) return "negative face count " + std::to_string(faces);
  size_t at = 1;
  std::vector<uint32_t> loop;
  std::string why;
  for (int64_t f = 0; f < faces; ++f) {
    if (at >= size)
      return "the face stream ends after " + std::to_string(f) + " of " + std::to_string(faces) + " faces";
    const int64_t n = data[at++];
    if (n < 0 || uint64_t(n) > size - at)
      return "face " + std::to_string(f) + " claims " + std::to_string(n) + " points, more than the stream holds";
    loop.resize(size_t(n));
    for (int64_t k = 0; k < n; ++k)
      if (!point_id(data[at + size_t(k)], point_base, num_points, loop[size_t(k)], why))
        return "face " + std::to_string(f) + ": " + why;
    at += size_t(n);
    builder.add_face(loop.data(), loop.size());
  }
  if (at != size)
    return "the face stream holds " + std::to_string(size - at) + " values after its " + std::to_string(faces) +
           " faces";
  builder.end_cell();
  return "";
}

}  // namespace

std::string append_vtk_cell(VolumeBuilder& builder, int64_t type, const int64_t* data, size_t size, uint64_t point_base,
                            uint64_t num_points) {
  if (type == kVtkPolyhedron) return append_polyhedron(builder, data, size, point_base, num_points);
  for (const CellShape& shape : kShapes) {
    if (shape.type != type) continue;
    if (size != shape.points)
      return std::string(shape.name) + " with " + std::to_string(size) + " points (needs " +
             std::to_string(shape.points) + ")";
    uint32_t ids[8];
    std::string why;
    for (size_t k = 0; k < size; ++k)
      if (!point_id(data[k], point_base, num_points, ids[k], why)) return why;
    std::vector<uint32_t> loop;
    for (int local : shape.faces) {
      if (local >= 0) {
        loop.push_back(ids[local]);
        continue;
      }
      builder.add_face(loop.data(), loop.size());
      loop.clear();
    }
    builder.end_cell();
    return "";
  }
  return "VTK cell type " + std::to_string(type) +
         " is not a volume cell read here (polyhedron 42, tetra 10, hexahedron 12, wedge 13, pyramid 14)";
}

namespace {
// The alphabet's values by byte, -1 elsewhere (a table: decoding runs per byte of large arrays).
struct Base64Table {
  int8_t value[256];
  constexpr Base64Table() : value() {
    for (int c = 0; c < 256; ++c) value[c] = -1;
    for (int c = 'A'; c <= 'Z'; ++c) value[c] = int8_t(c - 'A');
    for (int c = 'a'; c <= 'z'; ++c) value[c] = int8_t(c - 'a' + 26);
    for (int c = '0'; c <= '9'; ++c) value[c] = int8_t(c - '0' + 52);
    value[int('+')] = 62;
    value[int('/')] = 63;
  }
};
constexpr Base64Table kBase64;
int base64_value(unsigned char c) { return kBase64.value[c]; }
bool is_space(unsigned char c) { return c == ' ' || c == '\n' || c == '\r' || c == '\t' || c == '\f' || c == '\v'; }
}  // namespace

bool base64_decode(std::string_view text, std::string& out, size_t& bad_at, bool stop_at_padding, size_t* consumed) {
  out.reserve(out.size() + text.size() / 4 * 3 + 3);
  uint32_t quantum = 0;
  int have = 0, padding = 0;
  size_t i = 0;
  for (; i < text.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (is_space(c)) continue;
    if (c == '=') {
      if (have < 2) return bad_at = i, false;
      ++padding;
      quantum <<= 6;
      if (++have < 4) continue;
    } else {
      const int v = base64_value(c);
      if (v < 0 || padding > 0) return bad_at = i, false;
      quantum = quantum << 6 | uint32_t(v);
      if (++have < 4) continue;
    }
    out.push_back(static_cast<char>(quantum >> 16));
    if (padding < 2) out.push_back(static_cast<char>(quantum >> 8 & 0xff));
    if (padding < 1) out.push_back(static_cast<char>(quantum & 0xff));
    quantum = 0;
    have = 0;
    if (padding > 0) {
      padding = 0;
      if (stop_at_padding) {
        ++i;
        break;
      }
    }
  }
  if (consumed) *consumed = i;
  if (have != 0) return bad_at = text.size(), false;
  return true;
}

}  // namespace kergen::io
