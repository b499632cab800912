// The small-input path: the kernel of a few dozen planes (a polyhedral mesh's cell, a small
// mesh) clipped from a box, the plane-by-plane update of incremental half-space intersection
// (the "beneath-beyond" clipping of a convex polytope: Preparata & Shamos, Computational
// Geometry, 1985, Sec. 7.2.5; as KerGen's cuts, Asiler & Sahillioglu 2024). KerGen's tracer
// (tracer.h) pays per traced line for a scan of every plane, for the LP vertex's degenerate
// corners and for the bookkeeping that keeps large kernels output-sensitive; on a few dozen
// planes clipping the whole box by each plane once is cheaper, and its exact side tests make
// degenerate vertices (more than three planes, as a cell's split polygons have) cost nothing
// extra: a vertex on the cutting plane just gains it in its tight set.
//
// The result is a complete trace (tracer.h's contract: every vertex with its complete sorted
// tight set, every edge with its planes and orientation), so the certificate and the assembly
// are the general path's, and the answer is the same in the canonical order of kergen.h.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "exact/plane_store.h"
#include "small/clip_polytope.h"
#include "solve/tracer.h"

namespace kergen {

// Up to this many planes (box excluded) compute_kernel clips instead of tracing (measured:
// bench/README.md, "Small inputs").
constexpr size_t kSmallPlaneLimit = 64;

// The kernel of `planes` (inner half-spaces) within the box (`box`, add_bounding_box's planes),
// clipped from the box by each plane in turn, in `clip` (whose buffers are reused). False,
// leaving `out` unspecified, when the result is not full-dimensional (flat or empty) or a
// configuration a convex polytope cannot have came up: the caller then traces.
bool small_kernel_trace(const PlaneSet& ps, const std::vector<uint32_t>& planes, const std::vector<uint32_t>& box,
                        ClipPolytope& clip, TraceResult& out);

}  // namespace kergen
