// Kernel::face_sources, checked independently of how the library finds them: each kernel face's
// exact vertices (the traced ones, whose rounding is the result's vertices bit for bit) lie on the
// plane of the named input face, spanned by that face's own input corners, with the kernel on its
// inner side, and no input face of lower index lies on that oriented plane (exact orient3d and
// exact normals on the input's points); box and wall marks stand on box planes and boundary
// walls. On every shared mesh, analytic shapes (the README's L prism, a cube whose top is split
// into coplanar pieces, an open box clipped and walled) and the open fixtures.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "exact/predicates.h"
#include "exact/vertex.h"
#include "fixtures.h"
#include "kergen/io.h"
#include "kergen/kergen.h"
#include "open_surfaces.h"
#include "setup.h"

namespace {

namespace fs = std::filesystem;
using kergen::Expansion;
using kergen::KernelType;
using kergen::Mesh;
using kergen::Options;
using kergen::PlaneCoef;

// The input's faces as loops of input vertex ids.
struct Loops {
  std::vector<size_t> start;  // faces + 1
  std::vector<uint32_t> ids;
  size_t size(size_t f) const { return start[f + 1] - start[f]; }
  uint32_t at(size_t f, size_t i) const { return ids[start[f] + i]; }
  size_t num_faces() const { return start.size() - 1; }
};
Loops loops_of(const Mesh& m) {
  Loops l;
  l.ids = m.indices;
  l.start.push_back(0);
  for (size_t f = 0; f < m.num_faces(); ++f)
    l.start.push_back(l.start.back() + (m.face_sizes.empty() ? 3 : m.face_sizes[f]));
  return l;
}

// The kernel as compute_kernel traces it (its phases, setup.h), kept for its exact vertices, with
// exact plane tests on the input's points: their scaled copies in the plane set, checked to be the
// input's times a power of two.
class ExactKernel {
 public:
  ExactKernel(const Mesh& m, const Options& o, const kergen::Kernel& k) : loops_(loops_of(m)) {
    kergen::Stats stats;
    kergen::setup(m.view(), o, s_, stats);
    if (s_.mesh.error != kergen::Error::Ok || s_.lp.outcome != kergen::LpResult::Outcome::Optimal) return;
    ct_ = kergen::trace_kernel(s_, o);
    for (size_t v = 0; v < m.num_vertices(); ++v)
      for (int c = 0; c < 3; ++c)
        if (s_.mesh.to_input(s_.mesh.point(uint32_t(v))[c]) != m.positions[3 * v + c]) return;
    const auto& tv = ct_.trace.vertices;
    if (tv.size() != k.num_vertices()) return;
    // The result's vertex i is the trace's vertex traced_[i]: the same index when the result
    // was traced; else (a convex solid, answered without a trace) the one at the same point.
    std::map<std::array<double, 3>, uint32_t> at_point;
    traced_.resize(tv.size());
    for (uint32_t i = 0; i < tv.size(); ++i) {
      double hi[3], lo[3];
      kergen::precise_coordinates(*s_.planes, tv[i].geom, hi, lo);
      std::array<double, 3> x;
      for (int c = 0; c < 3; ++c) x[c] = std::ldexp(hi[c], -s_.mesh.scale_exp);
      if (!at_point.emplace(x, i).second) at_point[x] = kergen::kNoVertex;  // (ambiguous)
      traced_[i] = i;
    }
    for (size_t i = 0; i < tv.size(); ++i) {
      const std::array<double, 3> x{k.vertices[3 * i], k.vertices[3 * i + 1], k.vertices[3 * i + 2]};
      const auto it = at_point.find(x);
      if (it == at_point.end()) return;
      if (it->second != kergen::kNoVertex) traced_[i] = it->second;
    }
    if (std::set<uint32_t>(traced_.begin(), traced_.end()).size() != tv.size()) return;
    for (const kergen::Warning& w : s_.mesh.warnings) flipped_ |= w.kind == kergen::Warning::Kind::OrientationFlipped;
    ok_ = true;
  }
  bool ok() const { return ok_; }
  const kergen::Setup& setup() const { return s_; }
  const Loops& loops() const { return loops_; }
  size_t num_vertices() const { return ct_.trace.vertices.size(); }

