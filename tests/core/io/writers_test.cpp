// Writers (kergen/io.h): OFF, OBJ and binary STL round trips keep every bit (STL: every float),
// write_mesh_file by extension, Mesh::view and kernel_mesh.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "io/io_test_util.h"
#include "kergen/io.h"

namespace {

using namespace io_test;

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

}  // namespace
