// The public entry points (kergen.h), each stringing its phases together: the input prepared
// (prepare_input.h), then for compute_kernel and find_kernel_point the planes and the LP
// (setup.h), the trace and the polytope, every answer about the kernel certified (certify.h).
#include "kergen/kergen.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "certify/certify.h"
#include "exact/vertex.h"
#include "input/prepare_input.h"
#include "output/deepest_point.h"
#include "output/polytope.h"
#include "output/step_replay.h"
#include "progress.h"
#include "setup.h"
#include "small/extreme_vertex.h"
#include "small/kernel_path.h"
#include "small/small_kernel.h"
#include "solve/convex_answer.h"
#include "solve/plane_culling.h"
#include "solve/tracer.h"
#include "workspace.h"

namespace kergen {

namespace {

// Whether `path` takes the small-input path (small_kernel.h) for an input of `planes` mesh
// planes: Auto up to kSmallPlaneLimit, Small always, never with step events (they replay a
// trace from its start vertex, in the trace's numbering).
bool small_path(const Options& options, KernelPath path, size_t planes) {
  if (path == KernelPath::General || options.on_step || options.max_steps) return false;
  return path == KernelPath::Small || planes <= kSmallPlaneLimit;
}

// The kernel clipped on the small-input path into `ct`. False when it does not apply or the
// clipping hands over (a flat or empty kernel): the caller then traces.
bool clip_small(const Setup& s, const Options& options, KernelPath path, ClipPolytope& clip, CulledTrace& ct) {
  if (!small_path(options, path, s.planes->size() - s.box.size())) return false;
  std::vector<uint32_t> mesh_planes;
  mesh_planes.reserve(s.planes->size());
  for (uint32_t i = 0; i < s.planes->size(); ++i)
    if (!s.is_box[i]) mesh_planes.push_back(i);
  if (!small_kernel_trace(*s.planes, mesh_planes, s.box, clip, ct.trace)) return false;
  ct.active = std::move(mesh_planes);
  ct.active.insert(ct.active.end(), s.box.begin(), s.box.end());
  ct.start_vertex = 0;
  ct.rounds = 1;
  return true;
}

// The LP that setup deferred (Setup::defer_lp_up_to), answered from the clipped kernel when it
// is full-dimensional and has one vertex certainly extreme in the LP's direction: that vertex is
// the LP's optimum (its lexicographic tie-breaks never come into play). Else the LP is solved,
// and the kernel traced as usual. True when `ct` holds the clipped kernel.
// `tried` says whether the clipping ran (it is not tried twice).
bool clip_instead_of_lp(const Options& options, KernelPath path, Setup& s, ClipPolytope& clip, CulledTrace& ct,
                        Stats& stats, bool& tried) {
  if (!s.lp_deferred) return false;
  s.lp_deferred = false;
  tried = true;
  // (The phases are reported as without the clipping, which finds the LP's vertex here: the
  // progress a caller sees does not depend on the path.)
  report(options, Progress::Phase::Lp, stats.distinct_planes);
  const auto t = Clock::now();
  double dir[3];
  lp_direction(s, options, dir);
  const bool clipped = s.mesh.shells == 1 && clip_small(s, options, path, clip, ct);
  if (clipped) {
    const uint32_t top = certainly_extreme_vertex(ct.trace, dir);
    if (top != kNoVertex) {
      s.lp.outcome = LpResult::Outcome::Optimal;
      s.lp.vertex = ct.trace.vertices[top].geom;
      stats.ms_lp += ms_since(t);
      return true;
    }
  }
  s.lp = solve_lp(*s.planes, s.active, dir, kLpBound, options.seed);
  stats.ms_lp += ms_since(t);
  return clipped;
}

// The kernel traced from the LP's vertex and certified (certify.h), into `ct`. It is traced
// without events whatever the caller asked for; the stream is then replayed from the result
// (step_replay.h), so steps never change the algorithm. Small inputs are clipped instead
// (clip_small; `clipped`: already, `clip_tried`: tried in vain), with the same result. False when `out` is final: the
// surface is refused, or the trace failed (Error::Internal).
bool trace_certified(const Setup& s, const Options& options, KernelPath path, bool clipped, bool clip_tried,
                     int unscale_exp, ClipPolytope& clip, CulledTrace& ct, uint64_t& steps, Kernel& out) {
  const auto t = Clock::now();
  report(options, Progress::Phase::Tracing, out.stats.distinct_planes);
  ReplayOptions ropt;
  ropt.on_step = &options.on_step;
  ropt.max_steps = options.max_steps;
  ropt.steps = &steps;
  ropt.unscale_exp = unscale_exp;
  if (options.has_from) {
    ropt.has_from = true;
    for (int k = 0; k < 3; ++k) ropt.from[k] = s.mesh.to_scaled(options.from[k]);
  }
  if (!clipped && (clip_tried || !clip_small(s, options, path, clip, ct))) ct = trace_kernel(s, options);
  TraceResult& tr = ct.trace;
  if (!tr.internal_error && !certify_embedding(s, options, tr, out)) return false;
  if (!tr.internal_error && (options.on_step || options.max_steps)) replay_steps(*s.planes, ct.start_vertex, tr, ropt);
  out.stats.active_planes = 0;
  for (uint32_t p : ct.active) out.stats.active_planes += !s.is_box[p];
  out.stats.ms_trace = ms_since(t);
  out.stats.traced_lines = tr.traced_lines;
  out.complete = tr.complete;
  if (tr.internal_error) {
    out.error = Error::Internal;
    out.message = "internal error: kernel tracing could not certify a vertex (please report this mesh)";
    return false;
  }
  return true;
}

// The traced kernel `tr` assembled into `out` (polytope.h), its face events emitted while the
// caller goes on and `steps` stays under Options::max_steps, each face's source (face_source);
// then its type (Unbounded when the
// clipping box holds a vertex), the deepest point when asked for, and the volume ratio. False
// when `out` is final: the traced edges do not close (Error::Internal).
bool assemble(const Setup& s, const Options& options, int unscale_exp, const TraceResult& tr, uint64_t& steps,
              Kernel& out) {
  const auto t = Clock::now();
  report(options, Progress::Phase::Assembling, tr.vertices.size());
  bool stopped = !tr.complete;
  auto emit_face = [&](const StepEvent& e) {
    if (stopped) return false;
    ++steps;
    bool go = !options.on_step || options.on_step(e);
    if (options.max_steps && steps >= options.max_steps) go = false;
    if (!go) {
      stopped = true;
      out.complete = false;
    }
    return go;
  };
  double scaled_volume = 0;
  std::vector<uint32_t> face_planes;
  // With steps, the output keeps the replay's numbering, which the events used.
  const VertexOrder order = options.on_step || options.max_steps ? VertexOrder::Trace : VertexOrder::Canonical;
  if (!assemble_polytope(*s.planes, tr, unscale_exp, out, emit_face, scaled_volume, &face_planes, order)) {
    out.error = Error::Internal;
    out.message = "internal error: traced kernel edges do not close into a polytope (please report this mesh)";
    return false;
  }
  out.face_sources.reserve(face_planes.size());
  for (uint32_t h : face_planes) out.face_sources.push_back(face_source(s, h));
  for (const auto& v : tr.vertices)
    for (uint32_t p : v.tight)
      if (s.is_box[p]) out.type = KernelType::Unbounded;
  if (options.deepest_point && out.type == KernelType::Polyhedron && out.complete) {
    double p[3] = {0, 0, 0}, r = 0;
    if (deepest_point(*s.planes, facet_planes(tr), s.mesh.bbox_min, s.mesh.bbox_max, p, r)) {
      out.has_deepest_point = true;
      for (int k = 0; k < 3; ++k) out.deepest_point[k] = std::ldexp(p[k], unscale_exp);
      out.inscribed_radius = std::ldexp(r, unscale_exp);
    }
  }
  out.stats.ms_assemble = ms_since(t);
  // (An open mesh's volume is its surface's closed over its holes, which the kernel may exceed.)
  out.volume_ratio = s.mesh.volume > 0 && s.mesh.boundary_edges == 0 ? scaled_volume / s.mesh.volume : 0;
  return true;
}

// The kernel of a convex solid (convex_answer.h: setup certified it): the solid itself, assembled
// like a traced kernel; the kernel point is the vertex the LP would have started from.
bool convex_kernel(const Setup& s, const Options& options, int unscale_exp, Kernel& out) {
  TraceResult tr;
  if (!convex_trace(s, tr)) {
    out.error = Error::Internal;
    out.message = "internal error: a convex solid's edges do not form a polytope (please report this mesh)";
    return false;
  }
  double dir[3], hi[3], lo[3];
  lp_direction(s, options, dir);
  precise_coordinates(*s.planes, tr.vertices[extreme_vertex(tr, *s.planes, dir)].geom, hi, lo);
  out.has_kernel_point = true;
  for (int k = 0; k < 3; ++k) out.kernel_point[k] = std::ldexp(hi[k], unscale_exp);
  out.stats.active_planes = s.planes->size() - s.box.size();
  uint64_t steps = 0;
  return assemble(s, options, unscale_exp, tr, steps, out);
}

}  // namespace

namespace {

// An open surface whose faces point inward and whose kernel is empty: the warning says whether
// its faces turned over (Options::flip_faces) have a kernel, from one LP on them.
void offer_flipped(const MeshView& mesh, const Options& options, Kernel& out) {
  if (!out.ok() || out.type != KernelType::Empty || options.flip_faces) return;
  for (Warning& w : out.warnings) {
    if (w.kind != Warning::Kind::FacesPointInward) continue;
    Options flipped = options;
    flipped.flip_faces = true;
    flipped.on_step = nullptr;
    flipped.on_progress = nullptr;
    const KernelPoint p = find_kernel_point(mesh, flipped);
    if (p.error == Error::Ok && p.star_shaped) w.message += "; turned over, its kernel is not empty";
    return;
  }
}

// `out` as a default Kernel, its arrays emptied but keeping their capacity (KernelBatch fills
// the same Kernel again and again).
void clear_keeping_capacity(Kernel& out) {
  Kernel fresh;
  auto keep = [](auto& from, auto& to) {
    from.clear();
    std::swap(from, to);
  };
  keep(out.message, fresh.message);
  keep(out.vertices, fresh.vertices);
  keep(out.edges, fresh.edges);
  keep(out.face_indices, fresh.face_indices);
  keep(out.face_sizes, fresh.face_sizes);
  keep(out.triangles, fresh.triangles);
  keep(out.face_sources, fresh.face_sources);
  keep(out.witness_faces, fresh.witness_faces);
  keep(out.witness_boundary_edges, fresh.witness_boundary_edges);
  keep(out.warnings, fresh.warnings);
  out = std::move(fresh);
}

void compute_kernel_as_given(const MeshView& mesh, const Options& options, KernelPath path, KernelWorkspace& ws,
                             Kernel& out) {
  const auto t_total = Clock::now();
  Setup s;
  s.try_convex = !options.on_step && options.max_steps == 0;  // (step events replay a trace)
  if (small_path(options, path, 0)) s.defer_lp_up_to = path == KernelPath::Small ? SIZE_MAX : kSmallPlaneLimit;
  setup(mesh, options, s, out.stats);
  out.warnings = s.mesh.warnings;
  if (s.mesh.error != Error::Ok) {
    out.error = s.mesh.error;
    out.message = s.mesh.message;
    out.stats.ms_total = ms_since(t_total);
    return;
  }
  const int unscale_exp = -s.mesh.scale_exp;  // outputs: scaled values times 2^unscale_exp
  out.shape_volume = std::ldexp(s.mesh.volume, 3 * unscale_exp);
  if (s.rejected_early) {
    out.type = KernelType::Empty;
    input_witness(s, out.witness_faces, out.witness_boundary_edges);
    out.stats.ms_total = ms_since(t_total);
    return;
  }
  out.stats.active_planes = s.planes->size() - s.box.size();

  if (s.convex) {
    if (!convex_kernel(s, options, unscale_exp, out)) return;
    out.stats.exact_fallbacks = s.planes->exact_fallbacks;
    out.stats.ms_total = ms_since(t_total);
    return;
  }
  CulledTrace& ct = ws.trace;
  bool clip_tried = false;
  const bool clipped = clip_instead_of_lp(options, path, s, ws.clip, ct, out.stats, clip_tried);
  if (s.lp.outcome != LpResult::Outcome::Infeasible && s.mesh.shells > 1) {
    refuse_nested_shells(s.mesh, out.error, out.message);
    out.stats.ms_total = ms_since(t_total);
    return;
  }
  if (s.lp.outcome == LpResult::Outcome::Infeasible) {
    out.type = KernelType::Empty;
    input_witness(s, out.witness_faces, out.witness_boundary_edges);
  } else if (s.lp.outcome == LpResult::Outcome::Unbounded) {
    out.type = KernelType::Unbounded;
    if (!certify_no_contact(s, out.error, out.message, out.warnings)) {
      out.type = KernelType::Empty;
      out.stats.ms_total = ms_since(t_total);
      return;
    }
  } else {
    out.has_kernel_point = true;
    // Rounded to nearest like the output vertices (so it is one of them, bit for bit), not the
    // filter's value, whose last bits depend on which of the planes through it the LP ended on.
    double hi[3], lo[3];
    precise_coordinates(*s.planes, s.lp.vertex, hi, lo);
    for (int k = 0; k < 3; ++k) out.kernel_point[k] = std::ldexp(hi[k], unscale_exp);
    uint64_t steps = 0;  // events emitted, the replayed trace's then the faces'
    if (!trace_certified(s, options, path, clipped, clip_tried, unscale_exp, ws.clip, ct, steps, out)) return;
    if (!assemble(s, options, unscale_exp, ct.trace, steps, out)) return;
  }
  out.stats.exact_fallbacks = s.planes->exact_fallbacks;
  out.stats.ms_total = ms_since(t_total);
  return;
}

}  // namespace

void compute_kernel_into(const MeshView& mesh, const Options& options, KernelPath path, KernelWorkspace& ws,
                         Kernel& out) {
  clear_keeping_capacity(out);
  compute_kernel_as_given(mesh, options, path, ws, out);
  offer_flipped(mesh, options, out);
}

Kernel compute_kernel_on_path(const MeshView& mesh, const Options& options, KernelPath path) {
  KernelWorkspace ws;
  Kernel out;
  compute_kernel_into(mesh, options, path, ws, out);
  return out;
}

Kernel compute_kernel(const MeshView& mesh, const Options& options) {
  return compute_kernel_on_path(mesh, options, KernelPath::Auto);
}

KernelPoint find_kernel_point(const MeshView& mesh, const Options& options) {
  KernelPoint r;
  Setup s;
  Stats stats;
  setup(mesh, options, s, stats);
  r.warnings = s.mesh.warnings;
  if (s.mesh.error != Error::Ok) {
    r.error = s.mesh.error;
    r.message = s.mesh.message;
    return r;
  }
  if (s.lp.outcome != LpResult::Outcome::Infeasible && s.mesh.shells > 1) {
    refuse_nested_shells(s.mesh, r.error, r.message);
    return r;
  }
  if (s.lp.outcome != LpResult::Outcome::Infeasible && !certify_kernel_point(s, options, r)) return r;
  if (s.lp.outcome == LpResult::Outcome::Optimal) {
    r.star_shaped = true;
    double hi[3], lo[3];
    precise_coordinates(*s.planes, s.lp.vertex, hi, lo);  // rounded to nearest, as compute_kernel's
    for (int k = 0; k < 3; ++k) r.point[k] = s.mesh.to_input(hi[k]);
  } else if (s.lp.outcome == LpResult::Outcome::Unbounded) {
    r.star_shaped = true;  // non-empty but unbounded (open input)
  } else {
    input_witness(s, r.witness_faces, r.witness_boundary_edges);
  }
  return r;
}

RepairedMesh repair_mesh(const MeshView& mesh, const Options& options) {
  RepairedMesh r;
  Mesh validated;
  const PreparedMesh m = prepare_input(mesh, options, &validated);
  r.error = m.error;
  r.message = m.message;
  r.warnings = m.warnings;
  r.mesh = without_unused_vertices(std::move(validated));
  return r;
}

Validation validate_mesh(const MeshView& mesh, const Options& options) {
  Validation v;
  PreparedMesh m = prepare_input(mesh, options, nullptr, PrepareFor::Verdict);
  v.error = m.error;
  v.message = m.message;
  v.warnings = m.warnings;
  v.volume = std::ldexp(m.volume, -3 * m.scale_exp);
  return v;
}

}  // namespace kergen
