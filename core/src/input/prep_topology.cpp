// The topological phases of prepare_mesh (prep_state.h): faces cleaned of repeated consecutive
// vertices (clean_faces, which drops those left with fewer than 3 and counts the edge uses), the
// edge check that pairs the two uses of every edge by a counting sort (pair_edges, EdgePairing),
// the refusal of non-manifold, inconsistently oriented and open edges (report_edge_faults), the
// connected pieces (count_components), and distinct vertices at one position, where the surface
// touches itself (check_shared_positions).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "exact/predicates.h"
#include "input/prep_state.h"
#include "util/compiler_hints.h"
#include "util/plural.h"
#include "util/point_table.h"
#include "util/raw_vector.h"
#include "util/union_find.h"

namespace kergen::prep {

namespace {

// Whether two used vertices have the same position (coordinates compared with ==, so -0 and +0
// are one position), in expected linear time. A table of every vertex is larger than the caches
// on big meshes and every lookup missed; instead a first pass counts the vertices per bucket of
// their positions' hashes (saturating at two; two bits per bucket, about 8 buckets per vertex,
// so the counts stay in the caches) and keeps each vertex's bucket, and a second pass puts only
// the vertices of buckets met twice into a PointTable: both vertices of any shared position, and
// a few per cent of the others. The first pass takes the bounding box of the used vertices, in id
// order. The counts and buckets live in `scratch` (of `scratch_slots` words) when they fit.
bool has_shared_position(const std::vector<double>& pts, const std::vector<char>& used, size_t num_used, double lo3[3],
                         double hi3[3], uint64_t* scratch, size_t scratch_slots) {
  const double* P = pts.data();
  const char* us = used.data();
  const size_t nv = used.size();
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  auto take_box = [&](const double* p) KERGEN_INLINE {
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  };
  auto give_box = [&] {
    for (int k = 0; k < 3; ++k) {
      lo3[k] = lo[k];
      hi3[k] = hi[k];
    }
  };
  int bucket_bits = 6;
  while ((size_t(1) << bucket_bits) < 8 * num_used) ++bucket_bits;
  if (bucket_bits > 32) {  // (over 2^29 vertices: bucket ids of 32 bits do not suffice) a table of them all
    for (size_t v = 0; v < nv; ++v)
      if (us[v]) take_box(P + 3 * v);
    give_box();
    PointTable table(num_used);
    for (size_t v = 0; v < nv; ++v)
      if (us[v] && table.find_or_insert(P, P + 3 * v, PointTable::hash(P + 3 * v), uint32_t(v)) != v) return true;
    return false;
  }
  const int shift = 64 - bucket_bits;
  const size_t words = (size_t(1) << bucket_bits) / 32;  // (32 buckets of two bits a word)
  // The counts, then each used vertex's bucket (in id order), for the second pass.
  const size_t slots = words + (num_used + 1) / 2;
  RawVector<uint64_t> own;
  uint64_t* counts = scratch;
  if (!scratch || slots > scratch_slots) {
    own.resize(slots);
    counts = own.data();
  }
  std::fill(counts, counts + words, uint64_t(0));
  uint32_t* const bucket_of = reinterpret_cast<uint32_t*>(counts + words);
  // A block of used vertices at a time: their buckets first, with the count words prefetched,
  // then the counts (the words are in the caches by then, mostly).
  constexpr size_t kBlock = 64;
  size_t twice = 0, k = 0;  // buckets met twice, used vertices so far
  for (size_t v = 0; v < nv;) {
    const size_t k0 = k;
    for (; v < nv && k < k0 + kBlock; ++v) {
      if (!us[v]) continue;
      const double* p = P + 3 * v;
      take_box(p);
      bucket_of[k] = uint32_t(PointTable::hash(p) >> shift);
      prefetch(counts + (bucket_of[k] >> 5));
      ++k;
    }
    for (size_t j = k0; j < k; ++j) {
      const uint32_t b = bucket_of[j];
      const int at = int(2 * (b & 31));
      const uint64_t count = (counts[b >> 5] >> at) & 3;  // 0, 1, or 3 for two or more
      twice += count == 1;
      counts[b >> 5] |= ((count << 1 | 1) & 3) << at;
    }
  }
  give_box();
  if (twice == 0) return false;
  PointTable table(2 * twice + 16);  // (about as many vertices as that at the buckets met twice)
  // The candidates are taken a block at a time: their positions prefetched as they are found,
  // then hashed with their slots prefetched, then looked up in id order.
  uint32_t candidate[kBlock];
  uint64_t hash[kBlock];
  size_t found = 0;
  auto shared_in_block = [&] {
    for (size_t j = 0; j < found; ++j) {
      hash[j] = PointTable::hash(P + 3 * size_t(candidate[j]));
      table.prefetch_slot(hash[j]);
    }
    for (size_t j = 0; j < found; ++j)
      if (table.find_or_insert(P, P + 3 * size_t(candidate[j]), hash[j], candidate[j]) != candidate[j]) return true;
    found = 0;
    return false;
  };
  k = 0;
  for (size_t v = 0; v < nv; ++v) {
    if (!us[v]) continue;
    const uint32_t b = bucket_of[k];
    if (k + 32 < num_used) prefetch(counts + (bucket_of[k + 32] >> 5));
    ++k;
    if (((counts[b >> 5] >> (2 * (b & 31))) & 3) != 3) continue;
    prefetch(P + 3 * v);
    candidate[found++] = uint32_t(v);
    if (found == kBlock && shared_in_block()) return true;
  }
  return shared_in_block();
}

// The bounding box of the used vertices, taken in id order (as has_shared_position takes it).
void used_box(const std::vector<double>& pts, const std::vector<char>& used, double lo3[3], double hi3[3]) {
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  const double* P = pts.data();
  for (size_t v = 0; v < used.size(); ++v) {
    if (!used[v]) continue;
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], P[3 * v + k]);
      hi[k] = std::max(hi[k], P[3 * v + k]);
    }
  }
  for (int k = 0; k < 3; ++k) {
    lo3[k] = lo[k];
    hi3[k] = hi[k];
  }
}

