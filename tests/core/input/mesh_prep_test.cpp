// prepare_mesh: details of the validation pass that the kernel results do not show directly.
#include "input/mesh_prep.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "exact/predicates.h"
#include "fixtures.h"
#include "input/prep_state.h"

namespace {

using namespace kergen;

// A unit cube, 12 triangles counter-clockwise seen from outside.
Mesh unit_cube() {
  Mesh m;
  m.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1, 1, 1, 1};
  m.indices = {0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6, 0, 1, 5, 0, 5, 4,
               2, 6, 7, 2, 7, 3, 0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5};
  return m;
}

// A zero bound of the box has the sign of the first zero coordinate met in loop order, not of
// the lowest vertex id: the first face starts at vertex 2 here, vertex 0 comes later.
TEST(MeshPrep, ZeroBoundTakesTheSignOfTheFirstZeroInLoopOrder) {
  for (bool negative_first : {true, false}) {
    Mesh m = unit_cube();
    m.indices[0] = 2, m.indices[1] = 3, m.indices[2] = 0;  // (0, 2, 3) rotated
    m.positions[3 * 2] = negative_first ? -0.0 : 0.0;
    m.positions[3 * 0] = negative_first ? 0.0 : -0.0;
    PreparedMesh p = prepare_mesh(m.view(), Options{});
    ASSERT_EQ(p.error, Error::Ok) << p.message;
    EXPECT_EQ(p.bbox_min[0], 0.0);
    EXPECT_EQ(std::signbit(p.bbox_min[0]), negative_first);
    EXPECT_EQ(p.bbox_max[0], p.to_scaled(1.0));
  }
}

// Two cubes that share one vertex id are two pieces (faces connect through edges only).
TEST(MeshPrep, CubesSharingAVertexAreTwoPieces) {
  Mesh m = unit_cube();
  const uint32_t nv = 8;
  for (int i = 1; i < 8; ++i)
    for (int k = 0; k < 3; ++k) m.positions.push_back(-m.positions[3 * i + k]);  // vertex i -> 7 + i
  const size_t ni = m.indices.size();
  for (size_t i = 0; i < ni; i += 3) {  // mirrored through the origin: orientation reversed
    for (int j : {0, 2, 1}) {
      const uint32_t v = m.indices[i + j];
      m.indices.push_back(v == 0 ? 0 : nv - 1 + v);
    }
  }
  PreparedMesh p = prepare_mesh(m.view(), Options{});
  EXPECT_EQ(p.error, Error::MultipleComponents);
  EXPECT_NE(p.message.find("2 separate pieces"), std::string::npos) << p.message;
}

// The non-finite coordinate named is the first one, whatever its kind.
TEST(MeshPrep, FirstNonFiniteCoordinateIsNamed) {
  Mesh m = unit_cube();
  m.positions[3 * 5 + 1] = NAN;
  m.positions[3 * 2 + 2] = -INFINITY;
  PreparedMesh p = prepare_mesh(m.view(), Options{});
  EXPECT_EQ(p.error, Error::NonFiniteCoordinate);
  EXPECT_NE(p.message.find("vertex 2 has a non-finite coordinate (-inf)"), std::string::npos) << p.message;
}

// Coordinates are scanned four at a time, then a scalar tail: a non-finite value and the smallest
// non-zero magnitude (which sets the exact shift) count in a block and in the tail alike. Two
// unused vertices make 30 coordinates: 25 is in the last block, 29 in the tail.
TEST(MeshPrep, CoordinateExtremaInABlockAndInTheTail) {
  Mesh m = unit_cube();
  m.positions.insert(m.positions.end(), {0.5, 0.5, 0.5, 0.25, 0.25, 0.25});
  const PreparedMesh plain = prepare_mesh(m.view(), Options{});
  ASSERT_EQ(plain.error, Error::Ok) << plain.message;
  EXPECT_EQ(plain.exact_shift, 0);
  for (size_t at : {size_t(25), size_t(29)}) {
    Mesh t = m;
    t.positions[at] = -std::ldexp(1.0, -200);
    PreparedMesh p = prepare_mesh(t.view(), Options{});
    ASSERT_EQ(p.error, Error::Ok) << p.message;
    EXPECT_GT(p.exact_shift, 0) << "coordinate " << at;
    for (double bad : {double(NAN), -double(INFINITY)}) {
      t.positions[at] = bad;
      p = prepare_mesh(t.view(), Options{});
      EXPECT_EQ(p.error, Error::NonFiniteCoordinate) << "coordinate " << at;
      EXPECT_NE(p.message.find("vertex " + std::to_string(at / 3) + " has a non-finite"), std::string::npos)
          << p.message;
    }
  }
}

