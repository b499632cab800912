// Exact plane classes: coplanar faces with the same orientation become one plane; a coplanar
// class facing the other way becomes that plane's `opposite` (one plane used from both sides —
// this is how flat kernels arise). Edge-adjacent coplanar faces are joined first (union-find,
// exact orient3d), then class representatives are matched through a hash of the normalized
// plane, every match confirmed exactly; keys near a cell border also probe the neighbour cell,
// so rounding never hides a match.
#include "plane_classes.h"

#include "union_find.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace kergen {

namespace {

const double* P(const PreparedMesh& m, uint32_t v) { return &m.points[3 * size_t(v)]; }

// Every vertex of triangle b lies on the plane of triangle a (vertices shared with a trivially do).
bool same_plane(const PreparedMesh& m, const std::array<uint32_t, 3>& a, const std::array<uint32_t, 3>& b) {
  for (uint32_t v : b) {
    if (v == a[0] || v == a[1] || v == a[2]) continue;
    if (orient3d(P(m, a[0]), P(m, a[1]), P(m, a[2]), P(m, v), m.exact_shift) != 0) return false;
  }
  return true;
}

// Orientation agreement of two coplanar triangles: sign of n_a . n_b, which is never near zero
// for parallel non-zero normals; exact components decide if the doubles underflow.
int orientation_agreement(const PreparedMesh& m, const std::array<uint32_t, 3>& a, const std::array<uint32_t, 3>& b) {
  auto pa = approx_plane(P(m, a[0]), P(m, a[1]), P(m, a[2]));
  auto pb = approx_plane(P(m, b[0]), P(m, b[1]), P(m, b[2]));
  Approx dot = pa.n[0] * pb.n[0] + pa.n[1] * pb.n[1] + pa.n[2] * pb.n[2];
  if (dot.certain()) return dot.sign();
  auto ea = exact_plane(P(m, a[0]), P(m, a[1]), P(m, a[2]), m.exact_shift);
  auto eb = exact_plane(P(m, b[0]), P(m, b[1]), P(m, b[2]), m.exact_shift);
  for (int k = 0; k < 3; ++k) {
    int sa = ea.n[k].sign(), sb = eb.n[k].sign();
    if (sa != 0 && sb != 0) return sa == sb ? 1 : -1;
  }
  return 1;
}

// Normalized plane (unit normal, offset) for hashing, accurate to a few ulps.
std::array<double, 4> plane_key(const PreparedMesh& m, const std::array<uint32_t, 3>& t) {
  auto c = approx_plane(P(m, t[0]), P(m, t[1]), P(m, t[2]));
  double n[3] = {c.n[0].v, c.n[1].v, c.n[2].v}, d = c.d.v;
  double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  double err = std::max({c.n[0].e, c.n[1].e, c.n[2].e});
  if (!(len > 0) || err > 1e-13 * len || !std::isfinite(len)) {
    // Poorly determined in double (sliver or tiny triangle): round the exact coefficients.
    auto e = exact_plane(P(m, t[0]), P(m, t[1]), P(m, t[2]), m.exact_shift);
    for (int k = 0; k < 3; ++k) n[k] = e.n[k].estimate();
    d = e.d.estimate();
    double mx = std::max({std::fabs(n[0]), std::fabs(n[1]), std::fabs(n[2])});
    int ex = 0;
    std::frexp(mx, &ex);
    for (int k = 0; k < 3; ++k) n[k] = std::ldexp(n[k], -ex);
    d = std::ldexp(d, -ex);
    len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  }
  return {n[0] / len, n[1] / len, n[2] / len, d / len};
}

// Cells of ~2e-10 keep nearly-but-not-exactly coplanar planes (common in refined meshes with
// rounded coordinates) out of each other's chains; the border margin is far above the key's
// rounding error (a few ulps, ~1e-15) and far below the cell size.
constexpr double kCell = 1.0 / (int64_t(1) << 32);
constexpr double kBorder = 1e-13;

uint64_t cell_hash(const int64_t c[4]) {
  uint64_t h = 1469598103934665603ull;
  for (int i = 0; i < 4; ++i) { h ^= uint64_t(c[i]); h *= 1099511628211ull; h ^= h >> 29; }
  return h;
}

// Open-addressing table: cell hash -> first plane of a chain (chains continue in `next`).
// Different cells with equal hashes just share a chain: every candidate is confirmed exactly.
class CellTable {
 public:
  explicit CellTable(size_t n) {
    size_t cap = 16;
    while (cap < 2 * n + 16) cap <<= 1;
    keys_.assign(cap, 0);
    heads_.assign(cap, kNoPlane);
    mask_ = cap - 1;
  }
  uint32_t head(uint64_t h) const {
    for (size_t i = h & mask_;; i = (i + 1) & mask_) {
      if (heads_[i] == kNoPlane) return kNoPlane;
      if (keys_[i] == h) return heads_[i];
    }
  }
  // Makes `id` the new head of h's chain and returns the previous head.
  uint32_t push(uint64_t h, uint32_t id) {
    for (size_t i = h & mask_;; i = (i + 1) & mask_) {
      if (heads_[i] == kNoPlane) { keys_[i] = h; heads_[i] = id; return kNoPlane; }
      if (keys_[i] == h) { uint32_t old = heads_[i]; heads_[i] = id; return old; }
    }
  }

