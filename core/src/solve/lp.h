// Seidel's randomized linear programming in 3D (Seidel, "Small-dimensional linear programming
// and convex hulls made easy", 1991), expected O(N), on exact predicates: the extreme kernel
// vertex in a direction, or a proof that the kernel is empty.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "exact/predicates.h"

namespace kergen {

// Generic objective for the LP (ties are broken lexicographically anyway).
constexpr double kDefaultDirection[3] = {0.5773502691896258, 0.5773502691896257, 0.5773502691896256};
// The LP's bounding planes: scaled coordinates are below 1, the bounding box (add_bounding_box)
// is within 4.
constexpr double kLpBound = 8;

struct LpResult {
  enum class Outcome { Optimal, Infeasible, Unbounded };
  Outcome outcome = Outcome::Infeasible;
  VertexGeom vertex;  // Optimal: the unique lexicographic optimum, with its basis planes
  // Infeasible: the representative triangles of at most four of the planes (none explicit) whose
  // half-spaces have no common point within bounds far wider than the LP's, every one of them
  // needed for that; empty when none were found (the explicit planes were needed). Not yet
  // checked without any bounds: halfspaces_disjoint does that.
  std::vector<std::array<uint32_t, 3>> conflict;
};

// Maximizes `direction` (then two fixed tie-break directions, lexicographically, so the optimum
// is a unique point) over { x : f_i(x) <= 0 for i in `planes` }. Three bounding planes at
// +-bound (a power of two beyond the data) are appended to `ps`; an optimum on them is reported
// as Unbounded. The constraint order is shuffled with `seed` (the result does not depend on it;
// an infeasible conflict may).
LpResult solve_lp(PlaneSet& ps, const std::vector<uint32_t>& planes, const double direction[3], double bound,
                  uint64_t seed);

}  // namespace kergen
