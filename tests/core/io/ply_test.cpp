// The PLY reader: the same cube in every encoding, every scalar and list type, values read as
// written, and errors naming the line (ASCII, header) or byte (binary), header lies caught early.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "io/io_test_util.h"
#include "kergen/io.h"

namespace {

using namespace io_test;

ReadResult off_cube() { return kergen::read_off(kergen::write_off(quad_cube())); }

TEST(IoTest, PlySameCubeInEveryEncodingAsOff) {
  const ReadResult off = off_cube();
  ASSERT_TRUE(off.ok()) << off.message;
  for (Ply encoding : {Ply::Ascii, Ply::LittleEndian, Ply::BigEndian}) {
    for (bool extras : {false, true}) {
      PlyOptions o;
      o.encoding = encoding;
      o.extras = extras;
      const std::string file = ply_file(quad_cube(), o);
      ReadResult r = kergen::read_ply(file, "cube.ply");
      ASSERT_TRUE(r.ok()) << r.message << "\n" << file;
      expect_same_mesh(off.mesh, r.mesh);
      EXPECT_EQ(r.mesh.face_sizes, std::vector<uint32_t>(6, 4)) << "quads stay quads";
      ReadResult detected = kergen::read_mesh(file, kergen::MeshFormat::Unknown);
      ASSERT_TRUE(detected.ok()) << detected.message;
      expect_same_mesh(off.mesh, detected.mesh);
    }
  }
}

TEST(IoTest, PlyScalarTypesAndListTypes) {
  const Mesh cube = quad_cube(2.0);
  const char* types[][3] = {{"char", "uchar", "short"},
                            {"ushort", "int", "uint"},
                            {"float", "float32", "float64"},
                            {"int8", "uint8", "int16"},
                            {"uint16", "int32", "uint32"}};
  const char* counts[] = {"char", "uchar", "short", "ushort", "int", "uint"};
  const char* indices[] = {"ushort", "int", "uint", "int32", "uint32", "short"};
  int variant = 0;
  for (Ply encoding : {Ply::Ascii, Ply::LittleEndian, Ply::BigEndian}) {
    for (const auto& t : types) {
      PlyOptions o;
      o.encoding = encoding;
      std::copy(t, t + 3, o.vertex_types);
      o.count_type = counts[variant % 6];
      o.index_type = indices[variant % 6];
      o.index_name = variant % 2 ? "vertex_index" : "vertex_indices";
      ++variant;
      ReadResult r = kergen::read_ply(ply_file(cube, o), "types.ply");
      ASSERT_TRUE(r.ok()) << r.message << " (" << t[0] << " " << t[1] << " " << t[2] << ", " << o.count_type << " "
                          << o.index_type << ")";
      expect_same_mesh(cube, r.mesh);
    }
  }
  // Triangles only: face sizes are implicit, as from the other readers.
  Mesh tetra;
  tetra.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  tetra.indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  ReadResult r = kergen::read_ply(ply_file(tetra, PlyOptions{}));
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_TRUE(r.mesh.face_sizes.empty());
  expect_same_mesh(tetra, r.mesh);
}

TEST(IoTest, PlyAsciiValuesAreReadAsWritten) {
  // A coordinate declared float is kept as written (like OFF and OBJ): 0.1 is the double 0.1.
  ReadResult r = kergen::read_ply(
      "ply\r\nformat ascii 1.0\r\nelement vertex 3\r\nproperty float x\r\nproperty float y\r\nproperty float z\r\n"
      "element face 1\r\nproperty list uchar int vertex_indices\r\nend_header\r\n0.1 0 0\r\n\r\n1 0 0\r\n0 1 1e-320\r\n"
      "3 0 1 2\r\n");
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.mesh.positions[0], 0.1);
  EXPECT_EQ(r.mesh.positions[8], 1e-320);
}

const char* const kPlyHead =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n";  // 9 lines

std::string ply_text(const char* vertices, const char* faces) { return std::string(kPlyHead) + vertices + faces; }

