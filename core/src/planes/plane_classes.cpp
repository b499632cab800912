// Exact plane classes: coplanar faces with the same orientation become one plane; a coplanar
// class facing the other way becomes that plane's `opposite` (one plane used from both sides —
// this is how flat kernels arise).
//
// Every face gets a key: its normalized plane (unit normal, offset) in doubles, within a proven
// kKeyError of the exact normalized plane in each component. Keys of one plane (or of opposite
// planes, negated) therefore differ by at most kBorder, and keys further apart prove two faces
// are not on one plane — the float filter that spares most exact tests. Exact orient3d then
// decides every candidate; the sign under which the keys agree gives the relative orientation.
// Edge-adjacent coplanar faces are joined first (union-find), then class representatives are
// matched through a hash of the key's cell; keys near a cell border also probe the neighbour
// cell, so rounding never hides a match.
#include "planes/plane_classes.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <utility>

#include "util/compiler_hints.h"
#include "util/flat_map.h"
#include "util/raw_vector.h"
#include "util/union_find.h"

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

// Each key component is within kKeyError of the exact normalized plane's; two keys of one plane
// thus agree within 2 kKeyError < kBorder (the margin also absorbs the rounding of the tests).
constexpr double kKeyError = 4e-14;
constexpr double kBorder = 1e-13;
static_assert(2 * kKeyError < kBorder, "keys of one plane must agree within kBorder");

struct Key {
  double k[4];  // n / |n|, d / |n|
};

// The key of triangle t, from its double plane c = (n, d) with error bounds (e_n per normal
// component, e_d). With E = sum e_n >= |n - N|: |n/|n| - N/|N|| <= 2E/|n|, and
// |d/|n| - D/|N|| <= (e_d + E |D|/|N|)/|n| where |D|/|N|, the plane's distance to the origin, is
// at most |a| <= |a_x| + |a_y| + |a_z| for its vertex a. That bound, held below 3e-14, plus the
// normalization's own rounding (< 1e-15 for scaled coordinates, below 1) stays below kKeyError.
// Poorly determined planes (slivers, tiny or underflowing triangles) round the exact
// coefficients instead (error ~1e-15).
Key face_key(const PreparedMesh& m, const std::array<uint32_t, 3>& t, const PlaneCoef<Approx>& c) {
  const double* a = P(m, t[0]);
  const double dist = std::fabs(a[0]) + std::fabs(a[1]) + std::fabs(a[2]);
  const double len = std::sqrt(c.n[0].v * c.n[0].v + c.n[1].v * c.n[1].v + c.n[2].v * c.n[2].v);
  const double err = (2 + dist) * (c.n[0].e + c.n[1].e + c.n[2].e) + c.d.e;
  if (err <= 3e-14 * len && len < HUGE_VAL) {  // false for NaN
    const double inv = 1 / len;
    return {{c.n[0].v * inv, c.n[1].v * inv, c.n[2].v * inv, c.d.v * inv}};
  }
  // The exact plane is of the points times 2^s: normal 2^2s N, offset 2^3s D. Scale the rounded
  // coefficients to a largest normal component near 1 (no overflow in the norm) and undo the
  // extra 2^s of the offset.
  const auto e = exact_plane(P(m, t[0]), P(m, t[1]), P(m, t[2]), m.exact_shift);
  double n[3] = {e.n[0].estimate(), e.n[1].estimate(), e.n[2].estimate()};
  int ex = 0;
  std::frexp(std::fmax(std::fabs(n[0]), std::fmax(std::fabs(n[1]), std::fabs(n[2]))), &ex);
  for (double& x : n) x = std::ldexp(x, -ex);
  const double d = std::ldexp(e.d.estimate(), -ex - m.exact_shift);
  const double inv = 1 / std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  return {{n[0] * inv, n[1] * inv, n[2] * inv, d * inv}};
}

