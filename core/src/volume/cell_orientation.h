// cell_orientation.h — a cell's faces turned outward (cell_surface, volume.h), private to volume/.
#pragma once

#include "kergen/kergen.h"

namespace kergen::volume {

// Reverses faces of `cell` (face_sizes set) so that faces sharing an edge traverse it in opposite
// directions, breadth-first from each connected piece's first face; then reverses every face if
// the enclosed volume (in double) is negative. Edges not shared by exactly two faces link nothing
// (compute_kernel reports the open or non-manifold cell). Returns whether any face was reversed.
bool orient_cell_outward(Mesh& cell);

}  // namespace kergen::volume
