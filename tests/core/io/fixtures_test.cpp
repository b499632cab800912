// The outcome judged right for every file of the shared format/bad fixture folders.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <set>
#include <string>

#include "io/io_test_util.h"
#include "kergen/io.h"

namespace {

using namespace io_test;

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