// +1 if the keys agree within kBorder (possibly one plane, same orientation), -1 if a and -b do
// (possibly opposite planes), 0 if neither: then the faces are certainly not coplanar. Never
// both: a unit normal has a component of magnitude >= 1/sqrt(3).
int key_match(const Key& a, const Key& b) {
  bool same = true, opposite = true;
  for (int i = 0; i < 4; ++i) {
    same &= std::fabs(a.k[i] - b.k[i]) <= kBorder;
    opposite &= std::fabs(a.k[i] + b.k[i]) <= kBorder;
  }
  return same ? 1 : (opposite ? -1 : 0);
}

// Cells of 2^-32 (~2e-10) keep nearly-but-not-exactly coplanar planes (common in refined meshes
// with rounded coordinates) out of each other's chains. Cells are centred on multiples of 2^-32:
// the coordinates of axis-aligned planes (0, +-1, short dyadic offsets) lie in the middle of a
// cell, not on its border, so they probe one cell, not sixteen. The cell of the negated key is
// the mirror cell -c: a cell and its mirror share one hash (the sign that makes the first
// non-zero coordinate positive is taken out; a unit normal has a coordinate of at least
// 1/sqrt(3), so some coordinate is not 0), so one probe finds both orientations of a plane.
constexpr double kCell = 1.0 / (int64_t(1) << 32);

// floor(x) for |x| < 2^62 (cell coordinates are below 2^34): the cast truncates towards zero.
int64_t floor_int(double x) {
  const int64_t c = int64_t(x);
  return c - (double(c) > x);
}

// Key coordinate x's cell (the multiple of 2^-32 nearest to x, in cells) and the step to the
// neighbour cell when x lies within kBorder of the border between them (0 otherwise). Exact:
// x / kCell is a power-of-two scaling and frac is exact; a coordinate and its negation get
// mirror cells except exactly on a border, where both probe both cells.
struct CellCoord {
  int64_t cell;
  int step;
};
CellCoord cell_coord(double x) {
  const double v = x / kCell;
  const int64_t base = floor_int(v);
  const double frac = v - double(base);  // in [0, 1), exact
  const bool upper = frac >= 0.5;
  const bool near = std::fabs(frac - 0.5) <= kBorder / kCell;  // (exact for frac >= 0.25)
  return {base + upper, near ? (upper ? -1 : 1) : 0};
}

// A cell's hash is the xor of one mixed value per coordinate (so the neighbour cells of a key near
// a border cost an xor per stepped coordinate), with the mirror sign taken out.
uint64_t cell_coord_hash(int i, int64_t c) {
  static constexpr uint64_t kOdd[4] = {0x9E3779B97F4A7C15ull, 0xbf58476d1ce4e5b9ull, 0x94d049bb133111ebull,
                                       0xff51afd7ed558ccdull};
  const uint64_t h = uint64_t(c) * kOdd[i];
  return h ^ (h >> 29);
}

// +1 or -1: the sign making the cell's first non-zero coordinate positive.
int64_t mirror_sign(const int64_t c[4]) {
  for (int i = 0; i < 4; ++i)
    if (c[i] != 0) return c[i] < 0 ? -1 : 1;
  return 1;  // (unreachable: see above)
}

uint64_t cell_hash(const int64_t c[4]) {
  const int64_t sign = mirror_sign(c);
  uint64_t h = 0;
  for (int i = 0; i < 4; ++i) h ^= cell_coord_hash(i, sign * c[i]);
  return h;
}

// Calls visit(hash) for each cell whose closed extent lies within kBorder of the key in every
// component: the key's own cell, plus the neighbour across any border closer than kBorder (rare).
// So a key within kBorder of key k, or of -k, probes the cell that k was stored under (keys of
// one plane are within 2 kKeyError, far inside that margin).
template <class Visit>
void for_each_cell(const Key& key, Visit visit) {
  int64_t base[4];
  // The components near a border (increasing) and the step to their neighbour cell.
  int near_index[4], num_near = 0;
  int64_t step[4];
  for (int i = 0; i < 4; ++i) {
    const CellCoord c = cell_coord(key.k[i]);
    base[i] = c.cell;
    if (c.step != 0) {
      near_index[num_near] = i;
      step[num_near++] = c.step;
    }
  }
  visit(cell_hash(base));
  // Every non-empty subset of the near components stepped across, in increasing order of their
  // bit masks over the components.
  for (int sub = 1; sub < (1 << num_near); ++sub) {
    int64_t cell[4] = {base[0], base[1], base[2], base[3]};
    for (int j = 0; j < num_near; ++j)
      if ((sub >> j) & 1) cell[near_index[j]] += step[j];
    visit(cell_hash(cell));
  }
}

