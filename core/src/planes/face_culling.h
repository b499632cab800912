// Face culling, faces before planes: on a large closed mesh, the kernel of the planes of an
// evenly spread sample of faces, the face-sample kernel, contains the kernel. The kernel is empty
// when the face-sample kernel is (one small exact LP, before any plane classes of the whole mesh
// are built); otherwise only the faces whose planes reach above the face-sample kernel can touch
// the kernel, and the exact plane classes are built for them and the sample alone. (A non-empty
// face-sample kernel proves nothing about the kernel's emptiness: the LP over the kept planes
// decides it.)
#pragma once

#include <cstdint>
#include <vector>

#include "input/mesh_prep.h"
#include "solve/lp.h"

namespace kergen {

// Below this many faces the face-sample kernel would cost about as much as the plane classes it
// saves.
constexpr size_t kFaceCullingMinFaces = 700;

struct FaceCulling {
  bool kernel_empty = false;         // the face-sample kernel is empty, hence the kernel
  LpResult lp;                       // the face-sample LP's outcome and conflict planes (no vertex)
  bool culled = false;               // kept_faces holds every face that may touch the kernel
  std::vector<uint32_t> kept_faces;  // increasing
  double ms_lp = 0;                  // time in the face-sample LP
};

// Does nothing (returns a default FaceCulling) on meshes with a boundary or of at most
// kFaceCullingMinFaces faces. With `cull` false only the emptiness test runs.
FaceCulling cull_faces(const PreparedMesh& mesh, bool cull, uint64_t seed);

}  // namespace kergen
