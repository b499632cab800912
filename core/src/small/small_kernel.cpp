// The small-input path (small_kernel.h).
#include "small/small_kernel.h"

#include <cmath>
#include <utility>

#include "small/box_polytope.h"

namespace kergen {

namespace {

// `planes` in farthest-first order of their unit normals (O(n^2): n is small here).
void spread_order(const PlaneSet& ps, const std::vector<uint32_t>& planes, std::vector<uint32_t>& order) {
  const size_t n = planes.size();
  std::vector<double> unit(3 * n), closest(n, -2.0);
  for (size_t i = 0; i < n; ++i) {
    const uint32_t h = planes[i];
    const double x = ps.nx()[h], y = ps.ny()[h], z = ps.nz()[h];
    const double len = std::sqrt(x * x + y * y + z * z);
    unit[3 * i] = x / len;
    unit[3 * i + 1] = y / len;
    unit[3 * i + 2] = z / len;
  }
  order.clear();
  std::vector<char> taken(n, 0);
  size_t next = 0;
  for (size_t k = 0; k < n; ++k) {
    taken[next] = 1;
    order.push_back(planes[next]);
    const double* u = &unit[3 * next];
    size_t best = n;
    for (size_t i = 0; i < n; ++i) {
      if (taken[i]) continue;
      const double dot = u[0] * unit[3 * i] + u[1] * unit[3 * i + 1] + u[2] * unit[3 * i + 2];
      if (dot > closest[i]) closest[i] = dot;
      if (best == n || closest[i] < closest[best]) best = i;
    }
    next = best;
  }
}

}  // namespace

bool small_kernel_trace(const PlaneSet& ps, const std::vector<uint32_t>& planes, const std::vector<uint32_t>& box,
                        ClipPolytope& clip, TraceResult& out) {
  clip.reset(box_polytope(ps, box), planes.size());
  // Normals spread out first (each next plane the one whose normal is farthest from those of
  // the planes clipped by so far): the polytope is then near the kernel before the nearly
  // coplanar planes of a split polygon come, whose cuts would otherwise make vertices of poorly
  // conditioned lines across the box, each needing double-double evaluation.
  std::vector<uint32_t> order;
  spread_order(ps, planes, order);
  for (uint32_t h : order)
    if (!clip.clip(ps, h)) return false;
  return clip.finish(ps, out);
}

}  // namespace kergen
