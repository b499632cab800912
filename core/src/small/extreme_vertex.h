// The vertex of a clipped kernel that the LP would end on, without the LP: the small-input path
// (small_kernel.h) finds the whole kernel first, and a vertex certainly above every other in
// the LP's direction is its unique maximum, so the LP's optimum (whose lexicographic
// tie-breaks only act between vertices of equal value).
#pragma once

#include <cstdint>

#include "exact/plane_store.h"
#include "solve/tracer.h"

namespace kergen {

// The vertex of `tr` whose value dir . x is certainly (by the filtered coordinates' rigorous
// bounds) above every other vertex's, or kNoVertex when no vertex is certainly alone at the
// top (a tie, or values too close for the filter: the caller then solves the LP).
uint32_t certainly_extreme_vertex(const TraceResult& tr, const double dir[3]);

}  // namespace kergen