  // The exact sign of oriented plane (a, b, c) of input points at kernel vertex v.
  int side(const std::array<uint32_t, 3>& t, size_t v) {
    auto [it, added] = plane_ids_.try_emplace(t, 0);
    if (added) it->second = s_.planes->add_from_points(t[0], t[1], t[2]);
    return kergen::side(*s_.planes, it->second, ct_.trace.vertices[traced_[v]].geom);
  }
  int side_of_plane(uint32_t plane, size_t v) const {
    return kergen::side(*s_.planes, plane, ct_.trace.vertices[traced_[v]].geom);
  }
  int orient(const std::array<uint32_t, 3>& t, uint32_t p) const {
    const auto& m = s_.mesh;
    return kergen::orient3d(m.point(t[0]), m.point(t[1]), m.point(t[2]), m.point(p), m.exact_shift);
  }
  PlaneCoef<Expansion> plane(const std::array<uint32_t, 3>& t) const {
    const auto& m = s_.mesh;
    return kergen::exact_plane(m.point(t[0]), m.point(t[1]), m.point(t[2]), m.exact_shift);
  }

  // The sum of input face f's fan triangles' exact normals (its area vector, times 2), with the
  // orientation validation gave the mesh.
  std::array<Expansion, 3> area_vector(size_t f) const {
    std::array<Expansion, 3> sum{Expansion(0.0), Expansion(0.0), Expansion(0.0)};
    for (size_t i = 1; i + 1 < loops_.size(f); ++i) {
      const PlaneCoef<Expansion> p = plane({loops_.at(f, 0), loops_.at(f, i), loops_.at(f, i + 1)});
      for (int c = 0; c < 3; ++c) sum[c] = sum[c] + p.n[c];
    }
    if (flipped_)
      for (auto& x : sum) x = -x;
    return sum;
  }
  bool planar(size_t f) const {
    const size_t n = loops_.size(f);
    for (size_t i = 1; i + 1 < n; ++i) {
      const std::array<uint32_t, 3> t{loops_.at(f, 0), loops_.at(f, i), loops_.at(f, i + 1)};
      if (kergen::collinear(s_.mesh.point(t[0]), s_.mesh.point(t[1]), s_.mesh.point(t[2]), s_.mesh.exact_shift))
        continue;
      for (size_t j = 1; j < n; ++j)
        if (orient(t, loops_.at(f, j)) != 0) return false;
      return true;
    }
    return true;  // (no area: such a face is dropped and never a source)
  }

  // The oriented planes input face f spans: a planar face its own (a non-collinear corner triple,
  // turned to the face's orientation); a non-planar one (split into triangles by the library)
  // every triple of its corners in loop order.
  std::vector<std::array<uint32_t, 3>> planes_of_face(size_t f) const {
    std::vector<std::array<uint32_t, 3>> out;
    const size_t n = loops_.size(f);
    const bool flat = planar(f);
    for (size_t i = 0; i < n; ++i)
      for (size_t j = i + 1; j < n; ++j)
        for (size_t k = j + 1; k < n; ++k) {
          std::array<uint32_t, 3> t{loops_.at(f, i), loops_.at(f, j), loops_.at(f, k)};
          const auto& m = s_.mesh;
          if (kergen::collinear(m.point(t[0]), m.point(t[1]), m.point(t[2]), m.exact_shift)) continue;
          if (flat) {
            if (dot(plane(t).n, area_vector(f)) < 0) std::swap(t[1], t[2]);
            return {t};
          }
          if (flipped_) std::swap(t[1], t[2]);
          out.push_back(t);
        }
    return out;
  }

