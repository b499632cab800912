// compute_kernel against analytic kernels and polytope invariants.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

#include "../../fuzz/invariants.h"
#include "fixtures.h"
#include "kergen/kergen.h"

namespace {

using namespace kergen;
using namespace kergen_test;

// Checks what every correct result must satisfy, independent of how it was computed, with the
// fuzzers' invariant checker (fuzz/invariants.h: array sizes and ids, a closed 2-manifold with
// consistently oriented faces and Euler characteristic 2, vertices inside every input half-space
// up to output rounding, volume positive and not above the shape's) and its stricter checks for
// well-shaped meshes (convex counter-clockwise faces, no duplicate vertices).
void expect_valid_polyhedron(const Mesh& input, const Kernel& k) {
  ASSERT_TRUE(k.ok()) << k.message;
  ASSERT_EQ(k.type, KernelType::Polyhedron);
  kfuzz::violation_handler = [](const std::string& what) { throw std::runtime_error(what); };
  try {
    kfuzz::check_kernel(input.view(), k, false, true);
    kfuzz::check_convex_faces_and_distinct_vertices(k);
  } catch (const std::runtime_error& e) { ADD_FAILURE() << e.what(); }
  kfuzz::violation_handler = nullptr;
}

Kernel run(const Mesh& m, Options o = {}) { return compute_kernel(m.view(), o); }

TEST(Kernel, UnitCube) {
  Mesh m = unit_cube();
  Kernel k = run(m);
  expect_valid_polyhedron(m, k);
  EXPECT_EQ(k.num_vertices(), 8u);
  EXPECT_EQ(k.num_edges(), 12u);
  EXPECT_EQ(k.num_faces(), 6u);
  EXPECT_NEAR(k.volume, 1, 1e-14);
  EXPECT_NEAR(k.area, 6, 1e-13);
  EXPECT_NEAR(k.shape_volume, 1, 1e-14);
  EXPECT_NEAR(k.volume_ratio, 1, 1e-14);
  EXPECT_EQ(k.stats.distinct_planes, 6u);
}

TEST(Kernel, CubeTranslatedAndScaled) {
  struct T {
    double s, t;
  } cases[] = {
      {1, 1e6},  {1e-3, 0}, {1e3, 0}, {1e-3, -7e5}, {1e300 / 4, 0}, {1e-300, 0}, {1e-310, 0} /* subnormal only */,
      {4e307, 0} /* near the top */};
  for (const auto& c : cases) {
    Mesh m = transformed(unit_cube(), c.s, c.t, c.t, c.t);
    Kernel k = run(m);
    expect_valid_polyhedron(m, k);
    EXPECT_EQ(k.num_vertices(), 8u) << "scale " << c.s << " shift " << c.t;
    EXPECT_EQ(k.num_faces(), 6u);
    // The box as the doubles describe it (the shift rounds its sides).
    double side = m.positions[3 * 7] - m.positions[0];
    double expect = side * side * side;
    if (std::isfinite(expect) && expect > 1e-290)
      EXPECT_NEAR(k.volume / expect, 1, 1e-12) << "scale " << c.s << " shift " << c.t;
    EXPECT_NEAR(k.volume_ratio, 1, 1e-12) << "scale " << c.s << " shift " << c.t;
  }
}

TEST(Kernel, TessellatedCubeMergesCoplanarFaces) {
  for (int n : {2, 5, 12}) {
    Mesh m = tessellated_cube(n);
    Kernel k = run(m);
    expect_valid_polyhedron(m, k);
    EXPECT_EQ(k.stats.distinct_planes, 6u);
    EXPECT_EQ(k.num_vertices(), 8u);
    EXPECT_EQ(k.num_edges(), 12u);
    EXPECT_EQ(k.num_faces(), 6u);
    EXPECT_NEAR(k.volume, 1, 1e-13);
  }
}

TEST(Kernel, LPrism) {
  Mesh m = l_prism();
  Kernel k = run(m);
  expect_valid_polyhedron(m, k);
  EXPECT_EQ(k.num_vertices(), 8u);
  EXPECT_NEAR(k.volume, 1, 1e-13);
  EXPECT_NEAR(k.shape_volume, 3, 1e-13);
}

TEST(Kernel, PlusPrism) {
  for (double w : {0.5, 0.25, 0.1, 0.01}) {
    Mesh m = plus_prism(w);
    Kernel k = run(m);
    expect_valid_polyhedron(m, k);
    EXPECT_EQ(k.num_vertices(), 8u);
    EXPECT_NEAR(k.volume, 4 * w * w, 1e-13) << w;
  }
}

TEST(Kernel, DentedCube) {
  Mesh m = dented_cube();
  Kernel k = run(m);
  expect_valid_polyhedron(m, k);
  EXPECT_EQ(k.num_vertices(), 9u);
  EXPECT_EQ(k.num_faces(), 9u);
  EXPECT_NEAR(k.volume, 1.0 / 3.0, 1e-13);
}

TEST(Kernel, PyramidApexDegree) {
  for (int n : {3, 5, 16, 64, 200}) {
    Mesh m = pyramid(n);
    Kernel k = run(m);
    expect_valid_polyhedron(m, k);
    EXPECT_EQ(k.num_vertices(), size_t(n) + 1);
    EXPECT_EQ(k.num_faces(), size_t(n) + 1);
    std::map<uint32_t, int> degree;
    for (uint32_t e : k.edges) degree[e]++;
    int maxdeg = 0;
    for (const auto& [v, d] : degree) maxdeg = std::max(maxdeg, d);
    EXPECT_EQ(maxdeg, n == 3 ? 3 : n);
    EXPECT_NEAR(k.volume, k.shape_volume, 1e-12);
  }
}

TEST(Kernel, PyramidScaledIsScaleInvariant) {
  Mesh m = transformed(pyramid(64), 1000, 0, 0, 0);
  Kernel k = run(m);
  expect_valid_polyhedron(m, k);
  EXPECT_EQ(k.num_vertices(), 65u);
}

TEST(Kernel, RandomConvexKernelIsTheShape) {
  for (uint32_t seed = 1; seed <= 25; ++seed) {
    RandomConvex r = random_convex(seed, 6 + int(seed % 20));
    Kernel k = run(r.mesh);
    expect_valid_polyhedron(r.mesh, k);
    EXPECT_EQ(k.num_vertices(), size_t(r.n) + 2) << seed;
    EXPECT_EQ(k.num_faces(), size_t(2 * r.n)) << seed;
    EXPECT_NEAR(k.volume, r.volume, 1e-12 * r.volume) << seed;
    EXPECT_NEAR(k.volume_ratio, 1, 1e-12) << seed;
  }
}

// Above the culling threshold the kernel comes from a traced sample and incremental cuts; for
// a convex shape every plane cuts, every input point becomes a kernel vertex.
TEST(Kernel, LargeConvexKernelIsTheShape) {
  for (int n : {9, 16}) {
    kergen_test::GeodesicSphere g = kergen_test::geodesic_sphere(n);
    const size_t faces = g.mesh.indices.size() / 3, points = g.mesh.positions.size() / 3;
    for (uint64_t seed : {1ull, 2ull, 3ull}) {
      Options o;
      o.seed = seed;
      Kernel k = run(g.mesh, o);
      expect_valid_polyhedron(g.mesh, k);
      EXPECT_TRUE(k.warnings.empty()) << n;
      EXPECT_EQ(k.stats.distinct_planes, faces) << n;
      EXPECT_EQ(k.num_faces(), faces) << n << " seed " << seed;
      EXPECT_EQ(k.num_vertices(), points) << n << " seed " << seed;
      EXPECT_NEAR(k.volume, g.volume, 1e-12 * g.volume) << n << " seed " << seed;
      // The kernel's vertices are the input points (exactly: they are computed exactly, then
      // rounded once).
      std::vector<std::array<double, 3>> in, out;
      for (size_t i = 0; i < points; ++i)
        in.push_back({g.mesh.positions[3 * i], g.mesh.positions[3 * i + 1], g.mesh.positions[3 * i + 2]});
      for (size_t i = 0; i < k.num_vertices(); ++i)
        out.push_back({k.vertices[3 * i], k.vertices[3 * i + 1], k.vertices[3 * i + 2]});
      std::sort(in.begin(), in.end());
      std::sort(out.begin(), out.end());
      EXPECT_EQ(in, out) << n << " seed " << seed;
    }
  }
}

// Face culling (Options::cull_faces) drops faces before their planes are merged; the kernel
// must be the same, bit for bit, as with every face's plane. Large closed meshes only (small
// ones skip the step): star-shaped with a small kernel (most faces culled), convex with
// coplanar faces and with near-coplanar ones (nothing can be culled), a pyramid with a
// tessellated base, and a non-star one.
// s_prism with side i split into parts[i] equal steps (dyadic: the new corners are exact and
// exactly collinear): the same flat kernel, {y = 1, 1 <= x <= 2} x [0, 1].
Mesh subdivided_s_prism(const std::array<int, 8>& parts) {
  const std::vector<std::array<double, 2>> corners = {{1, 0}, {3, 0}, {3, 1}, {2, 1}, {2, 2}, {0, 2}, {0, 1}, {1, 1}};
  std::vector<std::array<double, 2>> poly;
  for (size_t i = 0; i < corners.size(); ++i) {
    const auto& a = corners[i];
    const auto& b = corners[(i + 1) % corners.size()];
    for (int k = 0; k < parts[i]; ++k) {
      const double t = double(k) / parts[i];
      poly.push_back({a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])});
    }
  }
  return prism(poly);
}

