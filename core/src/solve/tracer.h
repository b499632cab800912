// Additive kernel tracing (KerGen, Asiler & Sahillioglu 2024, Alg. 2): from a kernel vertex,
// follow every line where two of its tight planes meet and that stays in the kernel, find the
// nearest plane along it, add the new vertex, until every kernel edge was traced once.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "exact/predicates.h"
#include "kergen/kergen.h"
#include "util/small_vector.h"

namespace kergen {

// "No vertex" among the vertex ids of a trace (the same bits as kNoPlane, but a vertex's).
constexpr uint32_t kNoVertex = 0xffffffffu;

// Planes through a vertex or along an edge: three or two, a few more at degenerate corners.
using PlaneIds = SmallVector<uint32_t, 6>;

struct TracedVertex {
  VertexGeom geom;
  PlaneIds tight;  // every plane through the vertex, sorted (its identity)
};

struct TracedEdge {
  uint32_t a = 0, b = 0;  // traced from a to b
  uint32_t p = 0, q = 0;  // the direction is sigma * (n_p x n_q)
  int sigma = 1;
  PlaneIds planes;  // every plane containing the edge, sorted
};

struct TraceResult {
  std::vector<TracedVertex> vertices;
  std::vector<TracedEdge> edges;
  bool complete = true;         // false for a partial kernel (a stopped step replay)
  bool internal_error = false;  // a certification failed (never expected; reported, not hidden)
  size_t traced_lines = 0;
};

// (The tracer emits no step events: step_replay.h replays them from a finished trace.)
struct TraceOptions {
  bool has_from = false;       // expand the vertex nearest to `from` first
  double from[3] = {0, 0, 0};  // in the scaled units of the plane set
};

// `active` lists the planes that may touch the kernel (all of them, or the survivors of culling);
// `start` must be a kernel vertex on planes of `active`.
TraceResult trace_kernel_edges(const PlaneSet& ps, const std::vector<uint32_t>& active, const VertexGeom& start,
                               const TraceOptions& options);

// K_S' from a complete trace `prev` of K_S, where S' = `active` holds the planes `added` and
// every plane of S that some vertex of K_S lies on (other planes of S may be dropped). Only the
// part of K_S the added planes cut is traced again.
TraceResult update_kernel_trace(const PlaneSet& ps, const std::vector<uint32_t>& active, const TraceResult& prev,
                                const std::vector<uint32_t>& added, const TraceOptions& options);

// The facet planes of a traced polytope (planes holding three or more of its edges: a supporting
// plane through two non-collinear edges touches a 2D face), increasing.
std::vector<uint32_t> facet_planes(const TraceResult& trace);

// The complete tight set of `w` over `active` (planes in `known_tight` are not re-evaluated), or
// the first violated plane. Returns kNoPlane when w is a kernel point.
uint32_t certify_vertex(const PlaneSet& ps, const std::vector<uint32_t>& active, const VertexGeom& w,
                        const std::vector<char>& known_tight_mark, std::vector<uint32_t>& tight);

}  // namespace kergen
