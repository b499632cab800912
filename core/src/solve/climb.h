// Hill climbing to the maximum of a linear function over the vertex graph of a convex polytope
// (shared by culling's violation test and the incremental cuts).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "exact/error_bounds.h"
#include "exact/expansion.h"

namespace kergen {

// Cube map of directions: cell = face * k^2 + i * k + j, face = 2 * axis + (component < 0), with
// k cells per face side. Climb starts are kept per cell: the extreme vertex in direction n is
// usually a few steps from the one of a nearby direction.
constexpr size_t kNoCell = size_t(-1);
inline size_t cube_cell(size_t cells_per_side, double x, double y, double z) {
  const double v[3] = {x, y, z};
  int axis = 0;
  for (int k = 1; k < 3; ++k)
    if (std::fabs(v[k]) > std::fabs(v[axis])) axis = k;
  const double m = std::fabs(v[axis]);
  if (!(m > 0) || !std::isfinite(m)) return kNoCell;
  auto bin = [&](double w) {
    double t = (w / m + 1) * 0.5 * double(cells_per_side);
    return std::min(cells_per_side - 1, size_t(std::max(0.0, t)));
  };
  const size_t face = 2 * size_t(axis) + (v[axis] < 0);
  return (face * cells_per_side + bin(v[(axis + 1) % 3])) * cells_per_side + bin(v[(axis + 2) % 3]);
}

// Where a normal falls on the cube map (cube_cell, with what culling's support bound needs):
// its cell, the first of the cell's corners, its coordinates (fi, fj) in the cell and
// m = max_k |n_k|; the cell is meaningless unless usable(m) (not a zero or non-finite normal).
// The same operations as cube_cell (the bins of t in [0, k] fit an int; integers below 2^53 are
// exact in double), so the same cells; written in doubles without branches to vectorize. For
// an unusable m, t is NaN (std::max makes it 0) or 0, so the corner is still in range.
struct CubePosition {
  int32_t cell, corner;
  double fi, fj, m;
};
inline bool usable(double m) { return m > 0 && m <= std::numeric_limits<double>::max(); }
inline CubePosition cube_position(int cells_per_side, double a, double b, double c) {
  const double x = std::fabs(a), y = std::fabs(b), z = std::fabs(c);
  const bool y_over_x = y > x;
  const double mxy = y_over_x ? y : x;
  const bool z_top = z > mxy;  // axis 2, else axis 1 if y_over_x, else axis 0
  const double m = z_top ? z : mxy;
  const double u = z_top ? a : (y_over_x ? c : b), v = z_top ? b : (y_over_x ? a : c);  // n[axis + 1], n[axis + 2]
  const double n_axis = z_top ? c : (y_over_x ? b : a);
  const double face = (z_top ? 4.0 : (y_over_x ? 2.0 : 0.0)) + (n_axis < 0 ? 1.0 : 0.0);
  const double k = double(cells_per_side);
  const double tu = (u / m + 1) * 0.5 * k, tv = (v / m + 1) * 0.5 * k;
  const double i = double(std::min(cells_per_side - 1, int(std::max(0.0, tu))));
  const double j = double(std::min(cells_per_side - 1, int(std::max(0.0, tv))));
  CubePosition p;
  p.cell = int32_t((face * k + i) * k + j);
  p.corner = int32_t((face * (k + 1) + i) * (k + 1) + j);
  p.fi = std::min(1.0, std::max(0.0, tu - i));
  p.fj = std::min(1.0, std::max(0.0, tv - j));
  p.m = m;
  return p;
}

struct ClimbScratch {
  std::vector<uint32_t> mark, bfs;
  uint32_t stamp = 0;
};

// From `cur` (value `val` = f(cur)), returns a vertex whose value `val` no vertex exceeds, for
// values exact up to rounding far below `tie`: greedy ascent, then, at a local maximum in double,
// a search of the plateau of vertices within `tie` of it (they induce a connected subgraph of a
// convex polytope's skeleton, so any higher vertex is reachable through them).
// f(v) gives the double value; neighbors(v, fn) calls fn(w) for each neighbour w of v; there are
// at most num_vertices vertex ids.
template <class Value, class Neighbors>
uint32_t climb_to_max(uint32_t cur, double& val, const Value& f, const Neighbors& neighbors, double tie,
                      size_t num_vertices, ClimbScratch& s) {
  for (;;) {
    bool moved = false;
    neighbors(cur, [&](uint32_t w) {
      const double fw = f(w);
      if (fw > val) {
        val = fw;
        cur = w;
        moved = true;
      }
    });
    if (moved) continue;
    if (s.mark.size() < num_vertices) s.mark.resize(num_vertices, 0);
    if (++s.stamp == 0) {
      s.mark.assign(s.mark.size(), 0);
      s.stamp = 1;
    }
    uint32_t higher = uint32_t(-1);
    s.bfs.assign(1, cur);
    s.mark[cur] = s.stamp;
    for (size_t qi = 0; qi < s.bfs.size() && higher == uint32_t(-1); ++qi) {
      neighbors(s.bfs[qi], [&](uint32_t w) {
        if (higher != uint32_t(-1) || s.mark[w] == s.stamp) return;
        s.mark[w] = s.stamp;
        const double fw = f(w);
        if (fw > val)
          higher = w;
        else if (fw >= val - tie)
          s.bfs.push_back(w);
      });
    }
    if (higher == uint32_t(-1)) return cur;
    cur = higher;
    val = f(cur);
  }
}

}  // namespace kergen
