// Open surfaces (surfaces with a boundary) for the tests of Options::open_boundary, shared by the
// core tests and the CGAL oracle tests. Faces are counter-clockwise seen from their front; the
// kernel lies behind them.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

#include "fixtures.h"
#include "input/mesh_prep.h"  // (core/src: the walls as the library builds them)
#include "input/open_boundary.h"

namespace kergen_test {

// A bowl: the lower half of the unit sphere (nu cells around, nv rings from the south pole to the
// rim at z = 0), its faces facing away from the centre. With `lip` > 0 a vertical band of that
// height is inserted between the hemisphere (then centred at z = -lip) and the rim: the rim's faces
// are then exactly vertical, and their boundary walls exactly the plane z = 0. `lid` closes the
// rim with one polygon facing +z (the closed solid whose kernel the walled bowl should have).
inline Mesh bowl(int nu, int nv, double lip = 0, bool lid = false) {
  Mesh m;
  const double pi = 3.14159265358979323846;
  add_point(m, 0, 0, -1 - lip);
  for (int i = 1; i <= nv; ++i)
    for (int j = 0; j < nu; ++j) {
      const double th = (pi / 2) * i / nv - pi / 2, ph = 2 * pi * j / nu;
      add_point(m, std::cos(th) * std::cos(ph), std::cos(th) * std::sin(ph), std::sin(th) - lip);
    }
  int rings = nv;
  if (lip > 0) {  // the rim: the top ring's x and y, at z = 0
    const size_t top = 3 * (1 + size_t(nv - 1) * size_t(nu));
    for (int j = 0; j < nu; ++j) add_point(m, m.positions[top + 3 * j], m.positions[top + 3 * j + 1], 0);
    ++rings;
  }
  auto id = [&](int i, int j) { return uint32_t(1 + (i - 1) * nu + (j % nu)); };
  for (int j = 0; j < nu; ++j) add_face(m, {0, id(1, j + 1), id(1, j)});
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < nu; ++j) {
      add_face(m, {id(i, j), id(i, j + 1), id(i + 1, j + 1)});
      add_face(m, {id(i, j), id(i + 1, j + 1), id(i + 1, j)});
    }
  if (lid) {
    std::vector<uint32_t> loop;
    for (int j = 0; j < nu; ++j) loop.push_back(id(rings, j));
    add_face(m, loop);
  }
  return m;
}

// A height field z = height(x, y) over [-1, 1]^2 on an n x n grid, facing +z.
inline Mesh terrain(int n, const std::function<double(double, double)>& height) {
  Mesh m;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      const double x = -1 + 2.0 * i / n, y = -1 + 2.0 * j / n;
      add_point(m, x, y, height(x, y));
    }
  auto id = [&](int i, int j) { return uint32_t(i * (n + 1) + j); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      add_face(m, {id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      add_face(m, {id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

// A hill: concave, highest in the middle, a little bumpy.
inline Mesh hill(int n) {
  return terrain(n, [](double x, double y) {
    return 0.5 * (1 - 0.5 * (x * x + y * y)) + 0.02 * std::sin(3 * x) * std::cos(2 * y);
  });
}
// A valley: lowest in the middle.
inline Mesh valley(int n) {
  return terrain(n, [](double x, double y) { return 0.25 * (x * x + y * y); });
}

// A flat disc in z = 0 facing +z: a fan of n triangles around its centre.
inline Mesh disc(int n) {
  Mesh m;
  const double pi = 3.14159265358979323846;
  add_point(m, 0, 0, 0);
  for (int j = 0; j < n; ++j) add_point(m, std::cos(2 * pi * j / n), std::sin(2 * pi * j / n), 0);
  for (int j = 0; j < n; ++j) add_face(m, {0, uint32_t(1 + j), uint32_t(1 + (j + 1) % n)});
  return m;
}

// A flat square frustum, open at the top: the bottom [-3, 3]^2 at z = 0 (two triangles, faces 0
// and 1), the rim [-2, 2]^2 at z = 1 (vertices 4 to 7). Its faces' half-spaces hold the pyramid they lean
// into; the walls at the rim (perpendicular to the sides, leaning outward) hold only points below
// z = x - 1 and z = -x - 1 (so z <= -1) and the like in y: nothing above the bottom.
inline Mesh open_frustum() {
  Mesh m;
  for (double z : {0.0, 1.0}) {
    const double r = z == 0 ? 3 : 2;
    for (const auto& [x, y] : {std::pair{-r, -r}, {r, -r}, {r, r}, {-r, r}}) kergen_test::add_point(m, x, y, z);
  }
  kergen_test::add_face(m, {0, 2, 1});  // bottom, seen from below
  kergen_test::add_face(m, {0, 3, 2});
  for (uint32_t i = 0; i < 4; ++i) {  // sides: bottom edge i -> i+1, rim above it
    const uint32_t j = (i + 1) % 4;
    kergen_test::add_face(m, {i, j, 4 + j});
    kergen_test::add_face(m, {i, 4 + j, 4 + i});
  }
  return m;
}

// The walls the library adds to open mesh `m` (open_boundary.h), as triangles in the input's
// coordinates (exact: the prepared points are the input's times a power of two).
inline std::vector<std::array<std::array<double, 3>, 3>> boundary_walls(const Mesh& m) {
  kergen::Options o;
  o.allow_open = true;
  kergen::PreparedMesh p = kergen::prepare_mesh(m.view(), o);
  std::vector<std::array<std::array<double, 3>, 3>> walls;
  if (p.error != kergen::Error::Ok) return walls;
  const size_t faces = p.num_faces();
  const size_t added = kergen::add_boundary_walls(p, m.view());
  for (size_t f = faces; f < faces + added; ++f) {
    std::array<std::array<double, 3>, 3> t;
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) t[c][k] = p.to_input(p.point(p.rep[f][c])[k]);
    walls.push_back(t);
  }
  return walls;
}

}  // namespace kergen_test
