// Incremental cuts: K_S cut by the planes outside S gives exactly the polytope that tracing the
// cut part again (update_kernel_trace) and tracing everything from scratch give — the same
// vertices (as tight sets) and the same edges (as pairs of tight sets, with their plane sets).
#include "solve/cutting.h"

#include <gtest/gtest.h>

#include <random>
#include <set>

#include "fixtures.h"
#include "input/mesh_prep.h"
#include "output/polytope.h"
#include "planes/plane_classes.h"
#include "solve/lp.h"
#include "solve/tracer.h"

namespace {

using namespace kergen;

using Tight = std::vector<uint32_t>;
struct Canonical {
  std::set<Tight> vertices;
  std::set<std::tuple<Tight, Tight, Tight>> edges;  // (smaller end, larger end, planes)
  bool operator==(const Canonical& o) const { return vertices == o.vertices && edges == o.edges; }
};

Canonical canonical(const TraceResult& t) {
  Canonical c;
  auto ids = [](const PlaneIds& p) { return Tight(p.begin(), p.end()); };
  for (const auto& v : t.vertices) c.vertices.insert(ids(v.tight));
  for (const auto& e : t.edges) {
    const Tight a = ids(t.vertices[e.a].tight), b = ids(t.vertices[e.b].tight);
    c.edges.insert({std::min(a, b), std::max(a, b), ids(e.planes)});
  }
  return c;
}

// The planes of a closed mesh with a box around it, and a kernel vertex from the LP.
struct PlanesWithStart {
  PreparedMesh mesh;
  std::unique_ptr<PlaneSet> ps;
  std::vector<uint32_t> mesh_planes, box;
  VertexGeom start;
  explicit PlanesWithStart(const Mesh& m, const double dir[3]) {
    mesh = prepare_mesh(m.view(), Options{});
    EXPECT_EQ(mesh.error, Error::Ok) << mesh.message;
    ps = std::make_unique<PlaneSet>(&mesh.points, mesh.exact_shift);
    std::vector<uint32_t> face_plane;
    build_planes(mesh, *ps, face_plane);
    for (uint32_t i = 0; i < ps->size(); ++i) mesh_planes.push_back(i);
    for (int k = 0; k < 3; ++k)
      for (double s : {-1.0, 1.0}) {
        double n[3] = {0, 0, 0};
        n[k] = s;
        box.push_back(ps->add_explicit(n[0], n[1], n[2], -2));
      }
    LpResult lp = solve_lp(*ps, mesh_planes, dir, 8, 1);
    EXPECT_EQ(lp.outcome, LpResult::Outcome::Optimal);
    start = lp.vertex;
  }
  std::vector<uint32_t> planes_and_box() const {
    std::vector<uint32_t> v = mesh_planes;
    v.insert(v.end(), box.begin(), box.end());
    return v;
  }
};

// K_S for a random half of the planes (plus start's and the box), then S' and the cuts.
void check_cuts(const Mesh& m, const char* name, uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> N(0, 1);
  const double dir[3] = {N(rng), N(rng), N(rng)};
  PlanesWithStart s(m, dir);
  std::vector<uint32_t> all = s.planes_and_box();
  std::vector<char> in_s(s.ps->size(), 0);
  std::vector<uint32_t> S = s.box, added, hints;
  Tight start_tight;
  ASSERT_EQ(certify_vertex(*s.ps, all, s.start, std::vector<char>(), start_tight), kNoPlane) << name;
  for (uint32_t l : start_tight) in_s[l] = 1;
  for (uint32_t l : s.box) in_s[l] = 1;
  bool left_out = false;  // at least one plane is cut by
  for (uint32_t l : s.mesh_planes)
    if (!in_s[l]) {
      if (left_out && rng() % 3 == 0) in_s[l] = 1;
      left_out = true;
    }
  S.clear();
  for (uint32_t l = 0; l < s.ps->size(); ++l)
    if (in_s[l]) S.push_back(l);
  TraceResult ks = trace_kernel_edges(*s.ps, S, s.start, TraceOptions());
  ASSERT_FALSE(ks.internal_error) << name;
  // Every plane outside S, touching K_S or not (the cuts skip those that hold it strictly);
  // hints are arbitrary vertices (any is correct, a good one is only faster).
  std::vector<uint32_t> s_prime;
  for (const auto& v : ks.vertices) s_prime.insert(s_prime.end(), v.tight.begin(), v.tight.end());
  for (uint32_t l : s.mesh_planes)
    if (!in_s[l]) {
      added.push_back(l);
      hints.push_back(uint32_t(rng() % ks.vertices.size()));
    }
  ASSERT_FALSE(added.empty()) << name;
  s_prime.insert(s_prime.end(), added.begin(), added.end());
  std::sort(s_prime.begin(), s_prime.end());
  s_prime.erase(std::unique(s_prime.begin(), s_prime.end()), s_prime.end());

  TraceResult cut;
  ASSERT_TRUE(cut_kernel_trace(*s.ps, ks, added, hints, seed, cut)) << name;
  TraceResult updated = update_kernel_trace(*s.ps, s_prime, ks, added, TraceOptions());
  TraceResult full = trace_kernel_edges(*s.ps, all, s.start, TraceOptions());
  ASSERT_FALSE(updated.internal_error || full.internal_error) << name;
  const Canonical c = canonical(cut), f = canonical(full);
  EXPECT_GT(c.vertices.size(), 3u) << name;
  EXPECT_TRUE(c == f) << name << ": cut " << c.vertices.size() << " vertices, " << c.edges.size()
                      << " edges; full trace " << f.vertices.size() << ", " << f.edges.size();
  EXPECT_TRUE(canonical(updated) == f) << name;
  // The edge orientations (sigma) close every facet into a counter-clockwise loop: assembly
  // succeeds with the facets and volume of the full trace.
  Kernel kc, kf;
  double vol_c = 0, vol_f = 0;
  EXPECT_TRUE(assemble_polytope(*s.ps, cut, 0, kc, nullptr, vol_c)) << name;
  ASSERT_TRUE(assemble_polytope(*s.ps, full, 0, kf, nullptr, vol_f)) << name;
  // In the canonical order the two assemblies are the same arrays. The volume may differ in its
  // last bits: it is summed from each vertex's coordinates to ~1e-30, whose low parts depend on
  // the three planes the vertex was found on (kergen.h, the canonical order).
  EXPECT_EQ(kc.num_faces(), kf.num_faces()) << name;
  EXPECT_EQ(kc.vertices, kf.vertices) << name;
  EXPECT_EQ(kc.edges, kf.edges) << name;
  EXPECT_EQ(kc.face_indices, kf.face_indices) << name;
  EXPECT_NEAR(vol_c, vol_f, 1e-14 * vol_f) << name;
  // Each edge once, endpoints distinct and alive.
  for (const auto& e : cut.edges) {
    ASSERT_LT(e.a, cut.vertices.size());
    ASSERT_LT(e.b, cut.vertices.size());
    EXPECT_NE(e.a, e.b);
  }
}

TEST(Cutting, MatchesRetracingOnConvexShapes) {
  for (uint64_t seed = 1; seed <= 4; ++seed) {
    check_cuts(kergen_test::random_convex(uint32_t(seed), 40).mesh, "random_convex", seed);
    check_cuts(kergen_test::uv_sphere(16, 8, 0), "uv_sphere", seed);
  }
}

TEST(Cutting, MatchesRetracingOnDegenerateShapes) {
  // Near-coplanar split quads (features ~1e-16), a 40-plane apex, coplanar tessellation.
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    check_cuts(kergen_test::uv_sphere(20, 10, 0.03), "twisted uv_sphere", seed);
    check_cuts(kergen_test::pyramid(40), "pyramid", seed);
    check_cuts(kergen_test::dented_cube(), "dented_cube", seed);
    check_cuts(kergen_test::plus_prism(0.3), "plus_prism", seed);
  }
}

