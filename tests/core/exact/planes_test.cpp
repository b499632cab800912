// Plane predicates on nearly coplanar planes that share an input edge or point (fine
// tessellations, rounding-split polygons): the shortcuts of sign_det3_normals and of the
// homogeneous coordinates through input points must give exactly what the textbook formulas
// (Cramer's rule) give in exact expansions.
#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "exact/formulas.h"
#include "exact/predicates.h"
#include "fixtures.h"
#include "input/mesh_prep.h"
#include "kergen/io.h"
#include "planes/plane_classes.h"

namespace {

using namespace kergen;

struct Planes {
  PreparedMesh mesh;
  std::unique_ptr<PlaneSet> ps;
  explicit Planes(const Mesh& m) {
    mesh = prepare_mesh(m.view(), Options{});
    EXPECT_EQ(mesh.error, Error::Ok) << mesh.message;
    ps = std::make_unique<PlaneSet>(&mesh.points, mesh.exact_shift);
    std::vector<uint32_t> face_plane;
    build_planes(mesh, *ps, face_plane);
  }
};

int exact_det_sign(const PlaneSet& ps, uint32_t a, uint32_t b, uint32_t c) {
  return det3_normals(ps.exact(a), ps.exact(b), ps.exact(c)).sign();
}

// The vertex of planes a, b, c by Cramer's rule in expansions: x_k = num[k] / den.
struct Cramer {
  Expansion num[3], den;
  Cramer(const PlaneSet& ps, uint32_t a, uint32_t b, uint32_t c) {
    const auto &A = ps.exact(a), &B = ps.exact(b), &C = ps.exact(c);
    den = det3_normals(A, B, C);
    const Expansion ma = -A.d, mb = -B.d, mc = -C.d;
    num[0] = det3(ma, A.n[1], A.n[2], mb, B.n[1], B.n[2], mc, C.n[1], C.n[2]);
    num[1] = det3(A.n[0], ma, A.n[2], B.n[0], mb, B.n[2], C.n[0], mc, C.n[2]);
    num[2] = det3(A.n[0], A.n[1], ma, B.n[0], B.n[1], mb, C.n[0], C.n[1], mc);
  }
  // Sign of f_l at the vertex.
  int side(const PlaneSet& ps, uint32_t l) const {
    const auto& L = ps.exact(l);
    return (L.n[0] * num[0] + L.n[1] * num[1] + L.n[2] * num[2] + L.d * den).sign() * den.sign();
  }
};

// Pairs of planes through one input edge (the planes of the two faces beside a mesh edge:
// shared == 2) or through exactly one input point (faces around a mesh vertex: shared == 1).
std::vector<std::array<uint32_t, 2>> planes_sharing(const Planes& p, int wanted) {
  std::vector<std::array<uint32_t, 2>> pairs;
  const PlaneSet& ps = *p.ps;
  for (uint32_t a = 0; a < ps.size(); ++a)
    for (uint32_t b = a + 1; b < ps.size(); ++b) {
      int shared = 0;
      for (uint32_t pt : ps.points_on(a)) shared += ps.point_on_plane(pt, b);
      if (std::min(shared, 2) == wanted) pairs.push_back({a, b});
    }
  return pairs;
}

struct Tally {
  size_t det_checked = 0, det_undecided_by_filters = 0, side_checked = 0, anchor_decided = 0, point_line_decided = 0;
  size_t point_line_by_stage[3] = {0, 0, 0};
};

// Pairs along an edge or through a point with nearby and random third planes, in all argument
// orders; then the vertex of each independent triple against nearby and random planes.
void check_mesh(const Mesh& m, const std::string& name, Tally& t, size_t max_pairs = 400) {
  SCOPED_TRACE(name);
  Planes p(m);
  const PlaneSet& ps = *p.ps;
  std::mt19937 rng(7);
  std::vector<std::array<uint32_t, 3>> pairs;  // a, b, shared points
  for (uint32_t shared : {2, 1}) {
    auto some = planes_sharing(p, int(shared));
    ASSERT_FALSE(some.empty()) << shared;
    std::shuffle(some.begin(), some.end(), rng);
    if (some.size() > max_pairs / 2) some.resize(max_pairs / 2);
    for (const auto& pr : some) pairs.push_back({pr[0], pr[1], shared});
  }
  for (const auto& pr : pairs) {
    const uint32_t a = pr[0], b = pr[1];
    const bool on_edge = pr[2] == 2;
    // Third planes: the nearest in index (neighbouring faces, the nearly coplanar ones) and a
    // few at random.
    std::vector<uint32_t> thirds;
    for (uint32_t c = a > 3 ? a - 3 : 0; c < std::min<uint32_t>(uint32_t(ps.size()), b + 4); ++c) thirds.push_back(c);
    for (int i = 0; i < 4; ++i) thirds.push_back(uint32_t(rng() % ps.size()));
    for (uint32_t c : thirds) {
      if (c == a || c == b) continue;
      const uint32_t orders[6][3] = {{a, b, c}, {b, c, a}, {c, a, b}, {b, a, c}, {a, c, b}, {c, b, a}};
      for (const auto& o : orders) {
        ASSERT_EQ(sign_det3_normals(ps, o[0], o[1], o[2]), exact_det_sign(ps, o[0], o[1], o[2]))
            << "planes " << o[0] << " " << o[1] << " " << o[2];
        ++t.det_checked;
      }
      if (on_edge && det3_normals(ps.approx(a), ps.approx(b), ps.approx(c)).sign() == 2 &&
          det3_normals(ps.dd(a), ps.dd(b), ps.dd(c)).sign() == 2) {
        // Decided by the line formula, not by the general exact stage (which counts itself).
        const size_t before = ps.exact_fallbacks;
        sign_det3_normals(ps, a, b, c);
        EXPECT_EQ(ps.exact_fallbacks, before) << "planes " << a << " " << b << " " << c;
        ++t.det_undecided_by_filters;
      }
      if (exact_det_sign(ps, a, b, c) == 0) continue;
      const VertexGeom v = make_vertex(ps, a, b, c, false);
      const Cramer ref(ps, a, b, c);
      std::vector<uint32_t> tested = thirds;
      for (int i = 0; i < 16; ++i) tested.push_back(uint32_t(rng() % ps.size()));
      for (uint32_t l : tested) {
        ASSERT_EQ(side(ps, l, v), ref.side(ps, l)) << "plane " << l << " at vertex " << a << " " << b << " " << c;
        ++t.side_checked;
        if (l == a || l == b || l == c) continue;
        // The factored formula wherever it applies, not only where the filters left it the sign.
        const int anchored = side_through_anchor(ps, l, v);
        if (anchored != 2) {
          ASSERT_EQ(anchored, ref.side(ps, l)) << "anchor: plane " << l << " at vertex " << a << " " << b << " " << c;
          ++t.anchor_decided;
        }
        // The orient3d factorisation on a line through one point, likewise.
        int stage = -1;
        const int on_point_line = side_on_point_line(ps, l, v, &stage);
        if (on_point_line != 2) {
          ASSERT_EQ(on_point_line, ref.side(ps, l))
              << "point line: plane " << l << " at vertex " << a << " " << b << " " << c << ", stage " << stage;
          ++t.point_line_decided;
          ++t.point_line_by_stage[stage];
        }
      }
      // Coordinates from the line formula agree with Cramer's quotient to double-double accuracy.
      double hi[3], lo[3];
      precise_coordinates(ps, v, hi, lo);
      const double x0 = std::ldexp(ref.num[0].estimate() / ref.den.estimate(), -ps.exact_shift());
      EXPECT_NEAR(hi[0], x0, 4e-16 * std::fabs(x0) + 1e-300);
    }
  }
}

TEST(Planes, LineShortcutsMatchExpansionsOnTwistedSphere) {
  // A fine, twisted UV sphere: neighbouring triangles are nearly coplanar.
  Tally t;
  check_mesh(kergen_test::uv_sphere(32, 16, 0.37), "uv_sphere 32x16", t, 100);
  std::printf(
      "sphere: %zu det signs, %zu undecided by both filters; %zu side tests, %zu by the anchor formula, %zu by the "
      "point-line factorisation (%zu / %zu / %zu in double / double-double / exactly)\n",
      t.det_checked, t.det_undecided_by_filters, t.side_checked, t.anchor_decided, t.point_line_decided,
      t.point_line_by_stage[0], t.point_line_by_stage[1], t.point_line_by_stage[2]);
  EXPECT_GT(t.side_checked, 0u);
  EXPECT_GT(t.anchor_decided, 0u);
  EXPECT_GT(t.point_line_decided, 0u);
  // Each stage of the factorisation met (and checked against Cramer above).
  for (size_t decided : t.point_line_by_stage) EXPECT_GT(decided, 10u);
}

TEST(Planes, LineShortcutsMatchExpansionsOnVoronoiCells) {
  // Voronoi cells with faces that are planar only up to rounding, split into nearly coplanar
  // triangles: the filters leave many of these signs to the exact stages.
  const std::filesystem::path dir = std::filesystem::path(KERGEN_SHARED_MESHES) / "polyhedra" / "voro";
  if (!std::filesystem::is_directory(dir)) GTEST_SKIP() << "shared meshes not found under " << dir;
  Tally t;
  for (int i : {0, 100, 250, 500, 777, 999}) {
    const auto file = dir / (std::to_string(i) + ".off");
    if (!std::filesystem::exists(file)) continue;
    ReadResult r = read_mesh_file(file.string());
    ASSERT_TRUE(r.ok()) << r.message;
    check_mesh(r.mesh, file.string(), t);
  }
  std::printf("voro: %zu det signs, %zu undecided by both filters; %zu side tests, %zu by the anchor formula\n",
              t.det_checked, t.det_undecided_by_filters, t.side_checked, t.anchor_decided);
  EXPECT_GT(t.det_undecided_by_filters, 0u) << "the sample no longer exercises the exact shortcut";
  EXPECT_GT(t.anchor_decided, 0u);
}

// side_on_point_line's two stages against Cramer's rule in expansions, on constructed planes:
// a and b are triangles with the common corner x, so their vertex with c lies on a line through
// x; c and l pass through copies of x moved by 0 to 3 ulps per coordinate (the vertex is then
// within a few ulps of x and nearly on l, the case a split polygon or a bent quad makes), or
// through x itself (the vertex is x, on l: an exact zero), or l is a plane far away. Every
// stage's sign must be the exact one, and each stage must decide some of the cases.
TEST(Planes, PointLineFactorisationMatchesCramerOnNearlyIncidentPlanes) {
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> U(-1, 1);
  auto nudged = [&](const double* p, double* out) {
    for (int k = 0; k < 3; ++k) {
      out[k] = p[k];
      const int ulps = int(rng() % 7) - 3;
      for (int i = 0; i < std::abs(ulps); ++i) out[k] = std::nextafter(out[k], ulps > 0 ? 2.0 : -2.0);
    }
  };
  size_t by_stage[3] = {0, 0, 0}, zeros = 0, cases = 0;
  for (int i = 0; i < 20000; ++i) {
    std::vector<double> pts(11 * 3);
    double* P[11];
    for (int j = 0; j < 11; ++j) P[j] = &pts[3 * j];
    const double size = std::ldexp(1.0, -int(rng() % 30));
    for (int k = 0; k < 3; ++k) P[0][k] = U(rng);
    for (int j = 1; j <= 4; ++j)  // a1, a2, b1, b2 around x
      for (int k = 0; k < 3; ++k) P[j][k] = P[0][k] + size * U(rng);
    nudged(P[0], P[5]);  // c through a copy of x
    if (i % 8 == 7) {    // c and l through x itself
      for (int k = 0; k < 3; ++k) P[5][k] = P[8][k] = P[0][k];
    } else if (i % 4 == 3) {
      for (int k = 0; k < 3; ++k) P[8][k] = U(rng);  // l anywhere
    } else if (i % 4 == 2) {
      for (int k = 0; k < 3; ++k) P[8][k] = P[5][k];  // l through c's point: the vertex may lie on l
    } else {
      nudged(P[0], P[8]);
    }
    for (int j : {6, 7})
      for (int k = 0; k < 3; ++k) P[j][k] = P[5][k] + size * U(rng);
    for (int j : {9, 10})
      for (int k = 0; k < 3; ++k) P[j][k] = P[8][k] + size * U(rng);
    PlaneSet ps(&pts);
    const uint32_t a = ps.add_from_points(0, 1, 2), b = ps.add_from_points(0, 3, 4), c = ps.add_from_points(5, 6, 7),
                   l = ps.add_from_points(8, 9, 10);
    RawVector<uint32_t> offsets = {0, 3, 6, 9, 12}, rows = {0, 1, 2, 0, 3, 4, 5, 6, 7, 8, 9, 10};
    ps.set_incidence(std::move(offsets), std::move(rows));
    if (exact_det_sign(ps, a, b, c) == 0) continue;
    const VertexGeom v = make_vertex(ps, a, b, c, false);
    const int expected = Cramer(ps, a, b, c).side(ps, l);
    int stage = -1;
    ASSERT_EQ(side_on_point_line(ps, l, v, &stage), expected) << "case " << i << ", stage " << stage;
    ASSERT_EQ(side(ps, l, v), expected) << "case " << i;
    ++by_stage[stage];
    zeros += expected == 0;
    ++cases;
  }
  std::printf("point line: %zu cases, decided in double %zu, double-double %zu, exactly %zu; %zu zeros\n", cases,
              by_stage[0], by_stage[1], by_stage[2], zeros);
  EXPECT_GT(by_stage[0], 10000u);
  EXPECT_GT(by_stage[2], 1000u);
  EXPECT_GT(zeros, 1000u);
}

// orient3d_value's bound must contain the exact value and be below 2^-30 of it, through each of
// its three ways: general points (double), points nearly coplanar by rounding (p a copy of a
// point of the plane moved by a few ulps: double-double) and exactly coplanar or nearly
// collinear ones (exact), at scales from 1 down to 2^-40.
TEST(Planes, Orient3dValueBoundsContainTheExactValue) {
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> U(-1, 1);
  size_t zeros = 0, refined = 0, cases = 0;
  for (int i = 0; i < 30000; ++i) {
    double p[4][3];
    const double size = std::ldexp(1.0, -int(rng() % 40));
    for (int k = 0; k < 3; ++k) p[0][k] = U(rng);
    for (int j = 1; j < 3; ++j)
      for (int k = 0; k < 3; ++k) p[j][k] = p[0][k] + size * U(rng);
    const int kind = i % 4;
    for (int k = 0; k < 3; ++k) {
      if (kind == 0) {
        p[3][k] = p[0][k] + size * U(rng);
      } else {  // a point of the plane (a, b, c, or on the line ab) moved by -3..3 ulps
        p[3][k] = kind == 3 ? p[1][k] : p[int(rng() % 3)][k];
        const int ulps = kind == 1 ? int(rng() % 7) - 3 : 0;
        for (int u = 0; u < std::abs(ulps); ++u) p[3][k] = std::nextafter(p[3][k], ulps > 0 ? 2.0 : -2.0);
      }
    }
    const Approx v = orient3d_value(p[0], p[1], p[2], p[3]);
    const Expansion exact = formula::orient3d_formula<Expansion>(p[0], p[1], p[2], p[3]);
    for (int end : {-1, 1}) {
      const int s = (exact - Expansion(v.v) - Expansion(end * v.e)).sign();  // exact - (v +- e)
      ASSERT_TRUE(end < 0 ? s >= 0 : s <= 0) << "case " << i << ": " << v.v << " +- " << v.e;
    }
    ASSERT_LE(v.e, std::ldexp(std::fabs(v.v), -30)) << "case " << i;
    zeros += exact.sign() == 0;
    // Nonzero values the double formula alone could not give to 2^-30 (the refined ways).
    const Approx in_double = formula::orient3d_formula<Approx>(p[0], p[1], p[2], p[3]);
    refined += exact.sign() != 0 && !(in_double.e <= std::ldexp(std::fabs(in_double.v), -30));
    ++cases;
  }
  std::printf("orient3d values: %zu cases, %zu exact zeros, %zu nonzero refined beyond double\n", cases, zeros,
              refined);
  EXPECT_GT(zeros, 1000u);
  EXPECT_GT(refined, 200u);
}

// The filtered plane of a triangle (the doubles every float scan uses) must contain the exact
// plane within its bounds: general triangles, slivers, nearly degenerate ones and triangles far
// from their size's scale.
TEST(Planes, ApproxPlaneBoundsContainTheExactPlane) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> U(-1, 1);
  size_t tight = 0;
  for (int i = 0; i < 50000; ++i) {
    double p[3][3];
    const double size = std::ldexp(1.0, -int(rng() % 30));
    for (int k = 0; k < 3; ++k) p[0][k] = U(rng);
    for (int j = 1; j < 3; ++j)
      for (int k = 0; k < 3; ++k) p[j][k] = p[0][k] + size * U(rng);
    if (i % 3 == 0)  // nearly collinear: c close to the line ab
      for (int k = 0; k < 3; ++k) p[2][k] = p[0][k] + 0.37 * (p[1][k] - p[0][k]) + std::ldexp(U(rng), -40) * size;
    const PlaneCoef<Approx> a = approx_plane(p[0], p[1], p[2]);
    const PlaneCoef<Expansion> e = exact_plane(p[0], p[1], p[2]);
    const Approx* av[4] = {&a.n[0], &a.n[1], &a.n[2], &a.d};
    const Expansion* ev[4] = {&e.n[0], &e.n[1], &e.n[2], &e.d};
    for (int k = 0; k < 4; ++k) {
      const double err = std::fabs((*ev[k] - Expansion(av[k]->v)).estimate());
      ASSERT_LE(err, av[k]->e) << "case " << i << " coefficient " << k;
      tight += err > 0.05 * av[k]->e;
    }
  }
  EXPECT_GT(tight, 1000u) << "bounds far looser than the actual errors";
}