// The pair reported when used vertices share a position: the two lowest ids at the
// lexicographically smallest shared position (a sort, run only once a pair is known to exist).
std::array<uint32_t, 2> first_shared_position(const std::vector<double>& pts, const std::vector<char>& used) {
  std::vector<uint32_t> order;
  for (uint32_t v = 0; v < used.size(); ++v)
    if (used[v]) order.push_back(v);
  auto at = [&](uint32_t v) { return &pts[3 * size_t(v)]; };
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    const double *p = at(a), *q = at(b);
    return p[0] != q[0] ? p[0] < q[0] : (p[1] != q[1] ? p[1] < q[1] : (p[2] != q[2] ? p[2] < q[2] : a < b));
  });
  for (size_t i = 1; i < order.size(); ++i) {
    const double *p = at(order[i - 1]), *q = at(order[i]);
    if (p[0] == q[0] && p[1] == q[1] && p[2] == q[2]) return {order[i - 1], order[i]};
  }
  return {0, 0};  // not reached: called only when a shared position exists
}

// The edge uses as the counting sort leaves them, use j of a bucket read by upper(j) (its upper
// vertex) and face(j). Polygons: two arrays indexed alike. Triangles: one array of use ids
// 3 f + c (the edge from corner c of clean face f to the next corner), half the bytes; the
// upper vertex is read from the face (the faces using one vertex are mostly near each other).
struct SeparateUses {
  const uint32_t* upper_id;
  const uint32_t* use_face;
  KERGEN_INLINE uint32_t upper(size_t j) const { return upper_id[j]; }
  KERGEN_INLINE uint32_t face(size_t j) const { return use_face[j]; }
};
struct TriangleUses {
  const uint32_t* use_id;
  const uint32_t* cl;  // the clean loops, face f at 3 f
  KERGEN_INLINE uint32_t upper(size_t j) const {
    const uint32_t u = use_id[j], corner = u % 3;
    return std::max(cl[u], cl[corner == 2 ? u - 2 : u + 1]);
  }
  KERGEN_INLINE uint32_t face(size_t j) const { return use_id[j] / 3; }
};