TEST(Kernel, FaceCullingKeepsTheKernel) {
  struct Case {
    const char* name;
    Mesh mesh;
    bool expect_culled;
    bool check_invariants;  // false where distinct kernel vertices round to one output point
  };
  std::vector<Case> cases = {
      {"bumpy sphere 80x40", bumpy_sphere(80, 40), true, false},
      {"bumpy sphere 150x76", bumpy_sphere(150, 76, 0.1), true, false},
      {"tessellated cube 20", tessellated_cube(20), false, true},
      {"twisted uv sphere", uv_sphere(48, 30, 1e-3), false, false},
      {"geodesic sphere 12", geodesic_sphere(12).mesh, false, true},
      {"pyramid 3000", pyramid(3000, 1, 0.3), false, true},
      {"torus", torus(80, 30), false, false},
      {"bumpy sphere, strong bumps", bumpy_sphere(90, 40, 0.9), false, false},
      // Sides 2, 3, 6, 7 lie on planes through the kernel. The sample kernel is bounded by the
      // planes of the split sides (their faces are most of the sample), and every face on such a
      // plane touches it: half of the faces do, and culling gives up.
      {"S prism, far sides split (flat kernel)", subdivided_s_prism({256, 128, 1, 1, 256, 128, 1, 1}), false, false},
      {"S prism, all sides split (flat kernel)", subdivided_s_prism({128, 128, 128, 128, 128, 128, 128, 128}), false,
       false},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    ASSERT_GT(c.mesh.num_faces(), 700u) << c.name;  // where face culling starts
    for (uint64_t seed : {1ull, 77ull}) {
      Options on, off;
      on.seed = off.seed = seed;
      off.cull_faces = false;
      const Kernel a = run(c.mesh, on), b = run(c.mesh, off);
      ASSERT_TRUE(a.ok()) << c.name << ": " << a.message;
      ASSERT_TRUE(b.ok()) << c.name << ": " << b.message;
      EXPECT_EQ(a.type, b.type) << c.name;
      EXPECT_EQ(b.stats.culled_faces, 0u) << c.name;
      if (c.expect_culled) EXPECT_GT(a.stats.culled_faces, c.mesh.num_faces() / 2) << c.name;
      EXPECT_LE(a.stats.distinct_planes, b.stats.distinct_planes) << c.name;
      EXPECT_EQ(a.num_edges(), b.num_edges()) << c.name;
      EXPECT_EQ(a.num_faces(), b.num_faces()) << c.name;
      std::vector<std::array<double, 3>> va, vb;
      for (size_t i = 0; i < a.num_vertices(); ++i)
        va.push_back({a.vertices[3 * i], a.vertices[3 * i + 1], a.vertices[3 * i + 2]});
      for (size_t i = 0; i < b.num_vertices(); ++i)
        vb.push_back({b.vertices[3 * i], b.vertices[3 * i + 1], b.vertices[3 * i + 2]});
      std::sort(va.begin(), va.end());
      std::sort(vb.begin(), vb.end());
      EXPECT_EQ(va, vb) << c.name << " seed " << seed;
      EXPECT_NEAR(a.volume, b.volume, 1e-12 * std::max(1.0, b.volume)) << c.name;
      EXPECT_EQ(a.kernel_point, b.kernel_point) << c.name;
      if (c.check_invariants) expect_valid_polyhedron(c.mesh, a);
    }
  }
}

