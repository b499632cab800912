// Contacts between shells (see shells.h): pieces by union-find over shared edges, a uniform grid
// of the faces' fan triangles, and exact segment-triangle tests of every face edge against the
// triangles of other pieces in the cells its bounding box reaches.
#include "input/shells.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "exact/predicates.h"
#include "util/flat_map.h"
#include "util/union_find.h"

namespace kergen {

namespace {

// The edge-connected piece of each prepared face.
std::vector<uint32_t> pieces(const PreparedMesh& m) {
  const size_t nf = m.num_faces();
  UnionFind uf(nf);
  FlatMap<uint64_t, uint32_t, IdentityHash> edge_face(~uint64_t(0), m.loops.size());  // (a < b: never ~0)
  for (uint32_t f = 0; f < nf; ++f)
    for (uint32_t i = m.loop_offsets[f]; i < m.loop_offsets[f + 1]; ++i) {
      const uint32_t a = m.loops[i], b = m.loops[i + 1 < m.loop_offsets[f + 1] ? i + 1 : m.loop_offsets[f]];
      const uint64_t key = (uint64_t(std::min(a, b)) << 32) | std::max(a, b);
      const auto [first, fresh] = edge_face.try_emplace(key, f);
      if (!fresh) uf.unite(*first, f);
    }
  std::vector<uint32_t> piece(nf);
  for (uint32_t f = 0; f < nf; ++f) piece[f] = uf.find(f);
  return piece;
}

// Whether the closed segment uv meets the closed triangle abc (exact signs).
bool segment_meets_triangle(const double* u, const double* v, const double* a, const double* b, const double* c,
                            int shift) {
  const int su = orient3d(a, b, c, u, shift), sv = orient3d(a, b, c, v, shift);
  if (su != 0 && su == sv) return false;
  if (su == 0 && sv == 0) {
    // Coplanar segment and triangle: counted as a contact as soon as their bounding boxes
    // overlap (conservative: pieces with coplanar faces that close are refused, never passed).
    for (int k = 0; k < 3; ++k) {
      const double lo = std::min({a[k], b[k], c[k]}), hi = std::max({a[k], b[k], c[k]});
      if (std::max(u[k], v[k]) < lo || std::min(u[k], v[k]) > hi) return false;
    }
    return true;
  }
  const int e1 = orient3d(u, v, a, b, shift), e2 = orient3d(u, v, b, c, shift), e3 = orient3d(u, v, c, a, shift);
  return (e1 >= 0 && e2 >= 0 && e3 >= 0) || (e1 <= 0 && e2 <= 0 && e3 <= 0);
}

struct Grid {
  double lo[3], cell;
  int n;
  FlatMap<uint64_t, std::vector<uint32_t>, IdentityHash> cells{~uint64_t(0)};  // cell (< n^3) -> triangles
  int index(double x, int k) const { return std::clamp(int((x - lo[k]) / cell), 0, n - 1); }
  uint64_t key(int i, int j, int l) const {
    return (uint64_t(i) * uint64_t(n) + uint64_t(j)) * uint64_t(n) + uint64_t(l);
  }
  template <class Fn>
  void visit(const double bmin[3], const double bmax[3], Fn&& fn) const {
    for (int i = index(bmin[0], 0); i <= index(bmax[0], 0); ++i)
      for (int j = index(bmin[1], 1); j <= index(bmax[1], 1); ++j)
        for (int l = index(bmin[2], 2); l <= index(bmax[2], 2); ++l) fn(key(i, j, l));
  }
};

}  // namespace

ShellContact find_shell_contact(const PreparedMesh& m) {
  ShellContact out;
  const std::vector<uint32_t> piece = pieces(m);
  // Fan triangles (face, corner b) of every face.
  struct Tri {
    uint32_t face, a, b, c;
  };
  std::vector<Tri> tris;
  for (uint32_t f = 0; f < m.num_faces(); ++f)
    for (uint32_t i = m.loop_offsets[f] + 1; i + 1 < m.loop_offsets[f + 1]; ++i)
      tris.push_back({f, m.loops[m.loop_offsets[f]], m.loops[i], m.loops[i + 1]});
  Grid g;
  double hi[3];
  for (int k = 0; k < 3; ++k) {
    g.lo[k] = m.bbox_min[k];
    hi[k] = m.bbox_max[k];
  }
  const double side = std::max({hi[0] - g.lo[0], hi[1] - g.lo[1], hi[2] - g.lo[2]});
  g.n = std::max(1, std::min(256, int(std::cbrt(double(tris.size())))));
  g.cell = side > 0 ? side / g.n * (1 + 1e-9) : 1;
  auto box = [&](std::initializer_list<uint32_t> vs, double bmin[3], double bmax[3]) {
    for (int k = 0; k < 3; ++k) {
      bmin[k] = HUGE_VAL;
      bmax[k] = -HUGE_VAL;
    }
    for (uint32_t v : vs)
      for (int k = 0; k < 3; ++k) {
        bmin[k] = std::min(bmin[k], m.point(v)[k]);
        bmax[k] = std::max(bmax[k], m.point(v)[k]);
      }
  };
  for (uint32_t t = 0; t < tris.size(); ++t) {
    double bmin[3], bmax[3];
    box({tris[t].a, tris[t].b, tris[t].c}, bmin, bmax);
    g.visit(bmin, bmax, [&](uint64_t key) { g.cells.try_emplace(key, {}).first->push_back(t); });
  }
  std::vector<uint32_t> seen(tris.size(), UINT32_MAX);
  uint32_t stamp = 0;
  for (uint32_t f = 0; f < m.num_faces(); ++f)
    for (uint32_t i = m.loop_offsets[f]; i < m.loop_offsets[f + 1]; ++i, ++stamp) {
      const uint32_t u = m.loops[i], v = m.loops[i + 1 < m.loop_offsets[f + 1] ? i + 1 : m.loop_offsets[f]];
      double bmin[3], bmax[3];
      box({u, v}, bmin, bmax);
      g.visit(bmin, bmax, [&](uint64_t key) {
        if (out.found) return;
        const std::vector<uint32_t>* in_cell = g.cells.find(key);
        if (!in_cell) return;
        for (uint32_t t : *in_cell) {
          if (seen[t] == stamp || piece[tris[t].face] == piece[f]) continue;
          seen[t] = stamp;
          const Tri& x = tris[t];
          if (segment_meets_triangle(m.point(u), m.point(v), m.point(x.a), m.point(x.b), m.point(x.c), m.exact_shift)) {
            out = {true, f, x.face};
            return;
          }
        }
      });
      if (out.found) return out;
    }
  return out;
}

}  // namespace kergen
