// Welding (see weld.h). Which pairs are compared is defined by a grid of cubic cells of the
// tolerance's size ("fine cells"): two vertices are compared iff their fine cells differ by at most
// one along each axis, and merged iff their distance, computed in double, is within the tolerance;
// union-find joins them. Looking up the 27 fine cells around every vertex in a hash table cost
// ~2.6 µs a vertex on a 500k-vertex mesh, so the grid is searched in two levels: coarse cells of
// 2^shift fine cells each, about as wide as the mean spacing of the vertices, hold the vertices
// (usually one each); a vertex whose fine cell is inside its coarse cell, not on its boundary,
// has all 27 fine neighbours in its own coarse cell, and only vertices on a coarse cell's boundary
// look into the coarse cells next to it. The coarse cells are found by a radix sort of the
// vertices by cell (a hash table of them cost a cache miss a vertex, and its keys 24 bytes).
// Coarse cells that hold many vertices (a dense cluster) are searched by fine cell, as a
// single-level grid would, so the work stays bounded by the fine cells' occupancy. The pairs
// compared and merged are exactly the single-level grid's. When none merge, nothing is copied.
#include "input/weld.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

#include "util/compiler_hints.h"
#include "util/raw_vector.h"
#include "util/union_find.h"

namespace kergen {

namespace {

using Cell = std::array<int64_t, 3>;

// The fine cell of a coordinate; exact equality (tolerance 0) uses the coordinates' bits instead.
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

inline Cell fine_cell(const double* p, double tolerance) {
  return {cell_of(p[0], tolerance), cell_of(p[1], tolerance), cell_of(p[2], tolerance)};
}

// floor(c / 2^shift), also for negative c.
int64_t coarse_of(int64_t c, int shift) { return c >= 0 ? c >> shift : ~(~c >> shift); }

uint64_t cell_hash(const Cell& c) {
  uint64_t h = uint64_t(c[0]) * 0x9e3779b97f4a7c15ull ^ uint64_t(c[1]) * 0xc2b2ae3d27d4eb4full ^
               uint64_t(c[2]) * 0x165667b19e3779f9ull;
  h ^= h >> 32;
  h *= 0xd6e8feb86659fd93ull;
  return h ^ (h >> 32);
}

// Fine cells numbered 0, 1, 2, ... in the order first inserted (open addressing, linear probing, at
// most half full). A slot holds 32 bits of the cell's hash and its number, so probing past another
// cell's slot reads that cell's key only when those bits agree.
class CellTable {
 public:
  static constexpr uint32_t kNone = 0xffffffffu;

  explicit CellTable(size_t expected) {
    size_t cap = 16;
    while (cap < 2 * expected + 2) cap <<= 1;
    slots_.assign(cap, kEmptySlot);
    mask_ = cap - 1;
    while ((size_t(1) << (64 - shift_)) < cap) --shift_;
    keys_.reserve(expected);
  }
  void prefetch_slot(uint64_t h) const { prefetch(slots_.data() + home(h)); }
  uint32_t find(const Cell& c, uint64_t h) const {
    for (size_t s = home(h);; s = (s + 1) & mask_) {
      if (slots_[s] == kEmptySlot) return kNone;
      if (holds(slots_[s], c, h)) return uint32_t(slots_[s]);
    }
  }
  // Called at most `expected` times (the table does not grow).
  uint32_t find_or_insert(const Cell& c, uint64_t h) {
    for (size_t s = home(h);; s = (s + 1) & mask_) {
      if (slots_[s] == kEmptySlot) {
        slots_[s] = uint64_t(uint32_t(h)) << 32 | keys_.size();
        keys_.push_back(c);
        return uint32_t(keys_.size() - 1);
      }
      if (holds(slots_[s], c, h)) return uint32_t(slots_[s]);
    }
  }
  size_t size() const { return keys_.size(); }
  const Cell& key(uint32_t id) const { return keys_[id]; }

