// Helpers shared by the reader and writer tests of tests/core/io/: meshes and comparisons, the
// expected-error table, and test files written independently of the readers (an ASCII STL
// tetrahedron, PLY in every encoding).
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "kergen/io.h"

namespace io_test {

namespace fs = std::filesystem;
using kergen::Error;
using kergen::Mesh;
using kergen::ReadResult;

// A unit cube with quad faces, outward (counter-clockwise seen from outside).
inline Mesh quad_cube(double size = 1.0) {
  Mesh m;
  for (int i = 0; i < 8; ++i) {
    m.positions.push_back((i & 1) ? size : 0.0);
    m.positions.push_back((i & 2) ? size : 0.0);
    m.positions.push_back((i & 4) ? size : 0.0);
  }
  m.indices = {0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4, 2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5};
  m.face_sizes = {4, 4, 4, 4, 4, 4};
  return m;
}

// Same polygon soup regardless of whether sizes are implicit (all triangles) or explicit.
inline std::vector<uint32_t> sizes_of(const Mesh& m) {
  return m.face_sizes.empty() ? std::vector<uint32_t>(m.indices.size() / 3, 3) : m.face_sizes;
}

inline void expect_same_mesh(const Mesh& expected, const Mesh& actual) {
  ASSERT_EQ(expected.positions.size(), actual.positions.size());
  for (size_t i = 0; i < expected.positions.size(); ++i) EXPECT_EQ(expected.positions[i], actual.positions[i]) << i;
  EXPECT_EQ(expected.indices, actual.indices);
  EXPECT_EQ(sizes_of(expected), sizes_of(actual));
}

// Triangles as sets of 3 points (order within a triangle kept), for meshes that went through STL
// (float coordinates, welded vertices renumbered).
inline std::multiset<std::vector<float>> triangle_set(const Mesh& m) {
  std::multiset<std::vector<float>> out;
  std::vector<uint32_t> sizes = sizes_of(m);
  size_t offset = 0;
  for (uint32_t k : sizes) {
    for (uint32_t j = 1; j + 1 < k; ++j) {
      std::vector<float> t;
      for (uint32_t v : {m.indices[offset], m.indices[offset + j], m.indices[offset + j + 1]})
        for (int d = 0; d < 3; ++d) t.push_back(static_cast<float>(m.positions[3 * v + d]));
      out.insert(t);
    }
    offset += k;
  }
  return out;
}

inline std::string shared_meshes() { return KERGEN_SHARED_MESHES; }

#define REQUIRE_SHARED_MESHES()                                                                   \
  do {                                                                                            \
    if (!fs::is_directory(shared_meshes() + "/fixtures"))                                         \
      GTEST_SKIP() << "shared meshes not found at " << shared_meshes() << " (fixtures/ missing)"; \
  } while (0)

inline fs::path temp_dir() {
  fs::path dir = fs::temp_directory_path() / ("kergen_io_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

inline bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

struct ErrorCase {
  std::string text;
  Error error;
  const char* message_part;
};

inline void expect_errors(ReadResult (*reader)(std::string_view, const std::string&),
                          const std::vector<ErrorCase>& cases) {
  for (const ErrorCase& c : cases) {
    ReadResult r = reader(c.text, "in.txt");
    EXPECT_EQ(r.error, c.error) << c.text << "\n-> " << r.message;
    EXPECT_TRUE(contains(r.message, c.message_part)) << "expected '" << c.message_part << "' in: " << r.message;
    EXPECT_TRUE(r.mesh.positions.empty() && r.mesh.indices.empty()) << "a failed read returns no mesh";
  }
}

inline std::string ascii_tetra_stl(const char* solid_name = "tet") {
  const double v[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  std::string s = std::string("solid ") + solid_name + "\n";
  for (const auto& f : faces) {
    s += "  facet normal 0 0 0\n    outer loop\n";
    for (int k : f) {
      char line[128];
      std::snprintf(line, sizeof line, "      vertex %.17g %.17g %.17g\n", v[k][0], v[k][1], v[k][2]);
      s += line;
    }
    s += "    endloop\n  endfacet\n";
  }
  return s + "endsolid " + solid_name + "\n";
}

enum class Ply { Ascii, LittleEndian, BigEndian };

// A PLY file of a mesh, written here independently of the reader. `vertex_types` are the types
// of x, y, z; with `extras`, properties and elements the reader must read past surround the ones
// it uses: a comment and obj_info, vertex properties before x and after z (a list among them), an
// edge element between vertex and face, face properties before and after the index list.
struct PlyOptions {
  Ply encoding = Ply::Ascii;
  const char* vertex_types[3] = {"double", "double", "double"};
  const char* count_type = "uchar";
  const char* index_type = "int";
  const char* index_name = "vertex_indices";
  bool extras = false;
};

inline void put_ply_value(std::string& out, double value, const std::string& type, Ply encoding) {
  if (encoding == Ply::Ascii) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g ", value);
    out += buf;
    return;
  }
  unsigned char bytes[8];
  size_t n = 0;
  auto raw = [&](const void* p, size_t size) { std::memcpy(bytes, p, n = size); };
  if (type == "char" || type == "int8") {
    int8_t v = int8_t(value);
    raw(&v, 1);
  } else if (type == "uchar" || type == "uint8") {
    uint8_t v = uint8_t(value);
    raw(&v, 1);
  } else if (type == "short" || type == "int16") {
    int16_t v = int16_t(value);
    raw(&v, 2);
  } else if (type == "ushort" || type == "uint16") {
    uint16_t v = uint16_t(value);
    raw(&v, 2);
  } else if (type == "int" || type == "int32") {
    int32_t v = int32_t(value);
    raw(&v, 4);
  } else if (type == "uint" || type == "uint32") {
    uint32_t v = uint32_t(value);
    raw(&v, 4);
  } else if (type == "float" || type == "float32") {
    float v = float(value);
    raw(&v, 4);
  } else {
    raw(&value, 8);
  }
  if (encoding == Ply::BigEndian) std::reverse(bytes, bytes + n);  // the test host is little-endian
  out.append(reinterpret_cast<const char*>(bytes), n);
}

inline std::string ply_file(const Mesh& m, const PlyOptions& o) {
  const char* format = o.encoding == Ply::Ascii          ? "ascii"
                       : o.encoding == Ply::LittleEndian ? "binary_little_endian"
                                                         : "binary_big_endian";
  std::string header = std::string("ply\nformat ") + format + " 1.0\n";
  if (o.extras) header += "comment written by io_test\nobj_info a cube\n";
  header += "element vertex " + std::to_string(m.num_vertices()) + "\n";
  if (o.extras) header += "property float nx\nproperty list uchar short tags\n";
  for (int k = 0; k < 3; ++k) header += std::string("property ") + o.vertex_types[k] + " " + char('x' + k) + "\n";
  if (o.extras) header += "property uchar red\n";
  if (o.extras) header += "element edge 2\nproperty int vertex1\nproperty int vertex2\nproperty list uint8 double w\n";
  header += "element face " + std::to_string(m.num_faces()) + "\n";
  if (o.extras) header += "property ushort flags\n";
  header += std::string("property list ") + o.count_type + " " + o.index_type + " " + o.index_name + "\n";
  if (o.extras) header += "property list uchar float texcoord\n";
  if (o.extras) header += "element material 1\nproperty uchar ambient_red\n";
  header += "end_header\n";

  std::string body;
  auto value = [&](double v, const std::string& type) { put_ply_value(body, v, type, o.encoding); };
  auto end_line = [&] {
    if (o.encoding == Ply::Ascii) body.back() = '\n';
  };
  for (size_t v = 0; v < m.num_vertices(); ++v) {
    if (o.extras) value(-1.5, "float"), value(2, "uchar"), value(7, "short"), value(-8, "short");
    for (int k = 0; k < 3; ++k) value(m.positions[3 * v + k], o.vertex_types[k]);
    if (o.extras) value(200, "uchar");
    end_line();
  }
  if (o.extras) {
    for (int e = 0; e < 2; ++e)
      value(e, "int"), value(e + 1, "int"), value(1, "uint8"), value(0.25, "double"), end_line();
  }
  std::vector<uint32_t> sizes = sizes_of(m);
  size_t offset = 0;
  for (uint32_t size : sizes) {
    if (o.extras) value(65535, "ushort");
    value(size, o.count_type);
    for (uint32_t k = 0; k < size; ++k) value(m.indices[offset + k], o.index_type);
    if (o.extras) value(2, "uchar"), value(0.5, "float"), value(0.75, "float");
    end_line();
    offset += size;
  }
  if (o.extras) value(9, "uchar"), end_line();
  return header + body;
}

}  // namespace io_test
