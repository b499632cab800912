// Several closed pieces (shells) in one mesh. When no two of them cross or touch, the input is a
// well-defined set of solids, and its kernel is empty unless they are nested alike: a point in
// every face's inner half-space sees each shell from inside, so it lies inside every shell, and
// an inner shell facing inward (a void) has no such point at all (see compute_kernel). Shells
// that cross or touch are no surface of a solid: they are refused.
#pragma once

#include <cstdint>

#include "input/mesh_prep.h"

namespace kergen {

struct ShellContact {
  bool found = false;
  uint32_t face_a = 0, face_b = 0;  // faces of two different shells that meet (prepared faces)
};

// The first contact found between faces of different edge-connected pieces of `mesh`: an edge of
// one meeting a face of another, decided with exact orient3d signs (touching counts), after a
// grid of the faces' bounding boxes narrows the pairs. Expected O(faces) for well-spread meshes.
ShellContact find_shell_contact(const PreparedMesh& mesh);

}  // namespace kergen
