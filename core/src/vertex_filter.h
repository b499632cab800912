// The double filter of side(l, v) for many planes l at one vertex v: f_l(v) is certainly below
// zero when it is below -bound, with a rigorous bound from the plane's coefficient errors, v's
// coordinate errors and the rounding of the evaluation (coefficients and coordinates of any
// magnitude; the tracer's vectorized scan uses the same bound, see PlaneArrays).
#pragma once

#include <algorithm>
#include <cmath>

#include "exact/predicates.h"

namespace kergen {

class VertexFilter {
 public:
  explicit VertexFilter(const VertexGeom& v) {
    double xm = 0, dx = 0;
    for (int k = 0; k < 3; ++k) { xm = std::max(xm, std::fabs(v.x[k].v)); dx = std::max(dx, v.x[k].e); }
    c1_ = (xm + 2 * dx) * exact::kBoundScale;
    c2_ = (dx + 4 * exact::kEps * xm) * exact::kBoundScale;
    for (int k = 0; k < 3; ++k) x_[k] = v.x[k].v;
  }
  // -1 where f_l(v) is certainly negative, 1 where certainly positive, 0 where the exact side
  // test must decide.
  int sign(const PlaneCoef<Approx>& c) const {
    const double f = c.n[0].v * x_[0] + c.n[1].v * x_[1] + c.n[2].v * x_[2] + c.d.v;
    const double b = ((c.n[0].e + c.n[1].e + c.n[2].e) * c1_ +
                      (std::fabs(c.n[0].v) + std::fabs(c.n[1].v) + std::fabs(c.n[2].v)) * c2_ +
                      (c.d.e + 4 * exact::kEps * std::fabs(c.d.v) + exact::kUnderflowFloor)) *
                     exact::kBoundScale;
    return f < -b ? -1 : (f > b ? 1 : 0);
  }

 private:
  double x_[3], c1_, c2_;
};

}  // namespace kergen
