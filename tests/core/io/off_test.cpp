// The OFF reader: header variants, strict errors naming the line, a truncated file.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "io/io_test_util.h"
#include "kergen/io.h"

namespace {

using namespace io_test;

TEST(IoTest, OffVariants) {
  // Header and counts on one line, comments, colours after faces, COFF vertex colours.
  ReadResult r = kergen::read_off(
      "OFF 4 4 6 # counts on the header line\n"
      "# a comment\n\n"
      "0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
      "3 0 2 1 255 0 0\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.mesh.num_vertices(), 4u);
  EXPECT_EQ(r.mesh.num_faces(), 4u);

  r = kergen::read_off(
      "COFF\n4 4 0\n0 0 0 1 1 1 1\n1 0 0 1 1 1 1\n0 1 0 1 1 1 1\n0 0 1 1 1 1 1\n"
      "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.mesh.positions[3], 1.0);
  EXPECT_EQ(r.mesh.positions[4], 0.0);

  r = kergen::read_off("NOFF\n3 1\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2");  // no edge count, no final newline
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.mesh.num_faces(), 1u);
}

TEST(IoTest, OffErrorsNameLineAndReason) {
  expect_errors(
      kergen::read_off,
      {
          {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", Error::ParseError, "in.txt:6: vertex index 3 out of range"},
          {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -1\n", Error::ParseError, "in.txt:6: vertex index -1 out of range"},
          {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", Error::ParseError, "in.txt:6: face has 2 vertices"},
          {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n", Error::ParseError, "in.txt:6: face declares 4 vertices"},
          {"OFF\n3 1 0\n0 0 0\n1 0 x\n0 1 0\n3 0 1 2\n", Error::ParseError, "in.txt:4: invalid number 'x'"},
          {"OFF\n3 1 0\n0 0 0\n1 0 inf\n0 1 0\n3 0 1 2\n", Error::ParseError, "in.txt:4: non-finite coordinate"},
          {"OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", Error::ParseError,
           "unexpected end of file: 1 of 2 faces read"},
          {"OFF\n300 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", Error::ParseError,
           "in.txt:2: header declares 300 vertices and 2 faces but only 26 bytes follow"},
          {"OFF\n1000000000000 1000000000000 0\n0 0 0\n", Error::ParseError,
           "in.txt:2: header declares 1000000000000 vertices"},
          {"OFF\n-3 1 0\n", Error::ParseError, "in.txt:2: invalid vertex count '-3'"},
          {"OFF\n3 x 0\n", Error::ParseError, "in.txt:2: invalid face count 'x'"},
          {"OFF\n", Error::ParseError, "missing vertex/face counts"},
          {"PLY\n3 1 0\n", Error::ParseError, "in.txt:1: expected an OFF header, found 'PLY'"},
          {"4OFF\n3 1 0\n", Error::ParseError, "4D / n-dimensional OFF is not supported"},
          {"OFF BINARY\n", Error::ParseError, "binary OFF is not supported"},
          {"OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n", Error::EmptyInput, "in.txt: no faces"},
          {"", Error::EmptyInput, "empty file"},
      });
}

TEST(IoTest, OffTruncatedFile) {
  // The size check is a lower bound; a file that passes it but ends early still fails cleanly.
  ReadResult r = kergen::read_off("OFF\n3 1 0\n0 0 0\n1 0 0\n\n\n\n\n\n\n\n\n\n\n\n\n\n\n");
  EXPECT_EQ(r.error, Error::ParseError);
  EXPECT_TRUE(contains(r.message, "unexpected end of file: 2 of 3 vertices read")) << r.message;
}

}  // namespace
