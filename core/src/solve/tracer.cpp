// Kernel edge tracing on exact predicates.
//  - A vertex is identified by its exact tight plane set; its coordinates always come from a
//    defining plane triple (or are an input point), never accumulated along the walk.
//  - Valid directions at v: for tight planes p, q, the ray sigma * (n_p x n_q) stays in the kernel
//    iff sigma * det3(n_r, n_p, n_q) <= 0 for every other tight r. A ray is keyed by the planes
//    containing it, so each kernel edge is traced once, however many planes meet along it.
//  - Nearest plane along a ray: a double scan (structure of arrays, no exactness needed) proposes
//    a winner; an exact certification of the candidate vertex either returns its complete tight
//    set or a plane that cuts the segment earlier, which becomes the next candidate.
#include "solve/tracer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <iterator>
#include <limits>
#include <optional>

#include "solve/vertex_filter.h"
#include "util/compiler_hints.h"
#include "util/flat_map.h"

namespace kergen {

namespace {

// The two hot loops of tracing run over the structure-of-arrays plane store four planes at a
// time (vector extensions: SSE2 pairs, AVX2 where the CPU has it — function multi-versioning
// picks at load time; plain scalar code on targets without it). Array lengths are padded to a
// multiple of kLanes with planes that never hit a ray (n = 0) and are never near (d = -1).
constexpr size_t kLanes = 4;
typedef double Vec4 __attribute__((vector_size(32)));
typedef int64_t Mask4 __attribute__((vector_size(32)));
// Unaligned view of four consecutive doubles (no helper functions: clones must not call code
// compiled for another target).
typedef double Vec4Unaligned __attribute__((vector_size(32), aligned(8), may_alias));
#define KERGEN_LOAD4(ptr) (*reinterpret_cast<const Vec4Unaligned*>(ptr))
// Whether any lane of a Mask4 is set. On x86 the two halves' sign bits (movmskpd, SSE2, so in
// every clone); element by element elsewhere (GCC moves each lane to an integer register).
#if defined(__SSE2__)
typedef double Vec2Mask __attribute__((vector_size(16)));
#define KERGEN_ANY4(m)                                                                          \
  (__builtin_ia32_movmskpd(reinterpret_cast<Vec2Mask>(__builtin_shufflevector((m), (m), 0, 1) | \
                                                      __builtin_shufflevector((m), (m), 2, 3))) != 0)
#else
#define KERGEN_ANY4(m) (((m)[0] | (m)[1] | (m)[2] | (m)[3]) != 0)
#endif

// Index of the smallest positive hit t_i = -f_i(p) / (n_i . u) over planes approaching along u
// (n_i . u > 0), or n when none approaches; the lowest such index on ties. Each lane keeps its
// smallest hit and where it was first met (strict <, so the lowest index of the lane); the lanes
// are merged at the end. (Indices are exact as doubles: n is far below 2^53.)
KERGEN_MULTIVERSION
size_t nearest_hit(const double* ax, const double* ay, const double* az, const double* ad, size_t n, const double p[3],
                   const double u[3]) {
  const double inf = std::numeric_limits<double>::infinity();
  const Vec4 inf4 = {inf, inf, inf, inf}, zero4 = {0, 0, 0, 0}, four = {4, 4, 4, 4};
  const Vec4 x = {p[0], p[0], p[0], p[0]}, y = {p[1], p[1], p[1], p[1]}, z = {p[2], p[2], p[2], p[2]};
  const Vec4 u0 = {u[0], u[0], u[0], u[0]}, u1 = {u[1], u[1], u[1], u[1]}, u2 = {u[2], u[2], u[2], u[2]};
  Vec4 lo = inf4, lo_index = inf4, index = {0, 1, 2, 3};
  for (size_t i = 0; i < n; i += kLanes) {
    const Vec4 X = KERGEN_LOAD4(ax + i), Y = KERGEN_LOAD4(ay + i), Z = KERGEN_LOAD4(az + i), D = KERGEN_LOAD4(ad + i);
    const Vec4 a = X * u0 + Y * u1 + Z * u2;
    const Vec4 f = X * x + Y * y + Z * z + D;
    const Vec4 t = a > zero4 ? -f / a : inf4;
    const Mask4 better = t < lo;
    lo = better ? t : lo;
    lo_index = better ? index : lo_index;
    index += four;
  }
  double best = inf, best_index = inf;
  for (size_t k = 0; k < kLanes; ++k)
    if (lo[k] < best || (lo[k] == best && lo_index[k] < best_index)) {
      best = lo[k];
      best_index = lo_index[k];
    }
  return best < inf ? size_t(best_index) : n;
}

// Indices of the planes whose value at p is not certainly negative: f_i(p) >= -b_i with the
// rigorous bound b_i = ben_i c1 + bn1_i c2 + be0_i (exact/error_bounds.h, vertex_filter_bound,
// in the same order of operations).
KERGEN_MULTIVERSION
void near_planes(const double* ax, const double* ay, const double* az, const double* ad, const double* bn1,
                 const double* ben, const double* be0, size_t n, const double p[3], double c1, double c2,
                 std::vector<uint32_t>& out) {
  const double ms = -exact::kBoundScale;
  const Vec4 x = {p[0], p[0], p[0], p[0]}, y = {p[1], p[1], p[1], p[1]}, z = {p[2], p[2], p[2], p[2]};
  const Vec4 C1 = {c1, c1, c1, c1}, C2 = {c2, c2, c2, c2}, scale = {ms, ms, ms, ms};
  for (size_t i = 0; i < n; i += kLanes) {
    const Vec4 f =
        KERGEN_LOAD4(ax + i) * x + KERGEN_LOAD4(ay + i) * y + KERGEN_LOAD4(az + i) * z + KERGEN_LOAD4(ad + i);
    const Vec4 b = KERGEN_LOAD4(ben + i) * C1 + KERGEN_LOAD4(bn1 + i) * C2 + KERGEN_LOAD4(be0 + i);
    const Mask4 near = f >= b * scale;
    if (!KERGEN_ANY4(near)) continue;
    for (size_t k = 0; k < kLanes; ++k)
      if (near[k]) out.push_back(uint32_t(i + k));
  }
}

}  // namespace

namespace {

struct Ray {
  uint32_t from;
  uint32_t p, q;
  int sigma;
  uint32_t line_begin, line_size;  // planes containing the ray's line, in the tracer's line pool
  uint64_t key;
};

template <class Ids>
uint64_t line_key(const PlaneSet& ps, const Ids& planes) {
  // Two non-parallel planes determine the line; among planes through one line the only
  // parallel pairs are opposite planes. Canonical choice: the smallest id and the smallest
  // id that is neither it nor its opposite.
  uint32_t a = planes[0];
  uint32_t b = kNoPlane;
  for (size_t i = 1; i < planes.size(); ++i)
    if (planes[i] != ps.opposite(a)) {
      b = planes[i];
      break;
    }
  return (uint64_t(a) << 32) | b;
}

// Vertex id by tight plane set (a vertex's identity): open addressing on a hash of the set,
// every hit confirmed against the stored set. One flat table instead of a tree of vector keys,
// whose node and key copies were a large part of tracing a small kernel.
class VertexIndex {
 public:
  template <class Ids>
  uint32_t find(const Ids& tight, const std::vector<TracedVertex>& vertices) const {
    if (slots_.empty()) return kNoVertex;
    const uint64_t h = hash(tight);
    for (size_t i = h & mask_;; i = (i + 1) & mask_) {
      const Slot& s = slots_[i];
      if (s.id == kNoVertex) return kNoVertex;
      if (s.hash == h && vertices[s.id].tight == tight) return s.id;
    }
  }
  // The caller guarantees that no vertex with this tight set is indexed yet.
  template <class Ids>
  void insert(const Ids& tight, uint32_t id) {
    if (2 * (size_ + 1) > slots_.size()) grow();
    place({hash(tight), id});
    ++size_;
  }

