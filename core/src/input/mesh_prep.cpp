// Input validation: finite coordinates, valid indices, closed 2-manifold edges with consistent
// orientation, one connected piece, positive enclosed volume (flipped if negative). Zero-area
// faces are detected exactly and dropped (after the topology check, which still counts them:
// they are part of the closed surface, they only carry no plane). prepare_mesh, below, runs the
// checks as named phases over one state (Prep, prep_state.h), each refusing the mesh or leaving
// its part of the state for the next; the phases live by concern in prep_coordinates.cpp (arrays,
// coordinates, scale), prep_topology.cpp (clean faces, edges, pieces, shared positions),
// prep_volume.cpp (bounding box, volume, orientation) and prep_plane_faces.cpp (the faces that
// carry planes; non-planar polygons are split in polygon_split.cpp).
#include "input/mesh_prep.h"

#include <string>
#include <utility>

#include "input/prep_state.h"
#include "util/plural.h"

namespace kergen {

using namespace prep;  // the phases (prep_state.h)

Warning unused_vertices_warning(size_t count) {
  return {Warning::Kind::UnusedVertices, count,
          count_of(count, "vertex", "vertices") + verb_for(count, " is", " are") + " not used by any face"};
}

// The phases in order; each refuses the mesh or leaves its part of the state for the next.
PreparedMesh prepare_mesh(const MeshView& mesh, const Options& options, bool allow_shells, PrepareFor purpose,
                          bool positions_distinct) {
  Prep s(mesh, options, allow_shells, purpose == PrepareFor::Verdict);
  s.positions_distinct = positions_distinct;
  s.nv = mesh.num_vertices;
  s.nf = mesh.face_sizes ? mesh.num_faces : mesh.num_indices / 3;
  s.m.input_faces = s.nf;
  // (A phase that refuses the mesh has set m.error and m.message; m is returned as it stands.)
  // (clean_faces refuses indices out of range, before scale_points refuses a coordinate range;
  // faces that all collapse are refused after it.)
  if (!check_arrays(s) || !check_coordinates(s) || !clean_faces(s) || !scale_points(s) || !check_faces_left(s))
    return std::move(s.m);
  // (The shared positions and the box are found before the edge check, whose pass over a
  // verdict's triangles sums their volume about the box's centre; they are reported after it.)
  find_shared_positions(s);
  take_bounding_box(s);
  pair_edges(s);
  if (!report_edge_faults(s) || !count_components(s) || !check_shared_positions(s)) return std::move(s.m);
  sum_fan_volume(s);
  if (!orient_by_volume(s) || !build_plane_faces(s) || !check_split_volume(s)) return std::move(s.m);
  move_loops(s);
  certify_thin_volume(s);
  return std::move(s.m);
}

}  // namespace kergen