 private:
  static constexpr uint64_t kEmptySlot = ~uint64_t(0);
  size_t home(uint64_t h) const { return size_t(h >> shift_); }
  bool holds(uint64_t slot, const Cell& c, uint64_t h) const {
    if (uint32_t(slot >> 32) != uint32_t(h)) return false;
    const Cell& k = keys_[uint32_t(slot)];
    return k[0] == c[0] && k[1] == c[1] && k[2] == c[2];
  }
  std::vector<uint64_t> slots_;
  std::vector<Cell> keys_;
  size_t mask_ = 0;
  int shift_ = 64;
};

// Vertices grouped by cell: each cell's members chained in increasing order (built while the
// vertices are numbered in order, so no sorting): the fine cells of dense coarse cells.
struct Members {
  std::vector<uint32_t> first, last, count;  // per cell
  std::vector<uint32_t> next;                // per vertex: the next one in its cell, or kNone
  explicit Members(size_t n = 0) : next(n, CellTable::kNone) {}
  // Vertex v (above every vertex added before) joins cell c (c <= the number of cells so far).
  void add(uint32_t v, uint32_t c) {
    if (c == count.size()) {
      first.push_back(v);
      last.push_back(v);
      count.push_back(1);
      return;
    }
    next[last[c]] = v;
    last[c] = v;
    ++count[c];
  }
};

// A coarse cell holding more vertices than this is searched by fine cell.
constexpr uint32_t kDenseCell = 16;

// The points' bounding box.
struct Box {
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
};

// A coarse cell's 32-bit key (CloseVertices): its coordinates relative to the box's lowest cell,
// packed, when they fit in 32 bits, else 32 bits of its hash.
struct KeyRule {
  bool packed = false;
  int bits = 32;  // the keys' width
  int64_t low[3] = {0, 0, 0};
  uint64_t span[3] = {0, 0, 0};
  int axis_bits[3] = {0, 0, 0};
  // The key of coarse cell c; false when c lies outside the box's cells (no vertex is there).
  bool key_of(const Cell& c, uint32_t& key) const {
    if (!packed) {
      key = uint32_t(cell_hash(c) >> 32);
      return true;
    }
    uint64_t at_all = 0;
    for (int k = 0; k < 3; ++k) {
      const uint64_t at = uint64_t(c[k] - low[k]);
      if (c[k] < low[k] || at > span[k]) return false;
      at_all = at_all << axis_bits[k] | at;
    }
    key = uint32_t(at_all);
    return true;
  }
};

// Each point's key << 32 | its id, and on which sides its fine cell touches its coarse cell's
// boundary (bit 2k: the low side along axis k, bit 2k + 1: the high side; none when reach is 0).
// (Multiversioned: with AVX2 the floors of cell_of are one instruction each.)
KERGEN_MULTIVERSION
void key_points(const double* pts, size_t n, double tolerance, int shift, const KeyRule& rule, uint8_t* border_of,
                uint64_t* keyed) {
  const uint64_t last = (uint64_t(1) << shift) - 1;
  const bool reach = tolerance != 0;
  for (uint32_t v = 0; v < n; ++v) {
    const Cell f = fine_cell(pts + 3 * size_t(v), tolerance);
    uint8_t border = 0;
    Cell c;
    for (int k = 0; k < 3; ++k) {
      const uint64_t within = uint64_t(f[k]) & last;  // f[k] - 2^shift c[k]
      border |= uint8_t((reach && within == 0) << (2 * k) | (reach && within == last) << (2 * k + 1));
      c[k] = coarse_of(f[k], shift);
    }
    border_of[v] = border;
    uint32_t key = 0;
    rule.key_of(c, key);
    keyed[v] = uint64_t(key) << 32 | v;
  }
}

// The coarse cells are found by sorting, not hashing: each vertex gets a 32-bit key of its coarse
// cell (the cell's coordinates relative to the box's lowest cell, packed, when they fit in 32
// bits; else 32 bits of the cell's hash), and a stable radix sort of (key, vertex) lists the
// vertices cell by cell, each cell's in increasing order (a run of equal keys). A hashed key's
// run may hold several coarse cells; every pair compared is still judged by its fine cells
// (join_if_close), so the pairs merged are the single-level grid's whatever the runs hold.
class CloseVertices {
 public:
  CloseVertices(const double* positions, size_t n, double tolerance, int shift, const Box& box, UnionFind& groups)
      : pts_(positions),
        n_(n),
        t_(tolerance),
        t2_(tolerance * tolerance),
        reach_(tolerance == 0 ? 0 : 1),
        shift_(shift),
        groups_(groups),
        border_(n),
        sorted_(n) {
    choose_keys(box);
  }

  // The number of merges made (0: every vertex is its own group).
  size_t run() {
    sort_by_cell();
    index_dense_cells();
    join_within_cells();
    for (uint32_t v = 0; v < n_; ++v)
      if (border_[v] != 0) join_across_cells(v);
    return unions_;
  }

