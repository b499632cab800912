// The OBJ reader: face vertex forms, relative and forward indices, ignored records, strict errors
// naming the line, and numbers parsed exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "io/io_test_util.h"
#include "kergen/io.h"

namespace {

using namespace io_test;

TEST(IoTest, ObjFaceVertexForms) {
  const char* text =
      "# a tetrahedron written four ways\n"
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
      "vt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n"
      "f 1 3 2\n"
      "f 1/1 2/2 4/3\n"
      "f 1//1 4//1 3//1\n"
      "f 2/2/1 3/3/1 4/1/1\n";
  ReadResult r = kergen::read_obj(text, "tet.obj");
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.mesh.num_vertices(), 4u);
  EXPECT_EQ(r.mesh.indices, (std::vector<uint32_t>{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3}));
  EXPECT_TRUE(r.mesh.face_sizes.empty());
}

TEST(IoTest, ObjNegativeIndicesAreRelative) {
  const char* text =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
      "f -4 -3 -2 -1\n"
      "v 0 0 1\n"
      "f -5 -4 -1\n"  // 5 vertices so far: -5 -> 1, -4 -> 2, -1 -> 5
      "f -1/1/1 -2//3 -3/2\n";
  ReadResult r = kergen::read_obj(text);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.mesh.indices, (std::vector<uint32_t>{0, 1, 2, 3, 0, 1, 4, 4, 3, 2}));
  EXPECT_EQ(r.mesh.face_sizes, (std::vector<uint32_t>{4, 3, 3}));
}

TEST(IoTest, ObjPolygonsCommentsAndIgnoredRecords) {
  const char* text =
      "\xEF\xBB\xBF# BOM, then comments\r\n"
      "mtllib x.mtl\r\no thing\r\ng group one\r\ns off\r\nusemtl red\r\n"
      "v 0 0 0 1.0\r\n"          // w component
      "v 1 0 0 0.5 0.5 0.5\r\n"  // vertex colour
      "v   1   1   0   # trailing comment\r\n"
      "v\t0\t1\t0\r\n"
      "v 0.5 0.5 1\r\n"
      "vp 0.5\r\nl 1 2\r\np 3\r\n"
      "f 1 4 3 2   \r\n"
      "f 1 2 5\r\nf 2 3 5\r\nf 3 4 5\r\nf 4 1 5";  // no final newline
  ReadResult r = kergen::read_obj(text);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.mesh.num_vertices(), 5u);
  EXPECT_EQ(r.mesh.face_sizes, (std::vector<uint32_t>{4, 3, 3, 3, 3}));
  EXPECT_EQ(r.mesh.positions[3], 1.0);  // colour did not shift coordinates
  EXPECT_EQ(r.mesh.positions[4], 0.0);
}

TEST(IoTest, ObjForwardReferenceIsAllowed) {
  ReadResult r = kergen::read_obj("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.mesh.num_faces(), 1u);
}

TEST(IoTest, ObjErrorsNameLineAndReason) {
  expect_errors(
      kergen::read_obj,
      {
          {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", Error::ParseError, "in.txt:4: vertex index 0"},
          {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", Error::ParseError, "in.txt:4: vertex index 4 out of range"},
          {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n", Error::ParseError, "in.txt:4: relative vertex index -4"},
          {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n", Error::ParseError, "in.txt:4: face has 2 vertices"},
          {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n", Error::ParseError, "in.txt:4: invalid face vertex 'x'"},
          {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3/1/1/1\n", Error::ParseError, "in.txt:4: invalid face vertex"},
          {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999\n", Error::ParseError, "in.txt:4: vertex index 99999999999"},
          {"v 0 0\n", Error::ParseError, "in.txt:1: vertex needs 3 coordinates, found 2"},
          {"\nv 0 0 abc\n", Error::ParseError, "in.txt:2: invalid number 'abc'"},
          {"v 0 0 1.5.2\n", Error::ParseError, "invalid number '1.5.2'"},
          {"v 0 0 nan\n", Error::ParseError, "in.txt:1: non-finite coordinate 'nan'"},
          {"v 0 -inf 0\n", Error::ParseError, "in.txt:1: non-finite coordinate '-inf'"},
          {"v 0 1e999 0\n", Error::ParseError, "in.txt:1: non-finite coordinate '1e999'"},
          {"v 0 0 0\nv 1 0 0\n", Error::EmptyInput, "in.txt: no faces"},
          {"v 0 0 0\nv 1 0 0\nl 1 2\n", Error::EmptyInput, "no faces (only points/lines)"},
          {"# nothing\n", Error::EmptyInput, "no vertices and no faces"},
          {"", Error::EmptyInput, "in.txt: empty file"},
          {"  \n\n", Error::EmptyInput, "in.txt: empty file"},
          {"\xFF\xFEv\0 \0", Error::ParseError, "UTF-16 is not supported"},
      });
}

TEST(IoTest, NumbersAreParsedExactly) {
  ReadResult r = kergen::read_obj(
      "v 0.1 -0 1e-400\n"  // underflow rounds to zero
      "v +2. .5 -1E+2\n"
      "v 4.9406564584124654e-324 1.7976931348623157e308 123456789012345678901234567890\n"
      "f 1 2 3\n");
  ASSERT_TRUE(r.ok()) << r.message;
  const std::vector<double> expected = {0.1,
                                        -0.0,
                                        0.0,
                                        2.0,
                                        0.5,
                                        -100.0,
                                        4.9406564584124654e-324,
                                        1.7976931348623157e308,
                                        123456789012345678901234567890.0};
  ASSERT_EQ(r.mesh.positions.size(), expected.size());
  for (size_t i = 0; i < expected.size(); ++i) EXPECT_EQ(r.mesh.positions[i], expected[i]) << i;
  EXPECT_TRUE(std::signbit(r.mesh.positions[1]));
}

}  // namespace
