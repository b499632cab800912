// Boundary walls of an open surface (Options::open_boundary = OpenBoundary::Perpendicular).
//
// Asiler & Sahillioglu (2024), Sec. 6.3, bound the kernel of a surface with a boundary by a plane
// through each boundary edge, perpendicular to the surface along it. Here that plane is a face of
// its own, added to the prepared mesh before its planes are built: the triangle (a, b, c) of the
// boundary edge a -> b (as its face's loop runs) and c = a + n, n the face's outward normal
// rounded (kergen.h, OpenBoundary, says how and how close to perpendicular that is). Its plane
// holds the edge exactly and faces away from the face: (b - a) x n points out of the face's side,
// as the left of a -> b, seen from n, is the face's interior. Being a face like any other, the
// wall is merged with coplanar faces and walls exactly (plane_classes), and every predicate on it
// is exact.
#pragma once

#include <cstddef>

#include "input/mesh_prep.h"
#include "kergen/kergen.h"

namespace kergen {

// Appends one wall face per boundary edge to `m`, prepared from `validated` (the mesh as
// validation saw it: after weld and repair; same vertex ids): an edge used by one face of
// `validated` whose face is among m's (zero-area faces are not). The walls' third points are
// appended to m.points. Returns the number of walls added. m's volume, box and counts are those of
// the surface, unchanged.
size_t add_boundary_walls(PreparedMesh& m, const MeshView& validated);

}  // namespace kergen