 private:
  Cell coarse_cell(const Cell& f) const {
    return {coarse_of(f[0], shift_), coarse_of(f[1], shift_), coarse_of(f[2], shift_)};
  }
  // Packed keys when the coarse cells' coordinates span at most 32 bits in all (tolerance > 0:
  // cell_of is then monotone, so the box's corners hold the extreme cells).
  void choose_keys(const Box& box) {
    if (t_ == 0) return;
    const Cell lo = coarse_cell(fine_cell(box.lo, t_)), hi = coarse_cell(fine_cell(box.hi, t_));
    int bits = 0;
    for (int k = 0; k < 3; ++k) {
      rule_.low[k] = lo[k];
      rule_.span[k] = uint64_t(hi[k] - lo[k]);
      while (rule_.axis_bits[k] < 63 && (rule_.span[k] >> rule_.axis_bits[k]) != 0) ++rule_.axis_bits[k];
      bits += rule_.axis_bits[k];
    }
    rule_.packed = bits <= 32;
    rule_.bits = rule_.packed ? bits : 32;
  }
  uint32_t key_at(size_t i) const { return uint32_t(sorted_[i] >> 32); }
  uint32_t vertex_at(size_t i) const { return uint32_t(sorted_[i]); }

  // The keys, then their LSD radix sort, 11 bits a pass (stable: a cell's vertices stay in
  // increasing order).
  void sort_by_cell() {
    key_points(pts_, n_, t_, shift_, rule_, border_.data(), sorted_.data());
    constexpr int kDigit = 11;
    RawVector<uint64_t> other(n_);
    std::vector<uint32_t> start(size_t(1) << kDigit);
    for (int at = 32; at < 32 + rule_.bits; at += kDigit) {
      std::fill(start.begin(), start.end(), 0u);
      for (size_t i = 0; i < n_; ++i) ++start[(sorted_[i] >> at) & ((1u << kDigit) - 1)];
      uint32_t total = 0;
      for (uint32_t& s : start) {
        const uint32_t size = s;
        s = total;
        total += size;
      }
      for (size_t i = 0; i < n_; ++i) other[start[(sorted_[i] >> at) & ((1u << kDigit) - 1)]++] = sorted_[i];
      std::swap(sorted_, other);
    }
  }

  // The end of the run that starts at `begin`.
  size_t run_end(size_t begin) const {
    size_t end = begin + 1;
    while (end < n_ && key_at(end) == key_at(begin)) ++end;
    return end;
  }
  // The run of `key`, empty when no vertex has it.
  std::pair<size_t, size_t> run_of(uint32_t key) const {
    const uint64_t* first = sorted_.data();
    const uint64_t* at = std::lower_bound(first, first + n_, uint64_t(key) << 32);
    const size_t begin = size_t(at - first);
    return {begin, begin < n_ && key_at(begin) == key ? run_end(begin) : begin};
  }

  // The vertices of dense cells, grouped by fine cell.
  void index_dense_cells() {
    std::vector<uint32_t> dense;
    for (size_t begin = 0, end; begin < n_; begin = end) {
      end = run_end(begin);
      if (end - begin > kDenseCell)
        for (size_t i = begin; i < end; ++i) dense.push_back(vertex_at(i));
    }
    if (dense.empty()) return;
    std::sort(dense.begin(), dense.end());
    fine_ = CellTable(dense.size());
    fine_members_ = Members(n_);
    for (uint32_t v : dense) {
      const Cell f = fine_cell(pts_ + 3 * size_t(v), t_);
      fine_members_.add(v, fine_.find_or_insert(f, cell_hash(f)));
    }
  }

  // Each vertex against the earlier ones of its own coarse cell (its run).
  void join_within_cells() {
    for (size_t begin = 0, end; begin < n_; begin = end) {
      end = run_end(begin);
      if (end - begin == 1) continue;
      for (size_t i = begin; i < end; ++i) {
        const uint32_t v = vertex_at(i);
        const double* p = pts_ + 3 * size_t(v);
        const Cell f = fine_cell(p, t_);
        if (end - begin > kDenseCell)
          join_in_fine_cells(v, p, f, coarse_cell(f));
        else
          for (size_t j = begin; j < i; ++j) join_if_close(v, p, f, vertex_at(j));
      }
    }
  }

