// Deepest point: bisection on the inward offset of the facet planes, one exact LP per step.
#include "output/deepest_point.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "solve/lp.h"

namespace kergen {

// Centre of the largest ball inside the kernel: bisection on the inward offset r of the facet
// planes (unit normals, double coefficients taken as exact), each step one exact LP that says
// whether the offset polytope is non-empty. The last feasible LP vertex is within the bisection
// tolerance of a centre (any point of the final offset polytope is one when it is not unique).
bool deepest_point(const PlaneSet& ps, const std::vector<uint32_t>& facets, const double bbox_min[3],
                   const double bbox_max[3], double point[3], double& radius) {
  if (facets.size() < 4) return false;
  std::vector<double> no_points;
  std::vector<std::array<double, 4>> unit;
  for (uint32_t h : facets) {
    double n[3] = {ps.nx()[h], ps.ny()[h], ps.nz()[h]};
    double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 0)) return false;
    unit.push_back({n[0] / len, n[1] / len, n[2] / len, ps.d()[h] / len});
  }
  double hi = 0;
  for (int k = 0; k < 3; ++k) hi = std::max(hi, 0.5 * (bbox_max[k] - bbox_min[k]));
  double lo = 0;
  bool found = false;
  for (int it = 0; it < 60 && hi - lo > 1e-15 * std::max(hi, 1e-300); ++it) {
    double r = 0.5 * (lo + hi);
    PlaneSet shrunk(&no_points);
    std::vector<uint32_t> ids;
    for (const auto& u : unit) ids.push_back(shrunk.add_explicit(u[0], u[1], u[2], u[3] + r));
    LpResult lp = solve_lp(shrunk, ids, kDefaultDirection, kLpBound, 7);
    if (lp.outcome == LpResult::Outcome::Optimal) {
      lo = r;
      for (int k = 0; k < 3; ++k) point[k] = lp.vertex.x[k].v;
      found = true;
    } else {
      hi = r;
    }
  }
  radius = lo;
  return found;
}

}  // namespace kergen
