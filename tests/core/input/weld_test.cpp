// Options::weld: a triangle soup and seams that differ by rounding become the closed surface they
// describe; the kernel is then the one of the indexed mesh. Welding never runs on malformed input
// (validation reports that as given), and exact equality (weld = 0) merges only equal positions.
#include "input/weld.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <numeric>
#include <random>
#include <vector>

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
  EXPECT_NE(welded(k)->message.find("1 face that collapsed was dropped"), std::string::npos) << welded(k)->message;
}

// A weld that merges nothing leaves the input as it is (no copy): the kernel, its face sources
// and the warnings are those of the run without weld. A face repeating a corner is still dropped
// by the weld when nothing merges.
TEST(Weld, NothingMergedIsTheInputAsGiven) {
  const Mesh cube = kergen_test::unit_cube();
  const kergen::WeldResult w = kergen::weld_vertices(cube.view(), 1e-9, true);
  EXPECT_TRUE(w.unchanged);
  EXPECT_EQ(w.merged_vertices, 0u);
  EXPECT_TRUE(w.mesh.indices.empty());
  Options o;
  o.weld = 1e-9;
  o.weld_relative = true;
  const kergen::Kernel plain = kergen::compute_kernel(cube.view()), weld = kergen::compute_kernel(cube.view(), o);
  ASSERT_TRUE(weld.ok()) << weld.message;
  EXPECT_EQ(weld.vertices, plain.vertices);
  EXPECT_EQ(weld.face_sources, plain.face_sources);
  EXPECT_EQ(weld.warnings.size(), plain.warnings.size());
  EXPECT_EQ(welded(weld), nullptr);
  Options repaired = o;
  repaired.repair = true;
  EXPECT_EQ(kergen::compute_kernel(cube.view(), repaired).vertices, plain.vertices);

  Mesh repeats = cube;  // one more face, a -> a -> b: dropped by the weld, no vertex merged
  repeats.indices.insert(repeats.indices.end(), {0, 0, 1});
  const kergen::WeldResult r = kergen::weld_vertices(repeats.view(), 1e-9, true);
  EXPECT_FALSE(r.unchanged);
  EXPECT_EQ(r.merged_vertices, 0u);
  EXPECT_EQ(r.dropped_faces, 1u);
  EXPECT_EQ(r.mesh.num_faces(), 12u);
  const kergen::Kernel k = kergen::compute_kernel(repeats.view(), o);
  ASSERT_TRUE(k.ok()) << k.message;
  EXPECT_EQ(k.stats.dropped_faces, 1u);
  EXPECT_EQ(k.vertices, plain.vertices);
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
  Mesh inf = kergen_test::unit_cube();
  inf.positions.back() = -INFINITY;
  EXPECT_EQ(kergen::compute_kernel(inf.view(), o).error, Error::NonFiniteCoordinate);
  Mesh last = kergen_test::unit_cube();
  last.indices.back() = uint32_t(last.num_vertices());  // (one past the end, in the last face)
  EXPECT_EQ(kergen::compute_kernel(last.view(), o).error, Error::IndexOutOfRange);
  // Off by default: the soup stays open and the message says what to try.
  const kergen::Kernel open = kergen::compute_kernel(soup(kergen_test::unit_cube(), 0, 3).view());
  EXPECT_EQ(open.error, Error::OpenMesh);
  EXPECT_NE(open.message.find("Options::weld"), std::string::npos) << open.message;
  EXPECT_NE(open.message.find("Options::allow_open"), std::string::npos) << open.message;
}

// The single-level grid weld_groups is specified by (weld.h), as weld.cpp did it before its
// two-level search: each point against every earlier point in the 27 cells of the tolerance's
// size around its own (only its own with tolerance 0, cells keyed by the coordinates' bits),
// merged when the distance in double is within the tolerance; groups by their lowest index.
std::vector<uint32_t> reference_groups(const std::vector<double>& p, double t) {
  const size_t n = p.size() / 3;
  auto cell_of = [t](double x) -> int64_t {
    if (t == 0) {
      const double y = x == 0 ? 0.0 : x;
      int64_t bits;
      std::memcpy(&bits, &y, sizeof bits);
      return bits;
    }
    return int64_t(std::max(-4.0e18, std::min(4.0e18, std::floor(x / t))));
  };
  std::vector<uint32_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](uint32_t x) {
    while (parent[x] != x) x = parent[x];
    return x;
  };
  std::map<std::array<int64_t, 3>, std::vector<uint32_t>> cells;
  const int reach = t == 0 ? 0 : 1;
  for (uint32_t v = 0; v < n; ++v) {
    const std::array<int64_t, 3> c = {cell_of(p[3 * v]), cell_of(p[3 * v + 1]), cell_of(p[3 * v + 2])};
    for (int dx = -reach; dx <= reach; ++dx)
      for (int dy = -reach; dy <= reach; ++dy)
        for (int dz = -reach; dz <= reach; ++dz) {
          auto it = cells.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == cells.end()) continue;
          for (uint32_t w : it->second) {
            const double d[3] = {p[3 * v] - p[3 * w], p[3 * v + 1] - p[3 * w + 1], p[3 * v + 2] - p[3 * w + 2]};
            const bool close =
                t == 0 ? d[0] == 0 && d[1] == 0 && d[2] == 0 : d[0] * d[0] + d[1] * d[1] + d[2] * d[2] <= t * t;
            if (!close) continue;
            const uint32_t a = find(v), b = find(w);
            parent[std::max(a, b)] = std::min(a, b);
          }
        }
    cells[c].push_back(v);
  }
  std::vector<uint32_t> root(n);
  for (uint32_t v = 0; v < n; ++v) root[v] = find(v);
  return root;
}