  // v, whose fine cell is on its coarse cell's boundary, against the earlier vertices of the
  // coarse cells next to it on those sides.
  void join_across_cells(uint32_t v) {
    const double* p = pts_ + 3 * size_t(v);
    const Cell f = fine_cell(p, t_);
    const Cell home = coarse_cell(f);
    int lo[3], hi[3];
    for (int k = 0; k < 3; ++k) {
      lo[k] = border_[v] >> (2 * k) & 1 ? -1 : 0;
      hi[k] = border_[v] >> (2 * k + 1) & 1 ? 1 : 0;
    }
    for (int dx = lo[0]; dx <= hi[0]; ++dx)
      for (int dy = lo[1]; dy <= hi[1]; ++dy)
        for (int dz = lo[2]; dz <= hi[2]; ++dz) {
          if (dx == 0 && dy == 0 && dz == 0) continue;  // (join_within_cells)
          const Cell c = {home[0] + dx, home[1] + dy, home[2] + dz};
          uint32_t key;
          if (!rule_.key_of(c, key)) continue;
          const auto run = run_of(key);
          if (run.second - run.first > kDenseCell)
            join_in_fine_cells(v, p, f, c);
          else
            for (size_t j = run.first; j < run.second && vertex_at(j) < v; ++j) join_if_close(v, p, f, vertex_at(j));
        }
  }

  // v against the earlier vertices of the fine cells around f that lie in the coarse cell c.
  void join_in_fine_cells(uint32_t v, const double* p, const Cell& f, const Cell& c) {
    for (int dx = -reach_; dx <= reach_; ++dx)
      for (int dy = -reach_; dy <= reach_; ++dy)
        for (int dz = -reach_; dz <= reach_; ++dz) {
          const Cell g = {f[0] + dx, f[1] + dy, f[2] + dz};
          if (coarse_of(g[0], shift_) != c[0] || coarse_of(g[1], shift_) != c[1] || coarse_of(g[2], shift_) != c[2])
            continue;
          const uint32_t id = fine_.find(g, cell_hash(g));
          if (id == CellTable::kNone) continue;
          for (uint32_t w = fine_members_.first[id]; w < v; w = fine_members_.next[w]) join_if_close(v, p, f, w);
        }
  }

  // The single-level grid's test: fine cells adjacent, distance within the tolerance.
  void join_if_close(uint32_t v, const double* p, const Cell& f, uint32_t w) {
    const double* q = pts_ + 3 * size_t(w);
    const Cell g = fine_cell(q, t_);
    for (int k = 0; k < 3; ++k)
      if (!(f[k] == g[k] || (reach_ && (f[k] == g[k] + 1 || f[k] + 1 == g[k])))) return;
    const double d[3] = {p[0] - q[0], p[1] - q[1], p[2] - q[2]};
    const bool close = t_ == 0 ? d[0] == 0 && d[1] == 0 && d[2] == 0 : d[0] * d[0] + d[1] * d[1] + d[2] * d[2] <= t2_;
    if (close) unions_ += groups_.unite(v, w);
  }

