// Culling by a subset kernel (in the spirit of Clarkson's sampling LP algorithm). The kernel
// K_S of a random plane subset S is traced; K_S contains the kernel, so a plane outside S
// matters only if some vertex of K_S lies outside it. Finding that vertex is a support query on
// the convex polytope K_S: hill climbing on its vertex graph from a cube map of extreme
// vertices. K_S is then cut by the planes found.
#include "culling.h"

#include <algorithm>
#include <cmath>

#include "climb.h"
#include "cutting.h"

namespace kergen {

namespace {

uint64_t mix(uint64_t& s) {
  s += 0x9e3779b97f4a7c15ull;
  uint64_t z = s;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

// Direction of the point (i + fi, j + fj) / k of cell (face, i, j); fi = fj = 0.5 is the centre,
// 0 or 1 the corners.
void cube_cell_direction(size_t cells_per_side, size_t cell, double fi, double fj, double dir[3]) {
  const size_t face = cell / (cells_per_side * cells_per_side), i = cell / cells_per_side % cells_per_side, j = cell % cells_per_side;
  const int axis = int(face / 2);
  dir[axis] = face % 2 ? -1.0 : 1.0;
  dir[(axis + 1) % 3] = (double(i) + fi) / double(cells_per_side) * 2 - 1;
  dir[(axis + 2) % 3] = (double(j) + fj) / double(cells_per_side) * 2 - 1;
}

constexpr size_t kDirectTraceLimit = 1024;  // below this many planes culling costs more than it saves

}  // namespace

SupportTest::SupportTest(const TraceResult& tr, size_t expected_queries) {
  // Vertex graph of K_S.
  const size_t V = tr.vertices.size();
  xyz_.resize(3 * V);
  for (size_t v = 0; v < V; ++v)
    for (int k = 0; k < 3; ++k) {
      xyz_[3 * v + k] = tr.vertices[v].geom.x[k].v;
      coord_error_ = std::max(coord_error_, tr.vertices[v].geom.x[k].e);
    }
  adj_offset_.assign(V + 1, 0);
  for (const auto& e : tr.edges) { adj_offset_[e.a + 1]++; adj_offset_[e.b + 1]++; }
  for (size_t v = 0; v < V; ++v) adj_offset_[v + 1] += adj_offset_[v];
  adj_.resize(adj_offset_[V]);
  {
    std::vector<uint32_t> fill(adj_offset_.begin(), adj_offset_.end() - 1);
    for (const auto& e : tr.edges) { adj_[fill[e.a]++] = e.b; adj_[fill[e.b]++] = e.a; }
  }
  // Bounding box of K_S: max over K_S of f_l <= f_l(box centre) + sum_k |n_k| half_k, one
  // dot product that clears most planes without a climb (they lie far from the kernel).
  double lo[3] = {xyz_[0], xyz_[1], xyz_[2]}, hi[3] = {xyz_[0], xyz_[1], xyz_[2]};
  for (size_t v = 1; v < V; ++v)
    for (int k = 0; k < 3; ++k) { lo[k] = std::min(lo[k], xyz_[3 * v + k]); hi[k] = std::max(hi[k], xyz_[3 * v + k]); }
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
  cells_per_side_ = std::min<size_t>(24, std::max<size_t>(2, size_t(std::sqrt(double(expected_queries) / 100))));
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
        if (g(adj_[i]) > val) { at = adj_[i]; val = g(at); moved = true; }
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
      climb_to_max(at, h, g, neighbors, 1e-12 * (std::fabs(dir[0]) + std::fabs(dir[1]) + std::fabs(dir[2])), V, climb);
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
        // Strictly descending by a margin far above the rounding of the coordinates (which
        // are below ~2): the rounded direction of a very short edge says nothing about the
        // exact one, so such vertices are left to the climb and its plateau search.
        const double cd1 = std::fabs(cd[0]) + std::fabs(cd[1]) + std::fabs(cd[2]);
        strict = cd[0] * e[0] + cd[1] * e[1] + cd[2] * e[2] < -1e-9 * cd1;
      }
    }
    cell_resolved_[cell] = strict;
  }
}

