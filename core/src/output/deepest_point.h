// Centre of the largest ball inside a kernel (its Chebyshev centre), for Options::deepest_point.
#pragma once

#include <cstdint>
#include <vector>

#include "exact/predicates.h"

namespace kergen {

// `facets`: the kernel's facet planes in `ps`; the ball is searched within the box
// [bbox_min, bbox_max]. False when the kernel has fewer than four facets or a facet's normal is
// zero (no centre is computed).
bool deepest_point(const PlaneSet& ps, const std::vector<uint32_t>& facets, const double bbox_min[3],
                   const double bbox_max[3], double point[3], double& radius);

}  // namespace kergen