// Edge-adjacent face pairs: ordered by lower vertex id, then by the face using the edge upwards,
// lower face first; one per edge of a closed mesh.
TEST(MeshPrep, AdjacentPairsOfATetrahedron) {
  Mesh m;
  m.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  m.indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  PreparedMesh p = prepare_mesh(m.view(), Options{});
  ASSERT_EQ(p.error, Error::Ok) << p.message;
  // Uses up from 0, in face order: 0->2 (face 0, back in face 2), 0->1 (face 1, back in 0),
  // 0->3 (face 2, back in 1). From 1: 1->3 (face 1, back in 3), 1->2 (face 3, back in 0).
  // From 2: 2->3 (face 3, back in 2).
  const decltype(PreparedMesh::adjacent) expected = {{0, 2}, {0, 1}, {1, 2}, {1, 3}, {0, 3}, {2, 3}};
  EXPECT_EQ(p.adjacent, expected);
  EXPECT_EQ(p.num_faces(), 4u);
}

// The cube with quadrilateral faces (counter-clockwise seen from outside), for the path that
// handles faces other than triangles.
Mesh quad_cube() {
  Mesh m = unit_cube();
  m.indices = {0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4, 2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5};
  m.face_sizes = {4, 4, 4, 4, 4, 4};
  return m;
}

// The pairs as specified, found by brute force: for each lower vertex, the uses running up
// from it in face order (loop order within a face), each with the face using the edge back.
decltype(PreparedMesh::adjacent) adjacent_pairs_by_definition(const PreparedMesh& p, size_t num_vertices) {
  decltype(PreparedMesh::adjacent) pairs;
  const size_t faces = p.loop_offsets.size() - 1;
  auto for_each_use = [&](auto&& visit) {
    for (uint32_t f = 0; f < faces; ++f) {
      const uint32_t b = p.loop_offsets[f], e = p.loop_offsets[f + 1];
      for (uint32_t i = b; i < e; ++i) visit(f, p.loops[i], p.loops[i + 1 < e ? i + 1 : b]);
    }
  };
  for (uint32_t lo = 0; lo < num_vertices; ++lo)
    for_each_use([&](uint32_t f, uint32_t u, uint32_t v) {
      if (u != lo || v < lo) return;
      for_each_use([&](uint32_t g, uint32_t x, uint32_t y) {
        if (x == v && y == u) pairs.push_back({std::min(f, g), std::max(f, g)});
      });
    });
  return pairs;
}

// The adjacent pairs follow their definition whether the faces are triangles, polygons or both
// (the check keeps its scratch in different places for the two kinds).
TEST(MeshPrep, AdjacentPairsOfTriangleQuadAndMixedCubes) {
  Mesh mixed = quad_cube();
  mixed.indices = {0, 2, 3, 0, 3, 1, 4, 5, 7, 6, 0, 1, 5, 0, 5, 4, 2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 1, 7, 5};
  mixed.face_sizes = {3, 3, 4, 3, 3, 4, 4, 3, 3};
  for (const Mesh& m : {unit_cube(), quad_cube(), mixed}) {
    PreparedMesh p = prepare_mesh(m.view(), Options{});
    ASSERT_EQ(p.error, Error::Ok) << p.message;
    EXPECT_EQ(p.adjacent, adjacent_pairs_by_definition(p, 8));
    EXPECT_TRUE(p.warnings.empty());  // (the quadrilaterals are planar: kept whole)
    EXPECT_EQ(p.num_faces(), m.num_faces());
  }
}