// The edge check's pass over the edge uses, bucketed (Prep::bucket) by lower vertex: the uses of
// the edges of one lower vertex are marked per upper vertex (4 bytes a vertex), or tallied when
// they do not pair up, then each edge is judged once. On a
// closed, consistently oriented 2-manifold every edge has one use each way, and its two faces
// are a pair. Pairs are listed by lower vertex id, then in the order of the faces using the edge
// upwards; each pair lists its lower face first. At most one pair per two uses; written through
// a pointer (push_back went through a stack copy, a store-forwarding stall) into the storage
// of the uses themselves (pair_edges), behind the uses still to be read.
template <class Uses>
class EdgePairing {
 public:
  EdgePairing(Prep& s, Uses uses, size_t nv)
      : s_(s), uses_(uses), mark_(nv), parent_(s.components.parent.data()), pair_out_(s.face_pairs.data()) {}
  void pair_all(size_t nv) {
    const uint32_t* start = s_.bucket.data();  // (bucket b is [start[b], start[b + 1]))
    for (size_t lo = 0; lo < nv; ++lo) pair_lower_vertex(lo, start[2 * lo], start[2 * lo + 1], start[2 * lo + 2]);
    s_.face_pairs.resize(size_t(pair_out_ - s_.face_pairs.data()));
  }

