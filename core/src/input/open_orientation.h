// Which way an open surface faces. An open surface (edges used by one face only) is never
// flipped: its kernel lies behind the faces as given (kergen.h, OpenBoundary). A surface given
// inside out (a box without its lid whose faces point into the box) then has an empty kernel,
// although its faces, turned over, bound one. This says so: the surface closed over its holes
// (each hole capped by a fan of triangles from its centroid) encloses a negative volume.
#pragma once

#include <string>

#include "input/mesh_prep.h"
#include "kergen/kergen.h"

namespace kergen {

struct CappedVolume {
  double volume = 0;    // enclosed volume of the capped surface, in the input's units
  bool inward = false;  // volume < 0, by more than the rounding of its terms
  size_t holes = 0;     // boundary loops capped (0: the surface is closed)
};

// `mesh` must be a valid surface except for being open (every edge used by one or two faces,
// consistently oriented): what prepare_mesh accepts with allow_open, or refuses with OpenMesh
// only. Double precision, about the bounding box's centre: a verdict for messages, not for
// geometry (an almost flat surface is never said to face inward).
CappedVolume capped_volume(const MeshView& mesh);

// The fact as the library says it (Warning::Kind::FacesPointInward's message and the OpenMesh
// refusal's addition): "its faces point inward (closed over its hole, it encloses a volume of
// -1e+06): ...".
std::string faces_point_inward_message(const CappedVolume& c);

}  // namespace kergen
