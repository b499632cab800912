// Output-sensitive tracing: only the planes that can touch the kernel are traced against.
#pragma once

#include <vector>

#include "planes.h"
#include "tracer.h"

namespace kergen {

struct CulledTrace {
  TraceResult trace;            // the kernel, traced against `active` only
  std::vector<uint32_t> active; // the planes kept (a superset of those touching the kernel)
  size_t rounds = 0;
};

// Kernel of `planes` from the kernel vertex `start` (tight set computed over `planes`).
// Clarkson-style sampling: trace the kernel K_S of a subset S (S holds start's tight planes,
// `always` — e.g. bounding planes — and a random sample), find every plane some vertex of K_S
// violates, and cut K_S by them (cutting.h; retraced where the cuts do not apply): every other
// plane holds K_S, hence the result, strictly. Violation is found per plane by hill climbing on
// K_S's vertex graph in the plane's normal direction, in double with a margin far above
// rounding, so a violated plane is never missed (near-touching planes are merely kept).
// Events are emitted only by the final trace.
CulledTrace trace_with_culling(const PlaneSet& ps, const std::vector<uint32_t>& planes, const std::vector<uint32_t>& always,
                               const VertexGeom& start, const TraceOptions& options, uint64_t seed);

}  // namespace kergen