  // Whether input face g lies on oriented plane t with the same inner side: a planar face with
  // all its corners on it and its area vector along t's normal; a non-planar one with a corner
  // triple in loop order on it, facing the same way (so that a triangle of its split could be).
  bool lies_on(size_t g, const std::array<uint32_t, 3>& t) const {
    if (orient(t, loops_.at(g, 0)) != 0) return false;  // (most faces: one filtered orient3d)
    const PlaneCoef<Expansion> pt = plane(t);
    if (planar(g)) {
      for (size_t i = 1; i < loops_.size(g); ++i)
        if (orient(t, loops_.at(g, i)) != 0) return false;
      return dot(pt.n, area_vector(g)) > 0;
    }
    for (const auto& u : planes_of_face(g)) {
      bool on = true;
      for (uint32_t p : u) on &= orient(t, p) == 0;
      if (on && dot(pt.n, plane(u).n) > 0) return true;
    }
    return false;
  }

  template <class A, class B>
  static int dot(const A& a, const B& b) {
    return (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]).sign();
  }

 private:
  Loops loops_;
  kergen::Setup s_;
  kergen::CulledTrace ct_;
  std::vector<uint32_t> traced_;
  std::map<std::array<uint32_t, 3>, uint32_t> plane_ids_;
  bool flipped_ = false;
  bool ok_ = false;
};

struct Counts {
  size_t faces = 0, box = 0, wall = 0;
};

// Checks every face source of kernel `k` of mesh `m` under options `o` (see the file's comment);
// returns what was checked.
Counts check_face_sources(const Mesh& m, const Options& o, const kergen::Kernel& k, const std::string& name) {
  Counts n;
  EXPECT_EQ(k.face_sources.size(), k.num_faces()) << name;
  if (k.num_faces() == 0 || k.face_sources.size() != k.num_faces()) return n;
  ExactKernel ek(m, o, k);
  EXPECT_TRUE(ek.ok()) << name << ": the traced kernel is not the result's, vertex for vertex";
  if (!ek.ok()) return n;
  const Loops& loops = ek.loops();
  const kergen::Setup& s = ek.setup();
  const bool polyhedron = k.type == KernelType::Polyhedron || k.type == KernelType::Unbounded;
  size_t at = 0;
  for (size_t face = 0; face < k.num_faces(); at += k.face_sizes[face], ++face) {
    const std::vector<uint32_t> corners(k.face_indices.begin() + long(at),
                                        k.face_indices.begin() + long(at + k.face_sizes[face]));
    const int32_t source = k.face_sources[face];
    // The kernel on the inner side of oriented plane `inside(v)`, the face's corners on it.
    auto bounds_face = [&](auto&& inside) {
      bool on = true, behind = true, strictly = false;
      for (uint32_t v : corners) on &= inside(v) == 0;
      for (size_t v = 0; v < ek.num_vertices(); ++v) {
        const int sd = inside(v);
        behind &= sd <= 0;
        strictly |= sd < 0;
      }
      return on && behind && (strictly || !polyhedron);
    };
    std::array<uint32_t, 3> plane{};  // the oriented plane the face lies on (input points), if found
    bool found = false;
    if (source >= 0) {
      ++n.faces;
      if (size_t(source) >= loops.num_faces()) {
        ADD_FAILURE() << name << ": face " << face << "'s source " << source << " is no input face";
        continue;
      }
      for (const auto& t : ek.planes_of_face(size_t(source))) {
        if (!bounds_face([&](size_t v) { return ek.side(t, v); })) continue;
        plane = t;
        found = true;
        break;
      }
      EXPECT_TRUE(found) << name << ": kernel face " << face << " does not lie on input face " << source
                         << "'s plane with the kernel behind it";
    } else if (source == kergen::kFaceSourceBox) {
      ++n.box;
      EXPECT_EQ(k.type, KernelType::Unbounded) << name << ": a box face in a bounded kernel";
      bool on_box = false;
      for (uint32_t b : s.box) on_box |= bounds_face([&](size_t v) { return ek.side_of_plane(b, v); });
      EXPECT_TRUE(on_box) << name << ": kernel face " << face << " is marked as a box face but lies on no box plane";
    } else if (source == kergen::kFaceSourceWall) {
      ++n.wall;
      EXPECT_EQ(o.open_boundary, kergen::OpenBoundary::Perpendicular) << name << ": a wall face without walls";
      for (size_t f = s.surface_faces; f < s.mesh.num_faces() && !found; ++f) {
        const std::array<uint32_t, 3>& t = s.mesh.rep[f];
        if (bounds_face([&](size_t v) { return ek.side(t, v); })) {
          plane = t;
          found = true;
        }
      }
      EXPECT_TRUE(found) << name << ": kernel face " << face << " is marked as a wall face but lies on no wall";
    } else {
      ADD_FAILURE() << name << ": face source " << source << " is neither a face index nor a mark";
    }
    // The lowest index: no input face before the source (before none: any face, for a wall) on
    // that oriented plane. (None for a box face: the box lies outside the mesh's bounding box.)
    if (!found) continue;
    const size_t below = source >= 0 ? size_t(source) : loops.num_faces();
    for (size_t g = 0; g < below; ++g)
      EXPECT_FALSE(ek.lies_on(g, plane)) << name << ": input face " << g << " lies on kernel face " << face
                                         << "'s plane, before its source " << source;
  }
  return n;
}