 private:
  struct Tally {
    uint32_t up = 0, down = 0, up_face = 0, down_face = 0;
  };
  // (Nine finds in ten end within one step, about half of them at once: both cases are taken
  // without a branch on which, which mispredicted often.)
  KERGEN_INLINE uint32_t find(uint32_t x) const {
    const uint32_t up = parent_[x], up2 = parent_[up];
    if (up2 == up) return up;
    x = up;
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  // (the smaller root wins, as in UnionFind::unite)
  KERGEN_INLINE void unite(uint32_t f0, uint32_t f1) {
    const uint32_t r0 = find(f0), r1 = find(f1);
    if (r0 != r1) {
      parent_[std::max(r0, r1)] = std::min(r0, r1);
      ++s_.unions;
    }
  }
  // The uses of lo's edges: [down_begin, up_begin) run down to lo, [up_begin, end) up from it.
  // Their upper ids and faces are read once, into upper_ids_ and faces_ (the pairs are written
  // over the uses: judge() may write pairs over uses not read yet).
  KERGEN_INLINE void pair_lower_vertex(size_t lo, size_t down_begin, size_t up_begin, size_t end) {
    const size_t downs = up_begin - down_begin, ups = end - up_begin;
    if (end - down_begin > upper_ids_.size()) {
      upper_ids_.resize(2 * (end - down_begin));
      faces_.resize(2 * (end - down_begin));
      match_.resize(2 * (end - down_begin));
    }
    uint32_t* const hi_of = upper_ids_.data();
    uint32_t* const face_of = faces_.data();
    for (size_t i = 0; i != downs + ups; ++i) {
      hi_of[i] = uses_.upper(down_begin + i);
      face_of[i] = uses_.face(down_begin + i);
    }
    // Each edge of lo (each upper vertex) has one mark: the index + 1 of its one downward use,
    // kManyDowns, or 0 for none; and kUpSeen once an upward use met it. When every upward use
    // meets an edge with one downward use and no upward use yet, and there are as many downward
    // uses, every edge of lo has one use each way: its pairs are the ones judge() would make, in
    // the same order, and each mark is cleared as its pair is written.
    bool paired = ups == downs && downs + ups < kManyDowns;
    for (size_t i = 0; i != downs; ++i) {
      uint32_t& mark = mark_[hi_of[i]];
      mark = mark == 0 ? uint32_t(i + 1) : kManyDowns;
    }
    uint32_t* const match = match_.data();
    for (size_t i = downs; i != downs + ups; ++i) {
      uint32_t& mark = mark_[hi_of[i]];
      paired &= mark != 0 && mark < kManyDowns;  // (none, several, or kUpSeen set: no pair)
      match[i] = mark - 1;
      mark |= kUpSeen;
    }
    if (paired) {
      for (size_t i = downs; i != downs + ups; ++i) {
        const uint32_t up_face = face_of[i], down_face = face_of[match[i]];
        const uint32_t f0 = std::min(up_face, down_face), f1 = std::max(up_face, down_face);
        mark_[hi_of[i]] = 0;
        (*pair_out_)[0] = f0;
        (*pair_out_)[1] = f1;
        ++pair_out_;
        unite(f0, f1);
      }
      return;
    }
    for (size_t i = 0; i != downs + ups; ++i) mark_[hi_of[i]] = 0;
    judge_each(lo, downs, ups);
  }
  // The edges of lo judged one by one (a fault, or an open mesh), their uses tallied in a table
  // of their own: tally(hi), cleared by judge().
  void judge_each(size_t lo, size_t downs, size_t ups) {
    const uint32_t* const hi_of = upper_ids_.data();
    const uint32_t* const face_of = faces_.data();
    size_t slots = 16;
    while (slots < 2 * (downs + ups)) slots <<= 1;
    tally_key_.assign(slots, kNoKey);
    tally_slot_.assign(slots, Tally{});
    for (size_t i = 0; i != downs; ++i) {
      Tally& t = tally(hi_of[i]);
      ++t.down;
      t.down_face = face_of[i];
    }
    for (size_t i = downs; i != downs + ups; ++i) {
      Tally& t = tally(hi_of[i]);
      ++t.up;
      t.up_face = face_of[i];
    }
    std::array<uint32_t, 2>* const pairs_before = pair_out_;
    for (size_t i = downs; i != downs + ups; ++i) judge(lo, hi_of[i]);
    // (as many pairs as downward uses: each pair took one, all are judged and cleared)
    if (size_t(pair_out_ - pairs_before) == downs) return;
    for (size_t i = 0; i != downs; ++i) judge(lo, hi_of[i]);
  }
  Tally& tally(uint32_t hi) {
    const size_t mask = tally_key_.size() - 1;
    for (size_t slot = size_t(uint64_t(hi) * 0x9e3779b97f4a7c15ull >> 32) & mask;; slot = (slot + 1) & mask) {
      if (tally_key_[slot] == hi) return tally_slot_[slot];
      if (tally_key_[slot] == kNoKey) {
        tally_key_[slot] = hi;
        return tally_slot_[slot];
      }
    }
  }
  // Edge (lo, hi), judged at its first upward use, or first downward use if it has none; then
  // its tally is cleared.
  void judge(size_t lo, uint32_t hi) {
    Tally& t = tally(hi);
    if (t.up == 1 && t.down == 1) {
      const uint32_t f0 = std::min(t.up_face, t.down_face), f1 = std::max(t.up_face, t.down_face);
      (*pair_out_)[0] = f0;
      (*pair_out_)[1] = f1;
      ++pair_out_;
      unite(f0, f1);
    } else if (t.up + t.down > 0) {  // else judged already
      const uint64_t key = uint64_t(lo) << 32 | hi;
      const size_t n = size_t(t.up) + t.down;
      if (n == 1)
        note(s_.open, s_.open_ex, key);
      else if (n > 2)
        note(s_.nonmanifold, s_.nonmanifold_ex, key);
      else
        note(s_.inconsistent, s_.inconsistent_ex, key);  // two uses the same way
    }
    t = Tally{};
  }
  static void note(size_t& count, uint64_t& example, uint64_t key) {
    ++count;
    example = std::min(example, key);
  }
  Prep& s_;
  Uses uses_;
  static constexpr uint32_t kUpSeen = 0x80000000u, kManyDowns = 0x7fffffffu;
  static constexpr uint64_t kNoKey = ~uint64_t(0);
  std::vector<uint32_t> mark_;       // per upper vertex id; all zero between lower vertices
  std::vector<uint64_t> tally_key_;  // judge_each's table: upper ids, or kNoKey
  std::vector<Tally> tally_slot_;
  // lo's uses (match: for an upward use, the index of the downward use of its edge)
  std::vector<uint32_t> upper_ids_ = std::vector<uint32_t>(64), faces_ = std::vector<uint32_t>(64),
                        match_ = std::vector<uint32_t>(64);
  uint32_t* parent_;
  std::array<uint32_t, 2>* pair_out_;
};

std::string edge_name(uint64_t k) {
  return "(" + std::to_string(uint32_t(k >> 32)) + ", " + std::to_string(uint32_t(k & 0xffffffffu)) + ")";
}

// The refusal of the first index out of range, in face f (the input's numbering).
bool fail_index(Prep& s, size_t f, uint32_t index) {
  std::ostringstream msg;
  msg << "face " << f << " refers to vertex " << index << " but the mesh has " << s.nv << " vertices";
  return s.fail(Error::IndexOutOfRange, msg.str());
}

}  // namespace