 private:
  struct Slot {
    uint64_t hash;
    uint32_t id;
  };
  template <class Ids>
  static uint64_t hash(const Ids& tight) {
    uint64_t h = 0x9E3779B97F4A7C15ull ^ tight.size();
    for (uint32_t l : tight) h = (h ^ l) * 0xff51afd7ed558ccdull;
    return h ^ (h >> 29);
  }
  void place(const Slot& x) {
    size_t i = x.hash & mask_;
    while (slots_[i].id != kNoVertex) i = (i + 1) & mask_;
    slots_[i] = x;
  }
  void grow() {
    std::vector<Slot> old;
    old.swap(slots_);
    slots_.assign(old.empty() ? 32 : 2 * old.size(), Slot{0, kNoVertex});
    mask_ = slots_.size() - 1;
    for (const Slot& x : old)
      if (x.id != kNoVertex) place(x);
  }
  std::vector<Slot> slots_;
  size_t mask_ = 0, size_ = 0;
};

// The planes a trace certifies against: a structure-of-arrays copy of a list of planes (doubles
// and the vertex filter's per-plane terms, exact/error_bounds.h), padded to a multiple of kLanes
// with planes that never hit a ray (n = 0) and are never near (d = -1, no error). (Culling's
// PlaneArrays is a view of coefficients with their raw error bounds, for the support test.)
struct CertifyPlanes {
  // Seven arrays of `size` doubles in one allocation (a small trace builds these once, and
  // seven allocations were a tenth of its calls to malloc).
  std::vector<double> buf;
  size_t size = 0;
  double *ax = nullptr, *ay = nullptr, *az = nullptr, *ad = nullptr;
  double *bn1 = nullptr, *ben = nullptr, *be0 = nullptr;  // per plane: |n|_1, error of n, of d + rounding