TEST(IoTest, PlyAsciiErrorsNameLineAndReason) {
  const char* v = "0 0 0\n1 0 0\n0 1 0\n";  // lines 10-12
  expect_errors(
      kergen::read_ply,
      {
          {ply_text(v, "3 0 1 3\n"), Error::ParseError,
           "in.txt:13: vertex index 3 out of range (the file has 3 vertices)"},
          {ply_text(v, "3 0 1 -1\n"), Error::ParseError, "in.txt:13: vertex index -1 out of range"},
          {ply_text(v, "3 0 1 x\n"), Error::ParseError, "in.txt:13: invalid vertex index 'x'"},
          {ply_text(v, "2 0 1\n"), Error::ParseError, "in.txt:13: face has 2 vertices (at least 3 needed)"},
          {ply_text(v, "-3 0 1 2\n"), Error::ParseError, "in.txt:13: negative list count -3"},
          {ply_text(v, "three 0 1 2\n"), Error::ParseError, "in.txt:13: invalid list count 'three'"},
          {ply_text(v, "4 0 1 2\n"), Error::ParseError,
           "in.txt:13: too few values for element 'face' (the line has 4)"},
          {ply_text(v, "3 0 1 2 7\n"), Error::ParseError,
           "in.txt:13: the line has more than the 4 values element 'face' declares"},
          {ply_text(v, ""), Error::ParseError, "in.txt:12: unexpected end of file: 0 of 1 faces read"},
          {ply_text("0 0 0\n1 0 x\n0 1 0\n", "3 0 1 2\n"), Error::ParseError, "in.txt:11: invalid number 'x'"},
          {ply_text("0 0 0\n1 0 nan\n0 1 0\n", "3 0 1 2\n"), Error::ParseError,
           "in.txt:11: non-finite coordinate 'nan'"},
          {ply_text("0 0 0\n1 0 1e999\n0 1 0\n", "3 0 1 2\n"), Error::ParseError,
           "in.txt:11: non-finite coordinate '1e999'"},
          {ply_text("0 0 0\n1 0\n0 1 0\n", "3 0 1 2\n"), Error::ParseError,
           "in.txt:11: too few values for element 'vertex' (the line has 2)"},
          {ply_text("0 0 0\n1 0 0 1\n0 1 0\n", "3 0 1 2\n"), Error::ParseError,
           "in.txt:11: the line has more than the 3 values element 'vertex' declares"},
          // Blank lines pass the size check (2 bytes per element) but hold no element.
          {ply_text("0 0 0\n\n\n\n\n\n", ""), Error::ParseError,
           "in.txt:15: unexpected end of file: 1 of 3 vertices read"},
      });
}

TEST(IoTest, PlyHeaderErrorsNameLineAndReason) {
  auto with = [](const std::string& from, const std::string& to) {
    std::string text = ply_text("0 0 0\n1 0 0\n0 1 0\n", "3 0 1 2\n");
    size_t at = text.find(from);
    return text.replace(at, from.size(), to);
  };
  expect_errors(
      kergen::read_ply,
      {
          {"plx\nformat ascii 1.0\n", Error::ParseError, "in.txt:1: expected 'ply' on the first line, found 'plx'"},
          {with("format ascii 1.0", "format ascii 2.0"), Error::ParseError,
           "in.txt:2: unsupported PLY version '2.0' (1.0 expected)"},
          {with("format ascii 1.0", "format binary 1.0"), Error::ParseError, "in.txt:2: unknown PLY format 'binary'"},
          {with("format ascii 1.0\n", ""), Error::ParseError, "in.txt:8: the header has no 'format' line"},
          {with("format ascii 1.0\n", "format ascii 1.0\nformat ascii 1.0\n"), Error::ParseError,
           "in.txt:3: second 'format' line"},
          {with("element vertex 3", "element vertex -3"), Error::ParseError, "in.txt:3: invalid element count '-3'"},
          {with("element vertex 3", "element vertex"), Error::ParseError,
           "in.txt:3: expected 'element <name> <count>'"},
          {with("element vertex 3", "element vertex 1000000000000"), Error::ParseError,
           "in.txt:3: header declares 1000000000000 vertices but only 26 bytes of data follow"},
          {with("element face 1", "element face 13"), Error::ParseError,
           "in.txt:7: header declares 13 faces but only 26 bytes"},
          {with("element face 1", "element vertex 1"), Error::ParseError, "in.txt:7: second 'vertex' element"},
          {with("element vertex 3\n", "property float w\nelement vertex 3\n"), Error::ParseError,
           "in.txt:3: property before any element"},
          {with("property float z", "property real z"), Error::ParseError, "in.txt:6: unknown property type 'real'"},
          {with("property float z", "property float"), Error::ParseError, "in.txt:6: property needs a name"},
          {with("property float z", "property float z w"), Error::ParseError,
           "in.txt:6: unexpected 'w' after the property name"},
          {with("property float z", "property float y"), Error::ParseError, "in.txt:6: second vertex property 'y'"},
          {with("property float z", "property float w"), Error::ParseError,
           "in.txt:3: vertex element has no 'z' property"},
          {with("property float z", "property list uchar float z"), Error::ParseError,
           "in.txt:6: vertex property 'z' is a list, not a number"},
          {with("list uchar int", "list float int"), Error::ParseError,
           "in.txt:8: list count type 'float' is not an integer type"},
          {with("list uchar int", "list uchar float"), Error::ParseError,
           "in.txt:8: face property 'vertex_indices' must be a list of integers"},
          {with("property list uchar int vertex_indices", "property uint vertex_indices"), Error::ParseError,
           "in.txt:8: face property 'vertex_indices' must be a list of integers"},
          {with("vertex_indices", "corners"), Error::ParseError, "in.txt:7: face element has no 'vertex_indices' list"},
          {with("end_header", "end_header now"), Error::ParseError, "in.txt:9: unexpected 'now' after 'end_header'"},
          {with("end_header", "end_heading"), Error::ParseError, "in.txt:9: unknown header keyword 'end_heading'"},
          {"ply\nformat ascii 1.0\nelement vertex 0\n", Error::ParseError,
           "in.txt:3: the header has no 'end_header' line"},
          {with("element face 1", "element face 0"), Error::EmptyInput, "in.txt: no faces"},
          {"ply\nformat ascii 1.0\nend_header\n", Error::EmptyInput, "in.txt: no vertices and no faces"},
          {"", Error::EmptyInput, "in.txt: empty file"},
      });
}