// The key's own cell (where its plane is stored): its hash, and whether for_each_cell would
// visit more cells than this one (a border within kBorder; rare).
struct OwnCell {
  uint64_t hash = 0;
  bool near_border = false;
};
OwnCell own_cell(const Key& key) {
  int64_t c[4];
  bool near = false;
  for (int i = 0; i < 4; ++i) {
    const CellCoord x = cell_coord(key.k[i]);  // as in for_each_cell
    c[i] = x.cell;
    near |= x.step != 0;
  }
  return {cell_hash(c), near};
}

// Open-addressing table: cell hash -> first plane of a chain (chains continue in `next`). Slots
// keep 32 bits of the hash; cells that collide just share a chain, as every candidate is
// confirmed exactly.
class CellTable {
 public:
  explicit CellTable(size_t n) {
    size_t cap = 16;
    while (cap < 2 * n + 16) cap <<= 1;
    slots_.assign(cap, Slot{0, kNoPlane});
    mask_ = cap - 1;
  }
  void prefetch(uint64_t h) const { kergen::prefetch(&slots_[h & mask_]); }
  uint32_t head(uint64_t h) const {
    const uint32_t tag = uint32_t(h >> 32);
    for (size_t i = h & mask_;; i = (i + 1) & mask_) {
      if (slots_[i].head == kNoPlane) return kNoPlane;
      if (slots_[i].tag == tag) return slots_[i].head;
    }
  }
  // Makes `id` the new head of h's chain and returns the previous head.
  uint32_t push(uint64_t h, uint32_t id) {
    const uint32_t tag = uint32_t(h >> 32);
    for (size_t i = h & mask_;; i = (i + 1) & mask_) {
      Slot& s = slots_[i];
      if (s.head == kNoPlane) {
        s = {tag, id};
        return kNoPlane;
      }
      if (s.tag == tag) {
        uint32_t old = s.head;
        s.head = id;
        return old;
      }
    }
  }

 private:
  struct Slot {
    uint32_t tag, head;
  };
  std::vector<Slot> slots_;
  size_t mask_;
};

// Fine keys, for planes whose float keys crowd one cell: a nearly (not exactly) flat region, such
// as a tessellated face rounded after a rotation, puts thousands of planes within 1e-16 of each
// other into one cell, and each new plane would be tested exactly against all of them. The fine
// key is the plane divided by the magnitude of its normal's largest component m, in double-double
// (error below kFineMaxError): one exact plane gives the same value from any of its triangles, so
// its fine keys agree within their error bounds, while planes 1e-16 apart fall into different
// cells of 2^-70. Like the float keys they only select candidates; the exact test decides.
constexpr double kFineScale = 1180591620717411303424.0;  // 2^70
constexpr double kFineMaxError = 1e-26;
constexpr size_t kCrowded = 8;  // float-key planes walked in vain before fine keys are used

// floor(x 2^70) of a double-double x (|x| < 2^9) and whether x lies within `margin` cells of the
// lower (-1) or upper (+1) border of that cell.
struct FineCoord {
  __int128 cell;
  int near;
};
FineCoord fine_coord(double hi, double lo, double margin) {
  const double hs = hi * kFineScale, ls = lo * kFineScale;  // exact: a power of two
  const double h = std::floor(hs);
  const double t = (hs - h) + ls;  // hs - h is exact; t is rounded once (far below the margin)
  const double ft = std::floor(t);
  const double frac = t - ft;
  return {static_cast<__int128>(h) + static_cast<__int128>(ft), frac < margin ? -1 : (frac > 1 - margin ? 1 : 0)};
}