// A sphere far smaller than its distance from the origin: its coordinates keep ~6 digits of its
// shape, so rounding makes it slightly non-convex. Vertex coordinates, margins and climbs work
// at the shape's scale (PlaneSet::set_extent, culling's and cutting's margins), not at the
// coordinates' magnitude; the kernel (most of the sphere, traced by sample and cuts above 1024
// planes) must be valid, the same with and without face culling, and nearly the whole shape.
TEST(Kernel, TinySphereFarFromTheOrigin) {
  const Mesh m = transformed(kergen_test::uv_sphere(48, 24, 0.1), 1e-9, 1000, 0, 0);
  Options all_faces;
  all_faces.cull_faces = false;
  const Kernel k = run(m), k_all = run(m, all_faces);
  expect_valid_polyhedron(m, k);
  EXPECT_GT(k.volume_ratio, 0.95);
  EXPECT_LE(k.volume_ratio, 1.0);
  ASSERT_EQ(k.num_vertices(), k_all.num_vertices());
  std::vector<std::array<double, 3>> a, b;
  for (size_t i = 0; i < k.num_vertices(); ++i) {
    a.push_back({k.vertices[3 * i], k.vertices[3 * i + 1], k.vertices[3 * i + 2]});
    b.push_back({k_all.vertices[3 * i], k_all.vertices[3 * i + 1], k_all.vertices[3 * i + 2]});
  }
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  EXPECT_EQ(a, b);
  EXPECT_EQ(k.volume, k_all.volume);
}

TEST(Kernel, ConvexUvSphereWithPoleFans) {
  // A convex UV sphere of 40 x 41 cells: the planes cutting the sample kernel at a pole's fan
  // of 40 triangles add more vertices per cut than the cutter had room for. Its split quads are
  // planar only up to rounding, so the kernel keeps slivers of them: it is the shape up to
  // rounding-size features, and no larger.
  const Mesh m = bumpy_sphere(40, 41, 0);
  const Kernel k = run(m);
  ASSERT_TRUE(k.ok()) << k.message;
  EXPECT_EQ(k.type, KernelType::Polyhedron);
  EXPECT_NEAR(k.volume_ratio, 1, 1e-9);
  EXPECT_GE(k.num_vertices(), m.positions.size() / 3);
}

TEST(Kernel, TwoNonPlanarQuadsClosingATetrahedron) {
  // Quads (0 1 2 3) and (3 2 1 0) over the corners of the unit tetrahedron: their fans enclose a
  // negative volume, so the mesh was flipped, and each split then folded outward for the flipped
  // orientation, which closed the tetrahedron inside out (a wrong EMPTY). Every loop start and
  // face order gives the tetrahedron.
  const std::vector<std::array<uint32_t, 8>> orders = {
      {0, 1, 2, 3, 3, 2, 1, 0}, {3, 2, 1, 0, 0, 1, 2, 3}, {1, 2, 3, 0, 0, 3, 2, 1}, {2, 3, 0, 1, 1, 0, 3, 2}};
  for (const auto& o : orders) {
    Mesh m;
    add_point(m, 0, 0, 0);
    add_point(m, 1, 0, 0);
    add_point(m, 0, 1, 0);
    add_point(m, 0, 0, 1);
    add_face(m, {o[0], o[1], o[2], o[3]});
    add_face(m, {o[4], o[5], o[6], o[7]});
    const Kernel k = run(m);
    ASSERT_TRUE(k.ok()) << k.message;
    EXPECT_EQ(k.type, KernelType::Polyhedron) << o[0];
    EXPECT_NEAR(k.volume, 1.0 / 6, 1e-15) << o[0];
    EXPECT_NEAR(k.shape_volume, 1.0 / 6, 1e-15) << o[0];
    EXPECT_EQ(k.num_vertices(), 4u) << o[0];
  }
}

TEST(Kernel, TallPyramidApexOfManyPlanes) {
  // The LP's vertex is the apex, on all 1000 side planes, and it is traced first: its edges are
  // the 1000 pairs of neighbouring planes among ~500,000 pairs (finding the ~499,000 that are not
  // edges used to cost (planes)^3 / 6 sign tests; the sweep's 5000-gon pyramid took minutes).
  const int n = 1000;
  const Mesh m = pyramid(n, 1, 1000);
  const Kernel k = run(m);
  expect_valid_polyhedron(m, k);
  EXPECT_EQ(k.num_vertices(), size_t(n + 1));
  EXPECT_EQ(k.num_faces(), size_t(n + 1));
  EXPECT_NEAR(k.volume_ratio, 1, 1e-12);
}

TEST(Kernel, NonPlanarQuadsWhoseFansEncloseNothing) {
  // Quads (0 1 2 3) and (2 1 0 3) over a tetrahedron of volume 5/6, every loop start: where both
  // fans take the same diagonal they enclose nothing, which was refused as DEGENERATE_INPUT before
  // the quads were split (the split surface is the tetrahedron).
  const double pts[4][3] = {{1, 0, 0.25}, {0, 1, 1.5}, {-1, 0, 0.25}, {0, -1, 1.5}};
  const uint32_t qa[4] = {0, 1, 2, 3}, qb[4] = {2, 1, 0, 3};
  for (int sa = 0; sa < 4; ++sa)
    for (int sb = 0; sb < 4; ++sb) {
      Mesh m;
      for (const auto& p : pts) add_point(m, p[0], p[1], p[2]);
      add_face(m, {qa[sa], qa[(sa + 1) % 4], qa[(sa + 2) % 4], qa[(sa + 3) % 4]});
      add_face(m, {qb[sb], qb[(sb + 1) % 4], qb[(sb + 2) % 4], qb[(sb + 3) % 4]});
      const Kernel k = run(m);
      ASSERT_TRUE(k.ok()) << sa << sb << ": " << k.message;
      EXPECT_EQ(k.type, KernelType::Polyhedron) << sa << sb;
      EXPECT_NEAR(k.volume, 5.0 / 6, 1e-14) << sa << sb;
      EXPECT_NEAR(k.volume_ratio, 1, 1e-14) << sa << sb;
    }
}

