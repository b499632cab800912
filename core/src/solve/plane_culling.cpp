// Culling by a subset kernel (in the spirit of Clarkson's sampling LP algorithm). The kernel
// K_S of a random plane subset S is traced; K_S contains the kernel, so a plane outside S
// matters only if some vertex of K_S lies outside it. Finding that vertex is a support query on
// the convex polytope K_S: hill climbing on its vertex graph from a cube map of extreme
// vertices (or, for many planes at once and a small K_S, a vectorized scan of all its vertices).
// K_S is then cut by the planes found.
#include "solve/plane_culling.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "solve/climb.h"
#include "solve/cutting.h"
#include "util/random.h"

namespace kergen {

namespace {

// Direction of the point (i + fi, j + fj) / k of cell (face, i, j); fi = fj = 0.5 is the centre,
// 0 or 1 the corners.
void cube_cell_direction(size_t cells_per_side, size_t cell, double fi, double fj, double dir[3]) {
  const size_t face = cell / (cells_per_side * cells_per_side), i = cell / cells_per_side % cells_per_side,
               j = cell % cells_per_side;
  const int axis = int(face / 2);
  dir[axis] = face % 2 ? -1.0 : 1.0;
  dir[(axis + 1) % 3] = (double(i) + fi) / double(cells_per_side) * 2 - 1;
  dir[(axis + 2) % 3] = (double(j) + fj) / double(cells_per_side) * 2 - 1;
}

constexpr size_t kDirectTraceLimit = 1024;  // below this many planes culling costs more than it saves

// may_reach's margin and box test (see there), shared by the scalar and the batched test: the
// same operations in the same order (no FMA contraction in this library) give the same bits,
// hence the same decisions.
// The margin is kReachMargin delta, delta = value_error_bound (exact/error_bounds.h): how far a
// computed value of the plane at a vertex of K_S can be off. The climbs' tie is kClimbTie delta.
inline double reach_margin(double a, double b, double c, double d, double ea, double eb, double ec, double ed,
                           double max_abs, double coord_error) {
  return kReachMargin * value_error_bound(a, b, c, d, ea, eb, ec, ed, max_abs, coord_error);
}
inline bool box_clears(double a, double b, double c, double d, double margin, const double centre[3],
                       const double half[3]) {
  return a * centre[0] + b * centre[1] + c * centre[2] + d + std::fabs(a) * half[0] + std::fabs(b) * half[1] +
             std::fabs(c) * half[2] <
         -2 * margin;
}

// The bound on max f over K_S from the support values s_ij at the corners of the normal's cell
// (see may_reach).
inline double support_bound(double s00, double s01, double s10, double s11, double fi, double fj, double m, double d) {
  const double h = (1 - fi) * ((1 - fj) * s00 + fj * s01) + fi * ((1 - fj) * s10 + fj * s11);
  return m * h + d;
}

// may_reach over many planes runs in passes over structure of arrays, the branch-free ones
// vectorized: the box test for all planes, then the cube positions and support bounds of those
// it leaves, then the rest of the test one plane at a time. (Every array is a restrict
// parameter: no aliasing to check at run time.) box_test: maybe[i] = 0 where the box clears
// plane i, else 1.
constexpr size_t kBatch = 64;
// Up to this many vertices of K_S a scan of them all costs less than a climb (about 2 V
// instructions with AVX2, a climb ~500).
constexpr size_t kScanLimit = 128;
KERGEN_MULTIVERSION
void box_test(size_t n, const double* __restrict nx, const double* __restrict ny, const double* __restrict nz,
              const double* __restrict d, const double* __restrict enx, const double* __restrict eny,
              const double* __restrict enz, const double* __restrict ed, const double centre[3], const double half[3],
              double max_abs, double coord_error, char* __restrict maybe, double* __restrict margin) {
  const double c[3] = {centre[0], centre[1], centre[2]}, h[3] = {half[0], half[1], half[2]};
  for (size_t i = 0; i < n; ++i) {
    margin[i] = reach_margin(nx[i], ny[i], nz[i], d[i], enx[i], eny[i], enz[i], ed[i], max_abs, coord_error);
    maybe[i] = !box_clears(nx[i], ny[i], nz[i], d[i], margin[i], c, h);
  }
}
KERGEN_MULTIVERSION
void cube_positions(size_t n, const double* __restrict a, const double* __restrict b, const double* __restrict c,
                    int cells_per_side, int32_t* __restrict cell, int32_t* __restrict corner, double* __restrict fi,
                    double* __restrict fj, double* __restrict m) {
  for (size_t i = 0; i < n; ++i) {
    const CubePosition q = cube_position(cells_per_side, a[i], b[i], c[i]);
    cell[i] = q.cell;
    corner[i] = q.corner;
    fi[i] = q.fi;
    fj[i] = q.fj;
    m[i] = q.m;
  }
}
KERGEN_MULTIVERSION
void support_bounds(size_t n, const double* __restrict s00, const double* __restrict s01, const double* __restrict s10,
                    const double* __restrict s11, const double* __restrict fi, const double* __restrict fj,
                    const double* __restrict m, const double* __restrict d, double* __restrict bound) {
  for (size_t i = 0; i < n; ++i) bound[i] = support_bound(s00[i], s01[i], s10[i], s11[i], fi[i], fj[i], m[i], d[i]);
}
// Whether some vertex (x, y, z) has a x + b y + c z + d > threshold, each value computed as the
// climb computes it.
KERGEN_MULTIVERSION
bool any_above(size_t n, const double* __restrict x, const double* __restrict y, const double* __restrict z, double a,
               double b, double c, double d, double threshold) {
  int above = 0;
  for (size_t v = 0; v < n; ++v) above |= a * x[v] + b * y[v] + c * z[v] + d > threshold;
  return above;
}

// The vertex of `tr` (traced over the sorted planes `S`) whose tight set is `tight` (over a
// superset of S) restricted to S; 0 when none is (never expected: the start vertex is a vertex
// of every kernel traced from it).
uint32_t vertex_with_tight_set(const TraceResult& tr, const std::vector<uint32_t>& tight,
                               const std::vector<uint32_t>& S) {
  std::vector<uint32_t> in_s;
  for (uint32_t l : tight)
    if (std::binary_search(S.begin(), S.end(), l)) in_s.push_back(l);
  std::sort(in_s.begin(), in_s.end());
  for (uint32_t v = 0; v < tr.vertices.size(); ++v)
    if (std::equal(in_s.begin(), in_s.end(), tr.vertices[v].tight.begin(), tr.vertices[v].tight.end())) return v;
  return 0;
}

}  // namespace

SupportTest::SupportTest(const TraceResult& tr, size_t expected_queries, bool batched) {
  // Vertex graph of K_S.
  const size_t V = tr.vertices.size();
  xyz_.resize(3 * V);
  for (size_t v = 0; v < V; ++v)
    for (int k = 0; k < 3; ++k) {
      xyz_[3 * v + k] = tr.vertices[v].geom.x[k].v;
      coord_error_ = std::max(coord_error_, tr.vertices[v].geom.x[k].e);
    }
  for (int k = 0; k < 3; ++k) {
    vertex_coord_[k].resize(V);
    for (size_t v = 0; v < V; ++v) vertex_coord_[k][v] = xyz_[3 * v + k];
  }
  adj_offset_.assign(V + 1, 0);
  for (const auto& e : tr.edges) {
    adj_offset_[e.a + 1]++;
    adj_offset_[e.b + 1]++;
  }
  for (size_t v = 0; v < V; ++v) adj_offset_[v + 1] += adj_offset_[v];
  adj_.resize(adj_offset_[V]);
  {
    std::vector<uint32_t> fill(adj_offset_.begin(), adj_offset_.end() - 1);
    for (const auto& e : tr.edges) {
      adj_[fill[e.a]++] = e.b;
      adj_[fill[e.b]++] = e.a;
    }
  }
  // Bounding box of K_S: max over K_S of f_l <= f_l(box centre) + sum_k |n_k| half_k, one
  // dot product that clears most planes without a climb (they lie far from the kernel).
  double lo[3] = {xyz_[0], xyz_[1], xyz_[2]}, hi[3] = {xyz_[0], xyz_[1], xyz_[2]};
  for (size_t v = 1; v < V; ++v)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], xyz_[3 * v + k]);
      hi[k] = std::max(hi[k], xyz_[3 * v + k]);
    }
  for (int k = 0; k < 3; ++k) {
    centre_[k] = 0.5 * (lo[k] + hi[k]);
    half_[k] = 0.5 * (hi[k] - lo[k]);
    max_abs_ = std::max(max_abs_, std::max(std::fabs(lo[k]), std::fabs(hi[k])));
  }
  // Climb starts: the vertex of K_S extreme in the direction of each cell of a cube map over
  // the sphere of normals. A cell whose four corner directions all have that vertex as their
  // strict maximum (every edge at the vertex descends along each corner) lies inside the
  // vertex's normal cone, which is convex, so every direction of the cell peaks there: planes
  // with normals in such a cell need one evaluation, no climb. Other cells only give the climb
  // a start a few steps from its answer, whatever the order of the planes.
  // A cell costs about what it spares a query that lands in it: a climb (~500 instructions),
  // or, for batched queries on a small K_S, a scan (~2 V + 40), which a coarser map balances.
  // (The resolution only changes which of the tests, each sound, settles a plane.)
  const double query_cost = batched && V <= kScanLimit ? (2 * double(V) + 40) / 500 : 1.0;
  cells_per_side_ =
      std::min<size_t>(24, std::max<size_t>(2, size_t(std::sqrt(double(expected_queries) * query_cost / 100))));
  const size_t cells = 6 * cells_per_side_ * cells_per_side_;
  start_of_cell_.resize(cells);
  cell_resolved_.assign(cells, 0);
  // Greedy climb to the extreme vertex in direction dir (a start, not a proof).
  auto extreme = [&](const double dir[3], uint32_t at) {
    auto g = [&](uint32_t v) { return dir[0] * xyz_[3 * v] + dir[1] * xyz_[3 * v + 1] + dir[2] * xyz_[3 * v + 2]; };
    double val = g(at);
    for (bool moved = true; moved;) {
      moved = false;
      for (uint32_t i = adj_offset_[at]; i < adj_offset_[at + 1]; ++i)
        if (g(adj_[i]) > val) {
          at = adj_[i];
          val = g(at);
          moved = true;
        }
    }
    return at;
  };
  auto neighbors = [&](uint32_t u, const auto& fn) {
    for (uint32_t i = adj_offset_[u]; i < adj_offset_[u + 1]; ++i) fn(adj_[i]);
  };
  // The corners of the cells too: along a ridge of K_S (an elongated kernel) the extreme
  // vertex jumps within a small change of direction, and the best of a cell's centre and
  // corner vertices starts the climb near its answer.
  const size_t side_pts = cells_per_side_ + 1;
  start_of_corner_.resize(6 * side_pts * side_pts);
  // The support function h(u) = max over K_S of u . x at each corner direction (up to rounding
  // far below the margins it is used with).
  corner_support_.resize(start_of_corner_.size());
  ClimbScratch climb;
  {
    uint32_t at = 0;
    for (size_t c = 0; c < start_of_corner_.size(); ++c) {
      const size_t face = c / (side_pts * side_pts), i = c / side_pts % side_pts, j = c % side_pts;
      double dir[3];
      cube_cell_direction(cells_per_side_, (face * cells_per_side_) * cells_per_side_, double(i), double(j), dir);
      at = start_of_corner_[c] = extreme(dir, at);
      // (The greedy climb can stop short where rounding makes neighbours tie; the full climb,
      // with its plateau search, gives the maximum. The greedy start is kept for the planes.)
      auto g = [&](uint32_t v) { return dir[0] * xyz_[3 * v] + dir[1] * xyz_[3 * v + 1] + dir[2] * xyz_[3 * v + 2]; };
      double h = g(at);
      // (tie: twice the most a computed g can be off, and twice again)
      const double tie = kClimbTie * value_error_bound(dir[0], dir[1], dir[2], 0, 0, 0, 0, 0, max_abs_, coord_error_);
      climb_to_max(at, h, g, neighbors, tie, V, climb);
      corner_support_[c] = h;
    }
  }
  for (size_t cell = 0; cell < cells; ++cell) {
    double dir[3];
    cube_cell_direction(cells_per_side_, cell, 0.5, 0.5, dir);
    const size_t face = cell / (cells_per_side_ * cells_per_side_), i = cell / cells_per_side_ % cells_per_side_,
                 j = cell % cells_per_side_;
    const uint32_t at = extreme(dir, start_of_corner_[(face * side_pts + i) * side_pts + j]);
    start_of_cell_[cell] = at;
    bool strict = adj_offset_[at + 1] > adj_offset_[at];
    for (int corner = 0; corner < 4 && strict; ++corner) {
      double cd[3];
      cube_cell_direction(cells_per_side_, cell, corner & 1, corner >> 1, cd);
      for (uint32_t k = adj_offset_[at]; k < adj_offset_[at + 1] && strict; ++k) {
        const double* w = &xyz_[3 * size_t(adj_[k])];
        const double* v = &xyz_[3 * size_t(at)];
        const double e[3] = {w[0] - v[0], w[1] - v[1], w[2] - v[2]};
        // Strictly descending by four times the most the computed value can be off (both ends'
        // coordinate errors, the rounding of the differences and of the dot product): the
        // rounded direction of a very short edge says nothing about the exact one, so such
        // vertices are left to the climb and its plateau search.
        const double cd1 = std::fabs(cd[0]) + std::fabs(cd[1]) + std::fabs(cd[2]);
        strict = cd[0] * e[0] + cd[1] * e[1] + cd[2] * e[2] <
                 -4 * cd1 * (2 * coord_error_ + 8 * exact::kEps * max_abs_) - exact::kUnderflowFloor;
      }
    }
    cell_resolved_[cell] = strict;
  }
}