  CertifyPlanes() = default;
  CertifyPlanes(const CertifyPlanes&) = delete;  // the pointers point into buf
  CertifyPlanes& operator=(const CertifyPlanes&) = delete;

  void build(const PlaneSet& ps, const std::vector<uint32_t>& list) {
    const size_t n = list.size(), padded = (n + kLanes - 1) / kLanes * kLanes;
    size = padded;
    buf.assign(7 * padded, 0);
    double* arrays[7];
    for (size_t a = 0; a < 7; ++a) arrays[a] = buf.data() + a * padded;
    ax = arrays[0], ay = arrays[1], az = arrays[2], ad = arrays[3], bn1 = arrays[4], ben = arrays[5], be0 = arrays[6];
    std::fill(ad, ad + padded, -1.0);
    for (size_t i = 0; i < n; ++i) {
      uint32_t l = list[i];
      ax[i] = ps.nx()[l];
      ay[i] = ps.ny()[l];
      az[i] = ps.nz()[l];
      ad[i] = ps.d()[l];
      const auto c = ps.approx(l);
      const PlaneFilterTerms t = plane_filter_terms(ax[i], ay[i], az[i], ad[i], c.n[0].e, c.n[1].e, c.n[2].e, c.d.e);
      bn1[i] = t.n1;
      ben[i] = t.en;
      be0[i] = t.e0;
    }
  }

  // Indices (into the list) of the planes whose sign at w the double filter cannot prove
  // negative: f(w) >= -b with a rigorous bound from the plane coefficient errors, the vertex
  // coordinate errors and the rounding of the evaluation.
  void near(const VertexGeom& w, std::vector<uint32_t>& out) const {
    out.clear();
    const VertexFilterTerms t = vertex_filter_terms(w.x);
    const double p[3] = {w.x[0].v, w.x[1].v, w.x[2].v};
    near_planes(ax, ay, az, ad, bn1, ben, be0, size, p, t.c1, t.c2, out);
  }
};

// The filter, then exact signs for the undecided planes of `list` (planes marked in
// known_tight_mark, if given, are tight without evaluation): the complete sorted tight set of w,
// or the first violated plane.
uint32_t certify_over(const PlaneSet& ps, const std::vector<uint32_t>& list, const CertifyPlanes& arr,
                      const VertexGeom& w, const std::vector<char>& known_tight_mark, std::vector<uint32_t>& cand,
                      std::vector<uint32_t>& tight) {
  tight.clear();
  arr.near(w, cand);  // every other plane is certainly strictly inside at w
  for (uint32_t i : cand) {
    const uint32_t l = list[i];
    if (!known_tight_mark.empty() && known_tight_mark[l]) {
      tight.push_back(l);
      continue;
    }
    int s = side(ps, l, w);
    if (s > 0) return l;
    if (s == 0) tight.push_back(l);
  }
  std::sort(tight.begin(), tight.end());
  return kNoPlane;
}

}  // namespace

uint32_t certify_vertex(const PlaneSet& ps, const std::vector<uint32_t>& active, const VertexGeom& w,
                        const std::vector<char>& known_tight_mark, std::vector<uint32_t>& tight) {
  // One pass straight over the plane store (compact arrays pay off only for the many vertices
  // of a trace); the same undecided planes as certify_over's, in the same order.
  tight.clear();
  const VertexFilter filter(w);
  for (uint32_t l : active) {
    if (filter.sign(ps.approx(l)) < 0) continue;
    if (!known_tight_mark.empty() && known_tight_mark[l]) {
      tight.push_back(l);
      continue;
    }
    const int s = side(ps, l, w);
    if (s > 0) return l;
    if (s == 0) tight.push_back(l);
  }
  std::sort(tight.begin(), tight.end());
  return kNoPlane;
}

namespace {

class Tracer {
 public:
  Tracer(const PlaneSet& ps, const std::vector<uint32_t>& active, const TraceOptions& opt)
      : ps_(ps), active_(active), opt_(opt), mark_(ps.size(), 0) {
    arr_.build(ps, active);
    on_list_.assign(active.size(), {kNoVertex, kNoVertex});
    slot_.assign(ps.size(), kNoPlane);
    for (size_t i = 0; i < active.size(); ++i) slot_[active[i]] = uint32_t(i);
    // Room for a small kernel up front (every call starts with empty vectors, and growing them
    // step by step was a tenth of the allocations on small meshes); large ones grow as needed.
    constexpr size_t kVertices = 32;
    res_.vertices.reserve(kVertices);
    res_.edges.reserve(3 * kVertices / 2);
    on_entry_.reserve(3 * kVertices);
    rays_.reserve(3 * kVertices);
    line_pool_.reserve(6 * kVertices);
    tight_.reserve(16);
    line_.reserve(16);
    cand_.reserve(16);
    seen_.reserve(16);
    rate_.reserve(16);
    saved_.reserve(16);
    // Only a trace towards a point orders its rays by distance; otherwise they are taken in
    // discovery order (a plain cursor over rays_, no heap).
    if (opt_.has_from) by_distance_.reserve(3 * kVertices);
  }