// A mesh oriented clockwise is flipped; each triangle is then its own representative, with the
// flipped orientation.
// After a weld no two vertices share a position, and prepare_mesh is told so (it skips that
// search): the box (zero bounds' signs included), volume and faces are the same as with the
// search. The cube is moved so that some coordinates are -0.
TEST(MeshPrep, DistinctPositionsSkipOnlyTheSearch) {
  Mesh cube = unit_cube();
  for (size_t i = 0; i < cube.positions.size(); ++i)
    if (cube.positions[i] == 0 && i % 2 == 0) cube.positions[i] = -0.0;
  for (const Mesh& m : {unit_cube(), cube, quad_cube()})
    for (const PrepareFor purpose : {PrepareFor::Faces, PrepareFor::Verdict}) {
      const PreparedMesh searched = prepare_mesh(m.view(), Options{}, true, purpose, false);
      const PreparedMesh skipped = prepare_mesh(m.view(), Options{}, true, purpose, true);
      ASSERT_EQ(searched.error, Error::Ok) << searched.message;
      ASSERT_EQ(skipped.error, Error::Ok) << skipped.message;
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(std::signbit(searched.bbox_min[k]), std::signbit(skipped.bbox_min[k]));
        EXPECT_EQ(searched.bbox_min[k], skipped.bbox_min[k]);
        EXPECT_EQ(searched.bbox_max[k], skipped.bbox_max[k]);
      }
      EXPECT_EQ(searched.volume, skipped.volume);
      EXPECT_EQ(searched.num_faces(), skipped.num_faces());
      EXPECT_EQ(searched.warnings.size(), skipped.warnings.size());
    }
}

TEST(MeshPrep, FlippedTrianglesAreTheirOwnRepresentatives) {
  Mesh m = unit_cube();
  for (size_t i = 0; i < m.indices.size(); i += 3) std::swap(m.indices[i], m.indices[i + 2]);
  PreparedMesh p = prepare_mesh(m.view(), Options{});
  ASSERT_EQ(p.error, Error::Ok) << p.message;
  ASSERT_EQ(p.warnings.size(), 1u);
  EXPECT_EQ(p.warnings[0].kind, Warning::Kind::OrientationFlipped);
  ASSERT_EQ(p.num_faces(), 12u);
  const Mesh cube = unit_cube();
  for (size_t f = 0; f < 12; ++f) {
    const std::array<uint32_t, 3> loop = {p.loops[3 * f], p.loops[3 * f + 1], p.loops[3 * f + 2]};
    EXPECT_EQ(p.rep[f], loop);
    // (reversing the input's reversal gives the original triangle back)
    const std::array<uint32_t, 3> original = {cube.indices[3 * f], cube.indices[3 * f + 1], cube.indices[3 * f + 2]};
    EXPECT_EQ(loop, original);
  }
}

// Input refused after the edge check carries no plane faces.
TEST(MeshPrep, RefusedMeshesHaveNoFaces) {
  Mesh open_triangles = unit_cube();
  open_triangles.indices.resize(open_triangles.indices.size() - 3);
  Mesh open_quads = quad_cube();
  open_quads.indices.resize(open_quads.indices.size() - 4);
  open_quads.face_sizes.pop_back();
  Mesh flat = unit_cube();
  for (size_t v = 0; v < 8; ++v) flat.positions[3 * v + 2] = 0;
  for (const Mesh& m : {open_triangles, open_quads, flat}) {
    PreparedMesh p = prepare_mesh(m.view(), Options{});
    EXPECT_NE(p.error, Error::Ok);
    EXPECT_TRUE(p.rep.empty());
  }
}