bool SupportTest::may_reach(const PlaneCoef<Approx>& plane, Scratch& scratch, uint32_t& hint) const {
  const double a = plane.n[0].v, b = plane.n[1].v, c = plane.n[2].v, d = plane.d.v;
  // The climb's values are doubles: their rounding is below 1e-15 (|n|_1 + |d|) for coordinates
  // below ~2 (scaled input, box at 2). `tie` is far above that; `margin` keeps every plane that
  // could be violated, and adds what the plane's coefficients and the vertices' coordinates
  // may be off by (both tiny, but not for a sliver's plane or an ill-conditioned vertex).
  const double scale = std::fabs(a) + std::fabs(b) + std::fabs(c) + std::fabs(d);
  const double coef_error = (plane.n[0].e + plane.n[1].e + plane.n[2].e) * (max_abs_ + coord_error_) + plane.d.e;
  const double tie = 1e-12 * scale;
  const double margin = 1e-9 * scale + coef_error + (scale - std::fabs(d)) * coord_error_;
  // (The box is a double computation like the climb; 2 * margin covers its rounding.)
  if (a * centre_[0] + b * centre_[1] + c * centre_[2] + d + std::fabs(a) * half_[0] + std::fabs(b) * half_[1] +
          std::fabs(c) * half_[2] < -2 * margin)
    return false;
  const double* xyz = xyz_.data();
  auto f = [&](uint32_t v) { return a * xyz[3 * v] + b * xyz[3 * v + 1] + c * xyz[3 * v + 2] + d; };
  const size_t cell = cube_cell(cells_per_side_, a, b, c);
  const size_t side_pts = cells_per_side_ + 1;
  size_t c0 = 0;
  if (cell != kNoCell && !cell_resolved_[cell]) {
    // h is convex and positively homogeneous, and n / |n_axis| is the bilinear interpolation of
    // the cell's four corner directions (exact: they are affine in the cell's coordinates), so
    // max f <= |n_axis| (the same interpolation of the corners' h) + d. Below -2 margin the
    // plane holds K_S strictly without a climb.
    const double n3[3] = {a, b, c};
    int axis = 0;
    for (int k = 1; k < 3; ++k)
      if (std::fabs(n3[k]) > std::fabs(n3[axis])) axis = k;
    const double m = std::fabs(n3[axis]);
    const size_t face = cell / (cells_per_side_ * cells_per_side_), i = cell / cells_per_side_ % cells_per_side_,
                 j = cell % cells_per_side_;
    const double fi = std::min(1.0, std::max(0.0, (n3[(axis + 1) % 3] / m + 1) * 0.5 * double(cells_per_side_) - double(i)));
    const double fj = std::min(1.0, std::max(0.0, (n3[(axis + 2) % 3] / m + 1) * 0.5 * double(cells_per_side_) - double(j)));
    c0 = (face * side_pts + i) * side_pts + j;
    const double h = (1 - fi) * ((1 - fj) * corner_support_[c0] + fj * corner_support_[c0 + 1]) +
                     fi * ((1 - fj) * corner_support_[c0 + side_pts] + fj * corner_support_[c0 + side_pts + 1]);
    if (m * h + d < -2 * margin) return false;
  }
  uint32_t cur = cell == kNoCell ? 0 : start_of_cell_[cell];
  double val = f(cur);
  if (cell != kNoCell && !cell_resolved_[cell]) {
    for (size_t k : {c0, c0 + 1, c0 + side_pts, c0 + side_pts + 1}) {
      const double fc = f(start_of_corner_[k]);
      if (fc > val) { val = fc; cur = start_of_corner_[k]; }
    }
  }
  if (cell == kNoCell || !cell_resolved_[cell]) {
    auto neighbors = [&](uint32_t u, const auto& fn) {
      for (uint32_t k = adj_offset_[u]; k < adj_offset_[u + 1]; ++k) fn(adj_[k]);
    };
    cur = climb_to_max(cur, val, f, neighbors, tie, xyz_.size() / 3, scratch.climb);
  }
  hint = cur;
  return val > -margin;
}


CulledTrace trace_with_culling(const PlaneSet& ps, const std::vector<uint32_t>& planes, const std::vector<uint32_t>& always,
                               const VertexGeom& start, const TraceOptions& options, uint64_t seed) {
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
    if (!in_s[l]) { in_s[l] = 1; S.push_back(l); }
  };
  for (uint32_t l : always) add(l);
  {
    std::vector<uint32_t> tight;
    std::vector<char> none;
    if (certify_vertex(ps, all, start, none, tight) != kNoPlane) {
      out.trace.internal_error = true;
      return out;
    }
    for (uint32_t l : tight) add(l);
  }
  uint64_t rng = seed;
  size_t sample = std::min(planes.size(), std::max<size_t>(64, size_t(4 * std::sqrt(double(planes.size())))));
  for (size_t i = 0; i < sample; ++i) add(planes[mix(rng) % planes.size()]);

  TraceOptions quiet = options;
  quiet.on_step = nullptr;
  quiet.max_steps = 0;
  quiet.steps = nullptr;
  std::vector<uint32_t> added_list, added_hint, on_kernel;
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
      if (support.may_reach(c, scratch, hint)) { in_s[l] = 1; added_list.push_back(l); added_hint.push_back(hint); }
    }
  }
  // Every plane outside S' = (planes some vertex of K_S lies on) + (added ones) is strictly
  // inside at every vertex of K_S, a superset of K_S': one update gives the kernel. The planes
  // of S no vertex lies on cannot touch K_S, hence neither K_S'; they are dropped.
  if (!added_list.empty()) {
    ++out.rounds;
    for (const auto& v : tr.vertices) on_kernel.insert(on_kernel.end(), v.tight.begin(), v.tight.end());
    std::sort(on_kernel.begin(), on_kernel.end());
    on_kernel.erase(std::unique(on_kernel.begin(), on_kernel.end()), on_kernel.end());
    S = on_kernel;
    S.insert(S.end(), added_list.begin(), added_list.end());
    std::sort(S.begin(), S.end());
    // The cuts keep K_S's structure and touch only what each added plane removes; retracing is
    // the fallback for what they do not handle (a flat result).
    TraceResult cut;
    if (cut_kernel_trace(ps, tr, added_list, added_hint, mix(rng), cut))
      tr = std::move(cut);
    else
      tr = update_kernel_trace(ps, S, tr, added_list, quiet);
  }
  out.active = S;
  if (!tr.internal_error && ((options.on_step && *options.on_step) || options.max_steps))
    out.trace = trace_kernel_edges(ps, S, start, options);  // the final trace, with events
  else
    out.trace = std::move(tr);
  return out;
}

}  // namespace kergen