// Faces without repeated consecutive vertices; faces left with < 3 distinct vertices carry no
// area and no edges of their own (a -> b -> a pairs cancel), so they are dropped here. The same
// pass refuses the first index out of range (each face is checked before it is used), marks the
// used vertices and counts the edge uses per bucket (Prep::bucket). (Raw pointers
// in the loops: the stores through char would otherwise make the compiler reload every vector's
// pointers after each one.)
bool clean_faces(Prep& s) {
  const MeshView& mesh = s.mesh;
  const size_t nf = s.nf, nv = s.nv;
  s.used.assign(s.nv, 0);
  s.bucket.assign(2 * s.nv + 2, 0);
  const uint32_t* in = mesh.indices;
  char* us = s.used.data();
  uint32_t* count = s.bucket.data() + 1;
  // (bucket 2 lo + 1 < 2 hi, bucket 2 lo < 2 hi + 1: the smaller is the use's bucket)
  auto count_use = [count](uint32_t u, uint32_t v) { count[std::min(2 * size_t(u) + 1, 2 * size_t(v))]++; };
  // The usual leading run of a triangle mesh: face f is at 3 f. For a verdict, when the run is
  // the whole mesh, the clean faces are the input's (Prep::cl), else the run is copied after;
  // for the faces, it is copied as it is read (the loops are the result's).
  size_t f = 0;
  auto leading_run = [&](uint32_t* copy) KERGEN_INLINE {
    for (; f < nf; ++f, in += 3) {
      const uint32_t a = in[0], b = in[1], c = in[2];
      if (a == b || b == c || c == a || std::max(a, std::max(b, c)) >= nv) break;
      if (copy) {
        copy[3 * f] = a;
        copy[3 * f + 1] = b;
        copy[3 * f + 2] = c;
      }
      us[a] = us[b] = us[c] = 1;
      count_use(a, b);
      count_use(b, c);
      count_use(c, a);
    }
  };
  if (!mesh.face_sizes && s.verdict_only) {
    leading_run(nullptr);
    if (f == nf) {
      s.cl = mesh.indices;
      s.clean_size = 3 * nf;
      s.clean_viewed = true;
      s.cf = nf;
      return true;
    }
  }
  s.clean.resize(mesh.num_indices);  // (written in full below)
  s.clean_offsets.resize(nf + 1);
  uint32_t* cl = s.clean.data();
  uint32_t* off = s.clean_offsets.data();
  if (!mesh.face_sizes && !s.verdict_only)
    leading_run(cl);
  else
    std::copy(mesh.indices, mesh.indices + 3 * f, cl);
  for (size_t g = 0; g <= f; ++g) off[g] = uint32_t(3 * g);
  size_t n = 3 * f, dropped = 0, cf = f;  // clean entries so far, faces dropped, clean faces
  for (; f < nf; ++f) {
    const size_t begin = n, k = mesh.face_sizes ? mesh.face_sizes[f] : 3;
    if (k == 3 && in[0] != in[1] && in[1] != in[2] && in[2] != in[0] &&
        std::max(in[0], std::max(in[1], in[2])) < nv) {  // the usual case
      const uint32_t a = in[0], b = in[1], c = in[2];
      cl[n] = a;
      cl[n + 1] = b;
      cl[n + 2] = c;
      n += 3;
      in += 3;
      off[++cf] = uint32_t(n);
      if (s.clean_renumbered) s.clean_source.push_back(uint32_t(f));
      us[a] = us[b] = us[c] = 1;
      count_use(a, b);
      count_use(b, c);
      count_use(c, a);
      continue;
    }
    for (size_t i = 0; i < k; ++i)
      if (in[i] >= nv) return fail_index(s, f, in[i]);
    for (size_t i = 0; i < k; ++i)
      if (n == begin || cl[n - 1] != in[i]) cl[n++] = in[i];
    while (n - begin > 1 && cl[n - 1] == cl[begin]) --n;
    in += k;
    if (n - begin < 3) {
      n = begin;
      ++dropped;
      if (!s.clean_renumbered) {
        s.clean_renumbered = true;
        s.clean_source.resize(cf);
        std::iota(s.clean_source.begin(), s.clean_source.end(), 0u);
      }
      continue;
    }
    off[++cf] = uint32_t(n);
    if (s.clean_renumbered) s.clean_source.push_back(uint32_t(f));
    for (size_t i = begin; i < n; ++i) {
      const uint32_t u = cl[i], v = cl[i + 1 < n ? i + 1 : begin];
      us[u] = 1;
      count_use(u, v);
    }
  }
  s.clean.resize(n);
  s.clean_offsets.resize(cf + 1);
  s.cl = s.clean.data();
  s.clean_size = n;
  s.m.dropped_faces += dropped;
  s.cf = cf;
  return true;
}