uint64_t fine_hash(int m, int sign, const __int128 c[3]) {
  uint64_t h = 0x9e3779b97f4a7c15ull ^ uint64_t(m * 2 + (sign > 0));
  for (int i = 0; i < 3; ++i)
    for (uint64_t part : {uint64_t(c[i]), uint64_t(c[i] >> 64)}) {
      h ^= part;
      h *= 0xff51afd7ed558ccdull;
      h ^= h >> 33;
    }
  return h;
}

// Calls visit(hash) for every fine cell a plane on the same exact plane as (key k, double-double
// plane p), or on its opposite, can have been stored under; sets `own` to the cell to store this
// plane under. Returns false when p is too poorly known for fine keys (then nothing is visited).
// `own_valid` is false when the largest normal component is not clear-cut (two candidates for
// m, both visited): such a plane is stored with the float keys.
template <class Visit>
bool for_each_fine_cell(const Key& k, const PlaneCoef<exact::ApproxDD>& p, Visit visit, uint64_t& own,
                        bool& own_valid) {
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int a, int b) { return std::fabs(k.k[a]) > std::fabs(k.k[b]); });
  // Keys are within kKeyError of the exact normalized plane: a gap of 1e-12 between the two
  // largest components means every plane with this exact plane picks the same m.
  const int candidates = std::fabs(k.k[order[0]]) - std::fabs(k.k[order[1]]) > 1e-12 ? 1 : 2;
  own_valid = candidates == 1;
  for (int ci = 0; ci < candidates; ++ci) {
    const int m = order[ci];
    const exact::ApproxDD& nm = p.n[m];
    if (!(std::fabs(nm.hi) - std::fabs(nm.lo) > 2 * nm.e)) return false;
    const int sign = nm.hi > 0 ? 1 : -1;
    exact::ApproxDD v[3];
    int slot = 0;
    for (int i = 0; i < 3; ++i)
      if (i != m) v[slot++] = p.n[i] / nm;
    v[2] = p.d / nm;
    for (auto& x : v) {
      if (!(x.e <= kFineMaxError) || !(std::fabs(x.hi) < 256)) return false;
      if (sign < 0) x = -x;  // divided by |n_m|: the orientation stays in `sign`
    }
    // Two fine keys of one exact plane differ by at most 2 kFineMaxError: in cells,
    const double margin = 2 * kFineMaxError * kFineScale + 1e-9;
    for (int orientation : {1, -1}) {
      FineCoord c[3];
      for (int i = 0; i < 3; ++i)
        c[i] = orientation > 0 ? fine_coord(v[i].hi, v[i].lo, margin) : fine_coord(-v[i].hi, -v[i].lo, margin);
      for (int mask = 0; mask < 8; ++mask) {
        __int128 cell[3];
        bool skip = false;
        for (int i = 0; i < 3; ++i) {
          const bool bit = (mask >> i) & 1;
          if (bit && c[i].near == 0) {
            skip = true;
            break;
          }
          cell[i] = c[i].cell + (bit ? c[i].near : 0);
        }
        if (skip) continue;
        const uint64_t h = fine_hash(m, orientation * sign, cell);
        if (ci == 0 && orientation > 0 && mask == 0) own = h;
        visit(h);
      }
    }
  }
  return true;
}

// An unordered pair of face ids as one key of a U64Set (never ~0: a face is never paired with
// itself).
uint64_t pair_key(uint32_t a, uint32_t b) { return a < b ? uint64_t(a) << 32 | b : uint64_t(b) << 32 | a; }

// The faces to build planes for: prepared faces (all, or a subset renumbered from 0).
struct FaceLists {
  const std::array<uint32_t, 3>* rep;
  size_t num_faces;
  const std::array<uint32_t, 2>* adjacent;  // edge-adjacent pairs among these faces
  size_t num_adjacent;
  const uint32_t* loop_offsets;  // num_faces + 1
  const uint32_t* loops;
};

void face_incidence(const FaceLists& fl, PlaneSet& ps, const std::vector<uint32_t>& face_plane);

// Prefetch distance of build_planes' loops: loads a few iterations ahead are prefetched, as the
// loops are bound by cache misses on keys and table slots of faces spread over the mesh.
constexpr size_t kAhead = 8;