bool SupportTest::may_reach(const PlaneCoef<Approx>& plane, Scratch& scratch, uint32_t& hint) const {
  const double a = plane.n[0].v, b = plane.n[1].v, c = plane.n[2].v, d = plane.d.v;
  // `margin` (reach_margin) keeps every plane that could be violated: it is far above what a
  // computed value can be off by (rounding, the plane's coefficients, the vertices' coordinates).
  const double margin =
      reach_margin(a, b, c, d, plane.n[0].e, plane.n[1].e, plane.n[2].e, plane.d.e, max_abs_, coord_error_);
  // (The box is a double computation like the climb; 2 * margin covers its rounding.)
  if (box_clears(a, b, c, d, margin, centre_, half_)) return false;
  const CubePosition q = cube_position(int(cells_per_side_), a, b, c);
  if (!usable(q.m)) return climb_reaches(a, b, c, d, margin, -1, 0, scratch, hint);
  if (cell_resolved_[q.cell]) {
    hint = start_of_cell_[q.cell];
    return a * xyz_[3 * hint] + b * xyz_[3 * hint + 1] + c * xyz_[3 * hint + 2] + d > -margin;
  }
  // h is convex and positively homogeneous, and n / m (m = |n_axis|) is the bilinear
  // interpolation of the cell's four corner directions (exact: they are affine in the cell's
  // coordinates), so max f <= m (the same interpolation of the corners' h) + d. Below
  // -2 margin the plane holds K_S strictly without a climb.
  const double* s = &corner_support_[size_t(q.corner)];
  const size_t side_pts = cells_per_side_ + 1;
  if (support_bound(s[0], s[1], s[side_pts], s[side_pts + 1], q.fi, q.fj, q.m, d) < -2 * margin) return false;
  return climb_reaches(a, b, c, d, margin, q.cell, q.corner, scratch, hint);
}