bool check_faces_left(Prep& s) {
  if (s.cf == 0) return s.fail(Error::DegenerateInput, "every face has fewer than 3 distinct vertices");
  return true;
}

// The edge check: a counting sort of the edge uses into their buckets (no hashing and no
// comparison sort), then EdgePairing. The uses take no fresh memory where that can be avoided
// (first touches of fresh pages are costly): their faces go into the pairs' storage, which holds
// one face per use, and the pairs are written over the uses already read. The upper ids go into
// the representatives' storage (written after the check) when it holds one id per use, which is
// when every face is a triangle; a verdict writes no representatives, and its triangles' uses
// are 4-byte use ids in the pairs' storage alone (TriangleUses). Polygons take a separate array.
void pair_edges(Prep& s) {
  const size_t nv = s.nv, cf = s.cf;
  std::vector<uint32_t>& bucket = s.bucket;
  // Bucket b's size is bucket[b + 1]: it becomes the bucket's start (a running sum), then its
  // fill's cursor, and ends at the bucket's end, the start of bucket b + 1 (no separate cursor
  // array). Then bucket b is [bucket[b], bucket[b + 1]) (bucket[0] = 0). Filled in face order,
  // the buckets keep the uses in face order.
  uint32_t total_uses = 0;  // (the running sum stays in a register)
  for (size_t b = 1; b <= 2 * nv; ++b) {
    const uint32_t size = bucket[b];
    bucket[b] = total_uses;
    total_uses += size;
  }
  s.components = UnionFind(cf);
  s.face_pairs.resize((size_t(total_uses) + 1) / 2);  // (taken by find_shared_positions already)
  static_assert(sizeof(std::array<uint32_t, 2>) == 2 * sizeof(uint32_t), "packed pairs");
  uint32_t* const pair_storage = reinterpret_cast<uint32_t*>(s.face_pairs.data());
  const uint32_t* cl = s.cl;
  uint32_t* cursor = bucket.data() + 1;
  auto slot_of = [cursor](uint32_t u, uint32_t v) { return cursor[std::min(2 * size_t(u) + 1, 2 * size_t(v))]++; };
  if (total_uses == 3 * cf && s.verdict_only) {  // every clean face is a triangle
    // The same pass over the faces sums their fans' volume (sum_fan_volume's, in its order) and
    // finds the end of the leading run of triangles the float filter certifies.
    take_centre(s);
    double vol6 = 0, vol6_abs = 0;
    size_t first_general = cf;
    uint32_t* use_id = pair_storage;
    // The terms of a block of faces at a time (triangle_block_terms, vectorized), summed in face
    // order.
    double term[kTermBlock];
    for (size_t f0 = 0; f0 < cf; f0 += kTermBlock) {
      const size_t n = std::min(kTermBlock, cf - f0);
      const uint64_t uncertain = triangle_block_terms(s, cl + 3 * f0, n, term);
      if (first_general == cf && uncertain) first_general = f0 + size_t(__builtin_ctzll(uncertain));
      for (size_t j = 0; j < n; ++j) {
        const size_t f = f0 + j;
        const uint32_t a = cl[3 * f], b = cl[3 * f + 1], c = cl[3 * f + 2], u = uint32_t(3 * f);
        use_id[slot_of(a, b)] = u;
        use_id[slot_of(b, c)] = u + 1;
        use_id[slot_of(c, a)] = u + 2;
        vol6 += term[j];
        vol6_abs += std::fabs(term[j]);
      }
    }
    s.vol6 = vol6;
    s.vol6_abs = vol6_abs;
    s.first_general = first_general;
    s.volume_summed = true;
    EdgePairing<TriangleUses>(s, TriangleUses{use_id, cl}, nv).pair_all(nv);
    return;
  }
  // (The faces' representatives are written after the check: when there are as many as uses,
  // their storage holds the upper ids meanwhile.)
  static_assert(sizeof(std::array<uint32_t, 3>) == 3 * sizeof(uint32_t), "packed representatives");
  RawVector<uint32_t> upper_store;
  uint32_t* upper;
  if (total_uses == 3 * cf) {
    s.m.rep.resize(cf);
    upper = reinterpret_cast<uint32_t*>(s.m.rep.data());
  } else {
    upper_store.resize(total_uses);
    upper = upper_store.data();
  }
  uint32_t* use_face = pair_storage;
  auto put = [&](uint32_t u, uint32_t v, uint32_t f) KERGEN_INLINE {
    const uint32_t slot = slot_of(u, v);
    upper[slot] = std::max(u, v);
    use_face[slot] = f;
  };
  if (total_uses == 3 * cf) {
    for (size_t f = 0; f < cf; ++f) {
      const uint32_t a = cl[3 * f], b = cl[3 * f + 1], c = cl[3 * f + 2];
      put(a, b, uint32_t(f));
      put(b, c, uint32_t(f));
      put(c, a, uint32_t(f));
    }
  } else {
    const uint32_t* off = s.clean_offsets.data();
    for (size_t f = 0; f < cf; ++f) {
      const size_t b = off[f], e = off[f + 1];
      for (size_t i = b; i < e; ++i) put(cl[i], cl[i + 1 < e ? i + 1 : b], uint32_t(f));
    }
  }
  EdgePairing<SeparateUses>(s, SeparateUses{upper, use_face}, nv).pair_all(nv);
}