  TraceResult run(const VertexGeom& start) {
    std::vector<uint32_t>& tight = tight_;
    if (certify(start, tight) != kNoPlane) {
      res_.internal_error = true;
      return std::move(res_);
    }
    add_vertex(start, tight);
    return trace_queued();
  }

  // The kernel of active = S' from the trace of K_S and the planes `added` (S' may also drop
  // planes of S that no vertex of K_S lies on: they cannot touch K_S, so neither K_S'). What
  // survives is kept without tracing: a vertex of K_S inside every added plane is a vertex of
  // K_S' (an extreme point of a superset that the subset contains); an edge with both ends
  // surviving lies inside every added plane (convexity), so it is an edge of K_S'. Its tight and
  // line plane sets grow by the added planes through it. Only the rest is traced: the rays from
  // surviving vertices along lines not yet known, and everything from the new vertices.
  TraceResult run_update(const TraceResult& prev, const std::vector<uint32_t>& added) {
    CertifyPlanes added_arr;
    added_arr.build(ps_, added);
    std::vector<uint32_t> new_id(prev.vertices.size(), kNoVertex);
    std::vector<std::vector<uint32_t>> tight_added(prev.vertices.size());
    for (size_t v = 0; v < prev.vertices.size(); ++v) {
      const TracedVertex& tv = prev.vertices[v];
      added_arr.near(tv.geom, cand_);
      bool survives = true;
      for (uint32_t i : cand_) {
        int sgn = side(ps_, added[i], tv.geom);
        if (sgn > 0) {
          survives = false;
          break;
        }
        if (sgn == 0) tight_added[v].push_back(added[i]);
      }
      if (!survives) continue;
      PlaneIds tight = tv.tight;
      for (uint32_t l : tight_added[v]) tight.push_back(l);
      std::sort(tight.begin(), tight.end());
      std::sort(tight_added[v].begin(), tight_added[v].end());
      new_id[v] = uint32_t(res_.vertices.size());
      res_.vertices.push_back({tv.geom, std::move(tight)});
      vertex_ids_.insert(res_.vertices.back().tight, new_id[v]);
      for (uint32_t l : res_.vertices.back().tight) {
        if (slot_[l] == kNoPlane) {
          res_.internal_error = true;
          return finish();
        }  // caller broke the contract
        link_vertex_on(slot_[l], new_id[v]);
      }
    }
    if (res_.vertices.empty()) {
      res_.internal_error = true;
      return finish();
    }  // the LP vertex always survives
    for (const TracedEdge& e : prev.edges) {
      if (new_id[e.a] == kNoVertex || new_id[e.b] == kNoVertex) continue;
      TracedEdge k = e;
      k.a = new_id[e.a];
      k.b = new_id[e.b];
      const auto &ta = tight_added[e.a], &tb = tight_added[e.b];
      std::set_intersection(ta.begin(), ta.end(), tb.begin(), tb.end(), std::back_inserter(k.planes));
      std::sort(k.planes.begin(), k.planes.end());
      traced_.insert(line_key(ps_, k.planes));
      res_.edges.push_back(std::move(k));
    }
    for (uint32_t v = 0; v < res_.vertices.size(); ++v) queue_rays(v);
    return trace_queued();
  }