// Non-planar polygons are ear-clipped; above 128 corners the corners that could block an ear are
// looked up in a grid, and above 4096 corners (fanned before, which folds over a non-convex loop,
// so the mesh was refused) the budget counts the work done. The split of each cap of a turned
// prism must triangulate the cap: k - 2 triangles, each edge of the loop used once its own way and
// every other edge once each way, and no triangle turned against the loop in the cap's plane
// before the turn. (With the edges paired like that, the triangles' signed areas cover the loop's
// inside exactly once, so none may be negative: a corner missed inside an ear shows as an overlap,
// that is, a triangle turned over.) The caps: a star with random angles and radii (3000 corners,
// where an ear test that never blocks fails), a gear and a spiral band (5000 corners; the spiral's
// ears are often blocked by the next turn, and a grid that misses a column fails there), and a
// star of 300 corners whose edges are cut into 20 (6000 corners collinear up to rounding once
// turned: a walk that went on past each ear instead of stepping back got ears of rounding size
// there that faced against the loop).
TEST(MeshPrep, LargeNonConvexPolygonsAreEarClipped) {
  std::mt19937 rng(5);
  for (int shape = 0; shape < 4; ++shape) {
    const uint32_t k = shape == 0 ? 3000 : shape == 3 ? 6000 : 5000;
    SCOPED_TRACE("shape " + std::to_string(shape) + ", corners " + std::to_string(k));
    std::vector<std::array<double, 2>> poly;
    if (shape == 0) {
      std::vector<double> angles;
      for (uint32_t i = 0; i < k; ++i) angles.push_back(std::uniform_real_distribution<double>(0, 2 * M_PI)(rng));
      std::sort(angles.begin(), angles.end());
      for (double a : angles) {
        const double r = std::uniform_real_distribution<double>(0.2, 1.0)(rng);
        poly.push_back({r * std::cos(a), r * std::sin(a)});
      }
    } else if (shape == 1) {
      for (uint32_t i = 0; i < k; ++i) {
        const double a = 2 * M_PI * double(i) / double(k), r = (i / 2) % 2 ? 0.8 : 1.0;
        poly.push_back({r * std::cos(a), r * std::sin(a)});
      }
    } else if (shape == 3) {
      for (uint32_t i = 0; i < k / 20; ++i) {
        const double a0 = 2 * M_PI * i / double(k / 20), a1 = 2 * M_PI * (i + 1) / double(k / 20);
        const double r0 = i % 3 ? 1.0 : 0.3, r1 = (i + 1) % 3 ? 1.0 : 0.3;
        for (int t = 0; t < 20; ++t)
          poly.push_back({r0 * std::cos(a0) + (r1 * std::cos(a1) - r0 * std::cos(a0)) * t / 20,
                          r0 * std::sin(a0) + (r1 * std::sin(a1) - r0 * std::sin(a0)) * t / 20});
      }
    } else {  // three turns of a band 2.5 wide between r = 1 + a (outside) and r = a - 1.5 (inside, at least 0.3)
      const uint32_t half = k / 2;
      for (uint32_t i = 0; i < k; ++i) {
        const bool outside = i < half;
        const double a = 3 * 2 * M_PI * double(outside ? i : k - 1 - i) / double(half - 1);
        const double r = outside ? 1 + a : std::max(a - 1.5, 0.3);
        poly.push_back({r * std::cos(a), r * std::sin(a)});
      }
    }
    const Mesh m = kergen_test::turned(kergen_test::prism(poly));
    PreparedMesh p = prepare_mesh(m.view(), Options{});
    ASSERT_EQ(p.error, Error::Ok) << p.message;
    for (uint32_t cap = 0; cap < 2; ++cap) {  // the bottom (ids < k, its loop turned clockwise) and the top
      auto xy = [&](uint32_t v) { return poly[v % k]; };
      const double orientation = cap ? 1 : -1;  // seen from +z before the turn
      std::map<std::pair<uint32_t, uint32_t>, int> uses;
      size_t triangles = 0, turned_over = 0;
      for (size_t f = 0; f < p.num_faces(); ++f) {
        if (p.loop_offsets[f + 1] - p.loop_offsets[f] != 3) continue;
        const uint32_t* t = &p.loops[p.loop_offsets[f]];
        if ((t[0] >= k) != bool(cap) || (t[1] >= k) != bool(cap) || (t[2] >= k) != bool(cap)) continue;
        ++triangles;
        for (int e = 0; e < 3; ++e) ++uses[{t[e], t[(e + 1) % 3]}];
        const auto a = xy(t[0]), b = xy(t[1]), c = xy(t[2]);
        const double cross = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        if (orientation * cross < -1e-12) ++turned_over;
      }
      EXPECT_EQ(triangles, size_t(k - 2)) << "cap " << cap;
      EXPECT_EQ(turned_over, 0u) << "cap " << cap;
      size_t loop_edges = 0, unpaired = 0;
      for (const auto& use : uses) {
        const uint32_t u = use.first.first, v = use.first.second;
        const bool loop_edge = cap ? v == k + (u - k + 1) % k : v == (u + k - 1) % k;
        const auto back = uses.find({v, u});
        const int back_uses = back == uses.end() ? 0 : back->second;
        if (loop_edge)
          loop_edges += use.second == 1 && back_uses == 0;
        else
          unpaired += use.second != 1 || back_uses != 1;
      }
      EXPECT_EQ(loop_edges, size_t(k)) << "cap " << cap;
      EXPECT_EQ(unpaired, 0u) << "cap " << cap;
    }
  }
}

}  // namespace