TEST(Cutting, MatchesRetracingOnTurnedFlatFaces) {
  // Faces planar only up to rounding: each of their triangles' planes passes within rounding of
  // most vertices of the kernel's facet there, so the cuts must find the vertices they remove by
  // exact signs (a turned, finely tessellated cube; a turned prism over a 48-corner star, whose
  // caps are split polygons).
  std::vector<std::array<double, 2>> star;
  for (int i = 0; i < 48; ++i) {
    const double r = i % 2 ? 0.8 : 1.0, t = 2 * M_PI * i / 48;
    star.push_back({r * std::cos(t), r * std::sin(t)});
  }
  for (uint64_t seed = 1; seed <= 3; ++seed) {
    check_cuts(kergen_test::turned(kergen_test::tessellated_cube(8)), "turned tessellated cube", seed);
    check_cuts(kergen_test::turned(kergen_test::prism(star)), "turned star prism", seed);
  }
}

// The unit cube traced over its planes and the box: the polytope the explicit cuts start from.
struct TracedCube {
  static constexpr double kDir[3] = {0.31, -0.52, 0.79};
  PlanesWithStart s{kergen_test::unit_cube(), kDir};
  std::vector<uint32_t> all = s.planes_and_box();
  TraceResult cube = trace_kernel_edges(*s.ps, all, s.start, TraceOptions());
  // The cube's face plane whose normal points along +axis (sign 1) or -axis (sign -1).
  uint32_t face(int axis, int sign) const {
    const double* n[3] = {s.ps->nx(), s.ps->ny(), s.ps->nz()};
    for (uint32_t l : s.mesh_planes)
      if (n[axis][l] * sign > 0 && n[(axis + 1) % 3][l] == 0 && n[(axis + 2) % 3][l] == 0) return l;
    return kNoPlane;
  }
};