TEST(Kernel, NearlyFlatTetrahedronVolume) {
  // Four points on a plane up to rounding (a quad bent by 1e-17): the tetrahedron of volume
  // ~8.2e-18 came out with volume -9.3e-18 (summed in double from unit-size terms) and a
  // shape volume of +9.3e-18. Both are summed in double-double now.
  Mesh m;
  add_point(m, 1, 0, -0.20000000000000001);
  add_point(m, 6.123233995736766e-17, 1, 0.29999999999999999);
  add_point(m, -1, 1.2246467991473532e-16, 0.5);
  add_point(m, -1.8369701987210297e-16, -1, 0);
  add_face(m, {0, 1, 2, 3});
  add_face(m, {3, 2, 1, 0});
  const Kernel k = run(m);
  ASSERT_TRUE(k.ok()) << k.message;
  EXPECT_EQ(k.type, KernelType::Polyhedron);
  EXPECT_GT(k.volume, 0);
  EXPECT_NEAR(k.volume, k.shape_volume, 1e-6 * k.shape_volume);
  EXPECT_NEAR(k.volume_ratio, 1, 1e-6);
}

TEST(Kernel, SPrismIsPolygon) {
  Kernel k = run(s_prism());
  ASSERT_TRUE(k.ok()) << k.message;
  EXPECT_EQ(k.type, KernelType::Polygon);
  EXPECT_EQ(k.num_vertices(), 4u);
  EXPECT_EQ(k.num_edges(), 4u);
  ASSERT_EQ(k.num_faces(), 1u);
  EXPECT_NEAR(k.area, 1, 1e-13);
  EXPECT_EQ(k.volume, 0);
  for (size_t v = 0; v < 4; ++v) EXPECT_EQ(k.vertices[3 * v + 1], 1);
}

TEST(Kernel, PinwheelPrismIsSegment) {
  Kernel k = run(pinwheel_prism());
  ASSERT_TRUE(k.ok()) << k.message;
  EXPECT_EQ(k.type, KernelType::Segment);
  ASSERT_EQ(k.num_vertices(), 2u);
  EXPECT_EQ(k.num_edges(), 1u);
  std::set<double> zs;
  for (size_t v = 0; v < 2; ++v) {
    EXPECT_EQ(k.vertices[3 * v], 0);
    EXPECT_EQ(k.vertices[3 * v + 1], 0);
    zs.insert(k.vertices[3 * v + 2]);
  }
  EXPECT_EQ(zs, (std::set<double>{0, 1}));
}

TEST(Kernel, NotStarShapedIsEmpty) {
  for (const Mesh& m : {u_prism(), torus()}) {
    Kernel k = run(m);
    ASSERT_TRUE(k.ok()) << k.message;
    EXPECT_EQ(k.type, KernelType::Empty);
    EXPECT_EQ(k.num_vertices(), 0u);
    EXPECT_FALSE(k.has_kernel_point);
    KernelPoint p = find_kernel_point(m.view());
    EXPECT_TRUE(p.error == Error::Ok);
    EXPECT_FALSE(p.star_shaped);
  }
}

// The witness of an empty kernel on shapes whose answer is known: the U's inner walls (x = 1
// facing +x, x = 2 facing -x: x <= 1 and x >= 2 inside), also with the U's top face removed
// (allow_open), and for two disjoint cubes a face of each on facing planes. Each face named is the
// lowest-indexed one in its plane. (The oracle test checks witnesses of real meshes.)
namespace {
// The axis and coordinate of an axis-aligned face (all corners share it), or -1.
std::pair<int, double> axis_plane(const Mesh& m, uint32_t face) {
  size_t at = 0;
  for (uint32_t f = 0; f < face; ++f) at += m.face_sizes.empty() ? 3 : m.face_sizes[f];
  const size_t k = m.face_sizes.empty() ? 3 : m.face_sizes[face];
  for (int axis = 0; axis < 3; ++axis) {
    const double c = m.positions[3 * size_t(m.indices[at]) + axis];
    bool all = true;
    for (size_t i = 1; i < k; ++i) all &= m.positions[3 * size_t(m.indices[at + i]) + axis] == c;
    if (all) return {axis, c};
  }
  return {-1, 0};
}
}  // namespace