// PrepareFor::Verdict (validate_mesh's) skips work only the faces need: the input's triangles
// are not copied, the leading run's representatives not written. Its verdict is the one
// PrepareFor::Faces gives, on meshes that take each of the paths it changes: a flip, dropped
// zero-area triangles, polygons (planar and not), an open mesh accepted or refused, several
// shells, a thin slab, shared positions, faulty edges.
TEST(MeshPrep, VerdictIsTheFacesVerdict) {
  std::vector<std::pair<std::string, Mesh>> meshes = {
      {"tessellated cube", kergen_test::tessellated_cube(3)},
      {"flipped torus", kergen_test::flipped(kergen_test::torus())},
      {"turned l prism (polygons)", kergen_test::turned(kergen_test::l_prism())},
      {"bumpy sphere", kergen_test::bumpy_sphere(24, 12)},
      {"open cube", kergen_test::open_cube()},
      {"t-junction box", kergen_test::t_junction_box()},
      {"cubes sharing an edge", kergen_test::cubes_sharing_edge()},
      {"thin slab", kergen_test::box(0, 0, 0, 1, 1, 1e-9)},
  };
  {  // a zero-area triangle (1, 0, mid) in a cube: the face d -> 1 -> 0 split at mid, the middle of edge 0-1
    Mesh m = unit_cube();
    const uint32_t mid = kergen_test::add_point(m, 0.5, 0, 0);
    for (size_t t = 0; t < m.indices.size(); t += 3)
      for (int k = 0; k < 3; ++k)
        if (m.indices[t + k] == 1 && m.indices[t + (k + 1) % 3] == 0) {
          const uint32_t d = m.indices[t + (k + 2) % 3];
          m.indices[t + (k + 1) % 3] = mid;  // (1, mid, d)
          m.indices.insert(m.indices.end(), {mid, 0, d, 1, 0, mid});
          t = m.indices.size();
          break;
        }
    meshes.push_back({"cube with a zero-area triangle", m});
  }
  {  // two disjoint cubes: two shells
    Mesh m = unit_cube();
    const Mesh b = kergen_test::box(3, 0, 0, 4, 1, 1);
    const uint32_t base = uint32_t(m.num_vertices());
    m.positions.insert(m.positions.end(), b.positions.begin(), b.positions.end());
    for (uint32_t v : b.indices) m.indices.push_back(base + v);
    meshes.push_back({"two cubes", m});
  }
  {  // two cubes whose corners (1, 1, 1) are distinct vertices at one position
    Mesh m = unit_cube();
    const Mesh b = kergen_test::box(1, 1, 1, 2, 2, 2);
    const uint32_t base = uint32_t(m.num_vertices());
    m.positions.insert(m.positions.end(), b.positions.begin(), b.positions.end());
    for (uint32_t v : b.indices) m.indices.push_back(base + v);
    meshes.push_back({"shared position", m});
  }
  {  // one face turned over: inconsistent orientation
    Mesh m = unit_cube();
    std::swap(m.indices[0], m.indices[1]);
    meshes.push_back({"inconsistent", m});
  }
  {  // a face repeated: non-manifold edges
    Mesh m = unit_cube();
    m.indices.insert(m.indices.end(), m.indices.begin(), m.indices.begin() + 3);
    meshes.push_back({"repeated face", m});
  }
  for (bool allow_open : {false, true})
    for (const auto& [name, mesh] : meshes) {
      Options options;
      options.allow_open = allow_open;
      const PreparedMesh faces = prepare_mesh(mesh.view(), options, true, PrepareFor::Faces);
      const PreparedMesh verdict = prepare_mesh(mesh.view(), options, true, PrepareFor::Verdict);
      SCOPED_TRACE(name + (allow_open ? " (allow_open)" : ""));
      EXPECT_EQ(verdict.error, faces.error);
      EXPECT_EQ(verdict.message, faces.message);
      ASSERT_EQ(verdict.warnings.size(), faces.warnings.size());
      for (size_t i = 0; i < faces.warnings.size(); ++i) {
        EXPECT_EQ(verdict.warnings[i].kind, faces.warnings[i].kind);
        EXPECT_EQ(verdict.warnings[i].count, faces.warnings[i].count);
        EXPECT_EQ(verdict.warnings[i].message, faces.warnings[i].message);
      }
      EXPECT_EQ(std::memcmp(&verdict.volume, &faces.volume, sizeof(double)), 0);
      EXPECT_EQ(verdict.shells, faces.shells);
      EXPECT_EQ(verdict.boundary_edges, faces.boundary_edges);
      EXPECT_EQ(verdict.dropped_faces, faces.dropped_faces);
      EXPECT_EQ(verdict.num_faces(), faces.num_faces());
    }
}

