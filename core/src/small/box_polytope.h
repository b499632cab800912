// The clipping box as a traced polytope: the start of the small-input path's clipping
// (small_kernel.h), eight corners and twelve edges with complete tight sets over the box planes.
#pragma once

#include <cstdint>
#include <vector>

#include "exact/plane_store.h"
#include "solve/tracer.h"

namespace kergen {

// The edge from vertex a to vertex b of `tr` (two vertices of a convex polytope joined by an
// edge): its planes (those through both), the first two that are not opposite as its line, and
// the orientation sigma of a -> b along n_p x n_q. False when the vertices share no line
// (fewer than two non-opposite planes) or the orientation is not decided.
bool edge_between(const PlaneSet& ps, const TraceResult& tr, uint32_t a, uint32_t b, TracedEdge& e);

// The box of add_bounding_box (`box`: its six planes, low then high side per axis) as a complete
// trace: its corners (tight: their three box planes) and edges.
TraceResult box_polytope(const PlaneSet& ps, const std::vector<uint32_t>& box);

}  // namespace kergen
