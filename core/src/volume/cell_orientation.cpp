// cell_orientation.cpp — consistent outward orientation of one cell's faces (cell_orientation.h).
#include "volume/cell_orientation.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace kergen::volume {

namespace {

struct EdgeUse {
  uint64_t key;  // (low << 32) | high vertex id
  uint32_t face;
  bool forward;  // the face runs from low to high
  bool operator<(const EdgeUse& o) const { return key < o.key || (key == o.key && face < o.face); }
};

// Face f's flip relative to its neighbour across each edge used by exactly two faces: `flip` set
// when the two traverse the edge in the same direction (one of them must be reversed).
struct Link {
  uint32_t other;
  bool flip;
};

// Links of each face, flat: links[link_start[f] .. link_start[f + 1]).
void collect_links(const Mesh& cell, const std::vector<uint32_t>& starts, std::vector<Link>& links,
                   std::vector<uint32_t>& link_start) {
  std::vector<EdgeUse> uses;
  uses.reserve(cell.indices.size());
  for (uint32_t f = 0; f < cell.face_sizes.size(); ++f) {
    const uint32_t n = cell.face_sizes[f], s = starts[f];
    for (uint32_t i = 0; i < n; ++i) {
      const uint32_t a = cell.indices[s + i], b = cell.indices[s + (i + 1) % n];
      if (a == b) continue;
      const uint32_t lo = std::min(a, b), hi = std::max(a, b);
      uses.push_back({uint64_t(lo) << 32 | hi, f, a < b});
    }
  }
  std::sort(uses.begin(), uses.end());
  struct Pair {
    uint32_t a, b;
    bool flip;
  };
  std::vector<Pair> pairs;
  pairs.reserve(uses.size() / 2);
  for (size_t i = 0; i < uses.size();) {
    size_t j = i;
    while (j < uses.size() && uses[j].key == uses[i].key) ++j;
    if (j - i == 2 && uses[i].face != uses[i + 1].face)
      pairs.push_back({uses[i].face, uses[i + 1].face, uses[i].forward == uses[i + 1].forward});
    i = j;
  }
  const size_t faces = cell.face_sizes.size();
  link_start.assign(faces + 1, 0);
  for (const Pair& p : pairs) ++link_start[p.a + 1], ++link_start[p.b + 1];
  for (size_t f = 0; f < faces; ++f) link_start[f + 1] += link_start[f];
  links.resize(2 * pairs.size());
  std::vector<uint32_t> fill(link_start.begin(), link_start.end() - 1);
  for (const Pair& p : pairs) {
    links[fill[p.a]++] = {p.b, p.flip};
    links[fill[p.b]++] = {p.a, p.flip};
  }
}

void reverse_face(Mesh& cell, uint32_t start, uint32_t size) {
  std::reverse(cell.indices.begin() + start, cell.indices.begin() + start + size);
}

// Six times the signed volume, fan triangles from each face's first corner, relative to the
// cell's first vertex (small numbers for a cell far from the origin).
double six_volume(const Mesh& cell, const std::vector<uint32_t>& starts) {
  if (cell.positions.empty()) return 0;
  const double* o = cell.positions.data();
  double sum = 0;
  for (size_t f = 0; f < cell.face_sizes.size(); ++f) {
    const uint32_t* loop = cell.indices.data() + starts[f];
    const double* p0 = &cell.positions[3 * size_t(loop[0])];
    const double a[3] = {p0[0] - o[0], p0[1] - o[1], p0[2] - o[2]};
    for (uint32_t i = 1; i + 1 < cell.face_sizes[f]; ++i) {
      const double* p1 = &cell.positions[3 * size_t(loop[i])];
      const double* p2 = &cell.positions[3 * size_t(loop[i + 1])];
      const double b[3] = {p1[0] - o[0], p1[1] - o[1], p1[2] - o[2]};
      const double c[3] = {p2[0] - o[0], p2[1] - o[1], p2[2] - o[2]};
      sum +=
          a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
    }
  }
  return sum;
}

}  // namespace

bool orient_cell_outward(Mesh& cell) {
  const uint32_t faces = static_cast<uint32_t>(cell.face_sizes.size());
  std::vector<uint32_t> starts(faces);
  for (uint32_t f = 0, s = 0; f < faces; ++f) starts[f] = s, s += cell.face_sizes[f];

  std::vector<Link> links;
  std::vector<uint32_t> link_start;
  collect_links(cell, starts, links, link_start);
  // 0 = not reached, 1 = kept, 2 = reversed.
  std::vector<uint8_t> state(faces, 0);
  std::vector<uint32_t> queue;
  for (uint32_t seed = 0; seed < faces; ++seed) {
    if (state[seed]) continue;
    state[seed] = 1;
    queue.assign(1, seed);
    for (size_t q = 0; q < queue.size(); ++q) {
      const uint32_t f = queue[q];
      for (uint32_t k = link_start[f]; k < link_start[f + 1]; ++k) {
        const Link& l = links[k];
        if (state[l.other]) continue;  // a conflict (non-orientable) is left to compute_kernel
        state[l.other] = static_cast<uint8_t>(l.flip ? 3 - state[f] : state[f]);
        queue.push_back(l.other);
      }
    }
  }
  for (uint32_t f = 0; f < faces; ++f)
    if (state[f] == 2) reverse_face(cell, starts[f], cell.face_sizes[f]);
  bool whole_flip = six_volume(cell, starts) < 0;
  if (whole_flip)
    for (uint32_t f = 0; f < faces; ++f) reverse_face(cell, starts[f], cell.face_sizes[f]);
  // A face differs from the file when exactly one of the two passes reversed it.
  bool any = false;
  for (uint32_t f = 0; f < faces; ++f) any = any || ((state[f] == 2) != whole_flip);
  return any;
}

}  // namespace kergen::volume