void SupportTest::may_reach_all(const PlaneArrays& p, size_t n, Scratch& scratch, char* reaching) const {
  // Soundness: a plane is dropped only where K_S provably holds strictly inside it: by
  // may_reach's box test, the one vertex of a resolved cell or the support bound (the same double
  // operations on the same values and margins as may_reach, hence the same bits), or, on a small
  // K_S, when no vertex's value is above -margin: the margin exceeds each value's error
  // (rounding, the plane's coefficients, the vertex's coordinates), so every vertex, hence all
  // of K_S, is strictly inside. (The climb drops a plane when the vertex it reaches is not above
  // -margin: the scan, which sees every vertex, keeps whatever the climb keeps.)
  double margin[kBatch], a[kBatch], b[kBatch], c[kBatch], d[kBatch], fi[kBatch], fj[kBatch], m[kBatch];
  double s00[kBatch], s01[kBatch], s10[kBatch], s11[kBatch], bound[kBatch];
  int32_t cell[kBatch], corner[kBatch];
  uint32_t left[kBatch];
  const size_t side_pts = cells_per_side_ + 1;
  const size_t num_vertices = vertex_coord_[0].size();
  const bool scan = num_vertices <= kScanLimit;
  for (size_t first = 0; first < n; first += kBatch) {
    const size_t count = std::min(kBatch, n - first);
    char* maybe = reaching + first;
    box_test(count, p.nx + first, p.ny + first, p.nz + first, p.d + first, p.enx + first, p.eny + first, p.enz + first,
             p.ed + first, centre_, half_, max_abs_, coord_error_, maybe, margin);
    size_t k = 0;
    for (size_t i = 0; i < count; ++i)
      if (maybe[i]) {
        left[k] = uint32_t(i);
        a[k] = p.nx[first + i];
        b[k] = p.ny[first + i];
        c[k] = p.nz[first + i];
        d[k] = p.d[first + i];
        ++k;
      }
    cube_positions(k, a, b, c, int(cells_per_side_), cell, corner, fi, fj, m);
    for (size_t t = 0; t < k; ++t) {  // (the corner is in range even where the cell is not usable)
      const double* s = &corner_support_[size_t(corner[t])];
      s00[t] = s[0];
      s01[t] = s[1];
      s10[t] = s[side_pts];
      s11[t] = s[side_pts + 1];
    }
    support_bounds(k, s00, s01, s10, s11, fi, fj, m, d, bound);
    for (size_t t = 0; t < k; ++t) {
      const double mg = margin[left[t]];
      char& out = maybe[left[t]];
      if (usable(m[t]) && cell_resolved_[cell[t]]) {
        const uint32_t v = start_of_cell_[cell[t]];
        out = a[t] * xyz_[3 * v] + b[t] * xyz_[3 * v + 1] + c[t] * xyz_[3 * v + 2] + d[t] > -mg;
      } else if (usable(m[t]) && bound[t] < -2 * mg) {
        out = 0;
      } else if (scan) {
        out = any_above(num_vertices, vertex_coord_[0].data(), vertex_coord_[1].data(), vertex_coord_[2].data(), a[t],
                        b[t], c[t], d[t], -mg);
      } else {
        uint32_t hint = 0;
        out = climb_reaches(a[t], b[t], c[t], d[t], mg, usable(m[t]) ? cell[t] : -1, corner[t], scratch, hint);
      }
    }
  }
}

