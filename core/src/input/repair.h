// Repair (Options::repair): the defects of real-world meshes whose solid is still well defined,
// fixed exactly before validation. After welding (weld.h; equal positions when Options::weld is
// off), faces that repeat another face's corner cycle are removed (a duplicate, same orientation:
// one is kept; a pair that cancels, opposite orientations: both go), and T-junctions are split:
// a vertex lying exactly on the inside of an edge that only one face uses (its neighbours use the
// two halves) is inserted into that face's loop, so the edge pairs with the halves.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "kergen/kergen.h"

namespace kergen {

struct RepairCounts {
  size_t duplicate_faces = 0;   // faces removed as copies of another (same orientation)
  size_t cancelling_faces = 0;  // faces removed in pairs of opposite orientation
  size_t t_junctions = 0;       // vertices inserted into the loops of faces they split
};

// Repairs `mesh` in place (its positions are not changed; faces are removed or gain corners).
// `mesh` must have finite coordinates, indices in range and faces of at least three corners.
// `kept_faces` (optional) receives the index before the repair of each face after it.
RepairCounts repair_mesh(Mesh& mesh, std::vector<uint32_t>* kept_faces = nullptr);

}  // namespace kergen