// Step 1 of build_planes: edge-adjacent coplanar faces with the same orientation (the usual way
// faces share a plane) are united in `uf`; one exact orient3d confirms each pair whose keys agree.
// Pairs whose keys agree but which are not coplanar (neighbours a hair apart, as rounded vertices
// leave refined meshes) are returned, as pairs of their class representatives: their classes are
// then known to differ without a second exact test.
U64Set unite_coplanar_neighbours(const PreparedMesh& m, const FaceLists& fl, const std::vector<Key>& key,
                                 UnionFind& uf) {
  const std::array<uint32_t, 3>* rep = fl.rep;
  std::vector<std::array<uint32_t, 2>> apart;
  const std::array<uint32_t, 2>* adj = fl.adjacent;
  const size_t num_adj = fl.num_adjacent;
  for (size_t i = 0; i < num_adj; ++i) {
    if (i + kAhead < num_adj) {
      prefetch(&key[adj[i + kAhead][0]]);
      prefetch(&key[adj[i + kAhead][1]]);
    }
    const auto& pr = adj[i];
    if (key_match(key[pr[0]], key[pr[1]]) <= 0) continue;
    const uint32_t a = uf.find(pr[0]), b = uf.find(pr[1]);
    if (a == b) continue;
    if (!same_plane(m, rep[pr[0]], rep[pr[1]])) {
      apart.push_back(pr);
      continue;
    }
    uf.unite(a, b);
  }
  U64Set distinct(apart.size());  // pairs of class representatives on different planes
  for (const auto& pr : apart) distinct.insert(pair_key(uf.find(pr[0]), uf.find(pr[1])));
  return distinct;
}

