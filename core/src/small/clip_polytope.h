// A convex polytope clipped by planes one at a time, on small contiguous arrays: the update of
// incremental half-space intersection ("beneath-beyond"; Preparata & Shamos, Computational
// Geometry, 1985, Sec. 7.2.5), with exact incidences.
//
// Why a clip is exact: each vertex's side of the plane is the exact sign (side(), filtered);
// a vertex outside is removed; an edge from a removed vertex to one strictly inside gets the
// vertex of its line and the plane; the new face's edges join the cut points (new vertices and
// vertices on the plane) two by two: cut points on another plane g lie on the line of g and
// the plane, and a face of a convex polytope on a line holds exactly two vertices.
// Why the tight sets stay complete: a new vertex lies inside its edge, and a plane already
// clipped by that passes through an inner point of an edge holds the whole edge (it is linear
// along it and not positive at either end), so the edge's planes and the new plane are all of
// its planes; a vertex on the plane gains it. The planes through an edge are those through both
// ends. So degenerate vertices (four or more planes) need no special case.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "exact/error_bounds.h"
#include "exact/plane_store.h"
#include "solve/tracer.h"

namespace kergen {

class ClipPolytope {
 public:
  // Starts from the polytope `start` (a complete trace, e.g. box_polytope's) for about `clips`
  // clips; buffers are kept from earlier uses.
  void reset(const TraceResult& start, size_t clips);
  // Clips by the inner half-space of plane h (not yet clipped by, nor its opposite). False when
  // the result is not full-dimensional (no vertex strictly inside: empty or flat), or a cut
  // meets a configuration a convex polytope cannot have; the polytope is then unspecified.
  bool clip(const PlaneSet& ps, uint32_t h);
  // The polytope as a complete trace (edges with their planes and orientation; the vertices
  // made again by make_vertex, as the tracer makes them), moved out. False when an edge's
  // orientation is not decided (never for a consistent polytope).
  bool finish(const PlaneSet& ps, TraceResult& out);

 private:
  // A vertex's double filter (vertex_filter.h's terms), kept beside it for the scans.
  struct Filter {
    double x[3];
    VertexFilterTerms terms;
  };
  uint32_t add_vertex(TracedVertex&& v);
  bool connect_cut_points(const PlaneSet& ps, uint32_t h, size_t first_new);

  // Vertices are only appended (a cut-away one leaves the live list): a clip moves no vertex
  // record.
  std::vector<TracedVertex> vertices_;
  std::vector<Filter> filter_;
  std::vector<uint32_t> live_;  // the polytope's vertices, increasing
  std::vector<std::array<uint32_t, 2>> edges_;
  std::vector<int8_t> side_;          // per vertex: its side of the plane being clipped by
  std::vector<uint32_t> cut_points_;  // vertices on the plane after the cut
  std::vector<uint32_t> remap_;
  PlaneIds shared_;
};

}  // namespace kergen
