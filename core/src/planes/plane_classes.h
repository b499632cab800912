// Builds the exact, deduplicated plane set of a prepared mesh.
#pragma once

#include <vector>

#include "exact/predicates.h"
#include "input/mesh_prep.h"

namespace kergen {

// Adds one plane per class of coplanar, equally oriented faces to `ps` (opposite classes are
// linked with set_opposite), fills the point/plane incidence, and sets face_plane[f] for every
// prepared face. Expects coordinates below 1 in magnitude, as prepare_mesh scales them (the
// float filter's error bounds are absolute). `plane_face`, when given, receives for each plane
// added (plane id - the set's size before) the lowest face of its class, whose triangle defines
// it (ps.rep).
void build_planes(const PreparedMesh& mesh, PlaneSet& ps, std::vector<uint32_t>& face_plane,
                  std::vector<uint32_t>* plane_face = nullptr);

// The same for the prepared faces `faces` only (increasing ids; the others are ignored, as if
// absent): face_plane[k] is the plane of face faces[k], and the incidence is that of these faces;
// plane_face holds prepared face ids (the lowest of `faces` in each class).
void build_planes(const PreparedMesh& mesh, const std::vector<uint32_t>& faces, PlaneSet& ps,
                  std::vector<uint32_t>& face_plane, std::vector<uint32_t>* plane_face = nullptr);

}  // namespace kergen