 private:
  TraceResult finish() { return std::move(res_); }

  // Traces the queued rays (skipping lines already traced) until none is left.
  TraceResult trace_queued() {
    while (!queue_empty()) {
      uint32_t idx = pop();
      const Ray ray = rays_[idx];
      if (traced_.contains(ray.key)) continue;
      if (!trace(ray)) break;
    }
    return finish();
  }

  // The known vertex whose tight set holds planes a, b and c, or kNoVertex.
  uint32_t known_vertex_on(uint32_t a, uint32_t b, uint32_t c) const {
    for (uint32_t e = on_list_[slot_[a]].head; e != kNoVertex; e = on_entry_[e].next) {
      const uint32_t v = on_entry_[e].vertex;
      const auto& G = res_.vertices[v].tight;
      if (std::binary_search(G.begin(), G.end(), b) && std::binary_search(G.begin(), G.end(), c)) return v;
    }
    return kNoVertex;
  }

  // Adds a vertex and queues its untraced rays.
  void add_vertex(const VertexGeom& g, const std::vector<uint32_t>& tight) {
    uint32_t id = uint32_t(res_.vertices.size());
    res_.vertices.push_back({g, tight});
    vertex_ids_.insert(tight, id);
    for (uint32_t l : tight) link_vertex_on(slot_[l], id);
    queue_rays(id);
  }

  // Appends v to the known vertices on the active plane in `slot` (insertion order kept).
  void link_vertex_on(uint32_t slot, uint32_t v) {
    const uint32_t e = uint32_t(on_entry_.size());
    on_entry_.push_back({v, kNoVertex});
    if (on_list_[slot].head == kNoVertex)
      on_list_[slot].head = e;
    else
      on_entry_[on_list_[slot].tail].next = e;
    on_list_[slot].tail = e;
  }

  void queue_rays(uint32_t v) {
    const PlaneIds& G = res_.vertices[v].tight;
    seen_.clear();  // keys queued from this vertex (a handful: a linear search beats a hash set)
    std::vector<int>& s = rate_;
    s.assign(G.size(), 0);
    // The rate of plane G[k] along the line of G[i], G[j] is the sign of det3(n_k, n_i, n_j), an
    // alternating function of the triple: each triple serves three lines, so its sign is kept
    // (by sorted triple index; 2 = not known yet). At a degenerate vertex (nearly coplanar planes
    // of a split polygon) many of these signs need the exact fallback.
    const size_t n = G.size();
    const bool keep = n >= 3 && n <= kMaxKeptTight;  // (a vertex has at least three)
    if (keep) triple_sign_.assign(n * (n - 1) * (n - 2) / 6, 2);
    for (size_t i = 0; i < n; ++i)
      for (size_t j = i + 1; j < n; ++j) {
        uint32_t p = G[i], q = G[j];
        if (ps_.opposite(p) == q) continue;
        bool pos = false, neg = false;
        std::optional<LineDirection> line;  // built on the first sign not kept
        // At a vertex of many planes (a cone's apex) most pairs are not edges, and the first
        // plane of the other sign is usually a neighbour of i or j in the tight set (planes are
        // numbered in face order, which around an apex is usually the fan's order): those are
        // tried first, then the rest in a scrambled order (a stride coprime to n), so that a
        // few planes of the other sign are met after about n / (their number) tries wherever
        // they are. Testing in index order found them only after ~i tries: a 1000-face apex
        // cost (tight planes)^3 / 6 tests.
        auto sign_of = [&](size_t k) KERGEN_INLINE {
          if (k == i || k == j) {
            s[k] = 0;
            return;
          }
          // det3(n_k, n_i, n_j) is the sorted triple's determinant, negated when k lies between
          // i and j (one transposition; k < i or k > j is a rotation).
          const int parity = i < k && k < j ? -1 : 1;
          int8_t* kept = nullptr;
          if (keep) {
            const size_t a = std::min(i, k), c = std::max(j, k), b = i + j + k - a - c;
            kept = &triple_sign_[c * (c - 1) * (c - 2) / 6 + b * (b - 1) / 2 + a];
          }
          if (kept && *kept != 2) {
            s[k] = parity * *kept;
          } else {
            if (!line) line.emplace(ps_, p, q);
            s[k] = line->rate_sign(ps_, G[k]);
            if (kept) *kept = int8_t(parity * s[k]);
          }
          pos |= s[k] > 0;
          neg |= s[k] < 0;
        };
        if (n <= 8) {
          for (size_t k = 0; k < n && !(pos && neg); ++k) sign_of(k);
        } else {
          const size_t first[4] = {i + 1, j + 1 < n ? j + 1 : 0, i > 0 ? i - 1 : n - 1, j - 1};
          for (size_t t = 0; t < 4 && !(pos && neg); ++t) sign_of(first[t]);
          const size_t stride = (n % 7919 != 0 ? 7919 : 7927) % n;
          for (size_t t = 0, k = (31 * i + 17 * j) % n; t < n && !(pos && neg); ++t) {
            sign_of(k);
            k += stride;
            if (k >= n) k -= n;
          }
        }
        if (pos && neg) continue;
        if (!pos && !neg) continue;  // every tight plane contains the line: not a vertex (unreachable)
        line_.clear();
        for (size_t k = 0; k < G.size(); ++k)
          if (k == i || k == j || s[k] == 0) line_.push_back(G[k]);
        const uint64_t key = line_key(ps_, line_);
        if (traced_.contains(key) || std::find(seen_.begin(), seen_.end(), key) != seen_.end()) continue;
        seen_.push_back(key);
        Ray ray;
        ray.from = v;
        ray.p = p;
        ray.q = q;
        ray.sigma = pos ? -1 : 1;
        ray.line_begin = uint32_t(line_pool_.size());
        ray.line_size = uint32_t(line_.size());
        line_pool_.insert(line_pool_.end(), line_.begin(), line_.end());
        ray.key = key;
        push(ray);
      }
  }