bool SupportTest::climb_reaches(double a, double b, double c, double d, double margin, int32_t cell, int32_t corner,
                                Scratch& scratch, uint32_t& hint) const {
  const double tie = margin * (kClimbTie / kReachMargin);  // kClimbTie delta (see reach_margin)
  const double* xyz = xyz_.data();
  auto f = [&](uint32_t v) { return a * xyz[3 * v] + b * xyz[3 * v + 1] + c * xyz[3 * v + 2] + d; };
  uint32_t cur = cell < 0 ? 0 : start_of_cell_[cell];
  double val = f(cur);
  if (cell >= 0) {
    const size_t side_pts = cells_per_side_ + 1, c0 = size_t(corner);
    for (size_t k : {c0, c0 + 1, c0 + side_pts, c0 + side_pts + 1}) {
      const double fc = f(start_of_corner_[k]);
      if (fc > val) {
        val = fc;
        cur = start_of_corner_[k];
      }
    }
  }
  auto neighbors = [&](uint32_t u, const auto& fn) {
    for (uint32_t k = adj_offset_[u]; k < adj_offset_[u + 1]; ++k) fn(adj_[k]);
  };
  hint = climb_to_max(cur, val, f, neighbors, tie, xyz_.size() / 3, scratch.climb);
  return val > -margin;
}

