// vtu_writer.cpp — a volume mesh and its per-cell results as a VTK XML UnstructuredGrid
// (write_vtu_with_cell_data, volume.h), for ParaView: every cell a VTK_POLYHEDRON (42) with
// its faces as stored, in the layout VTK 9.1 to 9.3 and meshio read (connectivity = the cell's
// points, faces = [nfaces, (npts, ids...)...] per cell, faceoffsets = each cell's end in faces;
// VTK File Formats, "XML File Formats"; vtk.org/Wiki/VTK/Polyhedron_Support). Arrays are appended
// raw little-endian binary (header_type UInt64): compact, and every double kept exactly.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/reader.h"
#include "kergen/volume.h"

namespace kergen {

namespace {

void put_le(std::string& out, uint64_t v, size_t size) {
  for (size_t i = 0; i < size; ++i) out.push_back(static_cast<char>(v >> (8 * i) & 0xff));
}

// The XML declarations and the appended block, built together: each array's offset is where its
// bytes start in the block.
class VtuArrays {
 public:
  template <class Fill>
  void add(std::string& xml, const char* type, const char* name, int components, size_t count, size_t value_size,
           Fill fill) {
    xml += "        <DataArray type=\"" + std::string(type) + "\" Name=\"" + name + "\"";
    if (components > 1) xml += " NumberOfComponents=\"" + std::to_string(components) + "\"";
    xml += " format=\"appended\" offset=\"" + std::to_string(block_.size()) + "\"/>\n";
    put_le(block_, uint64_t(count) * value_size, 8);
    const size_t before = block_.size();
    fill(block_);
    if (block_.size() - before != count * value_size) throw std::logic_error("VTU array size mismatch");
  }
  const std::string& block() const { return block_; }

