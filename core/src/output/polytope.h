// From traced vertices and edges to the output polytope: type, facets as CCW loops, volume, area.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "kergen/kergen.h"
#include "solve/tracer.h"

namespace kergen {

// How the output vertices are numbered: Canonical (Kernel's documented order: by coordinates,
// edges as sorted (low, high) pairs), or Trace (the trace's own numbering and edge orientation,
// which the step events use).
enum class VertexOrder { Canonical, Trace };

// Fills type, vertices (times 2^unscale_exp), edges, face_indices/face_sizes, triangles, volume and
// area of `out`, numbered as `vertex_order` says; faces are always loops started at their lowest
// vertex, in increasing order of their vertex sequences, and volume and area are summed in that
// order (so they do not depend on the order the trace found the kernel in). A plane is a facet iff it holds >= 3 edges;
// its loop is walked counter-clockwise seen from outside, decided exactly per edge. `emit_face` is called per facet, in
// order; it returns false to stop (the remaining facets are still assembled but not announced). `scaled_volume`
// receives the volume in the plane set's units; `face_planes`, when given, each output face's plane (its facet plane; a
// polygon's: the lower of its two). Returns false if the traced edges do not close into a valid polytope (internal
// error).
bool assemble_polytope(const PlaneSet& ps, const TraceResult& trace, int unscale_exp, Kernel& out,
                       const std::function<bool(const StepEvent&)>& emit_face, double& scaled_volume,
                       std::vector<uint32_t>* face_planes = nullptr, VertexOrder vertex_order = VertexOrder::Canonical);

}  // namespace kergen
