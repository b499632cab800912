// Options::weld: a triangle soup and seams that differ by rounding become the closed surface they
// describe; the kernel is then the one of the indexed mesh. Welding never runs on malformed input
// (validation reports that as given), and exact equality (weld = 0) merges only equal positions.
#include "input/weld.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fixtures.h"
#include "kergen/kergen.h"

namespace {

using kergen::Error;
using kergen::Mesh;
using kergen::Options;

// Every triangle with its own three vertices; a random half of the copies moved by `jitter`.
Mesh soup(const Mesh& m, double jitter, uint64_t seed) {
  std::mt19937_64 rng(seed);
  Mesh out;
  for (uint32_t v : m.indices) {
    for (int k = 0; k < 3; ++k) out.positions.push_back(m.positions[3 * v + k] + (rng() % 2 ? jitter : 0.0));
    out.indices.push_back(uint32_t(out.indices.size()));
  }
  return out;
}

const kergen::Warning* welded(const kergen::Kernel& k) {
  for (const auto& w : k.warnings)
    if (w.kind == kergen::Warning::Kind::VerticesWelded) return &w;
  return nullptr;
}

TEST(Weld, SoupOfAnIndexedMeshGivesItsKernel) {
  for (const Mesh& m : {kergen_test::l_prism(), kergen_test::dented_cube(), kergen_test::bumpy_sphere(30, 16, 0.1)}) {
    Mesh tri = m;  // (polygon faces fanned, so every face is a triangle of the soup)
    if (!m.face_sizes.empty()) {
      tri.indices.clear();
      tri.face_sizes.clear();
      for (size_t f = 0, at = 0; f < m.face_sizes.size(); at += m.face_sizes[f++]) {
        // The fan's apex must see the whole polygon, or its triangles fold over each other (a
        // surface that overlaps itself): the L's reflex corner (1, 1) for its caps.
        const uint32_t n = m.face_sizes[f];
        uint32_t apex = 0;
        for (uint32_t i = 0; i < n; ++i)
          if (m.positions[3 * m.indices[at + i]] == 1 && m.positions[3 * m.indices[at + i] + 1] == 1) apex = i;
        auto corner = [&](uint32_t i) { return m.indices[at + (apex + i) % n]; };
        for (uint32_t i = 1; i + 1 < n; ++i)
          tri.indices.insert(tri.indices.end(), {corner(0), corner(i), corner(i + 1)});
      }
    }
    const kergen::Kernel reference = kergen::compute_kernel(tri.view());
    ASSERT_TRUE(reference.ok()) << reference.message;
    const Mesh s = soup(tri, 0.0, 1);
    EXPECT_EQ(kergen::compute_kernel(s.view()).error, Error::OpenMesh);
    for (double tolerance : {0.0, 1e-9}) {
      Options o;
      o.weld = tolerance;
      const kergen::Kernel k = kergen::compute_kernel(s.view(), o);
      ASSERT_TRUE(k.ok()) << k.message;
      EXPECT_EQ(k.type, reference.type);
      EXPECT_EQ(k.volume, reference.volume);
      EXPECT_EQ(k.num_vertices(), reference.num_vertices());
      ASSERT_NE(welded(k), nullptr);
      EXPECT_EQ(welded(k)->count, s.num_vertices() - tri.num_vertices());
      for (const auto& w : k.warnings) EXPECT_NE(w.kind, kergen::Warning::Kind::UnusedVertices) << w.message;
    }
  }
}

TEST(Weld, SeamsWithinTheToleranceCloseAndOthersDoNot) {
  const Mesh m = kergen_test::bumpy_sphere(24, 12, 0.1);
  const Mesh s = soup(m, 1e-12, 2);
  Options exact;
  exact.weld = 0;
  EXPECT_EQ(kergen::compute_kernel(s.view(), exact).error, Error::OpenMesh) << "1e-12 apart is not equal";
  Options absolute;
  absolute.weld = 1e-10;
  const kergen::Kernel a = kergen::compute_kernel(s.view(), absolute);
  ASSERT_TRUE(a.ok()) << a.message;
  EXPECT_NEAR(a.volume, kergen::compute_kernel(m.view()).volume, 1e-9);
  Options relative;
  relative.weld = 1e-9;  // of the diagonal, about 3.5: 3.5e-9
  relative.weld_relative = true;
  EXPECT_TRUE(kergen::compute_kernel(s.view(), relative).ok());
  Options tiny;
  tiny.weld = 1e-14;
  EXPECT_EQ(kergen::compute_kernel(s.view(), tiny).error, Error::OpenMesh);
}

TEST(Weld, CollapsedFacesAreDroppedAndCounted) {
  // A cube with one extra sliver triangle whose corners are within the tolerance of one vertex.
  Mesh m = kergen_test::unit_cube();
  m.positions.insert(m.positions.end(), {1e-12, 0, 0, 0, 1e-12, 0});
  m.indices.insert(m.indices.end(), {0, 8, 9});
  Options o;
  o.weld = 1e-9;
  const kergen::WeldResult w = kergen::weld_vertices(m.view(), 1e-9, false);
  EXPECT_EQ(w.merged_vertices, 2u);
  EXPECT_EQ(w.dropped_faces, 1u);
  EXPECT_EQ(w.mesh.num_faces(), 12u);
  const kergen::Kernel k = kergen::compute_kernel(m.view(), o);
  ASSERT_TRUE(k.ok()) << k.message;
  EXPECT_EQ(k.stats.input_faces, 13u);
  EXPECT_EQ(k.stats.dropped_faces, 1u);
  EXPECT_NE(welded(k)->message.find("1 faces that collapsed were dropped"), std::string::npos) << welded(k)->message;
}

TEST(Weld, MalformedInputIsReportedAsGiven) {
  Options o;
  o.weld = 1e-6;
  Mesh bad = kergen_test::unit_cube();
  bad.indices[5] = 99;
  EXPECT_EQ(kergen::compute_kernel(bad.view(), o).error, Error::IndexOutOfRange);
  Mesh nan = kergen_test::unit_cube();
  nan.positions[4] = std::nan("");
  EXPECT_EQ(kergen::compute_kernel(nan.view(), o).error, Error::NonFiniteCoordinate);
  // Off by default: the soup stays open and the message says what to try.
  const kergen::Kernel open = kergen::compute_kernel(soup(kergen_test::unit_cube(), 0, 3).view());
  EXPECT_EQ(open.error, Error::OpenMesh);
  EXPECT_NE(open.message.find("Options::weld"), std::string::npos) << open.message;
  EXPECT_NE(open.message.find("Options::allow_open"), std::string::npos) << open.message;
}

}  // namespace