  // Rays wait in rays_ itself: without a point to trace towards, breadth-first (discovery
  // order, the order a heap keyed by the ray's index gives); with one, nearest vertex first,
  // ties by index.
  void push(const Ray& r) {
    uint32_t idx = uint32_t(rays_.size());
    rays_.push_back(r);
    if (!opt_.has_from) return;
    const VertexGeom& g = res_.vertices[r.from].geom;
    double prio = 0;
    for (int k = 0; k < 3; ++k) prio += (g.x[k].v - opt_.from[k]) * (g.x[k].v - opt_.from[k]);
    by_distance_.push_back({prio, idx});
    std::push_heap(by_distance_.begin(), by_distance_.end(), std::greater<>());
  }
  bool queue_empty() const { return opt_.has_from ? by_distance_.empty() : next_ray_ == rays_.size(); }
  uint32_t pop() {
    if (!opt_.has_from) return next_ray_++;
    std::pop_heap(by_distance_.begin(), by_distance_.end(), std::greater<>());
    const uint32_t idx = by_distance_.back().second;
    by_distance_.pop_back();
    return idx;
  }

  // Direction sigma * (n_p x n_q) as doubles; when cancellation makes the double cross product
  // unreliable (nearly parallel planes: the triangles of a split polygon) it is taken from the
  // double-double one, and from the exact one only when that cancels too. (The direction only
  // steers the double scan; the exact certification decides.)
  void direction(const Ray& ray, double u[3]) const {
    const Approx* c = ray_line_->u;  // cross_normals of p and q, filtered
    double len = std::fabs(c[0].v) + std::fabs(c[1].v) + std::fabs(c[2].v);
    double err = c[0].e + c[1].e + c[2].e;
    if (err <= 1e-8 * len) {
      for (int k = 0; k < 3; ++k) u[k] = ray.sigma * c[k].v;
      return;
    }
    {
      const std::array<exact::ApproxDD, 3> d = cross_normals(ps_.dd(ray.p), ps_.dd(ray.q));
      double dlen = 0, derr = 0;
      for (int k = 0; k < 3; ++k) {
        dlen += std::fabs(d[k].hi + d[k].lo);
        derr += d[k].e;
      }
      if (derr <= 1e-8 * dlen) {
        for (int k = 0; k < 3; ++k) u[k] = ray.sigma * (d[k].hi + d[k].lo);
        return;
      }
    }
    const std::array<Expansion, 3> e = cross_normals(ps_.exact(ray.p), ps_.exact(ray.q));
    for (int k = 0; k < 3; ++k) u[k] = ray.sigma * e[k].estimate();
  }

