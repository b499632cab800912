// The STL reader, ASCII and binary: the same mesh from both, the weld by exact equality, binary
// headers that say "solid", count mismatches and errors naming the line or byte.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "io/io_test_util.h"
#include "kergen/io.h"

namespace {

using namespace io_test;

TEST(IoTest, StlAsciiAndBinaryGiveTheSameMesh) {
  ReadResult ascii = kergen::read_stl(ascii_tetra_stl());
  ASSERT_TRUE(ascii.ok()) << ascii.message;
  EXPECT_EQ(ascii.mesh.num_vertices(), 4u);  // 12 corners welded to 4 vertices
  EXPECT_EQ(ascii.mesh.num_faces(), 4u);
  ReadResult binary = kergen::read_stl(kergen::write_stl_binary(ascii.mesh));
  ASSERT_TRUE(binary.ok()) << binary.message;
  expect_same_mesh(ascii.mesh, binary.mesh);
}

TEST(IoTest, StlBinaryWhoseHeaderSaysSolid) {
  std::string bytes = kergen::write_stl_binary(kergen::read_stl(ascii_tetra_stl()).mesh);
  std::memcpy(&bytes[0], "solid tet", 9);
  ReadResult r = kergen::read_stl(bytes);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.mesh.num_faces(), 4u);
}

TEST(IoTest, StlWeldsByExactEqualityOnly) {
  std::string s =
      "solid w\n"
      "facet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
      // -0 welds with 0; 1.0000000000000002 (next double after 1) does not weld with 1.
      "facet normal 0 0 0\nouter loop\nvertex -0 -0 -0\nvertex 1.0000000000000002 0 0\nvertex 0 1.0 "
      "0\nendloop\nendfacet\n"
      "endsolid w\n";
  ReadResult r = kergen::read_stl(s);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.mesh.num_vertices(), 4u);
  EXPECT_EQ(r.mesh.indices, (std::vector<uint32_t>{0, 1, 2, 0, 3, 2}));
  EXPECT_FALSE(std::signbit(r.mesh.positions[0]));
}

TEST(IoTest, StlMultipleAndEmptySolids) {
  ReadResult r = kergen::read_stl(ascii_tetra_stl("a") + "solid empty\nendsolid empty\n" + ascii_tetra_stl("b"));
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.mesh.num_faces(), 8u);
  EXPECT_EQ(r.mesh.num_vertices(), 4u);
}

TEST(IoTest, StlBinaryCountMismatch) {
  std::string bytes = kergen::write_stl_binary(quad_cube());
  // Lying count: header says 1000 triangles, the file holds 12.
  std::string lying = bytes;
  const uint32_t claimed = 1000;
  std::memcpy(&lying[80], &claimed, 4);
  ReadResult r = kergen::read_stl(lying, "lying.stl");
  EXPECT_EQ(r.error, Error::ParseError);
  EXPECT_TRUE(contains(r.message, "lying.stl: byte 80: binary STL header declares 1000 triangles")) << r.message;
  EXPECT_TRUE(contains(r.message, "room for 12 triangles")) << r.message;

  // Truncated in the middle of a triangle.
  std::string truncated = bytes.substr(0, bytes.size() - 20);
  r = kergen::read_stl(truncated, "cut.stl");
  EXPECT_EQ(r.error, Error::ParseError);
  EXPECT_TRUE(contains(r.message, "declares 12 triangles")) << r.message;
  EXPECT_TRUE(contains(r.message, "room for 11 triangles")) << r.message;

  // Largest possible lie: no allocation proportional to it.
  const uint32_t huge = 0xFFFFFFFFu;
  std::memcpy(&lying[80], &huge, 4);
  r = kergen::read_stl(lying, "huge.stl");
  EXPECT_EQ(r.error, Error::ParseError);
  EXPECT_TRUE(contains(r.message, "4294967295 triangles")) << r.message;
}

TEST(IoTest, StlBinaryNonFiniteCoordinateNamesTheByte) {
  std::string bytes = kergen::write_stl_binary(quad_cube());
  const float nan = std::nanf("");
  std::memcpy(&bytes[84 + 50 * 2 + 12 + 12 + 4], &nan, 4);  // triangle 2, vertex 1, y: byte 212
  ReadResult r = kergen::read_stl(bytes, "nan.stl");
  EXPECT_EQ(r.error, Error::ParseError);
  EXPECT_TRUE(contains(r.message, "nan.stl: byte 212: non-finite coordinate in triangle 2 (vertex 1)")) << r.message;
}

TEST(IoTest, StlErrors) {
  expect_errors(
      kergen::read_stl,
      {
          {"", Error::EmptyInput, "in.txt: empty file"},
          {"solid x\nendsolid x\n", Error::EmptyInput, "in.txt: no facets"},
          {"solid x\n facet normal 0 0 1\n outer loop\n vertex 0 0 0\n vertex 1 0 0\n endloop\n endfacet\nendsolid\n",
           Error::ParseError, "in.txt:6: facet has 2 vertices"},
          {"solid x\n facet normal 0 0 1\n outer loop\n vertex 0 0 0\n vertex 1 0 0\n vertex 1 1 0\n vertex 1 2 0\n",
           Error::ParseError, "in.txt:7: facet has more than 3 vertices"},
          {"solid x\n facet normal 0 0 1\n outer loop\n vertex 0 0 0\n vertex 1 0 0\n vertex 1 1 0\n endloop\n",
           Error::ParseError, "unexpected end of file inside a facet"},
          {"solid x\n facet normal 0 0 1\n outer loop\n vertex 0 0 0 0\n", Error::ParseError,
           "in.txt:4: unexpected '0' after 'vertex x y z'"},
          {"solid x\n facet normal 0 0 1\n outer loop\n vertex 0 nan 0\n", Error::ParseError,
           "in.txt:4: non-finite coordinate 'nan'"},
          {"solid x\n facet 0 0 1\n", Error::ParseError, "in.txt:2: expected 'facet normal nx ny nz'"},
          {"solid x\n vertex 0 0 0\n", Error::ParseError, "in.txt:2: expected 'facet' or 'endsolid', found 'vertex'"},
          {"tiny", Error::ParseError, "in.txt: byte 0: not an STL file"},
      });
}

}  // namespace
