// Culling by iterated subset kernels (in the spirit of Clarkson's sampling LP algorithm).
// Every round traces the kernel K_S of a plane subset S; K_S contains the kernel, so a plane
// outside S matters only if some vertex of K_S lies outside it. Finding that vertex is a support
// query on the convex polytope K_S: hill climbing on its vertex graph from the previous answer
// (input planes come in spatially coherent order, so few steps are needed).
#include "culling.h"

#include <algorithm>
#include <cmath>

namespace kergen {

namespace {

uint64_t mix(uint64_t& s) {
  s += 0x9e3779b97f4a7c15ull;
  uint64_t z = s;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

constexpr size_t kDirectTraceLimit = 256;  // below this many planes culling costs more than it saves

}  // namespace

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
  const double* nx = ps.nx(); const double* ny = ps.ny(); const double* nz = ps.nz(); const double* nd = ps.d();
  std::vector<uint32_t> adj_offset, adj;
  std::vector<double> xyz;
  for (;;) {
    ++out.rounds;
    std::sort(S.begin(), S.end());
    TraceResult tr = trace_kernel_edges(ps, S, start, quiet);
    if (tr.internal_error) {
      out.trace = std::move(tr);
      return out;
    }
    // Vertex graph of K_S.
    const size_t V = tr.vertices.size();
    xyz.resize(3 * V);
    for (size_t v = 0; v < V; ++v)
      for (int k = 0; k < 3; ++k) xyz[3 * v + k] = tr.vertices[v].geom.x[k].v;
    adj_offset.assign(V + 1, 0);
    for (const auto& e : tr.edges) { adj_offset[e.a + 1]++; adj_offset[e.b + 1]++; }
    for (size_t v = 0; v < V; ++v) adj_offset[v + 1] += adj_offset[v];
    adj.resize(adj_offset[V]);
    {
      std::vector<uint32_t> fill(adj_offset.begin(), adj_offset.end() - 1);
      for (const auto& e : tr.edges) { adj[fill[e.a]++] = e.b; adj[fill[e.b]++] = e.a; }
    }
    size_t added = 0;
    uint32_t cur = 0;
    for (uint32_t l : planes) {
      if (in_s[l]) continue;
      const double a = nx[l], b = ny[l], c = nz[l], d = nd[l];
      double val = a * xyz[3 * cur] + b * xyz[3 * cur + 1] + c * xyz[3 * cur + 2] + d;
      for (bool moved = true; moved;) {
        moved = false;
        for (uint32_t i = adj_offset[cur]; i < adj_offset[cur + 1]; ++i) {
          uint32_t w = adj[i];
          double f = a * xyz[3 * w] + b * xyz[3 * w + 1] + c * xyz[3 * w + 2] + d;
          if (f > val) { val = f; cur = w; moved = true; }
        }
      }
      // Coordinates are below ~2 in magnitude (scaled input, box at 2): the rounding of val is
      // below 1e-15 (|n|_1 + |d|); the margin keeps every plane that could be violated.
      double margin = 1e-9 * (std::fabs(a) + std::fabs(b) + std::fabs(c) + std::fabs(d));
      if (val > -margin) { add(l); ++added; }
    }
    if (added == 0) {
      out.active = S;
      if ((options.on_step && *options.on_step) || options.max_steps) {
        out.trace = trace_kernel_edges(ps, S, start, options);  // the final trace, with events
      } else {
        out.trace = std::move(tr);
      }
      return out;
    }
  }
}

}  // namespace kergen