TEST(Kernel, WitnessOfKnownShapes) {
  const Mesh u = u_prism();
  Mesh open_u = u;  // without its top face (the one at z = 1)
  {
    open_u.indices.clear();
    open_u.face_sizes.clear();
    size_t at = 0;
    for (size_t f = 0; f < u.num_faces(); ++f) {
      const size_t k = u.face_sizes[f];
      if (axis_plane(u, uint32_t(f)) != std::pair<int, double>{2, 1.0}) {
        open_u.indices.insert(open_u.indices.end(), u.indices.begin() + long(at), u.indices.begin() + long(at + k));
        open_u.face_sizes.push_back(uint32_t(k));
      }
      at += k;
    }
    ASSERT_EQ(open_u.num_faces() + 1, u.num_faces());
  }
  Options open;
  open.allow_open = true;
  for (const auto& [m, o] : {std::pair<const Mesh&, Options>{u, {}}, {open_u, open}}) {
    const Kernel k = run(m, o);
    ASSERT_TRUE(k.ok()) << k.message;
    EXPECT_EQ(k.type, KernelType::Empty);
    ASSERT_EQ(k.witness_faces.size(), 2u);
    EXPECT_EQ(axis_plane(m, k.witness_faces[0]).first, 0);
    EXPECT_EQ(axis_plane(m, k.witness_faces[1]).first, 0);
    std::set<double> walls = {axis_plane(m, k.witness_faces[0]).second, axis_plane(m, k.witness_faces[1]).second};
    EXPECT_EQ(walls, (std::set<double>{1, 2}));
    EXPECT_EQ(find_kernel_point(m.view(), o).witness_faces, k.witness_faces);
  }
  Mesh cubes = unit_cube();
  const Mesh far = box(5, 0, 0, 6, 1, 1);
  const uint32_t base = uint32_t(cubes.num_vertices());
  cubes.positions.insert(cubes.positions.end(), far.positions.begin(), far.positions.end());
  for (uint32_t v : far.indices) cubes.indices.push_back(v + base);
  const Kernel two = run(cubes);
  ASSERT_TRUE(two.ok()) << two.message;
  ASSERT_EQ(two.witness_faces.size(), 2u);
  EXPECT_EQ(axis_plane(cubes, two.witness_faces[0]), (std::pair<int, double>{0, 1.0}));  // the first cube's x = 1
  EXPECT_EQ(axis_plane(cubes, two.witness_faces[1]), (std::pair<int, double>{0, 5.0}));  // the second's x = 5
  for (uint32_t f = 0; f < two.witness_faces[0]; ++f)
    EXPECT_NE(axis_plane(cubes, f), axis_plane(cubes, two.witness_faces[0]));
  for (uint32_t f = 0; f < two.witness_faces[1]; ++f)
    EXPECT_NE(axis_plane(cubes, f), axis_plane(cubes, two.witness_faces[1]));
  // Star-shaped: no witness.
  EXPECT_TRUE(run(unit_cube()).witness_faces.empty());
  EXPECT_TRUE(find_kernel_point(l_prism().view()).witness_faces.empty());
}

TEST(Kernel, OpenCube) {
  Mesh m = open_cube();
  Kernel k = run(m);
  EXPECT_EQ(k.error, Error::OpenMesh);
  EXPECT_NE(k.message.find("open"), std::string::npos) << k.message;
  Options o;
  o.allow_open = true;
  k = run(m, o);
  ASSERT_TRUE(k.ok()) << k.message;
  EXPECT_EQ(k.type, KernelType::Unbounded);
}

TEST(Kernel, InvertedCubeIsFlippedAndReported) {
  Mesh m = flipped(unit_cube());
  Kernel k = run(m);
  ASSERT_TRUE(k.ok()) << k.message;
  EXPECT_EQ(k.type, KernelType::Polyhedron);
  EXPECT_NEAR(k.volume, 1, 1e-14);
  ASSERT_FALSE(k.warnings.empty());
  EXPECT_EQ(k.warnings[0].kind, Warning::Kind::OrientationFlipped);
}

TEST(Kernel, NonManifoldIsRejected) {
  Kernel k = run(cubes_sharing_edge());
  EXPECT_EQ(k.error, Error::NonManifoldEdge);
  EXPECT_NE(k.message.find("more than two faces"), std::string::npos) << k.message;
}

TEST(Kernel, FindKernelPointIsAKernelVertex) {
  Mesh m = dented_cube();
  KernelPoint p = find_kernel_point(m.view());
  ASSERT_TRUE(p.star_shaped);
  Kernel k = run(m);
  bool found = false;
  for (size_t v = 0; v < k.num_vertices(); ++v)
    found |=
        k.vertices[3 * v] == p.point[0] && k.vertices[3 * v + 1] == p.point[1] && k.vertices[3 * v + 2] == p.point[2];
  EXPECT_TRUE(found);
}

// The kernel point is the LP optimum rounded to nearest like the output vertices: one of them,
// bit for bit, whichever planes through it the LP ends on (the seed reorders them). The star
// polyhedron (9 vertices, 14 triangles; polyhedra/tet10/1.off of the shared set) has an optimum
// off the input points whose coordinates, filtered from its planes, differ from the rounded
// ones in the last bit.
TEST(Kernel, KernelPointIsAnOutputVertexForEverySeed) {
  Mesh star;
  star.positions = {0.5545, 0.4858, 0.5371, 0.7,  0.45, 0.9,  0.49, 0.21, 0.15, 0.73, 0.25, 0.14, 0.22, 0.51,
                    0.49,   0.12,   0.61,   0.77, 0.35, 0.45, 0.83, 0.67, 0.98, 0.48, 0.79, 0.52, 0.85};
  star.indices = {2, 5, 4, 2, 6, 5, 6, 2, 1, 5, 6, 1, 5, 1, 8, 2, 7, 3, 7, 0, 3,
                  4, 5, 7, 5, 8, 7, 4, 7, 2, 1, 0, 8, 8, 0, 7, 2, 3, 1, 1, 3, 0};
  const Mesh meshes[] = {star, transformed(dented_cube(), 0.3, 0.1, 0.7, -0.2)};
  for (const Mesh& m : meshes) {
    std::array<double, 3> first{};
    for (uint64_t seed = 1; seed <= 6; ++seed) {
      Options o;
      o.seed = seed;
      Kernel k = run(m, o);
      ASSERT_TRUE(k.ok() && k.has_kernel_point);
      bool found = false;
      for (size_t v = 0; v < k.num_vertices() && !found; ++v)
        found = std::equal(&k.vertices[3 * v], &k.vertices[3 * v + 3], k.kernel_point.begin());
      EXPECT_TRUE(found) << "seed " << seed;
      if (seed == 1) first = k.kernel_point;
      EXPECT_EQ(k.kernel_point, first) << "seed " << seed;
      KernelPoint p = find_kernel_point(m.view(), o);
      EXPECT_EQ(p.point, k.kernel_point) << "seed " << seed;
    }
  }
}

