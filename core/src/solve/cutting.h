// Cutting a traced polytope by planes one at a time: the update step of incremental half-space
// intersection. A plane's outside vertices are found by climbing the vertex graph from a hint;
// they are removed, the edges leaving them are shortened to the plane, and the new face is
// closed from the cut points. A cut costs the size of what changes, where retracing the cut
// part scans every plane once per new edge.
#pragma once

#include <cstdint>
#include <vector>

#include "exact/predicates.h"
#include "solve/tracer.h"

namespace kergen {

// K_S' = K_S cut by every plane of `added`, from `prev`, a complete trace of the bounded,
// full-dimensional polytope K_S (vertex tight sets and edge plane sets complete over S, every
// plane of which some vertex lies on is in S'). hints[i] is a vertex of prev near the maximum
// of added[i]'s function (a start for the climb; any vertex is correct). Planes are applied in
// an order shuffled by `seed`. The result has the same contract as update_kernel_trace's.
// Returns false, leaving `out` unspecified, when the result would be flat (a plane and its
// opposite both bound it) or a cut meets a configuration a convex polytope cannot have; the
// caller then traces instead.
bool cut_kernel_trace(const PlaneSet& ps, const TraceResult& prev, const std::vector<uint32_t>& added,
                      const std::vector<uint32_t>& hints, uint64_t seed, TraceResult& out);

}  // namespace kergen
