// Small analytic fixture meshes shared by the core tests; every one has a kernel known in closed form.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "kergen/io.h"
#include "kergen/kergen.h"

namespace kergen_test {

using kergen::Mesh;

inline uint32_t add_point(Mesh& m, double x, double y, double z) {
  // Three push_backs: GCC 12 warns falsely (-Wstringop-overflow) on insert of an initializer list
  // once inlined into a test that starts from an empty vector.
  m.positions.push_back(x);
  m.positions.push_back(y);
  m.positions.push_back(z);
  return uint32_t(m.positions.size() / 3 - 1);
}
// Adds a polygon face (CCW seen from outside). A mesh stays triangles-only (face_sizes empty)
// until its first non-triangle face; from then on every face's size is recorded.
inline void add_face(Mesh& m, const std::vector<uint32_t>& loop) {
  bool polygons = !m.face_sizes.empty();
  if (!polygons && loop.size() != 3) {
    m.face_sizes.assign(m.indices.size() / 3, 3);
    polygons = true;
  }
  m.indices.insert(m.indices.end(), loop.begin(), loop.end());
  if (polygons) m.face_sizes.push_back(uint32_t(loop.size()));
}
inline void add_face(Mesh& m, std::initializer_list<uint32_t> loop) { add_face(m, std::vector<uint32_t>(loop)); }

// Axis-aligned box as 12 triangles.
inline Mesh box(double x0, double y0, double z0, double x1, double y1, double z1) {
  Mesh m;
  for (int i = 0; i < 8; ++i) add_point(m, i & 1 ? x1 : x0, i & 2 ? y1 : y0, i & 4 ? z1 : z0);
  const uint32_t q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : q) {
    add_face(m, {f[0], f[1], f[2]});
    add_face(m, {f[0], f[2], f[3]});
  }
  return m;
}
inline Mesh unit_cube() { return box(0, 0, 0, 1, 1, 1); }

inline Mesh transformed(Mesh m, double scale, double tx, double ty, double tz) {
  for (size_t i = 0; i < m.positions.size(); i += 3) {
    m.positions[i] = m.positions[i] * scale + tx;
    m.positions[i + 1] = m.positions[i + 1] * scale + ty;
    m.positions[i + 2] = m.positions[i + 2] * scale + tz;
  }
  return m;
}

// m turned by a fixed rotation about (0.3, 0.2, 0.1) (rows (0.36, 0.48, -0.8), (-0.8, 0.6, 0),
// (0.48, 0.64, 0.6)): the coordinates are rounded, so planar faces become planar only up to
// rounding, and the triangles of a tessellated face lie on distinct, nearly coplanar planes.
inline Mesh turned(Mesh m) {
  const double R[3][3] = {{0.36, 0.48, -0.8}, {-0.8, 0.6, 0}, {0.48, 0.64, 0.6}};
  for (size_t i = 0; i < m.positions.size(); i += 3) {
    const double p[3] = {m.positions[i] - 0.3, m.positions[i + 1] - 0.2, m.positions[i + 2] - 0.1};
    for (int r = 0; r < 3; ++r) m.positions[i + r] = R[r][0] * p[0] + R[r][1] * p[1] + R[r][2] * p[2];
  }
  return m;
}

inline Mesh flipped(Mesh m) {
  size_t off = 0;
  for (size_t f = 0; f < m.num_faces(); ++f) {
    size_t k = m.face_sizes.empty() ? 3 : m.face_sizes[f];
    std::reverse(m.indices.begin() + off, m.indices.begin() + off + k);
    off += k;
  }
  return m;
}