// (plane_face_out: see the header; ids in fl's numbering.)
void build_planes(const PreparedMesh& m, const FaceLists& fl, PlaneSet& ps, std::vector<uint32_t>& face_plane,
                  std::vector<uint32_t>* plane_face_out) {
  const size_t nf = fl.num_faces;
  const std::array<uint32_t, 3>* rep = fl.rep;
  // Plane ids index the per-plane arrays below, from the first one added here.
  const uint32_t first_plane = uint32_t(ps.size());
  // The plane arrays outlive everything below: reserved first (at most one plane per face, +16
  // for the few planes callers add afterwards, such as a bounding box), they sit below this
  // function's temporaries in the heap, whose space later phases then reuse.
  ps.reserve(first_plane + nf + 16);
  // Every face's filtered plane goes to the plane arrays as a candidate (the representatives'
  // are kept in place at the end instead of being computed again).
  ps.stage(nf);
  std::vector<Key> key;
  key.reserve(nf);
  for (uint32_t f = 0; f < nf; ++f) {
    const auto& t = rep[f];
    const PlaneCoef<Approx> c = approx_plane(P(m, t[0]), P(m, t[1]), P(m, t[2]));
    ps.put(f, c);
    key.push_back(face_key(m, t, c));
  }

  // 1. Edge-adjacent coplanar faces with the same orientation (unite_coplanar_neighbours).
  UnionFind uf(nf);
  const U64Set distinct = unite_coplanar_neighbours(m, fl, key, uf);

  // 2. Class representatives (the smallest face of each union) in face order, matched through
  //    the cell table; a new plane takes the representative's triangle (the first one met, so
  //    the class's lowest face: every union's lowest face is its representative). face_plane holds each
  //    representative's plane as soon as it is matched, so every other face (larger than its
  //    representative) takes it in the same pass.
  face_plane.resize(nf);
  std::vector<uint32_t> plane_face;  // plane - first_plane -> face whose triangle defines it
  std::vector<uint32_t> next;        // chain links, by plane - first_plane
  std::vector<std::array<uint32_t, 2>> opposites;
  size_t num_roots = 0;
  for (uint32_t f = 0; f < nf; ++f) num_roots += uf.parent[f] == f;
  plane_face.reserve(num_roots);
  next.reserve(num_roots);
  CellTable table(num_roots);
  // Planes stored under fine keys (crowded float-key cells) are in `fine`, and also in
  // `fine_by_cell` under their float-key cell for the rare plane that has no fine key of its own.
  CellTable fine(num_roots), fine_by_cell(num_roots);
  std::vector<uint32_t> next_by_cell;
  // The table slots of the next kAhead representatives are prefetched; their hashes wait in a
  // ring until used.
  OwnCell ahead[kAhead];
  uint32_t scan = 0;  // first face not yet looked at for prefetching
  auto prefetch_next = [&](size_t slot) KERGEN_INLINE {
    while (scan < nf && uf.parent[scan] != scan) ++scan;
    if (scan == nf) return;
    ahead[slot] = own_cell(key[scan++]);
    table.prefetch(ahead[slot].hash);
  };
  for (size_t i = 0; i < kAhead; ++i) prefetch_next(i);
  size_t root_index = 0;
  for (uint32_t f = 0; f < nf; ++f) {
    if (uf.parent[f] != f) {
      face_plane[f] = face_plane[uf.find(f)];
      continue;
    }
    const OwnCell cell = ahead[root_index % kAhead];
    prefetch_next(root_index++ % kAhead);
    const auto& r = rep[f];
    const Key& k = key[f];
    uint32_t found = kNoPlane, opposite = kNoPlane;
    size_t walked = 0;
    auto check = [&](uint32_t other) KERGEN_INLINE {
      ++walked;
      const uint32_t of = plane_face[other - first_plane];
      const int orientation = key_match(k, key[of]);
      if (orientation == 0 || (orientation > 0 && distinct.contains(pair_key(f, of))) || !same_plane(m, rep[of], r))
        return;
      if (orientation > 0)
        found = other;
      else
        opposite = other;  // at most one plane per orientation, so this one is unlinked
    };
    // The planes of table t's chain h (linked through `links`), until one is found.
    auto walk = [&](const CellTable& t, const std::vector<uint32_t>& links, uint64_t h) KERGEN_INLINE {
      for (uint32_t other = t.head(h); other != kNoPlane && found == kNoPlane; other = links[other - first_plane])
        check(other);
    };
    auto visit = [&](uint64_t h) KERGEN_INLINE { walk(table, next, h); };
    if (cell.near_border)
      for_each_cell(k, visit);
    else
      visit(cell.hash);
    bool store_fine = false;
    uint64_t fine_own = 0;
    if (found == kNoPlane && walked >= kCrowded) {
      bool own_valid = false;
      auto visit_fine = [&](uint64_t h) { walk(fine, next, h); };
      if (for_each_fine_cell(k, dd_plane(P(m, r[0]), P(m, r[1]), P(m, r[2])), visit_fine, fine_own, own_valid)) {
        store_fine = own_valid;
      } else {
        // No fine key: every fine-keyed plane of the float-key cells, as the float keys would.
        auto visit_by_cell = [&](uint64_t h) { walk(fine_by_cell, next_by_cell, h); };
        if (cell.near_border)
          for_each_cell(k, visit_by_cell);
        else
          visit_by_cell(cell.hash);
      }
    }
    if (found != kNoPlane) {
      face_plane[f] = found;
      continue;
    }
    const uint32_t id = first_plane + uint32_t(plane_face.size());
    face_plane[f] = id;
    plane_face.push_back(f);
    if (store_fine) {
      next.push_back(fine.push(fine_own, id));
      next_by_cell.resize(id - first_plane + 1, kNoPlane);
      next_by_cell[id - first_plane] = fine_by_cell.push(cell.hash, id);
    } else {
      next.push_back(table.push(cell.hash, id));
    }
    if (opposite != kNoPlane) opposites.push_back({opposite, id});
  }
  ps.keep_staged(rep, plane_face.data(), plane_face.size());
  for (const auto& o : opposites) ps.set_opposite(o[0], o[1]);

  // 3. Incidence.
  face_incidence(fl, ps, face_plane);
  if (plane_face_out) *plane_face_out = std::move(plane_face);
}

