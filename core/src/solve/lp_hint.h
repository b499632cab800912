// A floating-point run of Seidel's LP on the problem of solve_lp, as a guess of its answer: the
// planes that define the optimum, or a few planes with no common point. No guarantee of any
// kind; solve_lp only puts these planes first, and the exact run then mostly confirms that the
// others hold (one filtered side test each) instead of rebuilding the optimum many times.
#pragma once

#include <cstddef>
#include <cstdint>

#include "exact/predicates.h"

namespace kergen {

struct LpHint {
  uint32_t position[4];  // positions in the constraint array given (bounding planes excluded)
  int count = 0;
  bool infeasible = false;  // the guess is that these planes admit no common point
};

// Maximizes `direction` over { x : f_i(x) <= 0, i = planes[0..n) } and the box
// s_k x_k <= bound (s = sign pattern of the direction), in doubles on normalized coefficients,
// in the order given.
LpHint float_lp_hint(const PlaneSet& ps, const uint32_t* planes, size_t n, const double direction[3], double bound);

}  // namespace kergen