TEST(Cutting, RecordsPlanesThatTouchWithoutCutting) {
  // The unit cube and planes that touch it only along its edge x = y = 1 and at its corner
  // (1, 1, 1) (sums of its face planes, exact in double): nothing is cut, but the vertices and
  // the edge on them must list them, as a full trace does.
  TracedCube t;
  ASSERT_EQ(t.cube.vertices.size(), 8u);
  PlanesWithStart& s = t.s;
  uint32_t face[3] = {kNoPlane, kNoPlane, kNoPlane};  // the faces x = 1, y = 1, z = 1
  const double* n[3] = {s.ps->nx(), s.ps->ny(), s.ps->nz()};
  for (uint32_t l : s.mesh_planes)
    for (int k = 0; k < 3; ++k)
      if (n[k][l] > 0) face[k] = l;
  ASSERT_TRUE(face[0] != kNoPlane && face[1] != kNoPlane && face[2] != kNoPlane);
  auto sum = [&](int count) {
    double c[4] = {0, 0, 0, 0};
    for (int i = 0; i < count; ++i) {
      c[0] += s.ps->nx()[face[i]];
      c[1] += s.ps->ny()[face[i]];
      c[2] += s.ps->nz()[face[i]];
      c[3] += s.ps->d()[face[i]];
    }
    return s.ps->add_explicit(c[0], c[1], c[2], c[3]);
  };
  const std::vector<uint32_t> added = {sum(2), sum(3)};
  t.all.insert(t.all.end(), added.begin(), added.end());
  TraceResult cut;
  ASSERT_TRUE(cut_kernel_trace(*s.ps, t.cube, added, {0, 0}, 1, cut));
  TraceResult full = trace_kernel_edges(*s.ps, t.all, s.start, TraceOptions());
  EXPECT_EQ(cut.vertices.size(), 8u);
  EXPECT_TRUE(canonical(cut) == canonical(full));
  size_t on_corner = 0;
  for (const auto& v : cut.vertices) on_corner += std::binary_search(v.tight.begin(), v.tight.end(), added[1]);
  EXPECT_EQ(on_corner, 1u);
}

TEST(Cutting, OneCutAddsMoreVerticesThanItsRoom) {
  // The plane -x + y - z = -1/2 (in the cube's units) through the cube's centre cuts a hexagon
  // and keeps the trace's start, the corner (1, 0, 1). One cut adds 6 vertices, more than the 4
  // per cut reserved, so the vertex arrays grow while the outside vertices' edges are walked
  // (which read freed memory before the walk took a copy; the sanitizer build catches it).
  TracedCube t;
  ASSERT_EQ(t.cube.vertices.size(), 8u);
  PlanesWithStart& s = t.s;
  const uint32_t face_x1 = t.face(0, 1);
  ASSERT_NE(face_x1, kNoPlane);
  const double a = s.ps->nx()[face_x1], d = s.ps->d()[face_x1];  // a x + d <= 0 is x <= 1
  const std::vector<uint32_t> added = {s.ps->add_explicit(-a, a, -a, -0.5 * d)};
  t.all.insert(t.all.end(), added.begin(), added.end());
  TraceResult cut;
  ASSERT_TRUE(cut_kernel_trace(*s.ps, t.cube, added, {0}, 1, cut));
  TraceResult full = trace_kernel_edges(*s.ps, t.all, s.start, TraceOptions());
  EXPECT_EQ(cut.vertices.size(), 10u);  // 4 corners cut away, 6 cut points
  EXPECT_TRUE(canonical(cut) == canonical(full));
}

TEST(Cutting, DeclinesAFlatResult) {
  // The unit cube cut by x <= 0, the opposite of its own face x >= 0: the result is the square
  // x = 0, which the cuts leave to tracing.
  TracedCube t;
  ASSERT_EQ(t.cube.vertices.size(), 8u);
  PlanesWithStart& s = t.s;
  const uint32_t face_x0 = t.face(0, -1);
  ASSERT_NE(face_x0, kNoPlane);
  const uint32_t x_le_0 = s.ps->add_explicit(1, 0, 0, -s.ps->d()[face_x0] / -s.ps->nx()[face_x0]);
  s.ps->set_opposite(face_x0, x_le_0);
  TraceResult out;
  EXPECT_FALSE(cut_kernel_trace(*s.ps, t.cube, {x_le_0}, {0}, 1, out));
}

}  // namespace
