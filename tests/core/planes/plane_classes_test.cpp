// Exact plane classes against a brute-force reference: two faces share a class exactly when every
// vertex of one lies on the other's plane (exact orient3d) and their normals point the same way;
// opposite classes are linked. The meshes crowd one float-key cell with planes that are equal
// only up to rounding, so the fine double-double keys are exercised next to exact coplanarity.
#include "planes/plane_classes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <vector>

#include "exact/predicates.h"
#include "fixtures.h"
#include "input/mesh_prep.h"

namespace {

using namespace kergen;

// Rotates a mesh about three axes in double: coplanar faces become coplanar only up to rounding,
// except where the rotation happens to keep four points on one plane.
Mesh rotated(Mesh m, double a, double b, double c) {
  for (size_t i = 0; i < m.positions.size(); i += 3) {
    double x = m.positions[i], y = m.positions[i + 1], z = m.positions[i + 2];
    double t;
    t = y * std::cos(a) - z * std::sin(a);
    z = y * std::sin(a) + z * std::cos(a);
    y = t;
    t = x * std::cos(b) + z * std::sin(b);
    z = -x * std::sin(b) + z * std::cos(b);
    x = t;
    t = x * std::cos(c) - y * std::sin(c);
    y = x * std::sin(c) + y * std::cos(c);
    x = t;
    m.positions[i] = x;
    m.positions[i + 1] = y;
    m.positions[i + 2] = z;
  }
  return m;
}

// Same oriented plane, exactly: f's vertices on g's plane and the normals pointing the same way.
bool same_oriented_plane(const PreparedMesh& pm, uint32_t f, uint32_t g) {
  const auto& a = pm.rep[g];
  for (uint32_t v : pm.rep[f])
    if (orient3d(pm.point(a[0]), pm.point(a[1]), pm.point(a[2]), pm.point(v), pm.exact_shift) != 0) return false;
  const PlaneCoef<Expansion> p = exact_plane(pm.point(a[0]), pm.point(a[1]), pm.point(a[2]), pm.exact_shift);
  const auto& b = pm.rep[f];
  const PlaneCoef<Expansion> q = exact_plane(pm.point(b[0]), pm.point(b[1]), pm.point(b[2]), pm.exact_shift);
  return (p.n[0] * q.n[0] + p.n[1] * q.n[1] + p.n[2] * q.n[2]).sign() > 0;
}

// The classes of the faces `faces` (increasing ids; all faces when empty), built by the full or
// the subset overload, against the reference among those faces.
void expect_classes_match_brute_force(const PreparedMesh& pm, const std::vector<uint32_t>& faces, const char* name) {
  PlaneSet ps(&pm.points, pm.exact_shift);
  std::vector<uint32_t> face_plane, chosen = faces;
  if (faces.empty()) {
    build_planes(pm, ps, face_plane);
    for (uint32_t f = 0; f < pm.num_faces(); ++f) chosen.push_back(f);
  } else {
    build_planes(pm, faces, ps, face_plane);
  }
  const size_t n = chosen.size();
  ASSERT_EQ(face_plane.size(), n) << name;
  // The reference classes: each face joins the first earlier face on its oriented plane.
  std::vector<uint32_t> ref(n);
  std::vector<uint32_t> firsts;
  for (uint32_t k = 0; k < n; ++k) {
    ref[k] = k;
    for (uint32_t g : firsts)
      if (same_oriented_plane(pm, chosen[k], chosen[g])) {
        ref[k] = g;
        break;
      }
    if (ref[k] == k) firsts.push_back(k);
  }
  EXPECT_EQ(ps.size(), firsts.size()) << name;
  // The same partition: face_plane and ref map one to one.
  std::map<uint32_t, uint32_t> to_ref, from_ref;
  size_t mismatches = 0;
  for (uint32_t k = 0; k < n; ++k) {
    auto a = to_ref.emplace(face_plane[k], ref[k]).first;
    auto b = from_ref.emplace(ref[k], face_plane[k]).first;
    mismatches += a->second != ref[k] || b->second != face_plane[k];
  }
  EXPECT_EQ(mismatches, 0u) << name;
  // Opposite planes are linked both ways, and only to the reversed plane.
  for (uint32_t p = 0; p < ps.size(); ++p) {
    const uint32_t o = ps.opposite(p);
    if (o == kNoPlane) continue;
    EXPECT_EQ(ps.opposite(o), p) << name;
  }
}

// All faces, then two subsets as face culling passes them: every third face, and runs of
// neighbouring faces (whose shared edges the subset overload must pair itself).
void expect_classes_match_brute_force(const Mesh& m, const char* name) {
  const PreparedMesh pm = prepare_mesh(m.view(), Options{});
  ASSERT_EQ(pm.error, Error::Ok) << name << ": " << pm.message;
  expect_classes_match_brute_force(pm, {}, name);
  std::vector<uint32_t> thirds, runs;
  for (uint32_t f = 0; f < pm.num_faces(); ++f) {
    if (f % 3 == 0) thirds.push_back(f);
    if (f % 100 < 40) runs.push_back(f);
  }
  expect_classes_match_brute_force(pm, thirds, name);
  expect_classes_match_brute_force(pm, runs, name);
}

TEST(PlaneClasses, RotatedTessellationsMatchBruteForce) {
  // 6 x 12 x 12 x 2 = 1728 triangles: each side's 288 triangles crowd one float-key cell.
  expect_classes_match_brute_force(rotated(kergen_test::tessellated_cube(12), 0.3, 0.7, 1.1), "rotated cube");
  expect_classes_match_brute_force(rotated(kergen_test::tessellated_cube(12), 0.0, 0.0, 0.5), "cube rotated about z");
  // Unrotated: every side is one exact class (the float keys alone decide).
  expect_classes_match_brute_force(kergen_test::tessellated_cube(12), "cube");
  // Two opposite tessellated faces on one plane: a thin slab of zero thickness is not a valid
  // mesh, so the opposite links are checked on the flat-kernel prisms instead.
  expect_classes_match_brute_force(rotated(kergen_test::plus_prism(0.3), 0.2, 0.4, 0.6), "rotated plus prism");
}

// Key cells are centred on multiples of 2^-32: an axis-aligned plane whose offset lies half a
// cell from one (or within the border margin of that) has a key on a cell border, and its faces
// and its opposite faces must still find each other. The cube is shifted along x so that its
// x = 0 and x = 1 sides lie at such offsets (scaled units), exactly on the border and 2^-13 cell
// to either side; the shift rounds the other points' x, so the y and z sides break into
// nearly coplanar classes as well.
TEST(PlaneClasses, KeysOnCellBordersMatchBruteForce) {
  const Mesh cube = kergen_test::tessellated_cube(12);
  const PreparedMesh plain = prepare_mesh(cube.view(), Options{});
  ASSERT_EQ(plain.error, Error::Ok);
  for (const double off : {0.0, std::ldexp(1.0, -45), -std::ldexp(1.0, -45)}) {
    Mesh m = cube;
    const double shift = std::ldexp(std::ldexp(1.0, -33) + off, -plain.scale_exp);
    for (size_t i = 0; i < m.positions.size(); i += 3) m.positions[i] += shift;
    const PreparedMesh pm = prepare_mesh(m.view(), Options{});
    ASSERT_EQ(pm.error, Error::Ok);
    ASSERT_EQ(pm.scale_exp, plain.scale_exp);
    expect_classes_match_brute_force(pm, {}, "shifted cube");
    std::vector<uint32_t> thirds;
    for (uint32_t f = 0; f < pm.num_faces(); f += 3) thirds.push_back(f);
    expect_classes_match_brute_force(pm, thirds, "shifted cube, every third face");
  }
}

}  // namespace
