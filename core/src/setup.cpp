// The shared first phases of compute_kernel and find_kernel_point (setup.h), in their order:
// validation, face culling, planes, LP.
#include "setup.h"

#include <cmath>

#include "input/open_boundary.h"
#include "input/prepare_input.h"
#include "planes/face_culling.h"
#include "planes/plane_classes.h"
#include "progress.h"
#include "solve/convex_answer.h"

namespace kergen {

namespace {

// The input prepared and, with OpenBoundary::Perpendicular, walled at its boundary edges (the
// walls need the mesh that validation judged, welded and repaired).
void validate(const MeshView& mesh, const Options& options, Setup& s, Stats& stats) {
  const auto t = Clock::now();
  report(options, Progress::Phase::Validating, mesh.face_sizes ? mesh.num_faces : mesh.num_indices / 3);
  const bool walls = options.open_boundary == OpenBoundary::Perpendicular;
  Mesh validated;
  s.mesh = prepare_input(mesh, options, walls ? &validated : nullptr);
  s.surface_faces = s.mesh.num_faces();
  if (walls && s.mesh.error == Error::Ok && s.mesh.boundary_edges > 0) add_boundary_walls(s.mesh, validated.view());
  stats.input_vertices = mesh.num_vertices;
  stats.input_faces = s.mesh.input_faces;
  stats.dropped_faces = s.mesh.dropped_faces;
  stats.ms_validate = ms_since(t);
}

// The plane classes of the faces that face culling kept (all of them when it did not run), and
// the bounding box, which joins the LP's constraints only for an open mesh.
void build_plane_set(const FaceCulling& faces, Setup& s, Stats& stats) {
  const auto t = Clock::now();
  s.planes = std::make_unique<PlaneSet>(&s.mesh.points, s.mesh.exact_shift);
  s.planes->set_extent(s.mesh.extent());
  if (faces.culled)
    build_planes(s.mesh, faces.kept_faces, *s.planes, s.face_plane, &s.plane_face);
  else
    build_planes(s.mesh, *s.planes, s.face_plane, &s.plane_face);
  stats.distinct_planes = s.planes->size();
  s.active.reserve(s.planes->size() + 6);
  for (uint32_t i = 0; i < s.planes->size(); ++i) s.active.push_back(i);
  for (int k = 0; k < 3; ++k) s.center[k] = 0.5 * (s.mesh.bbox_min[k] + s.mesh.bbox_max[k]);
  add_bounding_box(*s.planes, s.box);
  if (s.mesh.boundary_edges > 0) s.active.insert(s.active.end(), s.box.begin(), s.box.end());
  s.is_box.assign(s.planes->size(), 0);
  for (uint32_t i = 0; i < s.planes->size(); ++i) s.is_box[i] = s.planes->explicit_plane(i);
  stats.ms_planes += ms_since(t);
}

// The LP's start vertex: the kernel's extreme vertex in the default direction, or in the
// direction of Options::from seen from the mesh's centre when one is given.
void solve_start_lp(const Options& options, Setup& s, Stats& stats) {
  const auto t = Clock::now();
  report(options, Progress::Phase::Lp, stats.distinct_planes);
  double dir[3];
  lp_direction(s, options, dir);
  s.lp = solve_lp(*s.planes, s.active, dir, kLpBound, options.seed);
  stats.ms_lp += ms_since(t);
}

}  // namespace

void setup(const MeshView& mesh, const Options& options, Setup& s, Stats& stats) {
  validate(mesh, options, s, stats);
  if (s.mesh.error != Error::Ok) return;

  const size_t nf = s.mesh.num_faces();
  report(options, Progress::Phase::Planes, nf);
  const auto t = Clock::now();
  if (s.try_convex && convex_solid(s.mesh)) {
    s.convex = true;
    stats.ms_planes = ms_since(t);
    build_plane_set(FaceCulling{}, s, stats);
    return;
  }
  const FaceCulling faces = cull_faces(s.mesh, options.cull_faces, options.seed);
  stats.ms_lp = faces.ms_lp;
  if (faces.kernel_empty) {
    s.lp = faces.lp;
    s.rejected_early = true;
    stats.ms_planes = ms_since(t) - stats.ms_lp;
    return;
  }
  if (faces.culled) stats.culled_faces = nf - faces.kept_faces.size();
  stats.ms_planes = ms_since(t) - stats.ms_lp;  // culling's own LP is counted as LP time

  build_plane_set(faces, s, stats);
  s.lp_deferred = s.mesh.boundary_edges == 0 && s.planes->size() - s.box.size() <= s.defer_lp_up_to;
  if (!s.lp_deferred) solve_start_lp(options, s, stats);
}

void lp_direction(const Setup& s, const Options& options, double dir[3]) {
  for (int k = 0; k < 3; ++k) dir[k] = kDefaultDirection[k];
  if (!options.has_from) return;
  double len = 0;
  for (int k = 0; k < 3; ++k) {
    double d = s.mesh.to_scaled(options.from[k]) - s.center[k];
    len += d * d;
  }
  if (len > 0 && std::isfinite(len))
    for (int k = 0; k < 3; ++k) dir[k] = s.mesh.to_scaled(options.from[k]) - s.center[k];
}

int32_t face_source(const Setup& s, uint32_t plane) {
  // (A culled face is never the lowest of a kernel face's class: its plane holds the face-sample
  // kernel, hence the kernel, strictly inside, and so does every plane of its class.)
  if (plane >= s.plane_face.size() || s.is_box[plane]) return kFaceSourceBox;
  const uint32_t f = s.plane_face[plane];
  return f >= s.surface_faces ? kFaceSourceWall : int32_t(s.mesh.input_face(f));
}

CulledTrace trace_kernel(const Setup& s, const Options& options) {
  TraceOptions topt;
  if (options.has_from) {
    topt.has_from = true;
    for (int k = 0; k < 3; ++k) topt.from[k] = s.mesh.to_scaled(options.from[k]);
  }
  std::vector<uint32_t> mesh_planes;
  mesh_planes.reserve(s.planes->size());
  for (uint32_t i = 0; i < s.planes->size(); ++i)
    if (!s.is_box[i]) mesh_planes.push_back(i);
  return trace_with_culling(*s.planes, mesh_planes, s.box, s.lp.vertex, topt, options.seed);
}

}  // namespace kergen
