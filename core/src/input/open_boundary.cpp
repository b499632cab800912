// Boundary walls (open_boundary.h): boundary edges found on the validated mesh, walls built on
// the prepared faces that hold them.
#include "input/open_boundary.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "exact/plane_store.h"

namespace kergen {

namespace {

uint64_t edge_key(uint32_t u, uint32_t v) { return uint64_t(std::min(u, v)) << 32 | std::max(u, v); }

// Edges used by exactly one face of `mesh` (as undirected keys, sorted). Validation has accepted
// the mesh, so no edge has more than two uses; an edge from a vertex to itself is none.
std::vector<uint64_t> boundary_edge_keys(const MeshView& mesh) {
  std::vector<uint64_t> keys;
  keys.reserve(mesh.num_indices);
  const size_t faces = mesh.face_sizes ? mesh.num_faces : mesh.num_indices / 3;
  size_t at = 0;
  for (size_t f = 0; f < faces; ++f) {
    const size_t k = mesh.face_sizes ? mesh.face_sizes[f] : 3;
    for (size_t i = 0; i < k; ++i) {
      const uint32_t u = mesh.indices[at + i], v = mesh.indices[at + (i + 1) % k];
      if (u != v) keys.push_back(edge_key(u, v));
    }
    at += k;
  }
  std::sort(keys.begin(), keys.end());
  std::vector<uint64_t> once;
  for (size_t i = 0; i < keys.size();) {
    size_t j = i + 1;
    while (j < keys.size() && keys[j] == keys[i]) ++j;
    if (j == i + 1) once.push_back(keys[i]);
    i = j;
  }
  return once;
}

// The outward normal of prepared face f, exact then rounded, scaled by a power of two to a
// largest component in [1/32, 1/16) and rounded to multiples of 2^-60: added to a point (below 1
// in magnitude) it gives a point below 1 + 1/16 whose lowest set bit is no lower than the point's
// or 2^-60 (so PreparedMesh::exact_shift still holds for it). False for a zero normal.
bool wall_direction(const PreparedMesh& m, uint32_t f, double n[3]) {
  const std::array<uint32_t, 3>& r = m.rep[f];
  const PlaneCoef<Expansion> plane = exact_plane(m.point(r[0]), m.point(r[1]), m.point(r[2]), m.exact_shift);
  double largest = 0;
  for (int k = 0; k < 3; ++k) {
    n[k] = plane.n[k].estimate();
    largest = std::max(largest, std::fabs(n[k]));
  }
  if (!(largest > 0) || !std::isfinite(largest)) return false;
  int e = 0;
  std::frexp(largest, &e);  // largest in [2^(e-1), 2^e)
  for (int k = 0; k < 3; ++k) n[k] = std::ldexp(std::nearbyint(std::ldexp(n[k], 60 - e - 4)), -60);
  return true;
}

}  // namespace

size_t add_boundary_walls(PreparedMesh& m, const MeshView& validated) {
  const std::vector<uint64_t> boundary = boundary_edge_keys(validated);
  if (boundary.empty()) return 0;
  std::vector<char> walled(boundary.size(), 0);
  const size_t faces = m.num_faces();
  size_t added = 0;
  for (uint32_t f = 0; f < faces; ++f) {
    const uint32_t begin = m.loop_offsets[f], end = m.loop_offsets[f + 1];
    for (uint32_t i = begin; i < end; ++i) {
      const uint32_t a = m.loops[i], b = m.loops[i + 1 < end ? i + 1 : begin];
      const auto it = std::lower_bound(boundary.begin(), boundary.end(), edge_key(a, b));
      if (it == boundary.end() || *it != edge_key(a, b) || walled[size_t(it - boundary.begin())]) continue;
      walled[size_t(it - boundary.begin())] = 1;
      double n[3];
      if (!wall_direction(m, f, n)) continue;
      const uint32_t c = uint32_t(m.points.size() / 3);
      const double third[3] = {m.point(a)[0] + n[0], m.point(a)[1] + n[1], m.point(a)[2] + n[2]};
      m.points.insert(m.points.end(), third, third + 3);  // (may move the points: read first)
      // (a, b, c) is never collinear: c - a is within 2e-14 radians of the face's normal, which
      // is perpendicular to b - a.
      m.loops.push_back(a);
      m.loops.push_back(b);
      m.loops.push_back(c);
      m.loop_offsets.push_back(uint32_t(m.loops.size()));
      m.rep.push_back({a, b, c});
      ++added;
    }
  }
  return added;
}

}  // namespace kergen