// Unit cube with every face split into n x n quads, two triangles each (shared vertices).
inline Mesh tessellated_cube(int n) {
  Mesh m;
  std::map<std::tuple<int, int, int>, uint32_t> ids;
  auto id = [&](int x, int y, int z) {
    auto key = std::make_tuple(x, y, z);
    auto it = ids.find(key);
    if (it != ids.end()) return it->second;
    uint32_t v = add_point(m, double(x) / n, double(y) / n, double(z) / n);
    ids[key] = v;
    return v;
  };
  // For each face: origin corner, two in-face axes (u, v) with u x v = outward normal.
  struct F {
    int o[3], u[3], v[3];
  };
  const F faces[6] = {{{n, 0, 0}, {0, 1, 0}, {0, 0, 1}}, {{0, 0, 0}, {0, 0, 1}, {0, 1, 0}},
                      {{0, n, 0}, {0, 0, 1}, {1, 0, 0}}, {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}},
                      {{0, 0, n}, {1, 0, 0}, {0, 1, 0}}, {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}}};
  for (const F& f : faces)
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        auto P = [&](int a, int b) {
          return id(f.o[0] + a * f.u[0] + b * f.v[0], f.o[1] + a * f.u[1] + b * f.v[1],
                    f.o[2] + a * f.u[2] + b * f.v[2]);
        };
        uint32_t a = P(i, j), b = P(i + 1, j), c = P(i + 1, j + 1), d = P(i, j + 1);
        add_face(m, {a, b, c});
        add_face(m, {a, c, d});
      }
  return m;
}

// Prism over a simple polygon given CCW in the xy plane, z in [0, h]; caps are single polygons,
// sides are quads (polygon faces exercise planar-polygon handling, also non-convex caps).
inline Mesh prism(const std::vector<std::array<double, 2>>& poly, double h = 1) {
  Mesh m;
  const uint32_t n = uint32_t(poly.size());
  for (const auto& p : poly) add_point(m, p[0], p[1], 0);
  for (const auto& p : poly) add_point(m, p[0], p[1], h);
  std::vector<uint32_t> bottom, top;
  for (uint32_t i = 0; i < n; ++i) {
    bottom.push_back(n - 1 - i);
    top.push_back(n + i);
  }
  m.indices.insert(m.indices.end(), bottom.begin(), bottom.end());
  m.face_sizes.push_back(n);
  add_face(m, top);
  for (uint32_t i = 0; i < n; ++i) {
    uint32_t j = (i + 1) % n;
    add_face(m, {i, j, n + j, n + i});
  }
  return m;
}

// L: kernel is the unit square corner [0,1]^2 x [0,1] (volume 1).
inline Mesh l_prism() { return prism({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}); }
// Plus with arm half-width w and arm reach 1: kernel is the central square, volume 4 w^2.
inline Mesh plus_prism(double w) {
  return prism(
      {{w, -w}, {1, -w}, {1, w}, {w, w}, {w, 1}, {-w, 1}, {-w, w}, {-1, w}, {-1, -w}, {-w, -w}, {-w, -1}, {w, -1}});
}
// S/Z: two bars meeting along y = 1: kernel is the rectangle {y = 1, 1 <= x <= 2} x [0, 1].
inline Mesh s_prism() { return prism({{1, 0}, {3, 0}, {3, 1}, {2, 1}, {2, 2}, {0, 2}, {0, 1}, {1, 1}}); }
// Pinwheel of four arms around the origin: kernel is the segment {(0,0)} x [0, 1].
inline Mesh pinwheel_prism() {
  return prism(
      {{2, 0}, {2, 1}, {0, 1}, {0, 2}, {-1, 2}, {-1, 0}, {-2, 0}, {-2, -1}, {0, -1}, {0, -2}, {1, -2}, {1, 0}});
}
// U: not star-shaped.
inline Mesh u_prism() { return prism({{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}}); }

