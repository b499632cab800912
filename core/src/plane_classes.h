// Builds the exact, deduplicated plane set of a prepared mesh.
#pragma once

#include <vector>

#include "mesh_prep.h"
#include "planes.h"

namespace kergen {

// Adds one plane per class of coplanar, equally oriented faces to `ps` (opposite classes are
// linked with set_opposite), fills the point/plane incidence, and sets face_plane[f] for every
// prepared face. Expects coordinates below 1 in magnitude, as prepare_mesh scales them (the
// float filter's error bounds are absolute).
void build_planes(const PreparedMesh& mesh, PlaneSet& ps, std::vector<uint32_t>& face_plane);

// Records which input vertices lie on which plane by construction: the vertices of every face
// f lie on plane face_plane[f].
void set_face_incidence(const PreparedMesh& mesh, PlaneSet& ps, const std::vector<uint32_t>& face_plane);

}  // namespace kergen
