// The exact contact test (self_contact.h): pairs of triangles in every configuration of shared
// corners, the answers that rely on it (find_kernel_point, open meshes), and no contact on any
// mesh of the shared sets that validation accepts.
#include "certify/self_contact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <vector>

#include "fixtures.h"
#include "kergen/io.h"
#include "kergen/kergen.h"

namespace {

namespace fs = std::filesystem;
using kergen::FaceContact;
using kergen::Mesh;
using Outcome = kergen::FaceContact::Outcome;

// A prepared mesh of the given faces as they are (no validation): the contact test alone.
// `dropped`: as if validation had dropped a zero-area face (vertices inside sides are then
// expected, and shared with the side).
kergen::PreparedMesh prepared(const std::vector<double>& positions, const std::vector<std::vector<uint32_t>>& faces,
                              bool dropped = false) {
  kergen::PreparedMesh m;
  m.dropped_faces = dropped ? 1 : 0;
  m.points = positions;
  m.loop_offsets.push_back(0);
  for (const auto& f : faces) {
    for (uint32_t v : f) m.loops.push_back(v);
    m.loop_offsets.push_back(uint32_t(m.loops.size()));
    m.rep.push_back({f[0], f[1], f[2]});
  }
  for (int k = 0; k < 3; ++k) {
    m.bbox_min[k] = HUGE_VAL;
    m.bbox_max[k] = -HUGE_VAL;
    for (size_t i = k; i < positions.size(); i += 3) {
      m.bbox_min[k] = std::min(m.bbox_min[k], positions[i]);
      m.bbox_max[k] = std::max(m.bbox_max[k], positions[i]);
    }
  }
  return m;
}

Outcome contact(const std::vector<double>& positions, const std::vector<std::vector<uint32_t>>& faces,
                bool dropped = false) {
  return kergen::find_face_contact(prepared(positions, faces, dropped)).outcome;
}

TEST(SelfContact, TrianglesWithoutSharedCorners) {
  // Crossing: the second triangle pierces the first.
  EXPECT_EQ(contact({0, 0, 0, 4, 0, 0, 0, 4, 0, 1, 1, -1, 1, 1, 1, 2, 2, 1}, {{0, 1, 2}, {3, 4, 5}}), Outcome::Found);
  // Apart (the second above the first).
  EXPECT_EQ(contact({0, 0, 0, 4, 0, 0, 0, 4, 0, 1, 1, 1, 3, 1, 1, 1, 3, 2}, {{0, 1, 2}, {3, 4, 5}}), Outcome::None);
  // Touching: a corner of the second on the inside of the first.
  EXPECT_EQ(contact({0, 0, 0, 4, 0, 0, 0, 4, 0, 1, 1, 0, 1, 1, 1, 2, 2, 1}, {{0, 1, 2}, {3, 4, 5}}), Outcome::Found);
  // Coplanar and overlapping; coplanar, one inside the other; coplanar and apart.
  EXPECT_EQ(contact({0, 0, 0, 4, 0, 0, 0, 4, 0, 1, 1, 0, 5, 1, 0, 1, 5, 0}, {{0, 1, 2}, {3, 4, 5}}), Outcome::Found);
  EXPECT_EQ(contact({0, 0, 0, 4, 0, 0, 0, 4, 0, 1, 1, 0, 2, 1, 0, 1, 2, 0}, {{0, 1, 2}, {3, 4, 5}}), Outcome::Found);
  EXPECT_EQ(contact({0, 0, 0, 4, 0, 0, 0, 4, 0, 3, 3, 0, 5, 3, 0, 3, 5, 0}, {{0, 1, 2}, {3, 4, 5}}), Outcome::None);
  // Two corners at one position under two ids: a touch.
  EXPECT_EQ(contact({0, 0, 0, 4, 0, 0, 0, 4, 0, 0, 0, 0, -4, 0, 1, 0, -4, 1}, {{0, 1, 2}, {3, 4, 5}}), Outcome::Found);
}

TEST(SelfContact, TrianglesSharingACorner) {
  // Corner 0 shared, otherwise apart (not coplanar).
  EXPECT_EQ(contact({0, 0, 0, 4, 0, 0, 0, 4, 0, -4, 0, 1, 0, -4, 1}, {{0, 1, 2}, {0, 3, 4}}), Outcome::None);
  // Coplanar, corners at 0 apart (opposite quadrants) and overlapping.
  EXPECT_EQ(contact({0, 0, 0, 4, 0, 0, 0, 4, 0, -4, 0, 0, 0, -4, 0}, {{0, 1, 2}, {0, 3, 4}}), Outcome::None);
  EXPECT_EQ(contact({0, 0, 0, 4, 0, 0, 0, 4, 0, 4, 1, 0, 1, 4, 0}, {{0, 1, 2}, {0, 3, 4}}), Outcome::Found);
  // An edge at 0 that lies in the other's plane and points into its corner there.
  EXPECT_EQ(contact({0, 0, 0, 4, 0, 0, 0, 4, 0, 1, 1, 0, 0, 0, 3}, {{0, 1, 2}, {0, 3, 4}}), Outcome::Found);
  // An edge at 0 that runs along the other's side and ends on it (or beyond its end): a touch
  // along the side; where a zero-area face was dropped, that end (or the side's) is taken as
  // shared with the side, and the two then share an edge.
  for (bool dropped : {false, true}) {
    const Outcome expected = dropped ? Outcome::None : Outcome::Found;
    EXPECT_EQ(contact({0, 0, 0, 4, 0, 0, 0, 4, 0, 2, 0, 0, 0, 0, 3}, {{0, 1, 2}, {0, 3, 4}}, dropped), expected);
    EXPECT_EQ(contact({0, 0, 0, 4, 0, 0, 0, 4, 0, 6, 0, 0, 0, 0, 3}, {{0, 1, 2}, {0, 3, 4}}, dropped), expected);
  }
  // The second's far side pierces the first.
  EXPECT_EQ(contact({0, 0, 0, 4, 0, 0, 0, 4, 0, 2, 2, -1, 1, 1, 2}, {{0, 1, 2}, {0, 3, 4}}), Outcome::Found);
}

TEST(SelfContact, TrianglesSharingAnEdge) {
  // A hinge (not coplanar), flat and unfolded, flat and folded onto each other.
  EXPECT_EQ(contact({0, 0, 0, 4, 0, 0, 0, 4, 0, 2, -2, 3}, {{0, 1, 2}, {1, 0, 3}}), Outcome::None);
  EXPECT_EQ(contact({0, 0, 0, 4, 0, 0, 0, 4, 0, 2, -2, 0}, {{0, 1, 2}, {1, 0, 3}}), Outcome::None);
  EXPECT_EQ(contact({0, 0, 0, 4, 0, 0, 0, 4, 0, 2, 2, 0}, {{0, 1, 2}, {1, 0, 3}}), Outcome::Found);
  // The same three corners twice.
  EXPECT_EQ(contact({0, 0, 0, 4, 0, 0, 0, 4, 0}, {{0, 1, 2}, {0, 2, 1}}), Outcome::Found);
}

TEST(SelfContact, PolygonsAreTriangulatedInTheirPlane) {
  // The L (non-convex): its corner fan from (0, 2) would leave the polygon; the ear clipping does
  // not, and a triangle standing on the L's notch, outside it, touches nothing.
  const std::vector<double> l = {0, 0, 0, 2, 0, 0, 2, 1, 0, 1, 1, 0, 1, 2, 0, 0, 2, 0, 1.5, 1.1, 0, 2, 2, 0, 2, 2, 1};
  EXPECT_EQ(contact(l, {{5, 0, 1, 2, 3, 4}, {6, 7, 8}}), Outcome::None);
  // The same triangle moved onto the L.
  std::vector<double> on = l;
  on[18] = 0.5;
  on[19] = 0.5;
  EXPECT_EQ(contact(on, {{5, 0, 1, 2, 3, 4}, {6, 7, 8}}), Outcome::Found);
  // A bow tie is not a simple polygon: undecided, never a silent pass.
  EXPECT_EQ(contact({0, 0, 0, 2, 2, 0, 2, 0, 0, 0, 2, 0}, {{0, 1, 2, 3}}), Outcome::Undecided);
}

TEST(SelfContact, VertexOnASideIsSharedWithItWhereAZeroAreaFaceWasDropped) {
  // Triangle (0, 1, 2) whose side 0-1 holds vertex 3, where two triangles meet it (the zero-area
  // face (0, 3, 1) between them was dropped): no contact; with no face dropped, a touch.
  const std::vector<double> p = {0, 0, 0, 4, 0, 0, 0, 4, 0, 2, 0, 0, 2, -2, 1};
  EXPECT_EQ(contact(p, {{0, 1, 2}, {3, 0, 4}, {1, 3, 4}}, true), Outcome::None);
  EXPECT_EQ(contact(p, {{0, 1, 2}, {3, 0, 4}, {1, 3, 4}}, false), Outcome::Found);
  // Folded onto the triangle instead: a contact either way.
  std::vector<double> folded = p;
  folded[13] = 2;
  folded[14] = 0;
  EXPECT_EQ(contact(folded, {{0, 1, 2}, {3, 0, 4}, {1, 3, 4}}, true), Outcome::Found);
}

TEST(SelfContact, FindKernelPointRefusesASurfaceWoundTwice) {
  for (int n : {5, 7, 9, 31}) {
    const kergen::KernelPoint once = kergen::find_kernel_point(kergen_test::wound_bipyramid(n, 1).view());
    ASSERT_TRUE(once.error == kergen::Error::Ok) << once.message;
    EXPECT_TRUE(once.star_shaped);
    const kergen::KernelPoint twice = kergen::find_kernel_point(kergen_test::wound_bipyramid(n, 2).view());
    EXPECT_EQ(twice.error, kergen::Error::SelfIntersection) << n << ": " << twice.message;
    EXPECT_FALSE(twice.star_shaped);
  }
}

TEST(SelfContact, OpenSurfaceWoundTwiceIsRefused) {
  kergen::Options o;
  o.allow_open = true;
  for (int n : {5, 7, 9}) {
    const kergen::Kernel once = kergen::compute_kernel(kergen_test::wound_bipyramid(n, 1, true).view(), o);
    ASSERT_TRUE(once.ok()) << once.message;
    const kergen::Kernel twice = kergen::compute_kernel(kergen_test::wound_bipyramid(n, 2, true).view(), o);
    EXPECT_EQ(twice.error, kergen::Error::SelfIntersection) << n << ": " << twice.message;
  }
}

TEST(SelfContact, NoContactOnAnySharedMeshValidationAccepts) {
  size_t meshes = 0, faces = 0;
  const bool found = kergen_test::for_each_shared_mesh([&](const fs::path& path, const Mesh& mesh) {
    const kergen::PreparedMesh m = kergen::prepare_mesh(mesh.view(), kergen::Options{});
    if (m.error != kergen::Error::Ok) return;
    const FaceContact c = kergen::find_face_contact(m);
    EXPECT_EQ(c.outcome, Outcome::None) << path << ": faces " << c.face_a << ", " << c.face_b;
    ++meshes;
    faces += m.num_faces();
  });
  if (!found) GTEST_SKIP() << "shared meshes not found at " << KERGEN_SHARED_MESHES;
  std::printf("%zu meshes (%zu faces) without contact\n", meshes, faces);
  EXPECT_GT(meshes, 3000u);
}

}  // namespace