// Byte offsets of the binary cube written by ply_file without extras: header, then 8 vertices of
// 3 doubles (24 bytes each), then 6 faces of a uchar count and 4 ints (17 bytes each).
size_t ply_header_size(const std::string& file) { return file.find("end_header\n") + 11; }

TEST(IoTest, PlyBinaryErrorsNameTheByte) {
  for (Ply encoding : {Ply::LittleEndian, Ply::BigEndian}) {
    PlyOptions o;
    o.encoding = encoding;
    const std::string good = ply_file(quad_cube(), o);
    const size_t h = ply_header_size(good), faces = h + 8 * 24;
    ASSERT_EQ(good.size(), faces + 6 * 17);
    auto expect = [&](const std::string& bytes, Error error, const std::string& message) {
      ReadResult r = kergen::read_ply(bytes, "b.ply");
      EXPECT_EQ(r.error, error) << r.message;
      EXPECT_EQ(r.message, message);
    };
    auto patched = [&](size_t at, double value, const char* type) {
      std::string bytes = good, v;
      put_ply_value(v, value, type, encoding);
      return bytes.replace(at, v.size(), v);
    };
    expect(good.substr(0, good.size() - 3), Error::ParseError,
           "b.ply: byte " + std::to_string(faces + 5 * 17 + 13) + ": unexpected end of file: 5 of 6 faces read");
    expect(good.substr(0, h + 30), Error::ParseError,
           "b.ply:3: header declares 8 vertices but only 30 bytes of data follow");
    expect(patched(h + 2 * 24 + 8, std::nan(""), "double"), Error::ParseError,
           "b.ply: byte " + std::to_string(h + 56) + ": non-finite coordinate in vertex 2");
    expect(patched(h + 5 * 24 + 16, -HUGE_VAL, "double"), Error::ParseError,
           "b.ply: byte " + std::to_string(h + 136) + ": non-finite coordinate in vertex 5");
    expect(patched(faces + 17 + 1 + 8, 8, "int"), Error::ParseError,
           "b.ply: byte " + std::to_string(faces + 26) + ": vertex index 8 out of range (the file has 8 vertices)");
    expect(patched(faces + 17 + 1 + 8, -2, "int"), Error::ParseError,
           "b.ply: byte " + std::to_string(faces + 26) + ": vertex index -2 out of range (the file has 8 vertices)");
    expect(patched(faces + 3 * 17, 2, "uchar"), Error::ParseError,
           "b.ply: byte " + std::to_string(faces + 51) + ": face has 2 vertices (at least 3 needed)");
    // A list count larger than the file: no allocation for it, the end of the data is reported.
    expect(patched(faces + 5 * 17, 255, "uchar"), Error::ParseError,
           "b.ply: byte " + std::to_string(good.size()) + ": unexpected end of file: 5 of 6 faces read");

    o.count_type = "int";  // signed counts can be negative
    const std::string signed_counts = ply_file(quad_cube(), o);
    const size_t count1 = ply_header_size(signed_counts) + 8 * 24 + 20;  // face 1's count (faces of 20 bytes)
    std::string bytes = signed_counts, v;
    put_ply_value(v, -4, "int", encoding);
    bytes.replace(count1, 4, v);
    expect(bytes, Error::ParseError, "b.ply: byte " + std::to_string(count1) + ": negative list count -4");
    // A huge count: its indices are read (nothing is reserved for it) until the data ends.
    v.clear();
    put_ply_value(v, 0x7fffffff, "int", encoding);
    bytes.replace(count1, 4, v);
    expect(bytes, Error::ParseError,
           "b.ply: byte " + std::to_string(bytes.size()) + ": unexpected end of file: 1 of 6 faces read");
  }
}

TEST(IoTest, PlyBinaryHeaderLiesAreCaughtBeforeAllocating) {
  PlyOptions o;
  o.encoding = Ply::LittleEndian;
  std::string lying = ply_file(quad_cube(), o);
  lying.replace(lying.find("element vertex 8"), 16, "element vertex 4294967295");
  ReadResult r = kergen::read_ply(lying, "lie.ply");
  EXPECT_EQ(r.error, Error::ParseError);
  EXPECT_TRUE(contains(r.message, "lie.ply:3: header declares 4294967295 vertices but only 294 bytes of data follow"))
      << r.message;
  // Elements the reader skips are checked too: an edge element claiming a billion instances.
  std::string edges = ply_file(quad_cube(), o);
  edges.replace(edges.find("end_header"), 10, "element edge 1000000000\nproperty int a\nend_header");
  r = kergen::read_ply(edges, "edges.ply");
  EXPECT_EQ(r.error, Error::ParseError);
  EXPECT_TRUE(contains(r.message, "edges.ply:9: header declares 1000000000 'edge' elements")) << r.message;
}

}  // namespace
