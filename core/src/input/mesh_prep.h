// Input validation and clean-up: the checks every mesh passes before its planes are built.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "kergen/kergen.h"
#include "util/raw_vector.h"

namespace kergen {

struct PreparedMesh {
  Error error = Error::Ok;
  std::string message;
  std::vector<Warning> warnings;

  std::vector<double> points;  // input positions times 2^scale_exp (exact)
  int scale_exp = 0;
  double to_scaled(double x) const { return std::ldexp(x, scale_exp); }
  double to_input(double x) const { return std::ldexp(x, -scale_exp); }
  // Exact evaluations use the points times 2^exact_shift (exact, sign-preserving): it lifts the
  // lowest set bit of every coordinate high enough that degree-9 products cannot underflow.
  int exact_shift = 0;

  // Faces that carry a plane: a loop of vertex ids (CCW from outside after any flip) and a
  // representative triangle with the loop's orientation. Planar polygons stay whole; zero-area
  // faces are gone; non-planar polygons are split into triangles (folded outward where possible).
  RawVector<uint32_t> loop_offsets;  // size = faces + 1
  RawVector<uint32_t> loops;
  RawVector<std::array<uint32_t, 3>> rep;
  // Pairs of plane-faces that share an edge (for merging coplanar neighbours).
  RawVector<std::array<uint32_t, 2>> adjacent;

  // The face of the input each face comes from, in increasing order (a split polygon's
  // triangles share it): source_face as prepare_mesh numbers the faces of its MeshView (empty:
  // face f is face f, nothing was dropped or split), then welded_source for the faces of a welded
  // or repaired mesh (prepare_input; empty: none). input_face composes them.
  std::vector<uint32_t> source_face;
  std::vector<uint32_t> welded_source;
  uint32_t input_face(uint32_t f) const {
    const uint32_t g = source_face.empty() ? f : source_face[f];
    return welded_source.empty() ? g : welded_source[g];
  }

  size_t input_faces = 0;
  size_t dropped_faces = 0;
  size_t shells = 1;                                        // connected pieces (> 1 only with allow_shells)
  size_t boundary_edges = 0;                                // > 0 only with allow_open
  double volume = 0;                                        // enclosed volume, in scaled units
  double bbox_min[3] = {0, 0, 0}, bbox_max[3] = {0, 0, 0};  // scaled units

  size_t num_faces() const { return rep.size(); }
  const double* point(uint32_t v) const { return &points[3 * size_t(v)]; }
  // The bounding box's largest side (scaled units).
  double extent() const {
    return std::max(bbox_max[0] - bbox_min[0], std::max(bbox_max[1] - bbox_min[1], bbox_max[2] - bbox_min[2]));
  }
};

// The warning for `count` vertices no face uses (prepare_mesh's; the weld reports it anew).
Warning unused_vertices_warning(size_t count);

// What a caller of prepare_mesh needs: the faces that carry planes (Faces), or only the verdict
// (Verdict: error, message, warnings, volume and the counts, as Faces gives them; the loops may
// then be left empty, which spares a copy of the input's faces when it is used as it is).
enum class PrepareFor { Faces, Verdict };

// `allow_shells`: a closed mesh of several pieces is prepared (PreparedMesh::shells counts them)
// instead of refused with Error::MultipleComponents. `positions_distinct`: no two vertices have
// the same position (a weld has just merged every such pair), so the search for used vertices
// that share one is skipped.
PreparedMesh prepare_mesh(const MeshView& mesh, const Options& options, bool allow_shells = false,
                          PrepareFor purpose = PrepareFor::Faces, bool positions_distinct = false);

}  // namespace kergen