  const double* pts_;
  size_t n_;
  double t_, t2_;
  int reach_;  // fine cells compared around a vertex's own: 1, or 0 for exact equality
  int shift_;  // a coarse cell is 2^shift fine cells wide
  UnionFind& groups_;
  size_t unions_ = 0;
  KeyRule rule_;
  RawVector<uint8_t> border_;
  RawVector<uint64_t> sorted_;  // key << 32 | vertex, by key, then vertex
  CellTable fine_{0};           // the fine cells of dense coarse cells' vertices
  Members fine_members_;
};

// The points' bounding box.
Box box_of(const double* pts, size_t n) {
  Box box;
  if (n == 0) return box;
  for (int k = 0; k < 3; ++k) box.lo[k] = box.hi[k] = pts[k];
  for (size_t v = 0; v < n; ++v)
    for (int k = 0; k < 3; ++k) {
      box.lo[k] = std::min(box.lo[k], pts[3 * v + k]);
      box.hi[k] = std::max(box.hi[k], pts[3 * v + k]);
    }
  return box;
}

double diagonal_of(const Box& b) { return std::hypot(b.hi[0] - b.lo[0], b.hi[1] - b.lo[1], b.hi[2] - b.lo[2]); }

// The coarse cells' width in fine cells, 2^shift: about the mean spacing of n vertices on a
// surface that spans `diagonal`, so that a coarse cell holds about one vertex and a vertex's fine
// cell is seldom on its boundary.
int coarse_shift(double tolerance, double diagonal, size_t n) {
  if (tolerance == 0 || n == 0) return 0;
  const double spacing = diagonal / std::sqrt(double(n));
  int shift = 0;
  while (shift < 40 && std::ldexp(tolerance, shift + 1) <= spacing) ++shift;
  return shift;
}

// Each point's group (its lowest-indexed member); empty when no two points merge.
std::vector<uint32_t> groups_of(const double* pts, size_t n, double tolerance, const Box& box) {
  UnionFind groups(n);
  const int shift = coarse_shift(tolerance, diagonal_of(box), n);
  if (CloseVertices(pts, n, tolerance, shift, box, groups).run() == 0) return {};
  // (union_find.h: the smaller id is the root, so a group's root is its lowest-indexed vertex.)
  std::vector<uint32_t> root(n);
  for (uint32_t v = 0; v < n; ++v) root[v] = groups.find(v);
  return root;
}

// Whether some face has equal consecutive corners (the last and the first included), which
// renumber_faces collapses even when no vertex merged.
bool repeats_a_corner(const MeshView& mesh) {
  const uint32_t* in = mesh.indices;
  if (!mesh.face_sizes) {
    bool repeats = false;  // (no early exit, and | rather than ||: the loop vectorizes)
    for (size_t i = 0; i + 3 <= mesh.num_indices; i += 3)
      repeats |= (in[i] == in[i + 1]) | (in[i + 1] == in[i + 2]) | (in[i + 2] == in[i]);
    return repeats;
  }
  for (size_t f = 0, at = 0; f < mesh.num_faces; at += mesh.face_sizes[f++])
    for (size_t i = 0, k = mesh.face_sizes[f]; i < k; ++i)
      if (in[at + i] == in[at + (i + 1 == k ? 0 : i + 1)]) return true;
  return false;
}

// The faces with each corner replaced by its group's vertex; equal consecutive corners collapse,
// and faces left with fewer than three are dropped.
void renumber_faces(const MeshView& mesh, const std::vector<uint32_t>& root, WeldResult& out) {
  const size_t faces = mesh.face_sizes ? mesh.num_faces : mesh.num_indices / 3;
  if (!mesh.face_sizes) {  // triangles: one stays iff its three corners stay distinct
    out.mesh.indices.resize(mesh.num_indices);
    out.source_face.resize(faces);
    uint32_t* to = out.mesh.indices.data();
    size_t kept = 0;
    for (size_t f = 0; f < faces; ++f) {
      const uint32_t a = root[mesh.indices[3 * f]], b = root[mesh.indices[3 * f + 1]],
                     c = root[mesh.indices[3 * f + 2]];
      to[3 * kept] = a;
      to[3 * kept + 1] = b;
      to[3 * kept + 2] = c;
      out.source_face[kept] = uint32_t(f);
      kept += a != b && b != c && c != a;
    }
    out.dropped_faces = faces - kept;
    out.mesh.indices.resize(3 * kept);
    out.source_face.resize(kept);
    return;
  }
  out.mesh.indices.reserve(mesh.num_indices);
  out.source_face.reserve(faces);
  bool all_triangles = true;
  std::vector<uint32_t> loop;
  for (size_t f = 0, at = 0; f < faces; ++f) {
    const size_t size = mesh.face_sizes[f];
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
}

}  // namespace

WeldResult weld_vertices(const MeshView& mesh, double tolerance, bool relative) {
  WeldResult out;
  const size_t n = mesh.num_vertices;
  const Box box = box_of(mesh.positions, n);
  if (relative && n > 0) tolerance *= diagonal_of(box);
  if (!(tolerance >= 0) || !std::isfinite(tolerance)) tolerance = 0;
  out.tolerance = tolerance;
  std::vector<uint32_t> root = groups_of(mesh.positions, n, tolerance, box);
  if (root.empty()) {  // no vertex merged: the faces change only where they repeat a corner
    if (!repeats_a_corner(mesh)) {
      out.unchanged = true;
      return out;
    }
    root.resize(n);
    std::iota(root.begin(), root.end(), 0u);
  }
  for (uint32_t v = 0; v < n; ++v) out.merged_vertices += root[v] != v;
  out.mesh.positions.assign(mesh.positions, mesh.positions + 3 * n);
  renumber_faces(mesh, root, out);
  return out;
}

std::vector<uint32_t> weld_groups(const double* positions, size_t n, double tolerance) {
  std::vector<uint32_t> root = groups_of(positions, n, tolerance, box_of(positions, n));
  if (root.empty()) {
    root.resize(n);
    std::iota(root.begin(), root.end(), 0u);
  }
  return root;
}

}  // namespace kergen