  // Nearest plane along the ray from its vertex (double scan; exactness comes after).
  uint32_t scan(const Ray& ray) {
    const VertexGeom& g = res_.vertices[ray.from].geom;
    double u[3];
    direction(ray, u);
    const double x = g.x[0].v, y = g.x[1].v, z = g.x[2].v;
    // Planes through the vertex never cut the ray (exactly); hide them from the scan.
    const auto& G = res_.vertices[ray.from].tight;
    for (uint32_t l : G) {
      uint32_t i = slot_[l];
      saved_.push_back({arr_.ax[i], arr_.ay[i], arr_.az[i], arr_.ad[i]});
      arr_.ax[i] = arr_.ay[i] = arr_.az[i] = 0;
      arr_.ad[i] = -1;
    }
    const double p[3] = {x, y, z};
    const size_t n = active_.size();
    size_t bi = nearest_hit(arr_.ax, arr_.ay, arr_.az, arr_.ad, arr_.size, p, u);
    for (size_t k = 0; k < G.size(); ++k) {
      uint32_t i = slot_[G[k]];
      arr_.ax[i] = saved_[k][0];
      arr_.ay[i] = saved_[k][1];
      arr_.az[i] = saved_[k][2];
      arr_.ad[i] = saved_[k][3];
    }
    saved_.clear();
    if (bi < n && approaching(ray, active_[bi])) return active_[bi];
    return exact_scan(ray);
  }

  // (The sign of det3(n_l, n_p, n_q), filtered against the ray's line direction first: a dot
  // product with its cross product, kept in ray_line_, instead of a determinant per plane.)
  bool approaching(const Ray& ray, uint32_t l) const {
    const auto& G = res_.vertices[ray.from].tight;
    return !std::binary_search(G.begin(), G.end(), l) && ray.sigma * ray_line_->rate_sign(ps_, l) > 0;
  }

  // The nearest plane by exact comparisons only (a tournament over the approaching planes):
  // the fallback when the double scan cannot be trusted.
  uint32_t exact_scan(const Ray& ray) {
    uint32_t r = kNoPlane;
    VertexGeom w;
    for (uint32_t l : active_) {
      if (!approaching(ray, l)) continue;
      if (r == kNoPlane || side(ps_, l, w) > 0) {
        r = l;
        w = make_vertex(ps_, ray.p, ray.q, r);
      }
    }
    return r;
  }

  // certify_vertex over the compact arrays: a double pass with a rigorous per-plane error bound
  // (plane coefficient errors, vertex coordinate errors, rounding) decides almost every plane;
  // only the undecided ones, and planes known to contain the current line, go further.
  uint32_t certify(const VertexGeom& w, std::vector<uint32_t>& tight) {
    return certify_over(ps_, active_, arr_, w, mark_, cand_, tight);
  }

  bool trace(const Ray& ray) {
    ++res_.traced_lines;
    ray_line_.emplace(ps_, ray.p, ray.q);
    uint32_t r = scan(ray);
    if (r == kNoPlane) {
      res_.internal_error = true;
      return false;
    }  // unbounded ray
    // (The pool may grow while the ray is traced: spans into it are taken afresh.)
    const uint32_t* line = line_pool_.data() + ray.line_begin;
    for (uint32_t i = 0; i < ray.line_size; ++i) mark_[line[i]] = 1;
    std::vector<uint32_t>& tight = tight_;
    VertexGeom w;
    uint32_t known = kNoVertex;
    bool exact_done = false;
    for (;;) {
      // A known vertex on p, q and r is the candidate itself (three independent planes meet in
      // one point) and is already certified: no need to evaluate anything.
      known = known_vertex_on(ray.p, ray.q, r);
      if (known != kNoVertex) break;
      w = make_vertex(ps_, ray.p, ray.q, r);
      uint32_t violator = certify(w, tight);
      if (violator == kNoPlane) break;
      // A violator cuts the segment before the candidate, so it approaches along the ray and is
      // strictly closer. Anything else means the candidate came from an unreliable scan.
      if (approaching(ray, violator)) {
        r = violator;
        continue;
      }
      if (exact_done) {
        res_.internal_error = true;
        break;
      }
      r = exact_scan(ray);
      exact_done = true;
      if (r == kNoPlane) {
        res_.internal_error = true;
        break;
      }
    }
    for (uint32_t i = 0; i < ray.line_size; ++i) mark_[line[i]] = 0;
    if (res_.internal_error) return false;

    uint32_t to = known != kNoVertex ? known : vertex_ids_.find(tight, res_.vertices);
    if (to == kNoVertex) {
      to = uint32_t(res_.vertices.size());
      add_vertex(w, tight);
    }
    traced_.insert(ray.key);
    TracedEdge e;
    e.a = ray.from;
    e.b = to;
    e.p = ray.p;
    e.q = ray.q;
    e.sigma = ray.sigma;
    e.planes.assign(line_pool_.begin() + ray.line_begin, line_pool_.begin() + ray.line_begin + ray.line_size);
    res_.edges.push_back(std::move(e));
    return true;
  }

