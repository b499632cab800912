// The canonical output order (kergen.h, before struct Kernel): the result arrays obey it, and they
// are the same, volume and area to the last bit, whatever order the computation found the kernel
// in: another LP seed, face culling off, the trace started towards another point, steps asked
// for (vertices then keep the events' numbering: the same vertex set, the same faces once
// renumbered, the same volume). On analytic shapes and on the shared meshes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "fixtures.h"
#include "kergen/kergen.h"

namespace {

using kergen::Kernel;
using kergen::Mesh;
using kergen::Options;

// Every property of the canonical order, checked on the arrays alone.
void expect_canonical(const Kernel& k, const std::string& name) {
  const size_t V = k.num_vertices();
  for (size_t i = 0; i + 1 < V; ++i) {
    const double* a = &k.vertices[3 * i];
    const double* b = &k.vertices[3 * i + 3];
    // (Equal rounded coordinates are allowed: distinct exact vertices may round alike.)
    EXPECT_FALSE(std::lexicographical_compare(b, b + 3, a, a + 3)) << name << ": vertex " << i;
  }
  for (double x : k.vertices) EXPECT_FALSE(x == 0 && std::signbit(x)) << name << ": a negative zero";
  for (size_t e = 0; e < k.num_edges(); ++e) {
    EXPECT_LT(k.edges[2 * e], k.edges[2 * e + 1]) << name << ": edge " << e;
    if (e > 0) {
      const std::array<uint32_t, 2> prev{k.edges[2 * e - 2], k.edges[2 * e - 1]},
          cur{k.edges[2 * e], k.edges[2 * e + 1]};
      EXPECT_LT(prev, cur) << name << ": edge " << e;
    }
  }
  std::vector<std::vector<uint32_t>> loops;
  size_t triangle = 0;
  for (size_t f = 0, at = 0; f < k.num_faces(); at += k.face_sizes[f++]) {
    const std::vector<uint32_t> loop(k.face_indices.begin() + at, k.face_indices.begin() + at + k.face_sizes[f]);
    EXPECT_EQ(loop[0], *std::min_element(loop.begin(), loop.end())) << name << ": face " << f;
    for (size_t i = 1; i + 1 < loop.size(); ++i, triangle += 3) {
      ASSERT_LT(triangle + 2, k.triangles.size()) << name;
      EXPECT_EQ(k.triangles[triangle], loop[0]) << name;
      EXPECT_EQ(k.triangles[triangle + 1], loop[i]) << name;
      EXPECT_EQ(k.triangles[triangle + 2], loop[i + 1]) << name;
    }
    loops.push_back(loop);
  }
  EXPECT_EQ(triangle, k.triangles.size()) << name;
  EXPECT_TRUE(std::is_sorted(loops.begin(), loops.end())) << name;
  EXPECT_EQ(k.face_sources.size(), k.num_faces()) << name;
}

// The result fields the order covers, bit for bit. The witness of an empty kernel is any minimal
// conflicting set, which one depending on the LP's constraint order (`same_lp_order` false: a
// different seed): then only its presence is compared.
void expect_same_result(const Kernel& a, const Kernel& b, const std::string& name, bool same_lp_order = true) {
  EXPECT_EQ(a.error, b.error) << name;
  EXPECT_EQ(a.type, b.type) << name;
  EXPECT_EQ(0, std::memcmp(&a.volume, &b.volume, sizeof(double))) << name << ": " << a.volume << " vs " << b.volume;
  EXPECT_EQ(0, std::memcmp(&a.area, &b.area, sizeof(double))) << name;
  EXPECT_EQ(a.vertices, b.vertices) << name;
  EXPECT_EQ(a.edges, b.edges) << name;
  EXPECT_EQ(a.face_indices, b.face_indices) << name;
  EXPECT_EQ(a.face_sizes, b.face_sizes) << name;
  EXPECT_EQ(a.triangles, b.triangles) << name;
  EXPECT_EQ(a.face_sources, b.face_sources) << name;
  if (same_lp_order)
    EXPECT_EQ(a.witness_faces, b.witness_faces) << name;
  else
    EXPECT_EQ(a.witness_faces.empty(), b.witness_faces.empty()) << name;
}

// The coordinates of each face's corners, face after face.
std::vector<double> face_corner_coordinates(const Kernel& k) {
  std::vector<double> out;
  for (uint32_t v : k.face_indices) out.insert(out.end(), &k.vertices[3 * v], &k.vertices[3 * v] + 3);
  return out;
}

// A run with steps against the canonical run: the same vertices as a set, the same faces (their
// corners' coordinates, in the same order), the same face sources, volume and area.
void expect_same_under_steps(const Mesh& mesh, const Kernel& canonical, const std::string& name) {
  Options o;
  size_t events = 0;
  o.on_step = [&](const kergen::StepEvent&) { return ++events, true; };
  const Kernel s = kergen::compute_kernel(mesh.view(), o);
  EXPECT_GT(events, 0u) << name;
  auto as_points = [](const Kernel& k) {
    std::vector<std::array<double, 3>> p(k.num_vertices());
    for (size_t i = 0; i < p.size(); ++i)
      p[i] = {k.vertices[3 * i] + 0.0, k.vertices[3 * i + 1] + 0.0, k.vertices[3 * i + 2] + 0.0};
    return p;
  };
  std::vector<std::array<double, 3>> stepped = as_points(s);
  std::sort(stepped.begin(), stepped.end());
  EXPECT_EQ(stepped, as_points(canonical)) << name;
  std::vector<double> corners = face_corner_coordinates(s);
  for (double& x : corners) x += 0.0;
  EXPECT_EQ(corners, face_corner_coordinates(canonical)) << name;
  EXPECT_EQ(s.face_sizes, canonical.face_sizes) << name;
  EXPECT_EQ(s.face_sources, canonical.face_sources) << name;
  EXPECT_EQ(0, std::memcmp(&s.volume, &canonical.volume, sizeof(double))) << name;
  EXPECT_EQ(0, std::memcmp(&s.area, &canonical.area, sizeof(double))) << name;
}

void check_mesh(const Mesh& mesh, const std::string& name) {
  const Kernel base = kergen::compute_kernel(mesh.view());
  ASSERT_TRUE(base.ok()) << name << ": " << base.message;
  if (base.type == kergen::KernelType::Empty) EXPECT_FALSE(base.witness_faces.empty()) << name;
  expect_canonical(base, name);
  Options seeded, unculled, towards;
  seeded.seed = 987654321;
  unculled.cull_faces = false;
  towards.has_from = true;
  towards.from = {mesh.positions[0], mesh.positions[1], mesh.positions[2]};
  expect_same_result(base, kergen::compute_kernel(mesh.view(), seeded), name + " (seed)", false);
  expect_same_result(base, kergen::compute_kernel(mesh.view(), unculled), name + " (no culling)");
  expect_same_result(base, kergen::compute_kernel(mesh.view(), towards), name + " (from)");
  if (base.num_vertices() > 0) expect_same_under_steps(mesh, base, name);
}

TEST(CanonicalOrder, AnalyticShapes) {
  using namespace kergen_test;
  check_mesh(l_prism(), "L prism");
  check_mesh(u_prism(), "U prism (empty)");
  check_mesh(dented_cube(), "dented cube");
  check_mesh(tessellated_cube(6), "tessellated cube");
  check_mesh(uv_sphere(24, 12, 0), "UV sphere");
  check_mesh(bumpy_sphere(32, 16), "bumpy sphere");
  check_mesh(pyramid(9), "pyramid");
  for (uint32_t seed = 1; seed <= 6; ++seed) check_mesh(random_convex(seed, 30).mesh, "random convex");
}

#ifdef KERGEN_SHARED_MESHES
// Every star-shaped shared fixture, Princeton and refinement mesh (the four polyhedra sets are
// covered by kernel_dump's comparisons; a sample of them here).
TEST(CanonicalOrder, SharedMeshes) {
  size_t checked = 0;
  const bool found = kergen_test::for_each_shared_mesh([&](const std::filesystem::path& path, const Mesh& mesh) {
    const std::string name = path.string();
    const bool polyhedra = name.find("polyhedra") != std::string::npos;
    if (polyhedra && (name.find("/1") == std::string::npos || name.size() > name.rfind('/') + 8)) return;
    if (mesh.face_sizes.size() > 40000) return;
    const Kernel k = kergen::compute_kernel(mesh.view());
    if (!k.ok()) return;
    check_mesh(mesh, name);
    ++checked;
  });
  if (!found) GTEST_SKIP() << "../shared/meshes not found";
  EXPECT_GT(checked, 50u);
}
#endif

}  // namespace
