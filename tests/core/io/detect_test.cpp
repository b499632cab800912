// Which reader a file goes to: format_from_path, detect_format by content, read_mesh's order
// (format, then name, then content) and read_mesh_file's errors.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <ios>
#include <string>

#include "io/io_test_util.h"
#include "kergen/io.h"

namespace {

using namespace io_test;

TEST(IoTest, FormatFromPath) {
  EXPECT_EQ(kergen::format_from_path("a/b.off"), kergen::MeshFormat::Off);
  EXPECT_EQ(kergen::format_from_path("B.OBJ"), kergen::MeshFormat::Obj);
  EXPECT_EQ(kergen::format_from_path("x.Stl"), kergen::MeshFormat::Stl);
  EXPECT_EQ(kergen::format_from_path("x.PLY"), kergen::MeshFormat::Ply);
  EXPECT_EQ(kergen::format_from_path("x.gltf"), kergen::MeshFormat::Unknown);
  EXPECT_EQ(kergen::format_from_path("dir.off/file"), kergen::MeshFormat::Unknown);
  EXPECT_EQ(kergen::format_from_path("noext"), kergen::MeshFormat::Unknown);
}

TEST(IoTest, ReadMeshFileErrors) {
  fs::path dir = temp_dir();
  ReadResult r = kergen::read_mesh_file((dir / "missing.off").string());
  EXPECT_EQ(r.error, Error::IoError);
  EXPECT_TRUE(contains(r.message, "missing.off")) << r.message;

  r = kergen::read_mesh_file(dir.string());
  EXPECT_EQ(r.error, Error::IoError);
  EXPECT_TRUE(contains(r.message, "is a directory")) << r.message;

  const std::string empty = (dir / "empty.obj").string();
  { std::ofstream create_empty(empty, std::ios::binary); }
  r = kergen::read_mesh_file(empty);
  EXPECT_EQ(r.error, Error::EmptyInput);
  EXPECT_TRUE(contains(r.message, "empty.obj: empty file")) << r.message;

  const std::string big = (dir / "big.off").string();
  ASSERT_EQ(kergen::write_mesh_file(big, quad_cube()), Error::Ok);
  r = kergen::read_mesh_file(big, 10);
  EXPECT_EQ(r.error, Error::TooLarge);
  EXPECT_TRUE(contains(r.message, "big.off")) << r.message;
  EXPECT_TRUE(kergen::read_mesh_file(big).ok());

  // Another extension: the content says the format, or the file is refused as unknown.
  const std::string text = (dir / "shape.txt").string();
  { std::ofstream(text, std::ios::binary) << kergen::write_off(quad_cube()); }
  r = kergen::read_mesh_file(text);
  ASSERT_TRUE(r.ok()) << r.message;
  expect_same_mesh(quad_cube(), r.mesh);
  { std::ofstream(text, std::ios::binary) << "some notes\n"; }
  r = kergen::read_mesh_file(text);
  EXPECT_EQ(r.error, Error::ParseError);
  EXPECT_EQ(r.message, text +
                           ": unknown mesh format: the name does not end in .off, .obj, .stl or .ply and the "
                           "content is none of them");
  fs::remove_all(dir);
}

TEST(IoTest, DetectFormatByContent) {
  using kergen::MeshFormat;
  const Mesh cube = quad_cube();
  EXPECT_EQ(kergen::detect_format(kergen::write_off(cube)), MeshFormat::Off);
  EXPECT_EQ(kergen::detect_format("# made by hand\n\n  COFF\n"), MeshFormat::Off);
  EXPECT_EQ(kergen::detect_format("STOFF 3 1 0\n"), MeshFormat::Off);
  EXPECT_EQ(kergen::detect_format(kergen::write_obj(cube)), MeshFormat::Obj);
  EXPECT_EQ(kergen::detect_format("\xEF\xBB\xBFmtllib a.mtl\nv 0 0 0\n"), MeshFormat::Obj);
  EXPECT_EQ(kergen::detect_format("g part\r\nf 1 2 3\r\n"), MeshFormat::Obj);
  EXPECT_EQ(kergen::detect_format(ascii_tetra_stl()), MeshFormat::Stl);
  EXPECT_EQ(kergen::detect_format(kergen::write_stl_binary(cube)), MeshFormat::Stl);
  // A binary STL whose header says something else is still told by its size.
  std::string binary = kergen::write_stl_binary(cube);
  std::memcpy(&binary[0], "OFF\nv 0 0 0\n", 12);
  EXPECT_EQ(kergen::detect_format(binary), MeshFormat::Stl);
  PlyOptions ply;
  ply.encoding = Ply::BigEndian;
  EXPECT_EQ(kergen::detect_format(ply_file(cube, ply)), MeshFormat::Ply);
  EXPECT_EQ(kergen::detect_format("ply\r\nformat ascii 1.0\r\n"), MeshFormat::Ply);
  for (const char* unknown :
       {"", "\n\n", "# only a comment\n", "hello world\n", "OFF4\n", "plywood\n", "solidified 1 2 3\n", "3 1 0\n"})
    EXPECT_EQ(kergen::detect_format(unknown), MeshFormat::Unknown) << unknown;
}

TEST(IoTest, ReadMeshUsesFormatThenNameThenContent) {
  const std::string off = kergen::write_off(quad_cube());
  EXPECT_TRUE(kergen::read_mesh(off, kergen::MeshFormat::Unknown).ok());
  EXPECT_TRUE(kergen::read_mesh(off, kergen::MeshFormat::Unknown, "cube").ok());
  EXPECT_TRUE(kergen::read_mesh(off, kergen::MeshFormat::Off, "cube.obj").ok());
  // The extension wins over the content: an OBJ reader finds no OBJ record in an OFF file.
  ReadResult r = kergen::read_mesh(off, kergen::MeshFormat::Unknown, "cube.obj");
  EXPECT_EQ(r.error, Error::EmptyInput);
  EXPECT_EQ(r.message, "cube.obj: no vertices and no faces");
  r = kergen::read_mesh(" \n\t\n", kergen::MeshFormat::Unknown, "blank");
  EXPECT_EQ(r.error, Error::EmptyInput);
  EXPECT_EQ(r.message, "blank: empty file");
  r = kergen::read_mesh("3 1 0\n", kergen::MeshFormat::Unknown);
  EXPECT_EQ(r.error, Error::ParseError);
  EXPECT_EQ(r.message,
            "<memory>: unknown mesh format: the name does not end in .off, .obj, .stl or .ply and the "
            "content is none of them");
}

}  // namespace