  const PlaneSet& ps_;
  const std::vector<uint32_t>& active_;
  TraceOptions opt_;
  std::vector<char> mark_;
  CertifyPlanes arr_;
  std::vector<uint64_t> seen_;
  std::vector<int> rate_;
  static constexpr size_t kMaxKeptTight = 64;  // triple signs are kept for up to this many tight planes
  std::vector<int8_t> triple_sign_;
  std::vector<uint32_t> cand_;
  std::vector<uint32_t> tight_, line_;  // scratch: a candidate's tight set, a ray's line planes
  std::vector<uint32_t> line_pool_;     // the line planes of every queued ray, concatenated
  // Known vertices on each active plane: linked lists by slot (head, tail) over entries
  // (vertex, next), in insertion order.
  struct OnList {
    uint32_t head, tail;
  };
  struct OnEntry {
    uint32_t vertex, next;
  };
  std::vector<OnList> on_list_;    // by slot
  std::vector<OnEntry> on_entry_;  // (pairs, not parallel arrays: half the allocations)
  std::vector<uint32_t> slot_;
  std::vector<std::array<double, 4>> saved_;
  std::optional<LineDirection> ray_line_;  // the line of the ray being traced (trace)
  TraceResult res_;
  VertexIndex vertex_ids_;
  U64Set traced_{48};  // line keys of traced edges (room for a small kernel's, as reserved above)
  std::vector<Ray> rays_;
  uint32_t next_ray_ = 0;                                 // the next ray to trace, without `from`
  std::vector<std::pair<double, uint32_t>> by_distance_;  // a min-heap of rays, with `from`
};

}  // namespace

TraceResult trace_kernel_edges(const PlaneSet& ps, const std::vector<uint32_t>& active, const VertexGeom& start,
                               const TraceOptions& options) {
  Tracer t(ps, active, options);
  return t.run(start);
}

TraceResult update_kernel_trace(const PlaneSet& ps, const std::vector<uint32_t>& active, const TraceResult& prev,
                                const std::vector<uint32_t>& added, const TraceOptions& options) {
  Tracer t(ps, active, options);
  return t.run_update(prev, added);
}

std::vector<uint32_t> facet_planes(const TraceResult& trace) {
  // (Sized first: growing the arrays step by step was a tenth of a small kernel's allocations.)
  size_t total = 0;
  uint32_t max_plane = 0;
  for (const TracedEdge& e : trace.edges) {
    total += e.planes.size();
    for (uint32_t h : e.planes) max_plane = std::max(max_plane, h);
  }
  std::vector<uint32_t> facets;
  facets.reserve(total / 3 + 1);  // (a facet holds three edges or more)
  if (total == 0) return facets;
  if (max_plane <= 8 * total) {
    // Plane ids within a few times the edges' plane count (a small mesh, or a large kernel): a
    // count per id, no sort.
    std::vector<uint8_t> count(size_t(max_plane) + 1, 0);
    for (const TracedEdge& e : trace.edges)
      for (uint32_t h : e.planes) count[h] = uint8_t(std::min(int(count[h]) + 1, 3));
    for (uint32_t h = 0; h <= max_plane; ++h)
      if (count[h] >= 3) facets.push_back(h);
    return facets;
  }
  std::vector<uint32_t> planes;
  planes.reserve(total);
  for (const TracedEdge& e : trace.edges) planes.insert(planes.end(), e.planes.begin(), e.planes.end());
  std::sort(planes.begin(), planes.end());
  for (size_t i = 0, j; i < planes.size(); i = j) {
    for (j = i; j < planes.size() && planes[j] == planes[i]; ++j) {}
    if (j - i >= 3) facets.push_back(planes[i]);
  }
  return facets;
}

}  // namespace kergen