 private:
  std::string block_;
};

uint64_t double_bits(double d) {
  uint64_t bits;
  std::memcpy(&bits, &d, 8);
  return bits;
}

// The ids the file will hold must exist (the offsets are checked as compute_cell_kernels checks them).
void check_mesh(const VolumeMesh& mesh, const std::vector<CellKernel>& cells) {
  auto refuse = [](const std::string& why) { throw std::invalid_argument("write_vtu_with_cell_data: " + why); };
  if (cells.size() != mesh.num_cells())
    refuse(std::to_string(cells.size()) + " results for " + std::to_string(mesh.num_cells()) + " cells");
  auto monotone = [](const std::vector<uint32_t>& offsets, size_t size) {
    for (size_t i = 1; i < offsets.size(); ++i)
      if (offsets[i] < offsets[i - 1]) return false;
    return offsets.empty() || (offsets[0] == 0 && offsets.back() <= size);
  };
  if (!monotone(mesh.face_offsets, mesh.face_indices.size()) || !monotone(mesh.cell_offsets, mesh.cell_faces.size()))
    refuse("malformed offsets");
  for (uint32_t v : mesh.face_indices)
    if (v >= mesh.num_vertices()) refuse("a face uses vertex " + std::to_string(v) + ", which does not exist");
  for (uint32_t f : mesh.cell_faces)
    if (f >= mesh.num_faces()) refuse("a cell names face " + std::to_string(f) + ", which does not exist");
}

// Per cell: its sorted distinct points (connectivity) and its face stream.
void cell_streams(const VolumeMesh& mesh, std::vector<uint64_t>& connectivity, std::vector<uint64_t>& offsets,
                  std::vector<uint64_t>& faces, std::vector<uint64_t>& faceoffsets) {
  std::vector<uint32_t> points;
  for (size_t c = 0; c < mesh.num_cells(); ++c) {
    points.clear();
    faces.push_back(mesh.cell_offsets[c + 1] - mesh.cell_offsets[c]);
    for (uint32_t k = mesh.cell_offsets[c]; k < mesh.cell_offsets[c + 1]; ++k) {
      const uint32_t f = mesh.cell_faces[k];
      faces.push_back(mesh.face_offsets[f + 1] - mesh.face_offsets[f]);
      for (uint32_t i = mesh.face_offsets[f]; i < mesh.face_offsets[f + 1]; ++i) {
        faces.push_back(mesh.face_indices[i]);
        points.push_back(mesh.face_indices[i]);
      }
    }
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
    connectivity.insert(connectivity.end(), points.begin(), points.end());
    offsets.push_back(connectivity.size());
    faceoffsets.push_back(faces.size());
  }
}

void add_u64s(VtuArrays& arrays, std::string& xml, const char* name, const std::vector<uint64_t>& values) {
  arrays.add(xml, "Int64", name, 1, values.size(), 8, [&](std::string& b) {
    for (uint64_t v : values) put_le(b, v, 8);
  });
}

void add_cell_doubles(VtuArrays& arrays, std::string& xml, const char* name, const std::vector<CellKernel>& cells,
                      double (*value)(const CellKernel&)) {
  arrays.add(xml, "Float64", name, 1, cells.size(), 8, [&](std::string& b) {
    for (const CellKernel& c : cells) put_le(b, double_bits(value(c)), 8);
  });
}

// Error cells have no kernel: NaN, which ParaView shows in its NaN colour.
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

std::string write_vtu_with_cell_data(const VolumeMesh& mesh, const std::vector<CellKernel>& cells) {
  check_mesh(mesh, cells);
  std::vector<uint64_t> connectivity, offsets, faces, faceoffsets;
  cell_streams(mesh, connectivity, offsets, faces, faceoffsets);
  std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
      "  <UnstructuredGrid>\n"
      "    <Piece NumberOfPoints=\"" +
      std::to_string(mesh.num_vertices()) + "\" NumberOfCells=\"" + std::to_string(mesh.num_cells()) + "\">\n";
  VtuArrays arrays;
  xml += "      <Points>\n";
  arrays.add(xml, "Float64", "Points", 3, mesh.positions.size(), 8, [&](std::string& b) {
    for (double p : mesh.positions) put_le(b, double_bits(p), 8);
  });
  xml += "      </Points>\n      <Cells>\n";
  add_u64s(arrays, xml, "connectivity", connectivity);
  add_u64s(arrays, xml, "offsets", offsets);
  arrays.add(xml, "UInt8", "types", 1, mesh.num_cells(), 1,
             [&](std::string& b) { b.append(mesh.num_cells(), char(42)); });
  add_u64s(arrays, xml, "faces", faces);
  add_u64s(arrays, xml, "faceoffsets", faceoffsets);
  xml += "      </Cells>\n      <CellData Scalars=\"kernel_status\">\n";
  arrays.add(xml, "Int32", "kernel_status", 1, cells.size(), 4, [&](std::string& b) {
    for (const CellKernel& c : cells) put_le(b, uint32_t(cell_status_code(c)), 4);
  });
  add_cell_doubles(arrays, xml, "kernel_volume", cells,
                   [](const CellKernel& c) { return c.ok() ? c.kernel_volume : kNaN; });
  add_cell_doubles(arrays, xml, "cell_volume", cells,
                   [](const CellKernel& c) { return c.ok() ? c.cell_volume : kNaN; });
  add_cell_doubles(arrays, xml, "kernel_ratio", cells,
                   [](const CellKernel& c) { return c.ok() ? c.kernel_ratio : kNaN; });
  add_cell_doubles(arrays, xml, "inscribed_radius", cells,
                   [](const CellKernel& c) { return c.ok() ? c.inscribed_radius : kNaN; });
  add_cell_doubles(arrays, xml, "rho_over_h", cells, [](const CellKernel& c) { return c.ok() ? c.rho_over_h : kNaN; });
  add_cell_doubles(arrays, xml, "diameter", cells,
                   [](const CellKernel& c) { return c.diameter > 0 ? c.diameter : kNaN; });
  xml += "      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n  <AppendedData encoding=\"raw\">\n   _";
  xml += arrays.block();
  xml += "\n  </AppendedData>\n</VTKFile>\n";
  return xml;
}

Error write_vtu_with_cell_data_file(const std::string& path, const VolumeMesh& mesh,
                                    const std::vector<CellKernel>& cells, std::string* message) {
  std::string bytes;
  try {
    bytes = write_vtu_with_cell_data(mesh, cells);
  } catch (const std::invalid_argument& e) {
    if (message) *message = path + ": " + e.what();
    return Error::InvalidArgument;
  } catch (const std::bad_alloc&) {
    if (message) *message = path + ": out of memory while formatting the mesh";
    return Error::IoError;
  }
  return io::write_file_bytes(path, bytes, message);
}

}  // namespace kergen