// Refuses non-manifold, inconsistently oriented and (unless allowed) open edges, in that order.
bool report_edge_faults(Prep& s) {
  if (s.nonmanifold) {
    return s.fail(Error::NonManifoldEdge,
                  count_of(s.nonmanifold, "edge", "edges") + verb_for(s.nonmanifold, " is", " are") +
                      " shared by more than two faces, e.g. edge " + edge_name(s.nonmanifold_ex) +
                      " (repeated faces? Options::repair removes them)");
  }
  if (s.inconsistent) {
    return s.fail(Error::InconsistentOrientation,
                  count_of(s.inconsistent, "edge", "edges") + verb_for(s.inconsistent, " is", " are") +
                      " traversed in the same direction by both of their faces (inconsistent "
                      "orientation), e.g. edge " +
                      edge_name(s.inconsistent_ex));
  }
  if (s.open && !s.options.allow_open) {
    // What may close it that was not done already (a mesh welded or repaired is not told to be).
    std::string closers;
    if (s.options.weld < 0) closers = "Options::weld merges nearly coincident vertices";
    if (!s.options.repair)
      closers += closers.empty() ? "Options::repair merges equal positions and splits T-junctions"
                                 : ", Options::repair also splits T-junctions";
    return s.fail(Error::OpenMesh, "the mesh is open: " + count_of(s.open, "edge", "edges") +
                                       verb_for(s.open, " belongs", " belong") + " to one face only, e.g. edge " +
                                       edge_name(s.open_ex) + " (" + closers + (closers.empty() ? "" : "; ") +
                                       "Options::allow_open accepts open meshes)");
  }
  s.m.boundary_edges = s.open;
  return true;
}