// Point clouds that probe the grid's edges: clusters whose members lie about the tolerance apart
// (some exactly the tolerance apart, along an axis), transitive chains of steps just inside it,
// points on a grid of the tolerance itself (on cell boundaries, around 0 where both levels of the
// grid have a boundary), dense clusters far from the rest (many points to one coarse cell),
// coordinates far from 0 (where x / tolerance rounds), and repeated positions with -0 and +0.
std::vector<double> probe_cloud(std::mt19937_64& rng, double t, int kind) {
  std::uniform_real_distribution<double> unit(-1, 1);
  std::vector<double> p;
  auto put = [&](double x, double y, double z) { p.insert(p.end(), {x, y, z}); };
  const double offset = kind % 3 == 2 ? 1e6 : 0.0;
  const int clusters = 40 + int(rng() % 80);
  for (int c = 0; c < clusters; ++c) {
    // Centres on a grid of 2^-30 (t is a power of two here, or 3 times one): sums with
    // multiples of t are exact, so ties at exactly t occur.
    const double cx = offset + std::ldexp(std::round(unit(rng) * 0x1p30), -30);
    const double cy = std::ldexp(std::round(unit(rng) * 0x1p30), -30),
                 cz = std::ldexp(std::round(unit(rng) * 0x1p30), -30);
    switch (rng() % 5) {
      case 0:  // a cluster about t apart
        for (int i = 0, m = 2 + int(rng() % 8); i < m; ++i) {
          const double r = t * (0.5 + unit(rng) * 0.6);
          put(cx + r * unit(rng), cy + r * unit(rng), cz + r * unit(rng));
        }
        break;
      case 1:  // exactly t apart along an axis
        put(cx, cy, cz);
        put(cx + t, cy, cz);
        put(cx, cy - t, cz);
        put(cx, cy, cz + 2 * t);
        break;
      case 2:  // a chain of steps just inside t
        for (int i = 0, m = 3 + int(rng() % 30); i < m; ++i) put(cx + 0.99 * t * i, cy + 0.1 * t * i, cz);
        break;
      case 3:  // points on the grid of t around 0 and around the centre
        for (int i = 0; i < 12; ++i) {
          const double gx = t * double(int(rng() % 5) - 2), gy = t * double(int(rng() % 5) - 2);
          const double gz = t * double(int(rng() % 5) - 2);
          put(gx + (rng() % 2 ? 0.0 : -0.0), gy, gz);
          put(cx + gx, cy + gy, cz + gz);
        }
        break;
      default:  // repeated positions, -0 and +0
        put(cx, cy, cz);
        put(cx, cy, cz);
        put(0.0, cy, cz);
        put(-0.0, cy, cz);
        break;
    }
  }
  if (kind % 3 == 1) {  // a dense cluster: hundreds of points within a few t
    const double cx = unit(rng), cy = unit(rng), cz = unit(rng);
    for (int i = 0; i < 600; ++i) put(cx + 6 * t * unit(rng), cy + 6 * t * unit(rng), cz + 6 * t * unit(rng));
  }
  // Shuffled points, so that groups' lowest indices are anywhere.
  const size_t n = p.size() / 3;
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), size_t(0));
  std::shuffle(order.begin(), order.end(), rng);
  std::vector<double> shuffled(p.size());
  for (size_t i = 0; i < n; ++i)
    for (int k = 0; k < 3; ++k) shuffled[3 * i + k] = p[3 * order[i] + k];
  return shuffled;
}

TEST(Weld, GroupsAreTheSingleLevelGridsOnProbeClouds) {
  std::mt19937_64 rng(33);
  size_t merged = 0, points = 0;
  for (int round = 0; round < 300; ++round) {
    // (Tolerances from about the clouds' spacing, where the grid has one level, down to 2^-27.)
    const double t = round % 4 == 3 ? 0.0 : std::ldexp(round % 2 ? 3.0 : 1.0, -4 - int(rng() % 24));
    const std::vector<double> p = probe_cloud(rng, t, round);
    const std::vector<uint32_t> expected = reference_groups(p, t);
    ASSERT_EQ(kergen::weld_groups(p.data(), p.size() / 3, t), expected) << "round " << round << ", t " << t;
    for (uint32_t v = 0; v < expected.size(); ++v) merged += expected[v] != v;
    points += expected.size();
  }
  // The clouds do merge (and do not merge everything).
  EXPECT_GT(merged, points / 10);
  EXPECT_LT(merged, points - points / 10);
}

}  // namespace