// The double-double coordinates of a vertex (dd_point's quotient, and those of the exact
// homogeneous coordinates, ExactHomogeneous::point) and the side stage that uses the latter,
// where the double-double homogeneous values cannot decide: vertices of three nearly coplanar
// planes (triangles of one face of a turned, finely tessellated cube, coplanar only up to
// rounding). Every bound must contain the exact quotient, every sign the stage gives must be
// the exact one, and the stage must decide most of the signs it is given.
TEST(Planes, DDCoordinatesOfNearlyCoplanarTriplesMatchExpansions) {
  Planes p(kergen_test::turned(kergen_test::tessellated_cube(6)));
  const PlaneSet& ps = *p.ps;
  ASSERT_GT(ps.size(), 6u * 36) << "rounding should leave the triangles of a face on distinct planes";
  std::mt19937 rng(11);
  size_t vertices = 0, bounds_checked = 0, quotients_checked = 0, homogeneous_undecided = 0, decided = 0;
  for (uint32_t a = 0; a + 2 < ps.size(); ++a) {
    for (uint32_t b : {a + 1, a + 2}) {
      const uint32_t c = uint32_t(rng() % ps.size());
      if (c == a || c == b || exact_det_sign(ps, a, b, c) == 0) continue;
      const VertexGeom v = make_vertex(ps, a, b, c, false);
      // dd_point before the exact coordinates exist (the double-double quotient), then
      // dd_coordinates: each bound must contain the exact quotient.
      exact::ApproxDD quotient[3];
      const bool has_quotient = dd_point(ps, v, quotient);
      const ExactHomogeneous& h = exact_homogeneous(ps, v);
      exact::ApproxDD point[3];
      ASSERT_TRUE(dd_coordinates(h, ps.exact_shift(), point)) << "vertex " << a << " " << b << " " << c;
      ++vertices;
      // x_k - e <= num_k / den <= x_k + e, checked in expansions (2^shift units).
      const int den_sign = h.den.sign();
      auto contains = [&](const exact::ApproxDD& x, int k) {
        for (int end : {-1, 1}) {
          const Expansion bound = (Expansion(x.hi) + Expansion(x.lo)) + Expansion(end * x.e);
          Expansion scaled;  // times 2^shift, component by component (exact)
          for (size_t i = 0; i < bound.size(); ++i)
            scaled = scaled + Expansion(std::ldexp(bound.data()[i], ps.exact_shift()));
          const int s = (h.num[k] - scaled * h.den).sign() * den_sign;  // sign of num / den - bound
          if (end < 0 ? s < 0 : s > 0) return false;
        }
        return true;
      };
      for (int k = 0; k < 3; ++k) {
        ASSERT_TRUE(contains(point[k], k)) << "coordinate " << k << " of vertex " << a << " " << b << " " << c;
        ++bounds_checked;
        if (!has_quotient) continue;
        ASSERT_TRUE(contains(quotient[k], k)) << "quotient " << k << " of vertex " << a << " " << b << " " << c;
        ++quotients_checked;
      }
      // ... and is about as tight as double-double allows (the vertices lie within ~10 of 0).
      const double size = std::max({std::fabs(point[0].hi), std::fabs(point[1].hi), std::fabs(point[2].hi), 1.0});
      for (int k = 0; k < 3; ++k) EXPECT_LE(point[k].e, 1e-28 * size) << "vertex " << a << " " << b << " " << c;
      const Cramer ref(ps, a, b, c);
      const DDHomogeneous& hd = dd_homogeneous(ps, v);
      for (uint32_t l = a > 4 ? a - 4 : 0; l < std::min<uint32_t>(uint32_t(ps.size()), b + 5); ++l) {
        if (l == a || l == b || l == c) continue;
        const PlaneCoef<exact::ApproxDD> d = ps.dd(l);
        const int expected = ref.side(ps, l);
        ASSERT_EQ(side(ps, l, v), expected) << "plane " << l << " at vertex " << a << " " << b << " " << c;
        if ((d.n[0] * hd.num[0] + d.n[1] * hd.num[1] + d.n[2] * hd.num[2] + d.d * hd.den).sign() != 2) continue;
        ++homogeneous_undecided;
        const int s = (d.n[0] * point[0] + d.n[1] * point[1] + d.n[2] * point[2] + d.d).sign();
        if (s == 2) continue;
        ASSERT_EQ(s, expected) << "plane " << l << " at vertex " << a << " " << b << " " << c;
        ++decided;
      }
    }
  }
  std::printf(
      "turned cube: %zu vertices, %zu coordinate bounds, %zu quotient bounds; %zu signs the homogeneous stage left, "
      "%zu decided\n",
      vertices, bounds_checked, quotients_checked, homogeneous_undecided, decided);
  EXPECT_GT(quotients_checked, bounds_checked / 2);
  EXPECT_GT(homogeneous_undecided, 50u) << "the sample no longer reaches the stage";
  EXPECT_GT(decided, homogeneous_undecided / 2) << "the stage decides too few of the signs it is given";
}

}  // namespace