// Unit cube whose top is a pyramidal dent to (0.5, 0.5, 0.6): kernel has 9 vertices, 9 faces,
// volume 1/3 (the part of the cube below all four dent planes).
inline Mesh dented_cube() {
  Mesh m;
  for (int i = 0; i < 8; ++i) add_point(m, i & 1 ? 1 : 0, i & 2 ? 1 : 0, i & 4 ? 1 : 0);
  uint32_t apex = add_point(m, 0.5, 0.5, 0.6);
  const uint32_t q[5][4] = {{0, 2, 3, 1}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : q) {
    add_face(m, {f[0], f[1], f[2]});
    add_face(m, {f[0], f[2], f[3]});
  }
  // Top ring 4 -> 5 -> 7 -> 6 (CCW from above); the dent faces point up-and-in.
  add_face(m, {4, 5, apex});
  add_face(m, {5, 7, apex});
  add_face(m, {7, 6, apex});
  add_face(m, {6, 4, apex});
  return m;
}

// Pyramid over a regular n-gon (convex: its kernel is itself, apex of degree n).
inline Mesh pyramid(int n, double radius = 1, double height = 1) {
  Mesh m;
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < n; ++i) add_point(m, radius * std::cos(2 * pi * i / n), radius * std::sin(2 * pi * i / n), 0);
  uint32_t apex = add_point(m, 0, 0, height);
  std::vector<uint32_t> base;
  for (int i = n - 1; i >= 0; --i) base.push_back(uint32_t(i));
  add_face(m, base);
  for (int i = 0; i < n; ++i) add_face(m, {uint32_t(i), uint32_t((i + 1) % n), apex});
  return m;
}

