// The kernel of an open surface with boundary walls (Options::open_boundary = Perpendicular)
// against CGAL: the oracle gets the same half-spaces, the surface's faces and the walls the
// library builds (their exact input points), as triangles taken as half-spaces only
// (OracleOptions::half_spaces_only). The walls' construction itself is checked in
// tests/core/input/open_boundary_test.cpp (perpendicular within 2e-14 radians, exactly z = 0 for a
// lipped bowl).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "cgal_oracle.h"
#include "fixtures.h"
#include "kergen/io.h"
#include "kergen/kergen.h"
#include "open_surfaces.h"

namespace {

using kergen::Mesh;

Mesh faces_and_walls(const Mesh& m) {
  Mesh soup = m;
  for (const auto& w : kergen_test::boundary_walls(m)) {
    uint32_t ids[3];
    for (int c = 0; c < 3; ++c) ids[c] = kergen_test::add_point(soup, w[c][0], w[c][1], w[c][2]);
    kergen_test::add_face(soup, {ids[0], ids[1], ids[2]});
  }
  return soup;
}

void expect_oracle_agrees(const Mesh& m, const char* name) {
  kergen::Options o;
  o.open_boundary = kergen::OpenBoundary::Perpendicular;
  const kergen::Kernel k = kergen::compute_kernel(m.view(), o);
  ASSERT_TRUE(k.ok()) << name << ": " << k.message;
  ASSERT_EQ(k.type, kergen::KernelType::Polyhedron) << name;
  kergen_oracle::OracleOptions half_spaces;
  half_spaces.half_spaces_only = true;
  const kergen_oracle::OracleResult r = kergen_oracle::oracle_kernel(faces_and_walls(m), half_spaces);
  ASSERT_TRUE(r.ok) << name << ": " << r.message;
  EXPECT_FALSE(r.flipped) << name;
  ASSERT_EQ(r.verdict, kergen_oracle::Verdict::Full) << name;
  EXPECT_EQ(r.vertices, k.num_vertices()) << name;
  EXPECT_EQ(r.facets, k.num_faces()) << name;
  EXPECT_NEAR(k.volume, r.volume, 1e-12 * r.volume) << name;
  std::printf("%s: kergen V %zu F %zu volume %.15g; CGAL V %zu F %zu volume %.15g\n", name, k.num_vertices(),
              k.num_faces(), k.volume, r.vertices, r.facets, r.volume);
}

TEST(OracleOpenBoundary, HemisphereBowl) { expect_oracle_agrees(kergen_test::bowl(32, 12), "bowl 32x12"); }
TEST(OracleOpenBoundary, LippedBowl) { expect_oracle_agrees(kergen_test::bowl(24, 8, 0.25), "lipped bowl 24x8"); }
TEST(OracleOpenBoundary, Hill) { expect_oracle_agrees(kergen_test::hill(12), "hill 12x12"); }
TEST(OracleOpenBoundary, OpenCube) { expect_oracle_agrees(kergen_test::open_cube(), "open cube"); }

// ---- closed shared meshes with a hole --------------------------------------------------------
// Every mesh loses the faces around one vertex (the first corner of face 0): an open surface with
// a hole, walled by the library. The oracle gets its faces, the walls and the library's clipping
// box (six planes at twice the power of two that bounds the coordinates, as add_bounding_box puts
// them in scaled units), so unbounded kernels are compared too: the same verdict, and for full
// kernels the same vertex count and volume.

namespace fs = std::filesystem;

Mesh with_hole(const Mesh& m) {
  Mesh out;
  out.positions = m.positions;
  const uint32_t gone = m.indices[0];
  size_t at = 0;
  for (size_t f = 0; f < m.num_faces(); ++f) {
    const size_t k = m.face_sizes.empty() ? 3 : m.face_sizes[f];
    const auto begin = m.indices.begin() + long(at), end = begin + long(k);
    at += k;
    if (std::find(begin, end, gone) != end) continue;
    if (!m.face_sizes.empty() || !out.face_sizes.empty()) {
      if (out.face_sizes.empty()) out.face_sizes.assign(out.indices.size() / 3, 3);
      out.face_sizes.push_back(uint32_t(k));
    }
    out.indices.insert(out.indices.end(), begin, end);
  }
  return out;
}

void add_clipping_box(Mesh& soup, const Mesh& m) {
  double largest = 0;
  for (double x : m.positions) largest = std::max(largest, std::fabs(x));
  int ex = 0;
  std::frexp(largest, &ex);
  const double b = std::ldexp(1.0, ex + 1);
  for (int k = 0; k < 3; ++k)
    for (int sign = -1; sign <= 1; sign += 2) {
      double p[3][3] = {};
      for (int c = 0; c < 3; ++c) p[c][k] = sign * b;
      p[sign > 0 ? 1 : 2][(k + 1) % 3] = b;  // CCW seen from outside the box
      p[sign > 0 ? 2 : 1][(k + 2) % 3] = b;
      uint32_t ids[3];
      for (int c = 0; c < 3; ++c) ids[c] = kergen_test::add_point(soup, p[c][0], p[c][1], p[c][2]);
      kergen_test::add_face(soup, {ids[0], ids[1], ids[2]});
    }
}

const char* expected_verdict(kergen::KernelType t) {
  switch (t) {
    case kergen::KernelType::Empty: return "EMPTY";
    case kergen::KernelType::Polyhedron:
    case kergen::KernelType::Unbounded: return "FULL";
    default: return "FLAT";
  }
}

}  // namespace