 private:
  std::vector<uint64_t> keys_;
  std::vector<uint32_t> heads_;
  size_t mask_;
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
    uf.unite(a, b);
  }
  // 2. Class representatives matched through the cell table.
  std::vector<uint32_t> class_plane(nf, kNoPlane);
  std::vector<uint32_t> plane_face;  // plane -> face whose triangle defines it
  std::vector<uint32_t> next;        // chain links per plane
  size_t roots = 0;
  for (uint32_t f = 0; f < nf; ++f) roots += uf.find(f) == f;
  CellTable table(roots);
  for (uint32_t f = 0; f < nf; ++f) {
    if (uf.find(f) != f) continue;
    const auto& r = m.rep[f];
    std::array<double, 4> key = plane_key(m, r);
    int64_t primary[4];
    for (int i = 0; i < 4; ++i) primary[i] = int64_t(std::floor(key[i] / kCell));
    uint32_t found = kNoPlane, opposite = kNoPlane;
    for (int sgn = 1; sgn >= -1 && found == kNoPlane; sgn -= 2) {
      int64_t base[4];
      int near[4];
      for (int i = 0; i < 4; ++i) {
        double k = sgn * key[i] / kCell;
        base[i] = int64_t(std::floor(k));
        double frac = k - double(base[i]);
        near[i] = frac < kBorder / kCell ? -1 : (frac > 1 - kBorder / kCell ? 1 : 0);
      }
      for (int mask = 0; mask < 16 && found == kNoPlane; ++mask) {
        int64_t cell[4];
        bool skip = false;
        for (int i = 0; i < 4; ++i) {
          bool bit = (mask >> i) & 1;
          if (bit && near[i] == 0) { skip = true; break; }
          cell[i] = base[i] + (bit ? near[i] : 0);
        }
        if (skip) continue;
        for (uint32_t other = table.head(cell_hash(cell)); other != kNoPlane; other = next[other]) {
          const auto& orep = m.rep[plane_face[other]];
          if (!same_plane(m, orep, r)) continue;
          int agree = orientation_agreement(m, orep, r);
          if (sgn == 1 && agree > 0) { found = other; break; }
          if (sgn == -1 && agree < 0 && ps.opposite(other) == kNoPlane) opposite = other;
        }
      }
    }
    if (found != kNoPlane) {
      class_plane[f] = found;
      continue;
    }
    uint32_t id = ps.add_from_points(r[0], r[1], r[2]);
    class_plane[f] = id;
    plane_face.push_back(f);
    next.push_back(table.push(cell_hash(primary), id));
    if (opposite != kNoPlane) ps.set_opposite(opposite, id);
  }
  face_plane.assign(nf, kNoPlane);
  for (uint32_t f = 0; f < nf; ++f) face_plane[f] = class_plane[uf.find(f)];

  // 3. Incidence.
  set_face_incidence(m, ps, face_plane);
}

void set_face_incidence(const PreparedMesh& m, PlaneSet& ps, const std::vector<uint32_t>& face_plane) {
  // Compressed rows: points on each plane, planes through each point (sorted, unique).
  const size_t nf = m.num_faces();
  const size_t np = ps.size(), nv = m.points.size() / 3;
  std::vector<uint32_t> plane_off(np + 1, 0), point_off(nv + 1, 0);
  for (uint32_t f = 0; f < nf; ++f)
    for (uint32_t i = m.loop_offsets[f]; i < m.loop_offsets[f + 1]; ++i) {
      plane_off[face_plane[f] + 1]++;
      point_off[m.loops[i] + 1]++;
    }
  for (size_t i = 0; i < np; ++i) plane_off[i + 1] += plane_off[i];
  for (size_t i = 0; i < nv; ++i) point_off[i + 1] += point_off[i];
  std::vector<uint32_t> plane_pts(plane_off[np]), point_pls(point_off[nv]);
  {
    std::vector<uint32_t> fp(plane_off.begin(), plane_off.end() - 1), fv(point_off.begin(), point_off.end() - 1);
    for (uint32_t f = 0; f < nf; ++f)
      for (uint32_t i = m.loop_offsets[f]; i < m.loop_offsets[f + 1]; ++i) {
        plane_pts[fp[face_plane[f]]++] = m.loops[i];
        point_pls[fv[m.loops[i]]++] = face_plane[f];
      }
  }
  // Sort and deduplicate each row in place, then compact.
  auto compact = [](std::vector<uint32_t>& off, std::vector<uint32_t>& data) {
    size_t out = 0;
    for (size_t r = 0; r + 1 < off.size(); ++r) {
      uint32_t b = off[r], e = off[r + 1];
      std::sort(data.begin() + b, data.begin() + e);
      off[r] = uint32_t(out);
      for (uint32_t i = b; i < e; ++i)
        if (i == b || data[i] != data[i - 1]) data[out++] = data[i];
    }
    off.back() = uint32_t(out);
    data.resize(out);
  };
  compact(plane_off, plane_pts);
  compact(point_off, point_pls);
  ps.set_incidence(std::move(plane_off), std::move(plane_pts), std::move(point_off), std::move(point_pls));
}

}  // namespace kergen
