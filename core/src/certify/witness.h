// The non-star witness: for an empty kernel, at most four faces whose inner half-spaces have no
// common point, so that no point sees all of them from the inside. By Helly's theorem four
// suffice in 3D whenever the half-spaces of all faces have no common point; the LP's minimal
// conflict (lp.h) is such a set of planes, and each plane is named by one face that carries it.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "input/mesh_prep.h"

namespace kergen {

// The prepared faces (mesh_prep.h) of a conflict given as representative triangles of prepared
// points, one per plane (the lowest-indexed face whose plane it is, same side inward), in
// increasing order, or nothing when the planes are not proven disjoint by halfspaces_disjoint
// (exact Farkas weights; a conflict that needed the LP's bounds is not a witness).
std::vector<uint32_t> witness_faces(const PreparedMesh& mesh, const std::vector<std::array<uint32_t, 3>>& conflict);

}  // namespace kergen