TEST(Kernel, StreamingPrefixesAndEarlyStop) {
  Mesh m = pyramid(32);
  std::vector<StepEvent::Kind> kinds;
  Options o;
  o.on_step = [&](const StepEvent& e) {
    kinds.push_back(e.kind);
    return true;
  };
  Kernel full = run(m, o);
  ASSERT_TRUE(full.ok());
  size_t nv = std::count(kinds.begin(), kinds.end(), StepEvent::Kind::Vertex);
  size_t ne = std::count(kinds.begin(), kinds.end(), StepEvent::Kind::Edge);
  size_t nf = std::count(kinds.begin(), kinds.end(), StepEvent::Kind::Face);
  EXPECT_EQ(nv, full.num_vertices());
  EXPECT_EQ(ne, full.num_edges());
  EXPECT_EQ(nf, full.num_faces());

  Options stop;
  stop.max_steps = 10;
  Kernel part = run(m, stop);
  ASSERT_TRUE(part.ok());
  EXPECT_FALSE(part.complete);
  EXPECT_LT(part.num_vertices(), full.num_vertices());
  // Every partial vertex is a vertex of the full kernel.
  for (size_t v = 0; v < part.num_vertices(); ++v) {
    bool found = false;
    for (size_t w = 0; w < full.num_vertices() && !found; ++w)
      found = std::equal(&part.vertices[3 * v], &part.vertices[3 * v + 3], &full.vertices[3 * w]);
    EXPECT_TRUE(found) << v;
  }
}

// Streaming on meshes whose kernel comes from the culled path (sample kernel, incremental cuts):
// the events are replayed from that result, so the result is the same kernel with or without a
// callback, and the stream keeps its contract: it starts at the LP vertex (kernel_point), each
// edge joins vertices reported before it, ids index the final arrays, and a stopped run holds
// exactly what was reported.
TEST(Kernel, StreamingOnTheCulledPathKeepsTheKernelAndTheContract) {
  const Mesh meshes[] = {geodesic_sphere(12).mesh, bumpy_sphere(60, 40, 0.05), bumpy_sphere(90, 60, 0.01)};
  for (const Mesh& m : meshes) {
    Options quiet;
    Kernel plain = compute_kernel(m.view(), quiet);
    ASSERT_TRUE(plain.ok()) << plain.message;
    ASSERT_GT(plain.stats.distinct_planes, 1024u) << "large enough for the culled path";
    std::vector<StepEvent> events;
    std::vector<std::vector<uint32_t>> loops;
    Options o;
    o.on_step = [&](const StepEvent& e) {
      events.push_back(e);
      if (e.kind == StepEvent::Kind::Face) loops.emplace_back(e.loop, e.loop + e.loop_size);
      return true;
    };
    Kernel k = compute_kernel(m.view(), o);
    ASSERT_TRUE(k.ok()) << k.message;
    EXPECT_TRUE(k.complete);
    // (The double checks of convexity need well-shaped faces: the geodesic sphere's.)
    if (&m == &meshes[0]) expect_valid_polyhedron(m, k);
    EXPECT_EQ(int64_t(k.num_vertices()) - int64_t(k.num_edges()) + int64_t(k.num_faces()), 2);
    // The same kernel, numbered in event order: the volume is summed in another order.
    EXPECT_NEAR(k.volume, plain.volume, 1e-12 * plain.volume);
    EXPECT_EQ(k.num_vertices(), plain.num_vertices());
    EXPECT_EQ(k.num_edges(), plain.num_edges());
    EXPECT_EQ(k.num_faces(), plain.num_faces());
    std::multiset<std::array<double, 3>> with, without;
    for (size_t v = 0; v < k.num_vertices(); ++v) {
      with.insert({k.vertices[3 * v], k.vertices[3 * v + 1], k.vertices[3 * v + 2]});
      without.insert({plain.vertices[3 * v], plain.vertices[3 * v + 1], plain.vertices[3 * v + 2]});
    }
    EXPECT_TRUE(with == without) << "the same vertices with and without a callback";

    ASSERT_FALSE(events.empty());
    ASSERT_EQ(events[0].kind, StepEvent::Kind::Vertex);
    EXPECT_EQ(events[0].position, k.kernel_point) << "the stream starts at the LP vertex";
    uint32_t next[3] = {0, 0, 0};
    size_t face = 0;
    for (const StepEvent& e : events) {
      ASSERT_EQ(e.id, next[int(e.kind)]++) << "ids in order";
      if (e.kind == StepEvent::Kind::Vertex) {
        EXPECT_EQ(e.position[0], k.vertices[3 * e.id]);
        EXPECT_EQ(e.position[1], k.vertices[3 * e.id + 1]);
        EXPECT_EQ(e.position[2], k.vertices[3 * e.id + 2]);
      } else if (e.kind == StepEvent::Kind::Edge) {
        EXPECT_LT(e.a, next[0]);
        EXPECT_LT(e.b, next[0]);
        EXPECT_EQ(k.edges[2 * e.id], e.a);
        EXPECT_EQ(k.edges[2 * e.id + 1], e.b);
      } else {
        ASSERT_LT(face, k.num_faces());
        EXPECT_EQ(loops[face].size(), k.face_sizes[face]);
        ++face;
      }
    }
    EXPECT_EQ(next[0], k.num_vertices());
    EXPECT_EQ(next[1], k.num_edges());
    EXPECT_EQ(next[2], k.num_faces());

    // Stopped after n events: exactly the reported vertices and edges, each a part of the kernel.
    for (uint64_t n : {uint64_t(1), uint64_t(2), uint64_t(57), uint64_t(events.size() / 3)}) {
      Options stop;
      stop.max_steps = n;
      Kernel part = compute_kernel(m.view(), stop);
      ASSERT_TRUE(part.ok());
      EXPECT_FALSE(part.complete);
      size_t nv = 0, ne = 0;
      for (uint64_t i = 0; i < n; ++i) (events[i].kind == StepEvent::Kind::Vertex ? nv : ne)++;
      ASSERT_EQ(part.num_vertices(), nv) << n;
      ASSERT_EQ(part.num_edges(), ne) << n;
      EXPECT_TRUE(std::equal(part.vertices.begin(), part.vertices.end(), k.vertices.begin())) << n;
      EXPECT_TRUE(std::equal(part.edges.begin(), part.edges.end(), k.edges.begin())) << n;
      EXPECT_EQ(part.volume, 0);
    }
  }
}