kergen::Kernel checked(const Mesh& m, const Options& o, const std::string& name, Counts* counts = nullptr) {
  const kergen::Kernel k = kergen::compute_kernel(m.view(), o);
  EXPECT_TRUE(k.ok()) << name << ": " << k.message;
  const Counts c = check_face_sources(m, o, k, name);
  if (counts) *counts = c;
  return k;
}

Options open_with(kergen::OpenBoundary b) {
  Options o;
  o.allow_open = b == kergen::OpenBoundary::Clip;
  o.open_boundary = b;
  return o;
}

// ---- analytic shapes ------------------------------------------------------------------------

// The axis-aligned plane a kernel face lies on, from its (exact, small) coordinates: axis and value,
// and its outer side (+1 or -1: where the kernel's vertex centroid is not).
struct AxisPlane {
  int axis = -1;
  double value = 0;
  int outward = 0;
  bool operator==(const AxisPlane& o) const { return axis == o.axis && value == o.value && outward == o.outward; }
  bool operator<(const AxisPlane& o) const {
    return std::tie(axis, value, outward) < std::tie(o.axis, o.value, o.outward);
  }
};
AxisPlane kernel_face_plane(const kergen::Kernel& k, size_t face) {
  size_t at = 0;
  for (size_t f = 0; f < face; ++f) at += k.face_sizes[f];
  double centroid[3] = {0, 0, 0};
  for (size_t v = 0; v < k.num_vertices(); ++v)
    for (int c = 0; c < 3; ++c) centroid[c] += k.vertices[3 * v + c] / double(k.num_vertices());
  for (int axis = 0; axis < 3; ++axis) {
    const double value = k.vertices[3 * size_t(k.face_indices[at]) + axis];
    bool all = true;
    for (size_t i = 1; i < k.face_sizes[face]; ++i)
      all &= k.vertices[3 * size_t(k.face_indices[at + i]) + axis] == value;
    if (all) return {axis, value, value > centroid[axis] ? 1 : -1};
  }
  return {};
}
// The same for input face f of an axis-aligned mesh (outward: its normal's sign, by the shoelace
// formula in the other two coordinates).
AxisPlane input_face_plane(const Mesh& m, size_t f) {
  const Loops l = loops_of(m);
  auto P = [&](size_t i, int c) { return m.positions[3 * size_t(l.at(f, i % l.size(f))) + c]; };
  for (int axis = 0; axis < 3; ++axis) {
    bool all = true;
    for (size_t i = 1; i < l.size(f); ++i) all &= P(i, axis) == P(0, axis);
    if (!all) continue;
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    double area = 0;
    for (size_t i = 0; i < l.size(f); ++i) area += P(i, u) * P(i + 1, v) - P(i + 1, u) * P(i, v);
    return {axis, P(0, axis), area > 0 ? 1 : -1};
  }
  return {};
}
// The expected source of each face of kernel k of axis-aligned mesh m: the lowest input face on
// the face's axis plane facing the same way, else `otherwise` (the box's or a wall's mark).
std::vector<int32_t> axis_sources(const Mesh& m, const kergen::Kernel& k, int32_t otherwise) {
  std::vector<int32_t> want;
  for (size_t face = 0; face < k.num_faces(); ++face) {
    const AxisPlane p = kernel_face_plane(k, face);
    int32_t source = otherwise;
    for (size_t f = 0; f < m.num_faces() && source == otherwise; ++f)
      if (input_face_plane(m, f) == p) source = int32_t(f);
    want.push_back(source);
  }
  return want;
}

