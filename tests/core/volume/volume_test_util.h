// Helpers of the volume mesh tests (tests/core/io/vtu_test.cpp, vtk_legacy_test.cpp,
// node_ele_test.cpp, tests/core/volume/): VTU text written here, independently of the reader,
// a base64 encoder, and small meshes whose kernels are known.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "kergen/volume.h"

namespace volume_test {

inline std::string join(const std::vector<long long>& v) {
  std::string s;
  for (size_t i = 0; i < v.size(); ++i) s += (i ? " " : "") + std::to_string(v[i]);
  return s;
}

inline std::string base64(const std::string& bytes) {
  static const char* abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    uint32_t q = uint32_t(uint8_t(bytes[i])) << 16;
    if (i + 1 < bytes.size()) q |= uint32_t(uint8_t(bytes[i + 1])) << 8;
    if (i + 2 < bytes.size()) q |= uint32_t(uint8_t(bytes[i + 2]));
    out += abc[q >> 18 & 63];
    out += abc[q >> 12 & 63];
    out += i + 1 < bytes.size() ? abc[q >> 6 & 63] : '=';
    out += i + 2 < bytes.size() ? abc[q & 63] : '=';
  }
  return out;
}

// Little-endian bytes of values of `size` bytes each.
template <class T>
std::string le_bytes(const std::vector<T>& values, size_t size) {
  std::string out;
  for (T v : values) {
    uint64_t bits = 0;
    std::memcpy(&bits, &v, sizeof(T));
    for (size_t i = 0; i < size; ++i) out.push_back(char(bits >> (8 * i) & 0xff));
  }
  return out;
}

// One of each linear cell and a cube polyhedron, apart from each other: unit-size tetra (volume
// 1/6), hexahedron (1), wedge (1/2), pyramid (1/3), polyhedron cube (1).
struct LinearCells {
  std::vector<double> points;
  std::vector<long long> connectivity, offsets, types, faces, faceoffsets;
  LinearCells() {
    auto add = [&](std::vector<std::vector<double>> pts, double dx, int type) {
      const long long base = (long long)points.size() / 3;
      for (auto& p : pts) points.insert(points.end(), {p[0] + dx, p[1], p[2]});
      for (size_t i = 0; i < pts.size(); ++i) connectivity.push_back(base + (long long)i);
      offsets.push_back((long long)connectivity.size());
      types.push_back(type);
      faceoffsets.push_back(-1);
    };
    add({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, 0, 10);
    add({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}, 2, 12);
    add({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}}, 4, 13);
    add({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}}, 6, 14);
    // The polyhedron: the hexahedron's points, its faces listed explicitly.
    const long long hex = 4;
    faces = {6};
    for (std::vector<long long> f :
         {std::vector<long long>{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}) {
      faces.push_back(4);
      for (long long v : f) faces.push_back(hex + v);
    }
    for (long long v = 0; v < 8; ++v) connectivity.push_back(hex + v);
    offsets.push_back((long long)connectivity.size());
    types.push_back(42);
    faceoffsets.push_back((long long)faces.size());
  }
  std::vector<double> volumes() const { return {1.0 / 6, 1, 0.5, 1.0 / 3, 1}; }
};

inline std::string vtu_ascii(const LinearCells& c) {
  std::string pts;
  for (double p : c.points) pts += std::to_string(p) + " ";
  return "<?xml version=\"1.0\"?>\n<!-- a comment <Piece> -->\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
         "<UnstructuredGrid><Piece NumberOfPoints=\"" +
         std::to_string(c.points.size() / 3) + "\" NumberOfCells=\"" + std::to_string(c.types.size()) +
         "\">\n<PointData/><Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n" + pts +
         "\n<InformationKey name=\"x\"><Value index=\"0\">1</Value></InformationKey></DataArray></Points>\n<Cells>\n"
         "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">" +
         join(c.connectivity) + "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">" +
         join(c.offsets) + "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">" + join(c.types) +
         "</DataArray>\n<DataArray type=\"Int64\" Name=\"faces\" format=\"ascii\">\n" + join(c.faces) +
         "\n</DataArray>\n<DataArray type=\"Int64\" Name=\"faceoffsets\" format=\"ascii\">" + join(c.faceoffsets) +
         "</DataArray>\n</Cells></Piece></UnstructuredGrid></VTKFile>\n";
}

inline std::vector<double> kernel_volumes(const kergen::VolumeMesh& mesh) {
  std::vector<double> out;
  for (const kergen::CellKernel& c : kergen::compute_cell_kernels(mesh).cells) out.push_back(c.kernel_volume);
  return out;
}

}  // namespace volume_test