TEST(Kernel, ProgressReportsEachPhaseOnceInOrder) {
  auto phases_of = [](const Mesh& m) {
    std::vector<std::pair<Progress::Phase, size_t>> seen;
    Options o;
    o.on_progress = [&](const Progress& p) { seen.push_back({p.phase, p.count}); };
    Kernel k = compute_kernel(m.view(), o);
    return std::make_pair(k, seen);
  };
  using P = Progress::Phase;
  // A star-shaped mesh goes through every phase; counts are the input's faces, the distinct
  // planes and the kernel's vertices.
  auto [k, seen] = phases_of(l_prism());
  ASSERT_TRUE(k.ok());
  ASSERT_EQ(seen.size(), 5u);
  EXPECT_EQ(seen[0], std::make_pair(P::Validating, l_prism().num_faces()));
  EXPECT_EQ(seen[1].first, P::Planes);
  EXPECT_EQ(seen[2], std::make_pair(P::Lp, k.stats.distinct_planes));
  EXPECT_EQ(seen[3], std::make_pair(P::Tracing, k.stats.distinct_planes));
  EXPECT_EQ(seen[4], std::make_pair(P::Assembling, k.num_vertices()));
  EXPECT_STREQ(progress_phase_name(P::Tracing), "tracing");
  EXPECT_STREQ(error_name(Error::Internal), "INTERNAL_ERROR");  // the JS package's code too
  // Bad input stops after validation; a non-star mesh after the LP.
  auto [bad, bad_seen] = phases_of(open_cube());
  EXPECT_EQ(bad.error, Error::OpenMesh);
  ASSERT_EQ(bad_seen.size(), 1u);
  EXPECT_EQ(bad_seen[0].first, P::Validating);
  auto [empty, empty_seen] = phases_of(u_prism());
  EXPECT_EQ(empty.type, KernelType::Empty);
  ASSERT_EQ(empty_seen.size(), 3u);
  EXPECT_EQ(empty_seen[2].first, P::Lp);
}

TEST(Kernel, Deterministic) {
  Mesh m = dented_cube();
  Kernel a = run(m), b = run(m);
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.face_indices, b.face_indices);
}

TEST(Kernel, BadInputGetsSpecificErrors) {
  Mesh m = unit_cube();
  Mesh nan = m;
  nan.positions[4] = std::nan("");
  EXPECT_EQ(run(nan).error, Error::NonFiniteCoordinate);
  Mesh oob = m;
  oob.indices[5] = 99;
  EXPECT_EQ(run(oob).error, Error::IndexOutOfRange);
  Mesh empty;
  EXPECT_EQ(run(empty).error, Error::EmptyInput);
  Mesh twocubes = unit_cube();
  Mesh far = box(5, 5, 5, 6, 6, 6);
  uint32_t base = uint32_t(twocubes.num_vertices());
  twocubes.positions.insert(twocubes.positions.end(), far.positions.begin(), far.positions.end());
  for (uint32_t v : far.indices) twocubes.indices.push_back(v + base);
  // Two closed pieces that neither cross nor touch: no point sees both from inside.
  const Kernel two = run(twocubes);
  ASSERT_TRUE(two.ok()) << two.message;
  EXPECT_EQ(two.type, KernelType::Empty);
  ASSERT_FALSE(two.warnings.empty());
  EXPECT_EQ(two.warnings.back().kind, Warning::Kind::SeparateShells);
  Mesh incons = m;
  std::swap(incons.indices[0], incons.indices[1]);
  EXPECT_EQ(run(incons).error, Error::InconsistentOrientation);
  // Two triangles back to back: closed, but encloses nothing.
  Mesh flat;
  add_point(flat, 0, 0, 0);
  add_point(flat, 1, 0, 0);
  add_point(flat, 0, 1, 0);
  add_face(flat, {0, 1, 2});
  add_face(flat, {0, 2, 1});
  EXPECT_EQ(run(flat).error, Error::DegenerateInput);
  Mesh small = m;
  small.face_sizes.assign(12, 3);
  small.face_sizes[0] = 2;
  small.face_sizes[1] = 4;
  EXPECT_EQ(run(small).error, Error::FaceTooSmall);
  Options limit;
  limit.max_faces = 5;
  EXPECT_EQ(run(m, limit).error, Error::TooLarge);
}

TEST(Kernel, ZeroAreaFacesAreDroppedAndReported) {
  // Cube whose edge (0,1) is split by a midpoint vertex: a zero-area triangle appears.
  Mesh m = unit_cube();
  Kernel ref = run(m);
  uint32_t mid = add_point(m, 0.5, 0, 0);
  // Faces using edge 0-1: bottom {0,2,3},{0,3,1} uses 3->1? Rebuild: replace triangle {0,3,1}
  // by {0,3,mid},{mid,3,1} and front {0,1,5} by {0,mid,5},{mid,1,5}; plus nothing else needed.
  std::vector<uint32_t> idx;
  for (size_t t = 0; t < m.indices.size(); t += 3) {
    uint32_t a = m.indices[t], b = m.indices[t + 1], c = m.indices[t + 2];
    if (a == 0 && b == 3 && c == 1) {
      idx.insert(idx.end(), {0, 3, mid, mid, 3, 1});
      continue;
    }
    if (a == 0 && b == 1 && c == 5) {
      idx.insert(idx.end(), {0, mid, 5, mid, 1, 5});
      continue;
    }
    idx.insert(idx.end(), {a, b, c});
  }
  m.indices = idx;
  Kernel k = run(m);
  ASSERT_TRUE(k.ok()) << k.message;
  EXPECT_NEAR(k.volume, 1, 1e-14);
  // With a real zero-area sliver: add triangle (0, mid, 1) and its twin by splitting differently.
  Mesh s = unit_cube();
  uint32_t mm = add_point(s, 0.5, 0, 0);
  idx.clear();
  for (size_t t = 0; t < s.indices.size(); t += 3) {
    uint32_t a = s.indices[t], b = s.indices[t + 1], c = s.indices[t + 2];
    if (a == 0 && b == 3 && c == 1) {
      idx.insert(idx.end(), {0, 3, 1, 0, 1, mm});
      continue;
    }
    if (a == 0 && b == 1 && c == 5) {
      idx.insert(idx.end(), {0, mm, 5, mm, 1, 5});
      continue;
    }
    idx.insert(idx.end(), {a, b, c});
  }
  s.indices = idx;
  k = run(s);
  ASSERT_TRUE(k.ok()) << k.message;
  EXPECT_EQ(k.stats.dropped_faces, 1u);
  bool warned = false;
  for (const auto& w : k.warnings) warned |= w.kind == Warning::Kind::DegenerateFacesDropped;
  EXPECT_TRUE(warned);
  EXPECT_NEAR(k.volume, 1, 1e-14);
  EXPECT_EQ(k.num_vertices(), ref.num_vertices());
}

}  // namespace