// Moves the distinct points of row[0..n) to its front, in order of first appearance, and returns
// their number. A long row is a flat region's triangles, where each point appears about six
// times: dropping the repeats in one hashed pass leaves a sixth of the row to sort. `seen` is
// scratch (an open-addressing set of point ids).
size_t distinct_points(uint32_t* row, size_t n, RawVector<uint32_t>& seen) {
  constexpr uint32_t kEmpty = ~uint32_t(0);  // (never a point id)
  int bits = 4;
  while ((size_t(1) << bits) < 2 * n) ++bits;
  const size_t mask = (size_t(1) << bits) - 1;
  seen.assign(mask + 1, kEmpty);
  size_t distinct = 0;
  for (size_t i = 0; i < n; ++i) {
    const uint32_t v = row[i];
    size_t s = size_t((uint64_t(v) * 0x9E3779B97F4A7C15ull) >> (64 - bits));
    while (seen[s] != kEmpty && seen[s] != v) s = (s + 1) & mask;
    if (seen[s] == kEmpty) {
      seen[s] = v;
      row[distinct++] = v;
    }
  }
  return distinct;
}

void face_incidence(const FaceLists& fl, PlaneSet& ps, const std::vector<uint32_t>& face_plane) {
  // Each plane's points as compressed rows (sorted, unique), in time linear in the faces' loops,
  // not in the mesh's vertices (a culled subset's faces touch few of them):
  //  a. the loops' points with repeats (one per face loop through a point), bucketed by plane;
  //  b. each row sorted (a plane of a few faces holds a handful of points; a merged flat region
  //     may hold thousands: its repeats are dropped before sorting) and deduplicated, compacted
  //     in place.
  // Buckets are filled through their offsets: row r's count goes to off[r + 2], the prefix sum
  // makes off[r + 1] row r's start, filling advances it to row r's end = row r + 1's start, so
  // off[0..n] are then the rows' offsets.
  const size_t nf = fl.num_faces;
  const size_t np = ps.size();
  // a.
  RawVector<uint32_t> off(np + 2, 0);
  for (size_t f = 0; f < nf; ++f) off[face_plane[f] + 2] += fl.loop_offsets[f + 1] - fl.loop_offsets[f];
  for (size_t i = 1; i < off.size(); ++i) off[i] += off[i - 1];
  RawVector<uint32_t> pts(off[np + 1]);
  for (size_t f = 0; f < nf; ++f) {
    uint32_t& fill = off[face_plane[f] + 1];
    for (uint32_t i = fl.loop_offsets[f]; i < fl.loop_offsets[f + 1]; ++i) pts[fill++] = fl.loops[i];
  }
  off.pop_back();
  // b. (Compacting writes never overtake the reads: out <= the row's read position.)
  RawVector<uint32_t> seen;
  uint32_t out = 0;
  for (size_t p = 0, begin = 0; p < np; ++p) {
    const size_t end = off[p + 1];
    uint32_t* row = pts.data() + begin;
    const size_t n = end - begin;
    size_t distinct = n;
    if (n <= 16) {
      for (size_t i = 1; i < n; ++i)
        for (size_t k = i; k > 0 && row[k] < row[k - 1]; --k) std::swap(row[k], row[k - 1]);
    } else {
      distinct = distinct_points(row, n, seen);
      std::sort(row, row + distinct);
    }
    off[p] = out;
    for (size_t i = 0; i < distinct; ++i)
      if (i == 0 || row[i] != row[i - 1]) pts[out++] = row[i];
    begin = end;
  }
  off[np] = out;
  pts.resize(out);
  ps.set_incidence(std::move(off), std::move(pts));
}

}  // namespace

void build_planes(const PreparedMesh& m, PlaneSet& ps, std::vector<uint32_t>& face_plane,
                  std::vector<uint32_t>* plane_face) {
  const FaceLists all{m.rep.data(),      m.num_faces(),         m.adjacent.data(),
                      m.adjacent.size(), m.loop_offsets.data(), m.loops.data()};
  build_planes(m, all, ps, face_plane, plane_face);
}