// Indices are checked while the faces are cleaned, after the coordinates' finiteness and before
// their range; faces that all collapse are refused after the range. The refusals keep that order,
// and name the first index out of range in input order (triangles and polygons alike).
TEST(MeshPrep, RefusalsKeepTheirPrecedence) {
  Mesh base;
  base.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  base.indices = {0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2};
  auto refusal = [](const Mesh& m) {
    const PreparedMesh p = prepare_mesh(m.view(), Options{});
    return std::make_pair(p.error, p.message);
  };
  Mesh wide = base;  // coordinates too wide for exact evaluation
  wide.positions[3] = 1e300;
  wide.positions[4] = 1e-300;
  EXPECT_EQ(refusal(wide).first, Error::CoordinateRange);
  Mesh m = wide;
  m.indices[7] = 9;
  EXPECT_EQ(refusal(m), std::make_pair(Error::IndexOutOfRange,
                                       std::string("face 2 refers to vertex 9 but the mesh has 4 vertices")));
  m = wide;
  m.indices = {0, 0, 1, 2, 2, 3};  // every face collapses
  EXPECT_EQ(refusal(m).first, Error::CoordinateRange);
  m.positions = base.positions;
  EXPECT_EQ(refusal(m).first, Error::DegenerateInput);
  m.indices = {0, 0, 1, 2, 2, 9};  // a collapsed face, then an index out of range
  EXPECT_EQ(refusal(m), std::make_pair(Error::IndexOutOfRange,
                                       std::string("face 1 refers to vertex 9 but the mesh has 4 vertices")));
  m = base;
  m.positions[5] = NAN;
  m.indices[2] = 7;
  EXPECT_EQ(refusal(m).first, Error::NonFiniteCoordinate);
  m = base;  // polygons: the first index out of range in input order
  m.face_sizes = {3, 3, 3, 3};
  m.indices[11] = 4;
  m.indices[5] = 5;
  EXPECT_EQ(refusal(m), std::make_pair(Error::IndexOutOfRange,
                                       std::string("face 1 refers to vertex 5 but the mesh has 4 vertices")));
}

