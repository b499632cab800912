// The volume of an open surface closed over its holes (open_orientation.h). Each hole is one
// loop of boundary edges (a vertex of a boundary loop that touches the boundary twice joins the
// loops through it into one cap: still a closed surface). A cap is the fan from its loop's
// centroid over the loop's edges taken backwards, so that it continues the surface's
// orientation; the volume is the sum of the signed tetrahedra of the faces (fanned from their
// first corner) and of the caps, about the centre of the bounding box.
#include "input/open_orientation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <unordered_map>
#include <vector>

#include "util/plural.h"
#include "util/union_find.h"

namespace kergen {

namespace {

// 6 times the signed volume of the tetrahedron (o, a, b, c).
double vol6(const double* o, const double* a, const double* b, const double* c) {
  const double u[3] = {a[0] - o[0], a[1] - o[1], a[2] - o[2]};
  const double v[3] = {b[0] - o[0], b[1] - o[1], b[2] - o[2]};
  const double w[3] = {c[0] - o[0], c[1] - o[1], c[2] - o[2]};
  return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
}

}  // namespace

CappedVolume capped_volume(const MeshView& mesh) {
  CappedVolume out;
  const size_t nv = mesh.num_vertices;
  const size_t nf = mesh.face_sizes ? mesh.num_faces : mesh.num_indices / 3;
  if (nv == 0 || nf == 0) return out;
  const double* p = mesh.positions;
  double lo[3] = {p[0], p[1], p[2]}, hi[3] = {p[0], p[1], p[2]};
  for (size_t v = 0; v < nv; ++v)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[3 * v + k]);
      hi[k] = std::max(hi[k], p[3 * v + k]);
    }
  const double centre[3] = {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2])};
  auto at = [&](uint32_t v) { return p + 3 * size_t(v); };

  // The faces' volume terms, and each undirected edge's uses (the last one's direction kept).
  double sum = 0, sum_abs = 0;
  std::unordered_map<uint64_t, std::array<uint32_t, 3>> uses;  // key -> {count, from, to}
  uses.reserve(2 * mesh.num_indices);
  size_t begin = 0;
  for (size_t f = 0; f < nf; ++f) {
    const size_t size = mesh.face_sizes ? mesh.face_sizes[f] : 3;
    const uint32_t* loop = mesh.indices + begin;
    for (size_t i = 1; i + 1 < size; ++i) {
      const double d = vol6(centre, at(loop[0]), at(loop[i]), at(loop[i + 1]));
      sum += d;
      sum_abs += std::fabs(d);
    }
    for (size_t i = 0; i < size; ++i) {
      const uint32_t a = loop[i], b = loop[(i + 1) % size];
      auto& u = uses[a < b ? uint64_t(a) << 32 | b : uint64_t(b) << 32 | a];
      u = {u[0] + 1, a, b};
    }
    begin += size;
  }

  // The boundary edges, grouped into holes through their shared vertices; each hole's centroid.
  std::vector<std::array<uint32_t, 2>> boundary;
  for (const auto& [key, u] : uses)
    if (u[0] == 1) boundary.push_back({u[1], u[2]});
  if (boundary.empty()) return out;
  std::sort(boundary.begin(), boundary.end());  // (a fixed order: the sum does not depend on the hash)
  UnionFind holes(nv);
  for (const auto& e : boundary) holes.unite(holes.find(e[0]), holes.find(e[1]));
  std::unordered_map<uint32_t, std::array<double, 4>> centroid;  // hole root -> {sum xyz, count}
  for (const auto& e : boundary) {
    auto& c = centroid[holes.find(e[0])];
    for (int k = 0; k < 3; ++k) c[k] += at(e[0])[k];
    c[3] += 1;
  }
  for (auto& [root, c] : centroid)
    for (int k = 0; k < 3; ++k) c[k] /= c[3];
  for (const auto& e : boundary) {
    const auto& c = centroid[holes.find(e[0])];
    const double d = vol6(centre, c.data(), at(e[1]), at(e[0]));
    sum += d;
    sum_abs += std::fabs(d);
  }
  out.holes = centroid.size();
  out.volume = sum / 6;
  out.inward = sum < -1e-9 * sum_abs;
  return out;
}

std::string faces_point_inward_message(const CappedVolume& c) {
  char volume[32];
  std::snprintf(volume, sizeof volume, "%.6g", c.volume);
  return std::string("its faces point inward (closed over its ") + verb_for(c.holes, "hole", "holes") +
         ", it encloses a volume of " + volume +
         "): an open surface is taken as oriented, never flipped; Options::flip_faces turns every face over";
}

}  // namespace kergen