// halfspaces_disjoint on constructed sets with known answers: planes n . x + d <= 0 with small
// integer coefficients (exact as given).
namespace {
PlaneCoef<Expansion> plane(double nx, double ny, double nz, double d) {
  return {{Expansion(nx), Expansion(ny), Expansion(nz)}, Expansion(d)};
}
}  // namespace

TEST(Planes, HalfspacesDisjointOnConstructedSets) {
  struct Case {
    const char* what;
    std::vector<PlaneCoef<Expansion>> planes;
    bool disjoint;
  };
  const Case cases[] = {
      {"slab z <= 0, z >= 1", {plane(0, 0, 1, 0), plane(0, 0, -2, 2)}, true},
      {"z <= 0, z >= 0 (a common plane)", {plane(0, 0, 1, 0), plane(0, 0, -1, 0)}, false},
      {"z <= 1, z >= 0", {plane(0, 0, 1, -1), plane(0, 0, -1, 0)}, false},
      {"z <= 0 twice (same side)", {plane(0, 0, 1, 0), plane(0, 0, 3, 1)}, false},
      {"crossing planes", {plane(1, 0, 0, 5), plane(0, 1, 0, 5)}, false},
      {"x <= -1, y <= -1, x + y >= 1", {plane(1, 0, 0, 1), plane(0, 1, 0, 1), plane(-1, -1, 0, 1)}, true},
      {"x <= 1, y <= 1, x + y >= 1 (a triangle prism)",
       {plane(1, 0, 0, -1), plane(0, 1, 0, -1), plane(-1, -1, 0, 1)},
       false},
      {"three with a disjoint pair (not minimal)", {plane(0, 0, 1, 0), plane(0, 0, -1, 1), plane(1, 0, 0, 0)}, false},
      {"three parallel", {plane(0, 0, 1, 0), plane(0, 0, -1, 1), plane(0, 0, 2, 0)}, false},
      {"inside-out tetrahedron",
       {plane(1, 1, 1, 1), plane(1, -1, -1, 1), plane(-1, 1, -1, 1), plane(-1, -1, 1, 1)},
       true},
      {"tetrahedron", {plane(1, 1, 1, -1), plane(1, -1, -1, -1), plane(-1, 1, -1, -1), plane(-1, -1, 1, -1)}, false},
      {"tetrahedron of one point",
       {plane(1, 1, 1, 0), plane(1, -1, -1, 0), plane(-1, 1, -1, 0), plane(-1, -1, 1, 0)},
       false},
      {"four with a disjoint pair (not minimal)",
       {plane(0, 0, 1, 0), plane(0, 0, -1, 1), plane(1, 0, 0, 0), plane(0, 1, 0, 0)},
       false},
      {"four of rank 2", {plane(1, 0, 0, 1), plane(0, 1, 0, 1), plane(-1, -1, 0, 1), plane(1, 1, 0, 1)}, false},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(halfspaces_disjoint(c.planes.data(), c.planes.size()), c.disjoint) << c.what;
    // The answer does not depend on the order of the planes, nor on positive scales.
    std::vector<PlaneCoef<Expansion>> turned(c.planes.rbegin(), c.planes.rend());
    for (auto& p : turned) {
      for (auto& n : p.n) n = n * Expansion(3);
      p.d = p.d * Expansion(3);
    }
    EXPECT_EQ(halfspaces_disjoint(turned.data(), turned.size()), c.disjoint) << c.what << " (reversed, scaled)";
  }
}
