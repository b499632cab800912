// Exact plane classes: coplanar faces with the same orientation become one plane; a coplanar
// class facing the other way becomes that plane's `opposite` (one plane used from both sides —
// this is how flat kernels arise). Edge-adjacent coplanar faces are joined first (union-find,
// exact orient3d), then class representatives are matched through a hash of the normalized
// plane, every match confirmed exactly; keys near a cell border also probe the neighbour cell,
// so rounding never hides a match.
#include "plane_classes.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

namespace kergen {

namespace {

struct UnionFind {
  std::vector<uint32_t> parent;
  explicit UnionFind(size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  uint32_t find(uint32_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
};

bool same_plane(const PreparedMesh& m, const std::array<uint32_t, 3>& a, const std::array<uint32_t, 3>& b) {
  const double* pa = &m.points[3 * size_t(a[0])];
  const double* pb = &m.points[3 * size_t(a[1])];
  const double* pc = &m.points[3 * size_t(a[2])];
  for (uint32_t v : b)
    if (orient3d(pa, pb, pc, &m.points[3 * size_t(v)]) != 0) return false;
  return true;
}

// Orientation agreement of two coplanar triangles: sign of n_a . n_b (never near zero for
// parallel non-zero normals, so the filtered value decides).
int orientation_agreement(const PreparedMesh& m, const std::array<uint32_t, 3>& a, const std::array<uint32_t, 3>& b) {
  auto normal = [&](const std::array<uint32_t, 3>& t, double n[3]) {
    const double* p = &m.points[3 * size_t(t[0])];
    const double* q = &m.points[3 * size_t(t[1])];
    const double* r = &m.points[3 * size_t(t[2])];
    double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]}, v[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
    n[0] = u[1] * v[2] - u[2] * v[1];
    n[1] = u[2] * v[0] - u[0] * v[2];
    n[2] = u[0] * v[1] - u[1] * v[0];
  };
  double na[3], nb[3];
  normal(a, na);
  normal(b, nb);
  double dot = na[0] * nb[0] + na[1] * nb[1] + na[2] * nb[2];
  if (dot != 0) return dot > 0 ? 1 : -1;
  // Both normals underflowed in double: compare along the dominant exact component.
  PlaneSet tmp(&m.points);
  uint32_t ia = tmp.add_from_points(a[0], a[1], a[2]);
  uint32_t ib = tmp.add_from_points(b[0], b[1], b[2]);
  const auto& ea = tmp.exact(ia);
  const auto& eb = tmp.exact(ib);
  for (int k = 0; k < 3; ++k) {
    int sa = ea.n[k].sign(), sb = eb.n[k].sign();
    if (sa != 0 && sb != 0) return sa == sb ? 1 : -1;
  }
  return 1;
}

struct Key {
  double k[4];
};

Key plane_key(const PlaneSet& ps, uint32_t i) {
  auto c = ps.approx(i);
  double n[3] = {c.n[0].v, c.n[1].v, c.n[2].v}, d = c.d.v;
  double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  double err = std::max({c.n[0].e, c.n[1].e, c.n[2].e});
  if (!(len > 0) || err > 1e-13 * len || !std::isfinite(len)) {
    // Poorly determined in double (sliver or tiny triangle): round the exact coefficients.
    const auto& e = ps.exact(i);
    for (int k = 0; k < 3; ++k) n[k] = e.n[k].estimate();
    d = e.d.estimate();
    double m = std::max({std::fabs(n[0]), std::fabs(n[1]), std::fabs(n[2])});
    int ex = 0;
    std::frexp(m, &ex);
    for (int k = 0; k < 3; ++k) n[k] = std::ldexp(n[k], -ex);
    d = std::ldexp(d, -ex);
    len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  }
  return {{n[0] / len, n[1] / len, n[2] / len, d / len}};
}

constexpr double kCell = 1.0 / (1 << 20);
constexpr double kBorder = 1e-9;  // far above the key's rounding error (~1e-15), far below kCell

struct CellHash {
  size_t operator()(const std::array<int64_t, 4>& c) const {
    uint64_t h = 1469598103934665603ull;
    for (int64_t x : c) { h ^= uint64_t(x); h *= 1099511628211ull; }
    return size_t(h);
  }
};

}  // namespace

void build_planes(const PreparedMesh& m, PlaneSet& ps, std::vector<uint32_t>& face_plane) {
  const size_t nf = m.num_faces();
  UnionFind uf(nf);
  // 1. Edge-adjacent coplanar faces with the same orientation.
  for (const auto& pr : m.adjacent) {
    uint32_t a = uf.find(pr[0]), b = uf.find(pr[1]);
    if (a == b) continue;
    if (!same_plane(m, m.rep[pr[0]], m.rep[pr[1]])) continue;
    if (orientation_agreement(m, m.rep[pr[0]], m.rep[pr[1]]) <= 0) continue;
    uf.parent[std::max(a, b)] = std::min(a, b);
  }
  // 2. Representatives of the classes, matched through the hash.
  std::vector<uint32_t> class_plane(nf, kNoPlane);
  std::unordered_map<std::array<int64_t, 4>, std::vector<uint32_t>, CellHash> cells;
  std::vector<uint32_t> plane_rep_face;  // plane -> face whose triangle defines it
  face_plane.assign(nf, kNoPlane);
  for (uint32_t f = 0; f < nf; ++f) {
    uint32_t root = uf.find(f);
    if (root != f) continue;
    const auto& r = m.rep[f];
    uint32_t id = ps.add_from_points(r[0], r[1], r[2]);
    Key key = plane_key(ps, id);
    uint32_t found = kNoPlane;
    for (int sgn = 1; sgn >= -1 && found == kNoPlane; sgn -= 2) {
      double k[4];
      int64_t base[4];
      int near[4];
      for (int i = 0; i < 4; ++i) {
        k[i] = sgn * key.k[i] / kCell;
        base[i] = int64_t(std::floor(k[i]));
        double frac = k[i] - double(base[i]);
        near[i] = frac < kBorder / kCell ? -1 : (frac > 1 - kBorder / kCell ? 1 : 0);
      }
      for (int mask = 0; mask < 16 && found == kNoPlane; ++mask) {
        std::array<int64_t, 4> cell;
        bool skip = false;
        for (int i = 0; i < 4; ++i) {
          bool bit = (mask >> i) & 1;
          if (bit && near[i] == 0) { skip = true; break; }
          cell[i] = base[i] + (bit ? near[i] : 0);
        }
        if (skip) continue;
        auto it = cells.find(cell);
        if (it == cells.end()) continue;
        for (uint32_t other : it->second) {
          uint32_t of = plane_rep_face[other];
          if (!same_plane(m, m.rep[of], r)) continue;
          int agree = orientation_agreement(m, m.rep[of], r);
          if (sgn == 1 && agree > 0) { found = other; break; }
          if (sgn == -1 && agree < 0) {
            if (ps.opposite(other) == kNoPlane) ps.set_opposite(other, id);
          }
        }
      }
    }
    if (found != kNoPlane) {
      ps.pop_last();  // the class joins an existing plane
      class_plane[f] = found;
      continue;
    }
    class_plane[f] = id;
    plane_rep_face.push_back(f);
    std::array<int64_t, 4> cell;
    for (int i = 0; i < 4; ++i) cell[i] = int64_t(std::floor(key.k[i] / kCell));
    cells[cell].push_back(id);
  }
  for (uint32_t f = 0; f < nf; ++f) face_plane[f] = class_plane[uf.find(f)];

  // 3. Incidence: points on each plane, planes through each point (both sorted, unique).
  auto& on = ps.incident_points();
  auto& through = ps.planes_through_point();
  through.assign(m.points.size() / 3, {});
  for (uint32_t f = 0; f < nf; ++f) {
    uint32_t p = face_plane[f];
    for (uint32_t i = m.loop_offsets[f]; i < m.loop_offsets[f + 1]; ++i) {
      on[p].push_back(m.loops[i]);
      through[m.loops[i]].push_back(p);
    }
  }
  for (auto& l : on) { std::sort(l.begin(), l.end()); l.erase(std::unique(l.begin(), l.end()), l.end()); }
  for (auto& l : through) { std::sort(l.begin(), l.end()); l.erase(std::unique(l.begin(), l.end()), l.end()); }
}

}  // namespace kergen