CulledTrace trace_with_culling(const PlaneSet& ps, const std::vector<uint32_t>& planes,
                               const std::vector<uint32_t>& always, const VertexGeom& start,
                               const TraceOptions& options, uint64_t seed) {
  CulledTrace out;
  std::vector<uint32_t> all = planes;
  all.insert(all.end(), always.begin(), always.end());
  if (planes.size() <= kDirectTraceLimit) {
    out.active = all;
    out.rounds = 1;
    out.trace = trace_kernel_edges(ps, out.active, start, options);
    return out;
  }

  std::vector<char> in_s(ps.size(), 0);
  std::vector<uint32_t> S;
  auto add = [&](uint32_t l) {
    if (!in_s[l]) {
      in_s[l] = 1;
      S.push_back(l);
    }
  };
  for (uint32_t l : always) add(l);
  std::vector<uint32_t> start_tight;  // over `all`
  {
    std::vector<char> none;
    if (certify_vertex(ps, all, start, none, start_tight) != kNoPlane) {
      out.trace.internal_error = true;
      return out;
    }
    for (uint32_t l : start_tight) add(l);
  }
  SplitMix64 rng{seed};
  size_t sample = std::min(planes.size(), std::max<size_t>(64, size_t(4 * std::sqrt(double(planes.size())))));
  for (size_t i = 0; i < sample; ++i) add(planes[rng.next() % planes.size()]);

  const TraceOptions& quiet = options;
  std::vector<uint32_t> added_list, added_hint;
  std::sort(S.begin(), S.end());
  TraceResult tr = trace_kernel_edges(ps, S, start, quiet);
  out.rounds = 1;
  if (tr.internal_error) {
    out.trace = std::move(tr);
    return out;
  }
  {
    const SupportTest support(tr, planes.size());
    SupportTest::Scratch scratch;
    for (uint32_t l : planes) {
      if (in_s[l]) continue;
      const PlaneCoef<Approx> c = ps.approx(l);
      uint32_t hint = 0;
      if (support.may_reach(c, scratch, hint)) {
        in_s[l] = 1;
        added_list.push_back(l);
        added_hint.push_back(hint);
      }
    }
  }
  // Every plane outside S' = (planes some vertex of K_S lies on) + (added ones) is strictly
  // inside at every vertex of K_S, a superset of K_S': one update gives the kernel. The planes
  // of S no vertex lies on cannot touch K_S, hence neither K_S'; they are dropped.
  if (!added_list.empty()) {
    ++out.rounds;
    // (Marks, then one pass over the plane ids: S' comes out increasing without sorting the
    // tens of thousands of planes a dense kernel adds.)
    std::vector<char> in_next(ps.size(), 0);
    for (const auto& v : tr.vertices)
      for (uint32_t l : v.tight) in_next[l] = 1;
    for (uint32_t l : added_list) in_next[l] = 1;
    S.clear();
    for (uint32_t l = 0; l < in_next.size(); ++l)
      if (in_next[l]) S.push_back(l);
    // The cuts keep K_S's structure and touch only what each added plane removes; retracing is
    // the fallback for what they do not handle (a flat result).
    TraceResult cut;
    if (cut_kernel_trace(ps, tr, added_list, added_hint, rng.next(), cut))
      tr = std::move(cut);
    else
      tr = update_kernel_trace(ps, S, tr, added_list, quiet);
  }
  out.active = S;
  out.trace = std::move(tr);
  out.start_vertex = vertex_with_tight_set(out.trace, start_tight, S);
  return out;
}

}  // namespace kergen