void build_planes(const PreparedMesh& m, const std::vector<uint32_t>& faces, PlaneSet& ps,
                  std::vector<uint32_t>& face_plane, std::vector<uint32_t>* plane_face) {
  // The faces renumbered 0..n-1 in the order given: their triangles, loops, and the pairs among
  // them that share an edge: for a few faces, found by matching their loops' edges in a hash
  // table, in time in the chosen faces, not in the mesh (a scan of the mesh's pairs cost more than
  // the classes of the few faces face culling keeps); for many, the mesh's pairs among them. The
  // pairs only spare exact tests: the classes are the same with any of them (and the pairs come
  // lower face first either way).
  const size_t nf = m.num_faces(), n = faces.size();
  RawVector<std::array<uint32_t, 3>> rep(n);
  std::vector<uint32_t> loop_offsets(n + 1);
  loop_offsets[0] = 0;
  for (size_t k = 0; k < n; ++k) {
    const uint32_t f = faces[k];
    assert(f < nf && (k == 0 || faces[k - 1] < f) && "faces must be increasing face ids");
    rep[k] = m.rep[f];
    loop_offsets[k + 1] = loop_offsets[k] + (m.loop_offsets[f + 1] - m.loop_offsets[f]);
  }
  RawVector<uint32_t> loops(loop_offsets[n]);
  for (size_t k = 0; k < n; ++k)
    std::copy(m.loops.begin() + m.loop_offsets[faces[k]], m.loops.begin() + m.loop_offsets[faces[k] + 1],
              loops.begin() + loop_offsets[k]);
  std::vector<std::array<uint32_t, 2>> adjacent;
  if (m.adjacent.size() <= 8 * loops.size()) {
    // Many of the mesh's faces (as face culling keeps on a mesh whose kernel touches much of the
    // surface): its pairs filtered through a renumbering of all faces, a sequential scan, cost
    // less than hashing the chosen faces' edges (a cache miss per edge).
    constexpr uint32_t kNotChosen = ~uint32_t(0);
    RawVector<uint32_t> local(nf);
    std::fill(local.begin(), local.end(), kNotChosen);
    for (uint32_t k = 0; k < n; ++k) local[faces[k]] = k;
    for (const auto& pr : m.adjacent) {
      const uint32_t a = local[pr[0]], b = local[pr[1]];
      if (a != kNotChosen && b != kNotChosen) adjacent.push_back({std::min(a, b), std::max(a, b)});
    }
  } else {
    // Each edge's key and first face in one slot (one cache miss per probe). A closed mesh's
    // loops hold each edge twice: the table is at most half full, and never full.
    constexpr uint64_t kNoEdge = ~uint64_t(0);
    struct EdgeSlot {
      uint64_t edge;
      uint32_t first_face;
    };
    int bits = 4;
    while ((size_t(1) << bits) < loops.size() + 1) ++bits;
    const size_t cap = size_t(1) << bits, mask = cap - 1;
    std::vector<EdgeSlot> table(cap, EdgeSlot{kNoEdge, 0});
    adjacent.reserve(loops.size() / 2);
    for (uint32_t k = 0; k < n; ++k) {
      const uint32_t b = loop_offsets[k], e = loop_offsets[k + 1];
      for (uint32_t i = b; i < e; ++i) {
        const uint32_t u = loops[i], v = loops[i + 1 < e ? i + 1 : b];
        const uint64_t x = uint64_t(std::min(u, v)) << 32 | std::max(u, v);
        size_t s = size_t((x * 0x9E3779B97F4A7C15ull) >> (64 - bits));  // (the product's top bits mix best)
        while (table[s].edge != kNoEdge && table[s].edge != x) s = (s + 1) & mask;
        if (table[s].edge == x) {
          adjacent.push_back({table[s].first_face, k});  // (the lower face first)
        } else {
          table[s] = {x, k};
        }
      }
    }
  }
  const FaceLists some{rep.data(), n, adjacent.data(), adjacent.size(), loop_offsets.data(), loops.data()};
  build_planes(m, some, ps, face_plane, plane_face);
  if (plane_face)
    for (uint32_t& k : *plane_face) k = faces[k];
}

}  // namespace kergen