// Torus (genus 1): not star-shaped.
inline Mesh torus(int nu = 16, int nv = 8, double R = 2, double r = 0.5) {
  Mesh m;
  const double pi = 3.14159265358979323846;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      double u = 2 * pi * i / nu, v = 2 * pi * j / nv;
      add_point(m, (R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v));
    }
  auto id = [&](int i, int j) { return uint32_t((i % nu) * nv + (j % nv)); };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      add_face(m, {id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      add_face(m, {id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

// Random convex polyhedron: a bipyramid over a convex polygon (random angles on a random
// ellipse in z = 0) with apexes above and below random points near the centre. Every face is a
// triangle; the shape is convex, so its kernel is the shape itself (n + 2 vertices, 2n faces,
// volume = polygon area * (h_top + h_bottom) / 3).
struct RandomConvex {
  Mesh mesh;
  double volume;
  int n;
};
inline RandomConvex random_convex(uint32_t seed, int n = 12) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> U(0, 1);
  const double pi = 3.14159265358979323846;
  double a = 1 + U(rng), b = 0.5 + U(rng);
  RandomConvex r;
  r.n = n;
  Mesh& m = r.mesh;
  std::vector<double> ang;
  for (int i = 0; i < n; ++i) ang.push_back(2 * pi * (i + 0.15 + 0.7 * U(rng)) / n);
  for (double t : ang) add_point(m, a * std::cos(t), b * std::sin(t), 0);
  double h1 = 0.5 + U(rng), h2 = 0.5 + U(rng);
  // (One draw per statement: argument evaluation order is unspecified and differs between g++
  // and clang++, and the fuzzers, built with clang++, decode meshes from this fixture too.)
  const double tx = 0.2 * (U(rng) - 0.5), ty = 0.2 * (U(rng) - 0.5);
  const uint32_t top = add_point(m, tx, ty, h1);
  const double bx = 0.2 * (U(rng) - 0.5), by = 0.2 * (U(rng) - 0.5);
  const uint32_t bottom = add_point(m, bx, by, -h2);
  double area2 = 0;
  for (int i = 0; i < n; ++i) {
    uint32_t j = uint32_t((i + 1) % n);
    add_face(m, {uint32_t(i), j, top});
    add_face(m, {j, uint32_t(i), bottom});
    const double* p = &m.positions[3 * size_t(i)];
    const double* q = &m.positions[3 * size_t(j)];
    area2 += p[0] * q[1] - p[1] * q[0];
  }
  r.volume = 0.5 * area2 * (h1 + h2) / 3;
  return r;
}

// Unit cube without its top: open.
inline Mesh open_cube() {
  Mesh c = unit_cube();
  Mesh m;
  m.positions = c.positions;
  for (size_t t = 0; t < c.indices.size(); t += 3) {
    bool top = true;
    for (int k = 0; k < 3; ++k) top &= c.positions[3 * c.indices[t + k] + 2] == 1;
    if (!top) m.indices.insert(m.indices.end(), c.indices.begin() + t, c.indices.begin() + t + 3);
  }
  return m;
}

// The box [0,2]x[0,1]x[0,1] whose bottom is two unit squares: their shared corners (1,0,0) and
// (1,1,0) lie inside the bottom edges of the front and back faces, which are single quads
// (T-junctions: open without Options::repair; the bad-input table's mesh_t_junction).
inline Mesh t_junction_box() {
  Mesh m;
  m.positions = {0, 0, 0, 2, 0, 0, 2, 1, 0, 0, 1, 0, 0, 0, 1, 2, 0, 1, 2, 1, 1, 0, 1, 1, 1, 0, 0, 1, 1, 0};
  // 0..7 the box's corners, 8 = (1,0,0), 9 = (1,1,0)
  m.indices = {0, 3, 9, 8, 8, 9, 2, 1,  // bottom: two squares, seen from below
               4, 5, 6, 7,              // top
               0, 1, 5, 4,              // front (y = 0): one quad over the split edge 0-8-1
               2, 3, 7, 6,              // back (y = 1): over 2-9-3
               1, 2, 6, 5, 3, 0, 4, 7};
  m.face_sizes = {4, 4, 4, 4, 4, 4, 4};
  return m;
}

// Two unit cubes sharing only the edge x = 1, y = 1 (same vertex ids): non-manifold.
inline Mesh cubes_sharing_edge() {
  Mesh a = unit_cube();
  Mesh b = box(1, 1, 0, 2, 2, 1);
  // b's vertices 0 (1,1,0) and 4 (1,1,1) are a's vertices 3 and 7.
  const uint32_t remap_shared[8] = {3, 0, 0, 0, 7, 0, 0, 0};
  std::vector<uint32_t> remap(8);
  for (uint32_t i = 0; i < 8; ++i) {
    if (i == 0 || i == 4)
      remap[i] = remap_shared[i];
    else
      remap[i] = add_point(a, b.positions[3 * i], b.positions[3 * i + 1], b.positions[3 * i + 2]);
  }
  for (uint32_t v : b.indices) a.indices.push_back(remap[v]);
  return a;
}

// UV sphere (convex: the kernel is the shape) with nu x nv cells, quads split into triangles;
// `twist` turns ring i by twist * i radians, so each quad's two triangles are almost coplanar
// and the kernel has tiny features (vertices ~1e-16 apart).
inline Mesh uv_sphere(int nu, int nv, double twist) {
  Mesh m;
  const double pi = 3.14159265358979323846;
  m.positions = {0, 0, -1};
  for (int i = 1; i < nv; ++i)
    for (int j = 0; j < nu; ++j) {
      double th = pi * i / nv - pi / 2, ph = 2 * pi * j / nu + twist * i;
      m.positions.insert(m.positions.end(), {std::cos(th) * std::cos(ph), std::cos(th) * std::sin(ph), std::sin(th)});
    }
  m.positions.insert(m.positions.end(), {0, 0, 1});
  auto id = [&](int i, int j) { return uint32_t(1 + (i - 1) * nu + (j % nu)); };
  const uint32_t top = uint32_t(m.positions.size() / 3 - 1);
  for (int j = 0; j < nu; ++j) m.indices.insert(m.indices.end(), {0, id(1, j + 1), id(1, j)});
  for (int i = 1; i < nv - 1; ++i)
    for (int j = 0; j < nu; ++j) {
      m.indices.insert(m.indices.end(), {id(i, j), id(i, j + 1), id(i + 1, j + 1)});
      m.indices.insert(m.indices.end(), {id(i, j), id(i + 1, j + 1), id(i + 1, j)});
    }
  for (int j = 0; j < nu; ++j) m.indices.insert(m.indices.end(), {top, id(nv - 1, j), id(nv - 1, j + 1)});
  return m;
}

// The UV sphere's grid (uv_sphere(nu, nv, 0): the same faces) with each point at radius
// radius(t, ph) along its direction, t the angle from the top pole (0 to pi), ph the longitude.
template <class Radius>
inline Mesh uv_sphere_shaped(int nu, int nv, Radius radius) {
  Mesh m = uv_sphere(nu, nv, 0);
  const double pi = 3.14159265358979323846;
  auto place = [&](size_t v, double t, double ph) {
    const double r = radius(t, ph);
    for (int k = 0; k < 3; ++k) m.positions[3 * v + k] *= r;
  };
  place(0, pi, 0);
  for (int i = 1; i < nv; ++i)
    for (int j = 0; j < nu; ++j) place(size_t(1 + (i - 1) * nu + j), pi - pi * i / nv, 2 * pi * j / nu);
  place(m.positions.size() / 3 - 1, 0, 0);
  return m;
}

// The UV sphere with a dimple at its top pole: within t0 = 0.6 rad of it the radius drops to
// 1 - 0.3 (1 - t / t0)^2 (0.7 at the pole, smooth at the rim). Not convex: the dimple's faces
// cut the sphere, and the kernel is the sphere below them.
inline Mesh dimpled_sphere(int nu, int nv) {
  return uv_sphere_shaped(nu, nv, [](double t, double) {
    const double t0 = 0.6, s = t < t0 ? 1 - t / t0 : 0;
    return 1 - 0.3 * s * s;
  });
}

// The UV sphere with bumps all over: r = 1 + 0.05 sin(5 t) cos(7 ph). Star-shaped about the
// centre, with a small kernel (most faces cannot touch it).
inline Mesh wavy_sphere(int nu, int nv) {
  return uv_sphere_shaped(nu, nv, [](double t, double ph) { return 1 + 0.05 * std::sin(5 * t) * std::cos(7 * ph); });
}

// Bumpy UV sphere r(theta, phi) = 1 + amp sin(3 theta) cos(2 phi) with nu x nv cells (as
// scripts/gen-big-mesh.mjs): 2 nu (nv - 1) triangles, star-shaped around the origin for small
// amp, with a kernel much smaller than the shape (most faces cannot touch it).
inline Mesh bumpy_sphere(int nu, int nv, double amp = 0.2) {
  Mesh m;
  const double pi = 3.14159265358979323846;
  m.positions = {0, 0, 1, 0, 0, -1};
  for (int j = 1; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const double th = pi * j / nv, ph = 2 * pi * i / nu, r = 1 + amp * std::sin(3 * th) * std::cos(2 * ph);
      m.positions.insert(m.positions.end(),
                         {r * std::sin(th) * std::cos(ph), r * std::sin(th) * std::sin(ph), r * std::cos(th)});
    }
  auto id = [&](int j, int i) { return uint32_t(2 + (j - 1) * nu + (i % nu)); };
  for (int i = 0; i < nu; ++i) {
    m.indices.insert(m.indices.end(), {0, id(1, i), id(1, i + 1)});
    m.indices.insert(m.indices.end(), {1, id(nv - 1, i + 1), id(nv - 1, i)});
  }
  for (int j = 1; j < nv - 1; ++j)
    for (int i = 0; i < nu; ++i) {
      m.indices.insert(m.indices.end(), {id(j, i), id(j + 1, i), id(j + 1, i + 1)});
      m.indices.insert(m.indices.end(), {id(j, i), id(j + 1, i + 1), id(j, i + 1)});
    }
  return m;
}

// Geodesic sphere: each face of an icosahedron cut into n^2 triangles, the points pushed onto
// the unit sphere; 20 n^2 faces, 10 n^2 + 2 vertices. Strictly convex (no four points coplanar
// in practice), so its kernel is the shape, face for face. `volume` is the mesh's own (the sum of
// the tetrahedra from the origin).
struct GeodesicSphere {
  Mesh mesh;
  double volume = 0;
};
inline GeodesicSphere geodesic_sphere(int n) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  const double ico[12][3] = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                             {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  const int faces[20][3] = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                            {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                            {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  GeodesicSphere g;
  // A point is named by its integer weights on the icosahedron's corners, so points on shared
  // edges are made once.
  std::map<std::vector<std::pair<int, int>>, uint32_t> ids;
  auto point = [&](const int* f, int i, int j) {
    const int w[3] = {n - i - j, i, j};
    std::vector<std::pair<int, int>> key;
    double p[3] = {0, 0, 0};
    for (int c = 0; c < 3; ++c) {
      if (w[c]) key.push_back({f[c], w[c]});
      for (int k = 0; k < 3; ++k) p[k] += w[c] * ico[f[c]][k];
    }
    std::sort(key.begin(), key.end());
    auto it = ids.find(key);
    if (it != ids.end()) return it->second;
    const double len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    const uint32_t id = add_point(g.mesh, p[0] / len, p[1] / len, p[2] / len);
    ids[key] = id;
    return id;
  };
  for (const auto& f : faces)
    for (int i = 0; i < n; ++i)
      for (int j = 0; i + j < n; ++j) {
        add_face(g.mesh, {point(f, i, j), point(f, i + 1, j), point(f, i, j + 1)});
        if (i + j + 1 < n) add_face(g.mesh, {point(f, i + 1, j), point(f, i + 1, j + 1), point(f, i, j + 1)});
      }
  const auto& P = g.mesh.positions;
  for (size_t k = 0; k < g.mesh.indices.size(); k += 3) {
    const double* a = &P[3 * size_t(g.mesh.indices[k])];
    const double* b = &P[3 * size_t(g.mesh.indices[k + 1])];
    const double* c = &P[3 * size_t(g.mesh.indices[k + 2])];
    g.volume +=
        (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])) /
        6;
  }
  return g;
}

// A bipyramid over a polygon of n corners that winds `turns` times around the z axis: for odd n
// and turns = 2 every face is still seen from inside at the origin, and the surface is a double
// cover of the sphere around it. `open`: without the first top face (an open surface).
inline Mesh wound_bipyramid(int n, int turns, bool open = false) {
  Mesh m;
  m.positions = {0, 0, 1, 0, 0, -1};
  for (int i = 0; i < n; ++i) {
    const double a = 2 * M_PI * turns * i / n;
    m.positions.insert(m.positions.end(), {std::cos(a), std::sin(a), 0.0});
  }
  for (uint32_t i = 0; i < uint32_t(n); ++i) {
    const uint32_t v = 2 + i, w = 2 + (i + 1) % n;
    if (!(open && i == 0)) m.indices.insert(m.indices.end(), {0, v, w});
    m.indices.insert(m.indices.end(), {1, w, v});
  }
  return m;
}

#ifdef KERGEN_SHARED_MESHES
// Calls fn(path, mesh) for every readable mesh file of the shared sets that the whole-set tests
// sweep (fixtures, princeton, refinements, the four polyhedra sets); false when the shared
// meshes are not there (the caller skips).
template <class Fn>
bool for_each_shared_mesh(Fn&& fn) {
  namespace fs = std::filesystem;
  const fs::path root = KERGEN_SHARED_MESHES;
  if (!fs::exists(root)) return false;
  for (const char* dir : {"fixtures", "princeton", "refinements", "polyhedra/tet10", "polyhedra/tet20",
                          "polyhedra/tet30", "polyhedra/voro"}) {
    if (!fs::exists(root / dir)) continue;
    for (const auto& entry : fs::directory_iterator(root / dir)) {
      if (kergen::format_from_path(entry.path().string()) == kergen::MeshFormat::Unknown) continue;
      const kergen::ReadResult r = kergen::read_mesh_file(entry.path().string());
      if (r.ok()) fn(entry.path(), r.mesh);
    }
  }
  return true;
}
#endif

}  // namespace kergen_test
