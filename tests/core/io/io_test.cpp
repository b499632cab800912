// Mesh file readers and writers (kergen/io.h): round trips, format variants, welding, strict errors,
// and the outcome for every file of the shared format/bad fixture folders.
#include "kergen/io.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using kergen::Error;
using kergen::Mesh;
using kergen::ReadResult;

// A unit cube with quad faces, outward (counter-clockwise seen from outside).
Mesh quad_cube(double size = 1.0) {
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
std::vector<uint32_t> sizes_of(const Mesh& m) {
  return m.face_sizes.empty() ? std::vector<uint32_t>(m.indices.size() / 3, 3) : m.face_sizes;
}

void expect_same_mesh(const Mesh& expected, const Mesh& actual) {
  ASSERT_EQ(expected.positions.size(), actual.positions.size());
  for (size_t i = 0; i < expected.positions.size(); ++i) EXPECT_EQ(expected.positions[i], actual.positions[i]) << i;
  EXPECT_EQ(expected.indices, actual.indices);
  EXPECT_EQ(sizes_of(expected), sizes_of(actual));
}

// Triangles as sets of 3 points (order within a triangle kept), for meshes that went through STL
// (float coordinates, welded vertices renumbered).
std::multiset<std::vector<float>> triangle_set(const Mesh& m) {
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

std::string shared_meshes() { return KERGEN_SHARED_MESHES; }

#define REQUIRE_SHARED_MESHES()                                                                   \
  do {                                                                                            \
    if (!fs::is_directory(shared_meshes() + "/fixtures"))                                         \
      GTEST_SKIP() << "shared meshes not found at " << shared_meshes() << " (fixtures/ missing)"; \
  } while (0)

fs::path temp_dir() {
  fs::path dir = fs::temp_directory_path() / ("kergen_io_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir;
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// ---------------------------------------------------------------------------------------------
// Round trips.

TEST(IoTest, OffRoundTripKeepsEveryBit) {
  Mesh m = quad_cube();
  m.positions[0] = 0.1;  // not exactly representable in decimal
  m.positions[4] = -1.0 / 3.0;
  m.positions[8] = 1e-300;
  m.positions[9] = 6.02214076e23;
  ReadResult r = kergen::read_off(kergen::write_off(m));
  ASSERT_TRUE(r.ok()) << r.message;
  expect_same_mesh(m, r.mesh);
}

TEST(IoTest, ObjRoundTripKeepsEveryBit) {
  Mesh m = quad_cube();
  m.positions[3] = 0.30000000000000004;
  m.positions[5] = -2.5e-310;  // subnormal
  ReadResult r = kergen::read_obj(kergen::write_obj(m));
  ASSERT_TRUE(r.ok()) << r.message;
  expect_same_mesh(m, r.mesh);
}

TEST(IoTest, TrianglesReadBackWithImplicitSizes) {
  Mesh m;
  m.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  m.indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  for (const std::string& text : {kergen::write_off(m), kergen::write_obj(m)}) {
    ReadResult r = text[0] == 'O' ? kergen::read_off(text) : kergen::read_obj(text);
    ASSERT_TRUE(r.ok()) << r.message;
    EXPECT_TRUE(r.mesh.face_sizes.empty());
    expect_same_mesh(m, r.mesh);
  }
}

TEST(IoTest, StlRoundTripFanTriangulatesAndWelds) {
  Mesh m = quad_cube(2.0);
  std::string bytes = kergen::write_stl_binary(m);
  ASSERT_EQ(bytes.size(), 84u + 50u * 12u);
  uint32_t count;
  std::memcpy(&count, bytes.data() + 80, 4);
  EXPECT_EQ(count, 12u);
  ReadResult r = kergen::read_stl(bytes);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_EQ(r.mesh.num_vertices(), 8u);  // welded back
  EXPECT_EQ(r.mesh.num_faces(), 12u);
  EXPECT_EQ(triangle_set(m), triangle_set(r.mesh));
  // The first triangle's normal is the unit outward normal of face 0 (z = 0 plane: -z).
  float normal[3];
  std::memcpy(normal, bytes.data() + 84, 12);
  EXPECT_EQ(normal[0], 0.0f);
  EXPECT_EQ(normal[1], 0.0f);
  EXPECT_EQ(normal[2], -1.0f);
}

TEST(IoTest, WriteMeshFileByExtensionAndReadBack) {
  fs::path dir = temp_dir();
  Mesh m = quad_cube(3.0);
  for (const char* name : {"cube.off", "cube.OBJ", "cube.stl"}) {
    std::string path = (dir / name).string();
    std::string message = "unchanged";
    ASSERT_EQ(kergen::write_mesh_file(path, m, &message), Error::Ok) << message;
    ReadResult r = kergen::read_mesh_file(path);
    ASSERT_TRUE(r.ok()) << r.message;
    EXPECT_EQ(triangle_set(m), triangle_set(r.mesh)) << name;
  }
  std::string message;
  EXPECT_EQ(kergen::write_mesh_file((dir / "cube.ply").string(), m, &message), Error::IoError);
  EXPECT_TRUE(contains(message, "cube.ply")) << message;
  EXPECT_EQ(kergen::write_mesh_file((dir / "no" / "such" / "dir.off").string(), m, &message), Error::IoError);
  EXPECT_TRUE(contains(message, "dir.off")) << message;
  fs::remove_all(dir);
}

TEST(IoTest, MeshViewMatchesMesh) {
  Mesh m = quad_cube();
  kergen::MeshView v = m.view();
  EXPECT_EQ(v.positions, m.positions.data());
  EXPECT_EQ(v.num_vertices, 8u);
  EXPECT_EQ(v.indices, m.indices.data());
  EXPECT_EQ(v.num_indices, 24u);
  EXPECT_EQ(v.face_sizes, m.face_sizes.data());
  EXPECT_EQ(v.num_faces, 6u);
  m.face_sizes.clear();
  v = m.view();
  EXPECT_EQ(v.face_sizes, nullptr);
  EXPECT_EQ(v.num_faces, 0u);
}

TEST(IoTest, KernelMeshByType) {
  kergen::Kernel k;
  k.type = kergen::KernelType::Polygon;
  k.vertices = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  k.face_indices = {0, 1, 2};
  k.face_sizes = {3};
  Mesh polygon = kergen::kernel_mesh(k);
  EXPECT_EQ(polygon.num_vertices(), 3u);
  EXPECT_EQ(polygon.num_faces(), 1u);

  k.type = kergen::KernelType::Segment;
  k.vertices = {0, 0, 0, 1, 1, 1};
  k.edges = {0, 1};
  k.face_indices.clear();
  k.face_sizes.clear();
  Mesh segment = kergen::kernel_mesh(k);
  EXPECT_EQ(segment.num_vertices(), 2u);
  EXPECT_EQ(segment.num_faces(), 0u);

  kergen::Kernel empty;
  EXPECT_EQ(kergen::kernel_mesh(empty).num_faces(), 0u);
  EXPECT_EQ(kergen::kernel_mesh(empty).num_vertices(), 0u);
  // An empty face list still writes valid files.
  EXPECT_TRUE(kergen::read_off(kergen::write_off(segment)).error == Error::EmptyInput);
}

TEST(IoTest, FormatFromPath) {
  EXPECT_EQ(kergen::format_from_path("a/b.off"), kergen::MeshFormat::Off);
  EXPECT_EQ(kergen::format_from_path("B.OBJ"), kergen::MeshFormat::Obj);
  EXPECT_EQ(kergen::format_from_path("x.Stl"), kergen::MeshFormat::Stl);
  EXPECT_EQ(kergen::format_from_path("x.PLY"), kergen::MeshFormat::Ply);
  EXPECT_EQ(kergen::format_from_path("x.gltf"), kergen::MeshFormat::Unknown);
  EXPECT_EQ(kergen::format_from_path("dir.off/file"), kergen::MeshFormat::Unknown);
  EXPECT_EQ(kergen::format_from_path("noext"), kergen::MeshFormat::Unknown);
}

// ---------------------------------------------------------------------------------------------
// OBJ.

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

struct ErrorCase {
  std::string text;
  Error error;
  const char* message_part;
};

void expect_errors(ReadResult (*reader)(std::string_view, const std::string&), const std::vector<ErrorCase>& cases) {
  for (const ErrorCase& c : cases) {
    ReadResult r = reader(c.text, "in.txt");
    EXPECT_EQ(r.error, c.error) << c.text << "\n-> " << r.message;
    EXPECT_TRUE(contains(r.message, c.message_part)) << "expected '" << c.message_part << "' in: " << r.message;
    EXPECT_TRUE(r.mesh.positions.empty() && r.mesh.indices.empty()) << "a failed read returns no mesh";
  }
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

// ---------------------------------------------------------------------------------------------
// OFF.

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

// ---------------------------------------------------------------------------------------------
// STL.

std::string ascii_tetra_stl(const char* solid_name = "tet") {
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

// ---------------------------------------------------------------------------------------------
// PLY.

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

void put_ply_value(std::string& out, double value, const std::string& type, Ply encoding) {
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

std::string ply_file(const Mesh& m, const PlyOptions& o) {
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

// ---------------------------------------------------------------------------------------------
// Files.

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

// The outcome judged right for every shared fixture: Ok with the face count, or the error and a
// fragment of the message. Geometric trouble (holes, zero-area or back-to-back triangles) is the
// core's business: those files parse.
struct FixtureOutcome {
  Error error;
  size_t faces;              // when Ok
  const char* message_part;  // when not Ok
};

void check_fixture_folder(const std::string& folder, const std::map<std::string, FixtureOutcome>& expected) {
  std::set<std::string> seen;
  for (const auto& entry : fs::directory_iterator(folder)) {
    const std::string name = entry.path().filename().string();
    if (kergen::format_from_path(name) == kergen::MeshFormat::Unknown) continue;  // licences
    seen.insert(name);
    auto it = expected.find(name);
    if (it == expected.end()) {
      ADD_FAILURE() << "no expectation for new fixture " << name;
      continue;
    }
    ReadResult r = kergen::read_mesh_file(entry.path().string());
    EXPECT_EQ(r.error, it->second.error) << name << ": " << r.message;
    if (it->second.error == Error::Ok) {
      EXPECT_EQ(r.mesh.num_faces(), it->second.faces) << name;
    } else {
      EXPECT_TRUE(contains(r.message, entry.path().string())) << "message names the file: " << r.message;
      EXPECT_TRUE(contains(r.message, it->second.message_part)) << name << ": " << r.message;
    }
  }
  for (const auto& [name, outcome] : expected) EXPECT_TRUE(seen.count(name)) << "fixture missing: " << name;
}

TEST(IoFixtures, FormatsFolder) {
  REQUIRE_SHARED_MESHES();
  check_fixture_folder(
      shared_meshes() + "/fixtures/formats",
      {
          {"3DSMaxExport.STL", {Error::Ok, 2000, ""}},
          {"Cube.off", {Error::Ok, 6, ""}},
          {"box.obj", {Error::Ok, 6, ""}},
          {"box_UTF16BE.obj", {Error::ParseError, 0, "box_UTF16BE.obj:1: UTF-16 is not supported"}},
          {"box_mat_with_spaces.obj", {Error::Ok, 6, ""}},
          {"box_without_lineending.obj", {Error::Ok, 6, ""}},
          {"concave_polygon.obj", {Error::Ok, 1, ""}},
          {"cube_usemtl.obj", {Error::Ok, 12, ""}},
          {"cube_with_vertexcolors.obj", {Error::Ok, 12, ""}},
          {"import_ascii.stl", {Error::Ok, 46, ""}},
          {"import_binary.stl", {Error::Ok, 46, ""}},
          {"multiple_spaces.obj", {Error::Ok, 1, ""}},
          // "3.1+e2" is not a number (the '+' precedes the 'e').
          {"number_formats.obj", {Error::ParseError, 0, "number_formats.obj:11: invalid number '3.1+e2'"}},
          {"sphereWithHole.stl", {Error::Ok, 285, ""}},
          {"testline.obj", {Error::EmptyInput, 0, "no faces (only points/lines)"}},
          {"testpoints.obj", {Error::EmptyInput, 0, "no faces (only points/lines)"}},
          {"triangle_with_empty_solid.stl", {Error::Ok, 1, ""}},
          {"triangle_with_two_solids.stl", {Error::Ok, 2, ""}},
      });
}

TEST(IoFixtures, FormatsSameShapeAcrossFormats) {
  REQUIRE_SHARED_MESHES();
  const std::string dir = shared_meshes() + "/fixtures/formats/";
  ReadResult ascii = kergen::read_mesh_file(dir + "import_ascii.stl");
  ReadResult binary = kergen::read_mesh_file(dir + "import_binary.stl");
  ASSERT_TRUE(ascii.ok() && binary.ok());
  EXPECT_EQ(ascii.mesh.num_vertices(), 25u);
  EXPECT_EQ(binary.mesh.num_vertices(), 25u);
  // The ascii file has 6 decimals, the binary one floats: same triangles up to float rounding.
  auto a = triangle_set(ascii.mesh), b = triangle_set(binary.mesh);
  ASSERT_EQ(a.size(), b.size());
  for (auto ia = a.begin(), ib = b.begin(); ia != a.end(); ++ia, ++ib)
    for (size_t k = 0; k < 9; ++k) EXPECT_NEAR((*ia)[k], (*ib)[k], 1e-6);

  ReadResult box = kergen::read_mesh_file(dir + "box.obj");
  ReadResult no_newline = kergen::read_mesh_file(dir + "box_without_lineending.obj");
  ASSERT_TRUE(box.ok() && no_newline.ok());
  expect_same_mesh(box.mesh, no_newline.mesh);
}

TEST(IoFixtures, BadFolder) {
  REQUIRE_SHARED_MESHES();
  check_fixture_folder(
      shared_meshes() + "/fixtures/bad",
      {
          // Well-formed binary STL of a broken model: the core judges it.
          {"bad-stl-tardis.stl", {Error::Ok, 3636, ""}},
          {"empty2.stl", {Error::EmptyInput, 0, "no facets"}},
          {"invalidvertex.stl", {Error::ParseError, 0, "invalidvertex.stl:89: invalid number 'blah'"}},
          {"issue1580-back-to-back.stl", {Error::Ok, 10, ""}},
          {"issue1580-zero-area-triangle.stl", {Error::Ok, 14, ""}},
          {"toomanyvertices.stl", {Error::ParseError, 0, "toomanyvertices.stl:91: facet has more than 3 vertices"}},
          {"unparseable.stl", {Error::ParseError, 0, "unparseable.stl:4: invalid number '\\x10'"}},
      });
}

TEST(IoFixtures, EveryMeshFixtureParses) {
  REQUIRE_SHARED_MESHES();
  size_t checked = 0;
  for (const auto& entry : fs::directory_iterator(shared_meshes() + "/fixtures")) {
    if (!entry.is_regular_file() || kergen::format_from_path(entry.path().string()) == kergen::MeshFormat::Unknown)
      continue;
    ReadResult r = kergen::read_mesh_file(entry.path().string());
    EXPECT_TRUE(r.ok()) << r.message;
    EXPECT_GT(r.mesh.num_faces(), 0u) << entry.path();
    ++checked;
  }
  EXPECT_GE(checked, 30u);
}

}  // namespace