// The README's L prism (examples/api_example.cpp): the kernel is the unit cube, bounded by the
// bottom (face 0), the top (1), the sides y = 0 (2) and x = 0 (7) and the L's inner walls y = 1
// facing +y (4) and x = 1 facing +x (5).
TEST(FaceSources, LPrism) {
  const double L[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  Mesh mesh;
  for (int z = 0; z <= 1; ++z)
    for (const auto& p : L) kergen_test::add_point(mesh, p[0], p[1], double(z));
  mesh.indices = {5, 4, 3, 2, 1, 0, 6, 7, 8, 9, 10, 11};
  mesh.face_sizes = {6, 6};
  for (uint32_t i = 0; i < 6; ++i) kergen_test::add_face(mesh, {i, (i + 1) % 6, 6 + (i + 1) % 6, 6 + i});
  const kergen::Kernel k = checked(mesh, {}, "L prism");
  ASSERT_EQ(k.type, KernelType::Polyhedron);
  const std::map<std::pair<int, int>, int32_t> by_plane = {{{2, -1}, 0}, {{2, 1}, 1}, {{1, -1}, 2},
                                                           {{1, 1}, 4},  {{0, 1}, 5}, {{0, -1}, 7}};
  ASSERT_EQ(k.face_sources.size(), 6u);
  for (size_t f = 0; f < 6; ++f) {
    const AxisPlane p = kernel_face_plane(k, f);
    EXPECT_EQ(k.face_sources[f], by_plane.at({p.axis, p.outward})) << "face " << f;
  }
  EXPECT_EQ(k.face_sources, axis_sources(mesh, k, -100));
  std::vector<int32_t> sorted = k.face_sources;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(sorted, (std::vector<int32_t>{0, 1, 2, 4, 5, 7}));
}

// A cube whose top is split into coplanar pieces listed among the other faces (and a copy of the
// bottom's plane split the same way): each kernel face names the lowest-indexed piece, also when
// the split pieces come first or last, and for the tessellated cube (each side 2 n^2 triangles).
TEST(FaceSources, LowestOfCoplanarPiecesWins) {
  Mesh m;
  for (int i = 0; i < 8; ++i) kergen_test::add_point(m, i & 1, (i >> 1) & 1, (i >> 2) & 1);
  const uint32_t centre_top = kergen_test::add_point(m, 0.5, 0.5, 1);
  // Sides as quads, bottom as one quad, the top as four triangles around its centre, interleaved.
  kergen_test::add_face(m, {0, 1, 5, 4});        // 0: y = 0
  kergen_test::add_face(m, {4, 5, centre_top});  // 1: top piece
  kergen_test::add_face(m, {1, 3, 7, 5});        // 2: x = 1
  kergen_test::add_face(m, {0, 2, 3, 1});        // 3: bottom
  kergen_test::add_face(m, {5, 7, centre_top});  // 4: top piece
  kergen_test::add_face(m, {3, 2, 6, 7});        // 5: y = 1
  kergen_test::add_face(m, {7, 6, centre_top});  // 6: top piece
  kergen_test::add_face(m, {2, 0, 4, 6});        // 7: x = 0
  kergen_test::add_face(m, {6, 4, centre_top});  // 8: top piece
  const kergen::Kernel k = checked(m, {}, "split top");
  ASSERT_EQ(k.type, KernelType::Polyhedron);
  EXPECT_EQ(k.face_sources, axis_sources(m, k, -100));
  for (size_t f = 0; f < k.num_faces(); ++f)
    if (kernel_face_plane(k, f) == AxisPlane{2, 1, 1}) EXPECT_EQ(k.face_sources[f], 1) << "the top's first piece";
  // The same faces in reverse order: the top's first piece is then face 0.
  Mesh reversed = m;
  reversed.indices.clear();
  reversed.face_sizes.clear();
  const Loops l = loops_of(m);
  for (size_t f = m.num_faces(); f-- > 0;) {
    std::vector<uint32_t> loop(l.ids.begin() + long(l.start[f]), l.ids.begin() + long(l.start[f + 1]));
    kergen_test::add_face(reversed, loop);
  }
  const kergen::Kernel r = checked(reversed, {}, "split top, reversed");
  EXPECT_EQ(r.face_sources, axis_sources(reversed, r, -100));
  for (size_t f = 0; f < r.num_faces(); ++f)
    if (kernel_face_plane(r, f) == AxisPlane{2, 1, 1}) EXPECT_EQ(r.face_sources[f], 0);
  for (int n : {1, 3, 24}) {  // (24: 6912 faces, face culling runs)
    const Mesh t = kergen_test::tessellated_cube(n);
    const kergen::Kernel kt = checked(t, {}, "tessellated cube " + std::to_string(n));
    EXPECT_EQ(kt.face_sources, axis_sources(t, kt, -100)) << n;
  }
}

// The open box (the unit cube without its top): clipped (allow_open), the kernel reaches up to the
// box above the hole, whose face alone is marked; walled, the four walls at the rim are the plane
// z = 1 (one plane, no input face on it), and the kernel is the unit cube with a wall face on top.
TEST(FaceSources, OpenBoxClippedAndWalled) {
  const Mesh m = kergen_test::open_cube();
  Counts c;
  const kergen::Kernel clip = checked(m, open_with(kergen::OpenBoundary::Clip), "open box, clip", &c);
  ASSERT_EQ(clip.type, KernelType::Unbounded);
  EXPECT_EQ(clip.face_sources, axis_sources(m, clip, kergen::kFaceSourceBox));
  EXPECT_EQ(c.box, 1u);
  EXPECT_EQ(c.faces, 5u);
  for (size_t f = 0; f < clip.num_faces(); ++f) {
    const AxisPlane p = kernel_face_plane(clip, f);
    EXPECT_EQ(clip.face_sources[f] == kergen::kFaceSourceBox, p.axis == 2 && p.outward == 1) << "face " << f;
  }
  const kergen::Kernel walled = checked(m, open_with(kergen::OpenBoundary::Perpendicular), "open box, walls", &c);
  ASSERT_EQ(walled.type, KernelType::Polyhedron);
  EXPECT_EQ(walled.face_sources, axis_sources(m, walled, kergen::kFaceSourceWall));
  EXPECT_EQ(c.wall, 1u);
  EXPECT_EQ(c.box, 0u);
  for (size_t f = 0; f < walled.num_faces(); ++f)
    if (walled.face_sources[f] == kergen::kFaceSourceWall)
      EXPECT_EQ(kernel_face_plane(walled, f), (AxisPlane{2, 1, 1}));
}

// A stopped run gives one source per face it reports, that of the same face of the whole kernel;
// an empty kernel has none.
TEST(FaceSources, OnePerFaceOfPartialAndEmptyKernels) {
  const Mesh m = kergen_test::tessellated_cube(4);
  for (uint64_t steps : {1, 5, 40, 60, 200}) {
    Options o;
    o.max_steps = steps;
    const kergen::Kernel k = kergen::compute_kernel(m.view(), o);
    ASSERT_TRUE(k.ok());
    EXPECT_EQ(k.face_sources.size(), k.num_faces()) << steps;
    // The partial kernel's faces are faces of the whole one, with the same sources.
    const kergen::Kernel whole = kergen::compute_kernel(m.view());
    std::map<AxisPlane, int32_t> by_plane;
    for (size_t f = 0; f < whole.num_faces(); ++f) by_plane[kernel_face_plane(whole, f)] = whole.face_sources[f];
    for (size_t f = 0; f < k.num_faces(); ++f) EXPECT_EQ(k.face_sources[f], by_plane.at(kernel_face_plane(k, f)));
  }
  const kergen::Kernel empty = kergen::compute_kernel(kergen_test::u_prism().view());
  ASSERT_EQ(empty.type, KernelType::Empty);
  EXPECT_TRUE(empty.face_sources.empty());
}

// The open fixtures, clipped and walled: every face is an input face's (checked exactly) or a
// mark, box marks only in Unbounded kernels and wall marks only with walls.
TEST(FaceSources, OpenFixtures) {
  const fs::path dir = fs::path(KERGEN_SHARED_MESHES) / "fixtures";
  if (!fs::exists(dir)) GTEST_SKIP() << "shared meshes not found at " << KERGEN_SHARED_MESHES;
  Counts total;
  for (const char* file : {"open_cube.off", "cube-ouvert.off", "mesh_with_border.off", "hedra_open.off", "plane.off"}) {
    const kergen::ReadResult r = kergen::read_mesh_file((dir / file).string());
    ASSERT_TRUE(r.ok()) << file << ": " << r.message;
    for (auto b : {kergen::OpenBoundary::Clip, kergen::OpenBoundary::Perpendicular}) {
      const std::string name = std::string(file) + ", " + kergen::open_boundary_name(b);
      Counts c;
      const kergen::Kernel k = checked(r.mesh, open_with(b), name, &c);
      std::printf("%-40s %-10s %zu faces: %zu input faces, %zu box, %zu wall\n", name.c_str(),
                  kergen::kernel_type_name(k.type), k.num_faces(), c.faces, c.box, c.wall);
      EXPECT_EQ(c.faces + c.box + c.wall, k.num_faces()) << name;
      if (k.type != KernelType::Unbounded) EXPECT_EQ(c.box, 0u) << name;
      total.faces += c.faces;
      total.box += c.box;
      total.wall += c.wall;
    }
  }
  EXPECT_GT(total.box, 0u);
  EXPECT_GT(total.wall, 0u);
}

// Every shared mesh (fixtures, princeton, refinements, the polyhedra sets): each face of every
// kernel, checked as above.
TEST(FaceSources, EverySharedMeshFaceLiesOnItsSource) {
  size_t meshes = 0, kernels = 0;
  Counts total;
  const bool found = kergen_test::for_each_shared_mesh([&](const fs::path& path, const Mesh& mesh) {
    const kergen::Kernel k = kergen::compute_kernel(mesh.view());
    if (!k.ok()) return;
    ++meshes;
    EXPECT_EQ(k.face_sources.size(), k.num_faces()) << path;
    if (k.num_faces() == 0) return;
    ++kernels;
    const Counts c = check_face_sources(mesh, {}, k, path.string());
    EXPECT_EQ(c.faces, k.num_faces()) << path << ": a closed mesh's kernel lies on input faces only";
    total.faces += c.faces;
  });
  if (!found) GTEST_SKIP() << "shared meshes not found at " << KERGEN_SHARED_MESHES;
  std::printf("%zu kernel faces of %zu kernels (%zu meshes) lie exactly on their source faces' planes\n", total.faces,
              kernels, meshes);
  EXPECT_GT(kernels, 3000u);
}

}  // namespace
