// What compute_kernel and find_kernel_point share, up to and including the LP: the input
// prepared (prepare_input.h) with its boundary walls (open_boundary.h), the faces culled
// (face_culling.h), the exact plane classes (plane_classes.h) and the LP's start vertex (lp.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "exact/plane_store.h"
#include "input/mesh_prep.h"
#include "kergen/kergen.h"
#include "solve/lp.h"
#include "solve/plane_culling.h"

namespace kergen {

struct Setup {
  PreparedMesh mesh;
  std::unique_ptr<PlaneSet> planes;
  std::vector<uint32_t> active;  // the LP's constraints: the mesh planes (+ the box for open meshes)
  std::vector<uint32_t> box;
  std::vector<char> is_box;
  // For each mesh plane (ids below its size; the box's and the LP's bounds follow), the lowest
  // prepared face of its class: what a kernel face on it lies on (face_source).
  std::vector<uint32_t> plane_face;
  LpResult lp;
  bool rejected_early = false;  // empty kernel proven before the plane classes were built
  // The convex answer (convex_answer.h): try_convex is the caller's wish (compute_kernel without
  // step events), convex says the certificate held: then the planes are every face's, face_plane
  // holds each prepared face's plane, and there is no LP (s.lp is unset).
  bool try_convex = false;
  bool convex = false;
  std::vector<uint32_t> face_plane;
  // The LP left to the caller for a closed mesh of at most defer_lp_up_to planes: the
  // small-input path (small_kernel.h) finds the kernel, and the LP's vertex, without it, and
  // needs it only for an empty or flat kernel. lp_deferred says it was left (s.lp is unset).
  size_t defer_lp_up_to = 0;
  bool lp_deferred = false;
  double center[3] = {0, 0, 0};
  size_t surface_faces = 0;  // the mesh's own faces (boundary walls follow them in `mesh`)
};

// Fills `s` phase by phase, each reported to Options::on_progress and timed in `stats`; stops
// after validation when s.mesh.error is set, and before the planes when face culling proves the
// kernel empty (s.rejected_early, with that LP's result in s.lp).
void setup(const MeshView& mesh, const Options& options, Setup& s, Stats& stats);

// The LP's objective: the default direction, or Options::from seen from the mesh's centre.
void lp_direction(const Setup& s, const Options& options, double dir[3]);

// What kernel face on `plane` lies on (Kernel::face_sources): the input face of the plane's lowest
// prepared face, kFaceSourceWall when that is a boundary wall, kFaceSourceBox for a box plane.
int32_t face_source(const Setup& s, uint32_t plane);

// The kernel traced from the LP's vertex over the mesh's planes (plane culling, then cuts), in
// the order Options::from asks for; no step events (step_replay.h replays them from it).
CulledTrace trace_kernel(const Setup& s, const Options& options);

}  // namespace kergen