namespace {
using namespace kergen;
using namespace kergen_test;

TEST(Kernel, DeepestPoint) {
  Options o;
  o.deepest_point = true;
  Kernel k = compute_kernel(unit_cube().view(), o);
  ASSERT_TRUE(k.has_deepest_point);
  EXPECT_NEAR(k.inscribed_radius, 0.5, 1e-12);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(k.deepest_point[i], 0.5, 1e-12);
  // A 2 x 1 x 1 box: radius 0.5, centre anywhere on the segment y = z = 0.5, 0.5 <= x <= 1.5.
  k = compute_kernel(box(0, 0, 0, 2, 1, 1).view(), o);
  ASSERT_TRUE(k.has_deepest_point);
  EXPECT_NEAR(k.inscribed_radius, 0.5, 1e-12);
  EXPECT_NEAR(k.deepest_point[1], 0.5, 1e-12);
  EXPECT_NEAR(k.deepest_point[2], 0.5, 1e-12);
  EXPECT_GE(k.deepest_point[0], 0.5 - 1e-12);
  EXPECT_LE(k.deepest_point[0], 1.5 + 1e-12);
  // Plus prism: kernel is the w x w x 1 central block, largest ball radius w.
  k = compute_kernel(plus_prism(0.2).view(), o);
  ASSERT_TRUE(k.has_deepest_point);
  EXPECT_NEAR(k.inscribed_radius, 0.2, 1e-12);
}

TEST(Kernel, FromStartsAtTheExtremeVertexTowardsThePoint) {
  Mesh m = pyramid(24);
  Options o;
  o.has_from = true;
  o.from = {0, 0, 5};  // above the apex: the apex is the extreme vertex in that direction
  std::vector<std::array<double, 3>> order;
  o.on_step = [&](const StepEvent& e) {
    if (e.kind == StepEvent::Kind::Vertex) order.push_back(e.position);
    return true;
  };
  Kernel k = compute_kernel(m.view(), o);
  ASSERT_TRUE(k.ok());
  ASSERT_FALSE(order.empty());
  EXPECT_EQ(order[0][2], 1.0);
  EXPECT_EQ(order.size(), 25u);
  // Vertices nearest to `from` are expanded first: the first edges leave the apex.
  EXPECT_EQ(k.edges[0], 0u);
}

}  // namespace

namespace {
// A convex prism over a regular n-gon, rotated: its caps and sides become non-planar by
// rounding (each vertex off its face's plane by an ulp, either way).
Mesh rotated_prism(int n, double angle) {
  std::vector<std::array<double, 2>> poly;
  for (int i = 0; i < n; ++i) poly.push_back({std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n)});
  Mesh m = prism(poly, 0.8);
  const double ax[3] = {1 / std::sqrt(14.0), 2 / std::sqrt(14.0), 3 / std::sqrt(14.0)};
  const double c = std::cos(angle), s = std::sin(angle);
  for (size_t v = 0; v < m.num_vertices(); ++v) {
    double* p = &m.positions[3 * v];
    const double d = ax[0] * p[0] + ax[1] * p[1] + ax[2] * p[2];
    const double x[3] = {ax[1] * p[2] - ax[2] * p[1], ax[2] * p[0] - ax[0] * p[2], ax[0] * p[1] - ax[1] * p[0]};
    double q[3];
    for (int k = 0; k < 3; ++k) q[k] = p[k] * c + x[k] * s + ax[k] * d * (1 - c);
    for (int k = 0; k < 3; ++k) p[k] = q[k];
  }
  return m;
}
}  // namespace

// A polygon that is non-planar only by rounding is split into triangles that fold outward
// wherever its corners allow (for a convex polygon: always, since every corner is extreme in
// the projection). The kernel of a convex shape is then the shape itself, corner for corner,
// instead of the shape minus slivers of rounding size cut by inward folds.
TEST(Kernel, RoundingSplitPolygonsFoldOutward) {
  size_t split_meshes = 0;
  for (int n : {5, 6, 8, 12})
    for (double angle : {0.3, 0.7, 1.9, 2.6}) {
      const Mesh m = rotated_prism(n, angle);
      const Kernel k = run(m);
      ASSERT_TRUE(k.ok()) << k.message;
      bool split = false;
      for (const auto& w : k.warnings) split |= w.kind == Warning::Kind::NonPlanarFacesSplit;
      split_meshes += split;
      expect_valid_polyhedron(m, k);
      ASSERT_EQ(k.type, KernelType::Polyhedron);
      // Every kernel vertex is a corner of the prism, and every corner is a kernel vertex.
      EXPECT_EQ(k.num_vertices(), m.num_vertices()) << n << " " << angle;
      std::set<std::array<double, 3>> corners;
      for (size_t v = 0; v < m.num_vertices(); ++v)
        corners.insert({m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]});
      for (size_t v = 0; v < k.num_vertices(); ++v)
        EXPECT_TRUE(corners.count({k.vertices[3 * v], k.vertices[3 * v + 1], k.vertices[3 * v + 2]}))
            << n << " " << angle << ": kernel vertex " << v << " is not a corner";
      EXPECT_NEAR(k.volume, k.shape_volume, 1e-12 * k.shape_volume);
    }
  EXPECT_GT(split_meshes, 8u) << "the rotations no longer make the faces non-planar";
}
