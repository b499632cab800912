// The double filter of side(l, v) for many planes l at one vertex v: f_l(v) is certainly below
// zero when it is below -bound (exact/error_bounds.h, the bound the tracer's vectorized scan uses
// too), for coefficients and coordinates of any magnitude.
#pragma once

#include <cmath>

#include "exact/error_bounds.h"
#include "exact/predicates.h"

namespace kergen {

class VertexFilter {
 public:
  explicit VertexFilter(const VertexGeom& v) : terms_(vertex_filter_terms(v.x)) {
    for (int k = 0; k < 3; ++k) x_[k] = v.x[k].v;
  }
  // -1 where f_l(v) is certainly negative, 1 where certainly positive, 0 where the exact side
  // test must decide.
  int sign(const PlaneCoef<Approx>& c) const {
    const double f = c.n[0].v * x_[0] + c.n[1].v * x_[1] + c.n[2].v * x_[2] + c.d.v;
    const PlaneFilterTerms p =
        plane_filter_terms(c.n[0].v, c.n[1].v, c.n[2].v, c.d.v, c.n[0].e, c.n[1].e, c.n[2].e, c.d.e);
    const double b = vertex_filter_bound(p, terms_) * exact::kBoundScale;
    return f < -b ? -1 : (f > b ? 1 : 0);
  }

 private:
  double x_[3];
  VertexFilterTerms terms_;
};

}  // namespace kergen