TEST(OracleOpenBoundary, SharedMeshesWithAHole) {
  const fs::path meshes = KERGEN_SHARED_MESHES;
  if (!fs::is_directory(meshes / "polyhedra")) GTEST_SKIP() << "shared meshes not found at " << meshes;
  std::vector<fs::path> files;
  for (const char* d :
       {"fixtures", "princeton", "polyhedra/tet10", "polyhedra/tet20", "polyhedra/tet30", "polyhedra/voro"}) {
    std::vector<fs::path> in;
    for (const auto& e : fs::directory_iterator(meshes / d))
      if (e.path().extension() == ".off") in.push_back(e.path());
    std::sort(in.begin(), in.end());
    const size_t stride = std::string(d).rfind("polyhedra", 0) == 0 ? 25 : 1;  // 40 of each 1000
    for (size_t i = 0; i < in.size(); i += stride) files.push_back(in[i]);
  }
  kergen::Options o;
  o.open_boundary = kergen::OpenBoundary::Perpendicular;
  kergen_oracle::OracleOptions half_spaces;
  half_spaces.half_spaces_only = true;
  size_t compared = 0, refused = 0, full = 0, unbounded = 0, empty = 0, flat = 0;
  for (const fs::path& file : files) {
    const kergen::ReadResult read = kergen::read_mesh_file(file.string());
    if (!read.ok() || read.mesh.num_faces() > 20000) continue;
    const Mesh holed = with_hole(read.mesh);
    const kergen::Kernel k = kergen::compute_kernel(holed.view(), o);
    EXPECT_NE(k.error, kergen::Error::Internal) << file << ": " << k.message;
    if (!k.ok()) {  // the closed mesh's own defects, or a hole that splits it
      ++refused;
      std::printf("refused: %s: %s: %s\n", file.filename().c_str(), kergen::error_name(k.error), k.message.c_str());
      continue;
    }
    Mesh soup = faces_and_walls(holed);
    add_clipping_box(soup, holed);
    const kergen_oracle::OracleResult r = kergen_oracle::oracle_kernel(soup, half_spaces);
    ASSERT_TRUE(r.ok) << file << ": " << r.message;
    ++compared;
    const std::string verdict = kergen_oracle::verdict_name(r.verdict);
    EXPECT_EQ(verdict, expected_verdict(k.type)) << file;
    empty += k.type == kergen::KernelType::Empty;
    flat += verdict == "FLAT";
    full += k.type == kergen::KernelType::Polyhedron;
    unbounded += k.type == kergen::KernelType::Unbounded;
    if (r.verdict == kergen_oracle::Verdict::Full && r.has_polyhedron) {
      EXPECT_EQ(r.vertices, k.num_vertices()) << file;
      EXPECT_NEAR(k.volume, r.volume, 1e-9 * r.volume) << file;
    }
  }
  std::printf(
      "shared meshes with a hole: %zu compared with CGAL (%zu bounded, %zu unbounded, %zu empty, %zu flat), "
      "%zu refused\n",
      compared, full, unbounded, empty, flat, refused);
  EXPECT_GE(compared, 150u);
}
