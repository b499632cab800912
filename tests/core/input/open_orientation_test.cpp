// An open surface given inside out (open_orientation.h): detected from the volume of the surface
// closed over its holes, said in the refusal and as Warning::Kind::FacesPointInward, never fixed
// silently; Options::flip_faces turns it over, and its kernel is then the solid it bounds. Also:
// an open mesh's shape volume is that capped volume, and it gets no volume ratio.
#include "input/open_orientation.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "fixtures.h"
#include "open_surfaces.h"

namespace {

using kergen::KernelType;
using kergen::Mesh;
using kergen::OpenBoundary;
using kergen::Options;
using kergen::Warning;

// `m` with every triangle reversed (inside out).
Mesh inside_out(Mesh m) {
  for (size_t t = 0; t < m.indices.size(); t += 3) std::swap(m.indices[t], m.indices[t + 2]);
  return m;
}

const Warning* find_warning(const std::vector<Warning>& ws, Warning::Kind kind) {
  auto it = std::find_if(ws.begin(), ws.end(), [&](const Warning& w) { return w.kind == kind; });
  return it == ws.end() ? nullptr : &*it;
}

// The unit cube without its top, its faces turned inward (the shared fixture open_cube.off is
// such a surface): its faces alone have no common point behind them.
TEST(OpenOrientation, CappedVolumeOfAnOpenCubeIsTheCubeSigned) {
  const Mesh out = kergen_test::open_cube();
  const kergen::CappedVolume a = kergen::capped_volume(out.view());
  EXPECT_NEAR(a.volume, 1.0, 1e-15);  // the cube, its lid the fan over the top square
  EXPECT_FALSE(a.inward);
  EXPECT_EQ(a.holes, 1u);
  const Mesh in = inside_out(out);
  const kergen::CappedVolume b = kergen::capped_volume(in.view());
  EXPECT_NEAR(b.volume, -1.0, 1e-15);
  EXPECT_TRUE(b.inward);
}

TEST(OpenOrientation, TwoHolesAreCappedEach) {
  // The unit cube without its top and bottom: a square tube, capped at both ends: the cube.
  const Mesh c = kergen_test::unit_cube();
  Mesh tube;
  tube.positions = c.positions;
  for (size_t t = 0; t < c.indices.size(); t += 3) {
    bool flat = true;
    const double z = c.positions[3 * c.indices[t] + 2];
    for (int k = 1; k < 3; ++k) flat &= c.positions[3 * c.indices[t + k] + 2] == z;
    if (!flat) tube.indices.insert(tube.indices.end(), c.indices.begin() + t, c.indices.begin() + t + 3);
  }
  const kergen::CappedVolume v = kergen::capped_volume(tube.view());
  EXPECT_EQ(v.holes, 2u);
  EXPECT_NEAR(v.volume, 1.0, 1e-15);
  EXPECT_FALSE(v.inward);
  EXPECT_TRUE(kergen::capped_volume(inside_out(tube).view()).inward);
}

TEST(OpenOrientation, AFlatPatchIsNeverSaidToFaceInward) {
  // A flat square of two triangles, either way up: the capped volume is zero.
  Mesh patch;
  kergen_test::add_point(patch, 0, 0, 0);
  kergen_test::add_point(patch, 1, 0, 0);
  kergen_test::add_point(patch, 1, 1, 0);
  kergen_test::add_point(patch, 0, 1, 0);
  kergen_test::add_face(patch, {0, 1, 2});
  kergen_test::add_face(patch, {0, 2, 3});
  EXPECT_FALSE(kergen::capped_volume(patch.view()).inward);
  EXPECT_FALSE(kergen::capped_volume(inside_out(patch).view()).inward);
}

TEST(OpenOrientation, TheRefusalSaysTheFacesPointInward) {
  const Mesh in = inside_out(kergen_test::open_cube());
  const kergen::Kernel k = kergen::compute_kernel(in.view());
  ASSERT_EQ(k.error, kergen::Error::OpenMesh);
  EXPECT_NE(k.message.find("its faces point inward (closed over its hole, it encloses a volume of -1)"),
            std::string::npos)
      << k.message;
  EXPECT_NE(k.message.find("Options::flip_faces"), std::string::npos) << k.message;
  const kergen::Kernel out = kergen::compute_kernel(kergen_test::open_cube().view());
  ASSERT_EQ(out.error, kergen::Error::OpenMesh);
  EXPECT_EQ(out.message.find("inward"), std::string::npos) << out.message;
}

TEST(OpenOrientation, AcceptedItIsAWarningWithTheFlippedKernelOffered) {
  const Mesh in = inside_out(kergen_test::open_cube());
  for (const bool walls : {false, true}) {
    Options o;
    o.allow_open = !walls;
    if (walls) o.open_boundary = OpenBoundary::Perpendicular;
    const kergen::Kernel k = kergen::compute_kernel(in.view(), o);
    ASSERT_TRUE(k.ok()) << k.message;
    EXPECT_EQ(k.type, KernelType::Empty);  // taken as given: never flipped silently
    const Warning* w = find_warning(k.warnings, Warning::Kind::FacesPointInward);
    ASSERT_NE(w, nullptr);
    EXPECT_EQ(w->count, in.num_faces());
    EXPECT_NE(w->message.find("turned over, its kernel is not empty"), std::string::npos) << w->message;
    EXPECT_DOUBLE_EQ(k.shape_volume, -1.0);
    EXPECT_EQ(k.volume_ratio, 0.0);
  }
}

TEST(OpenOrientation, FlippedWithWallsItsKernelIsTheCube) {
  const Mesh in = inside_out(kergen_test::open_cube());
  Options o;
  o.open_boundary = OpenBoundary::Perpendicular;
  o.flip_faces = true;
  const kergen::Kernel k = kergen::compute_kernel(in.view(), o);
  ASSERT_TRUE(k.ok()) << k.message;
  // The walls at the missing top's edges are the plane z = 1: the kernel is the unit cube.
  EXPECT_EQ(k.type, KernelType::Polyhedron);
  EXPECT_EQ(k.num_vertices(), 8u);
  EXPECT_DOUBLE_EQ(k.volume, 1.0);
  EXPECT_DOUBLE_EQ(k.shape_volume, 1.0);  // the cube the capped surface encloses
  EXPECT_EQ(k.volume_ratio, 0.0);         // open: no ratio
  EXPECT_EQ(find_warning(k.warnings, Warning::Kind::FacesPointInward), nullptr);
  // The same kernel as the surface given outward.
  Options given;
  given.open_boundary = OpenBoundary::Perpendicular;
  const kergen::Kernel g = kergen::compute_kernel(kergen_test::open_cube().view(), given);
  EXPECT_EQ(g.num_vertices(), k.num_vertices());
  EXPECT_EQ(g.volume, k.volume);
  // repair_mesh returns the flipped faces: what the kernel was computed on.
  const kergen::RepairedMesh r = kergen::repair_mesh(in.view(), o);
  EXPECT_EQ(r.mesh.indices, kergen_test::open_cube().indices);
}

TEST(OpenOrientation, AClosedMeshIsOrientedByItsVolumeWithOrWithoutFlipFaces) {
  Options o;
  o.flip_faces = true;
  const kergen::Kernel k = kergen::compute_kernel(kergen_test::unit_cube().view(), o);
  ASSERT_TRUE(k.ok()) << k.message;
  EXPECT_DOUBLE_EQ(k.volume, 1.0);
  EXPECT_DOUBLE_EQ(k.volume_ratio, 1.0);
  EXPECT_NE(find_warning(k.warnings, Warning::Kind::OrientationFlipped), nullptr);
}

TEST(OpenOrientation, AWeldedMeshIsNotToldToWeld) {
  const Mesh in = kergen_test::open_cube();
  Options o;
  o.weld = 0;
  const kergen::Kernel k = kergen::compute_kernel(in.view(), o);
  ASSERT_EQ(k.error, kergen::Error::OpenMesh);
  EXPECT_EQ(k.message.find("Options::weld"), std::string::npos) << k.message;
  EXPECT_NE(k.message.find("Options::repair"), std::string::npos) << k.message;
  o.repair = true;
  const kergen::Kernel r = kergen::compute_kernel(in.view(), o);
  ASSERT_EQ(r.error, kergen::Error::OpenMesh);
  EXPECT_EQ(r.message.find("Options::weld"), std::string::npos) << r.message;
  EXPECT_EQ(r.message.find("Options::repair"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("Options::allow_open"), std::string::npos) << r.message;
}

TEST(Plural, OneOfAThingIsSaidInTheSingular) {
  Mesh m = kergen_test::unit_cube();
  kergen_test::add_point(m, 5, 5, 5);  // used by no face
  const kergen::Kernel k = kergen::compute_kernel(m.view());
  ASSERT_TRUE(k.ok()) << k.message;
  const Warning* w = find_warning(k.warnings, Warning::Kind::UnusedVertices);
  ASSERT_NE(w, nullptr);
  EXPECT_EQ(w->message, "1 vertex is not used by any face");
  kergen_test::add_point(m, 6, 6, 6);
  const kergen::Kernel k2 = kergen::compute_kernel(m.view());
  const Warning* two = find_warning(k2.warnings, Warning::Kind::UnusedVertices);
  ASSERT_NE(two, nullptr);
  EXPECT_EQ(two->message, "2 vertices are not used by any face");
}

}  // namespace
