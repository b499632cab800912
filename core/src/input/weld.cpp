// Welding (see weld.h): a hash grid of cubic cells of the tolerance's size, so that vertices
// within the tolerance lie in the same or adjacent cells; union-find joins them.
#include "input/weld.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "util/flat_map.h"
#include "util/union_find.h"

namespace kergen {

namespace {

struct CellHash {
  uint64_t operator()(const std::array<int64_t, 3>& c) const {
    uint64_t h = 0x9e3779b97f4a7c15ull;
    for (int64_t x : c) h = (h ^ uint64_t(x)) * 0xff51afd7ed558ccdull;
    return h ^ (h >> 29);
  }
};

// The cell of a coordinate; exact equality (tolerance 0) uses the coordinates' bits instead.
int64_t cell_of(double x, double tolerance) {
  if (tolerance == 0) {
    int64_t bits;
    const double y = x == 0 ? 0.0 : x;  // -0 and +0 are one position
    static_assert(sizeof bits == sizeof y, "double is 64 bits");
    __builtin_memcpy(&bits, &y, sizeof bits);
    return bits;
  }
  const double c = std::floor(x / tolerance);
  // (Beyond 2^62 cells the grid folds: farther vertices share cells, which only costs tests.)
  return int64_t(std::max(-4.0e18, std::min(4.0e18, c)));
}

// The groups of vertices within `tolerance` of each other (transitively), by union-find.
void join_close_vertices(const MeshView& mesh, double tolerance, UnionFind& groups) {
  const size_t n = mesh.num_vertices;
  // Cells are within +-4e18 + 1, and with tolerance 0 a coordinate's bits with -0 made +0: INT64_MIN
  // (the bits of -0) is never one.
  FlatMap<std::array<int64_t, 3>, uint32_t, CellHash> head({INT64_MIN, INT64_MIN, INT64_MIN}, n);
  std::vector<uint32_t> next(n, UINT32_MAX);
  auto pos = [&](size_t v) { return mesh.positions + 3 * v; };
  const double t2 = tolerance * tolerance;
  for (uint32_t v = 0; v < n; ++v) {
    const double* p = pos(v);
    const std::array<int64_t, 3> cell = {cell_of(p[0], tolerance), cell_of(p[1], tolerance), cell_of(p[2], tolerance)};
    const int reach = tolerance == 0 ? 0 : 1;
    for (int dx = -reach; dx <= reach; ++dx)
      for (int dy = -reach; dy <= reach; ++dy)
        for (int dz = -reach; dz <= reach; ++dz) {
          const uint32_t* first = head.find({cell[0] + dx, cell[1] + dy, cell[2] + dz});
          if (!first) continue;
          for (uint32_t w = *first; w != UINT32_MAX; w = next[w]) {
            const double* q = pos(w);
            const double d[3] = {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
            const bool close =
                tolerance == 0 ? d[0] == 0 && d[1] == 0 && d[2] == 0 : d[0] * d[0] + d[1] * d[1] + d[2] * d[2] <= t2;
            if (close) groups.unite(v, w);
          }
        }
    auto [first, fresh] = head.try_emplace(cell, v);
    if (!fresh) {
      next[v] = *first;
      *first = v;
    }
  }
}

}  // namespace

WeldResult weld_vertices(const MeshView& mesh, double tolerance, bool relative) {
  WeldResult out;
  const size_t n = mesh.num_vertices;
  if (relative && n > 0) {
    double lo[3], hi[3];
    for (int k = 0; k < 3; ++k) lo[k] = hi[k] = mesh.positions[k];
    for (size_t v = 0; v < n; ++v)
      for (int k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], mesh.positions[3 * v + k]);
        hi[k] = std::max(hi[k], mesh.positions[3 * v + k]);
      }
    const double diagonal = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
    tolerance *= diagonal;
  }
  if (!(tolerance >= 0) || !std::isfinite(tolerance)) tolerance = 0;
  out.tolerance = tolerance;
  UnionFind groups(n);
  join_close_vertices(mesh, tolerance, groups);
  // Each group becomes its lowest-indexed vertex (union_find.h: the smaller id is the root).
  std::vector<uint32_t> root(n);
  for (uint32_t v = 0; v < n; ++v) {
    root[v] = groups.find(v);
    out.merged_vertices += root[v] != v;
  }
  out.mesh.positions.assign(mesh.positions, mesh.positions + 3 * n);
  const size_t faces = mesh.face_sizes ? mesh.num_faces : mesh.num_indices / 3;
  bool all_triangles = true;
  std::vector<uint32_t> loop;
  for (size_t f = 0, at = 0; f < faces; ++f) {
    const size_t size = mesh.face_sizes ? mesh.face_sizes[f] : 3;
    loop.clear();
    for (size_t i = 0; i < size; ++i) {
      const uint32_t v = root[mesh.indices[at + i]];
      if (loop.empty() || loop.back() != v) loop.push_back(v);
    }
    at += size;
    while (loop.size() > 1 && loop.back() == loop.front()) loop.pop_back();
    if (loop.size() < 3) {
      ++out.dropped_faces;
      continue;
    }
    all_triangles &= loop.size() == 3;
    out.mesh.indices.insert(out.mesh.indices.end(), loop.begin(), loop.end());
    out.mesh.face_sizes.push_back(uint32_t(loop.size()));
    out.source_face.push_back(uint32_t(f));
  }
  if (all_triangles) out.mesh.face_sizes.clear();
  return out;
}

}  // namespace kergen
