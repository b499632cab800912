// Step events from a finished trace. The kernel is always computed by the fast path (culling,
// incremental cuts); the stream a caller asked for is then replayed from its vertex graph in the
// order KerGen's additive tracing discovers it, so asking for steps never changes which
// algorithm runs and costs O(V + E) on top of it.
#pragma once

#include <cstdint>

#include "exact/predicates.h"
#include "solve/tracer.h"

namespace kergen {

struct ReplayOptions {
  const StepCallback* on_step = nullptr;
  uint64_t max_steps = 0;      // stop after this many events (0 = no limit)
  uint64_t* steps = nullptr;   // events emitted so far (shared with the face events after)
  bool has_from = false;       // expand the vertex nearest to `from` first
  double from[3] = {0, 0, 0};  // in the scaled units of the plane set
  int unscale_exp = 0;         // event coordinates are scaled ones times 2^unscale_exp
};

// Renumbers the complete trace `tr` (vertices and edges) in discovery order from vertex `start`
// and emits a Vertex event for each vertex as it is discovered and an Edge event for each edge
// as it is traced, exactly as the tracer does: rays leave the vertices in discovery order
// (nearest to `from` first with has_from), each vertex's edges in the order of the tracer's rays
// (by their first two planes), an edge oriented from the vertex it is traced from. The events
// and numbering are those the tracer would give tracing the same planes from `start`, whichever
// algorithm (full trace, incremental cuts) found the graph.
// When a callback returns false (or max_steps is reached), `tr` keeps exactly the vertices and
// edges reported so far and `complete` becomes false: a valid partial kernel whose ids are
// those of the events.
void replay_steps(const PlaneSet& ps, uint32_t start, TraceResult& tr, const ReplayOptions& options);

}  // namespace kergen