// Connected pieces. Faces joined by boundary edges only are joined through vertices. Several
// closed pieces are the caller's to judge (shells.h) when it says so; an open one is refused.
bool count_components(Prep& s) {
  if (s.open) {
    s.own_clean();
    std::vector<uint32_t> first_face(s.nv, 0xffffffffu);
    for (size_t f = 0; f < s.cf; ++f)
      for (size_t i = s.clean_offsets[f]; i < s.clean_offsets[f + 1]; ++i) {
        uint32_t v = s.clean[i];
        if (first_face[v] == 0xffffffffu)
          first_face[v] = uint32_t(f);
        else
          s.unions += s.components.unite(first_face[v], uint32_t(f));
      }
  }
  const size_t pieces = s.cf - s.unions;
  s.m.shells = pieces;
  if (pieces > 1 && (s.open || !s.allow_shells)) {
    return s.fail(Error::MultipleComponents,
                  "the mesh has " + std::to_string(pieces) +
                      " separate pieces; the kernel is defined for one closed surface (a triangle soup? "
                      "Options::weld merges its corners)");
  }
  return true;
}

// Unused vertices are a warning. Two distinct vertices of a closed surface at one position: the
// surface touches itself there (it is not embedded), and the intersection of its face
// half-spaces is then not its kernel — refused rather than answered wrongly (once the edges and
// pieces are judged: check_shared_positions). The same pass takes the bounding box of the used
// vertices (Prep::lo3, hi3).
void find_shared_positions(Prep& s) {
  s.unused = s.nv - size_t(std::count(s.used.begin(), s.used.end(), 1));
  // The pairs' storage, taken now (one pair per two edge uses, one use per clean loop entry),
  // is filled by the edge check only: the bucket counts live there (no fresh pages).
  s.face_pairs.resize((s.clean_size + 1) / 2);
  uint64_t* scratch = reinterpret_cast<uint64_t*>(s.face_pairs.data());
  const size_t scratch_slots = s.face_pairs.size() * sizeof(s.face_pairs[0]) / sizeof(uint64_t);
  if (s.positions_distinct) {
    used_box(s.m.points, s.used, s.lo3, s.hi3);
    return;
  }
  s.shared_position = has_shared_position(s.m.points, s.used, s.nv - s.unused, s.lo3, s.hi3, scratch, scratch_slots);
}

bool check_shared_positions(Prep& s) {
  if (s.unused) s.m.warnings.push_back(unused_vertices_warning(s.unused));
  if (!s.shared_position) return true;
  const auto pair = first_shared_position(s.m.points, s.used);
  return s.fail(Error::NonManifoldEdge,
                "vertices " + std::to_string(pair[0]) + " and " + std::to_string(pair[1]) +
                    " have the same position: the surface touches itself there (weld them, or separate the pieces)");
}

}  // namespace kergen::prep