// The volume terms and the float filter of the triangles, four at a time (triangle_terms), are
// the scalar functions' bits: on random triangles, exactly collinear ones, nearly collinear ones
// (the filter's margin) and repeated corners, for every block length.
TEST(MeshPrep, TriangleTermsAreTheScalarTerms) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coord(-3, 5);
  std::vector<double> pts;
  auto add = [&](double x, double y, double z) {
    pts.insert(pts.end(), {x, y, z});
    return uint32_t(pts.size() / 3 - 1);
  };
  for (int i = 0; i < 40; ++i) add(coord(rng), coord(rng), coord(rng));
  std::vector<uint32_t> tri;
  std::uniform_int_distribution<uint32_t> vertex(0, 39);
  for (int t = 0; t < 64; ++t) {
    const uint32_t a = vertex(rng), b = vertex(rng);
    switch (t % 4) {
      case 0:  // random
        tri.insert(tri.end(), {a, b, vertex(rng)});
        break;
      case 1: {  // exactly collinear: the midpoint of a and b (exact for these coordinates' halving)
        const double* p = &pts[3 * size_t(a)];
        const double* q = &pts[3 * size_t(b)];
        const uint32_t m = add(0.5 * (p[0] + q[0]), 0.5 * (p[1] + q[1]), 0.5 * (p[2] + q[2]));
        tri.insert(tri.end(), {a, m, b});
        break;
      }
      case 2: {  // nearly collinear, off the line by a few ulps
        const double* p = &pts[3 * size_t(a)];
        const double* q = &pts[3 * size_t(b)];
        const double off = std::ldexp(1.0, -50 + int(t % 7));
        const uint32_t m = add(0.5 * (p[0] + q[0]) + off, 0.5 * (p[1] + q[1]), 0.5 * (p[2] + q[2]) - off);
        tri.insert(tri.end(), {m, a, b});
        break;
      }
      default:  // a repeated corner
        tri.insert(tri.end(), {a, b, a});
    }
  }
  const Mesh no_mesh;
  const Options options;
  prep::Prep state(no_mesh.view(), options, false, true);  // (its centre and points are read)
  state.c[0] = 0.25, state.c[1] = -1.5, state.c[2] = 3;
  state.m.points = pts;
  for (size_t n = 0; n <= 64; n += 4) {
    SCOPED_TRACE(n);
    std::vector<double> d(64, -7.0);
    const uint64_t uncertain = prep::triangle_terms(pts.data(), tri.data(), n, state.c, d.data());
    for (size_t j = 0; j < n; ++j) {
      const uint32_t* t = &tri[3 * j];
      const double expected = state.vol6_about_centre(t[0], t[1], t[2]);
      EXPECT_EQ(std::memcmp(&d[j], &expected, sizeof(double)), 0) << j;
      const bool certain =
          certainly_not_collinear(&pts[3 * size_t(t[0])], &pts[3 * size_t(t[1])], &pts[3 * size_t(t[2])]);
      EXPECT_EQ((uncertain >> j & 1) == 0, certain) << j;
    }
    EXPECT_EQ(n == 64 ? 0 : uncertain >> n, 0u);
    if (n == 64) EXPECT_TRUE(uncertain != 0 && ~uncertain != 0);  // (both kinds met)
    for (size_t j = n; j < 64; ++j) EXPECT_EQ(d[j], -7.0);
  }
}
