// Public entry points: validation -> exact planes -> LP start vertex -> tracing -> polytope.
#include "kergen/kergen.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <iterator>

#include "deepest_point.h"
#include "embedding.h"
#include "exact/predicates.h"
#include "lp.h"
#include "mesh_prep.h"
#include "plane_culling.h"
#include "polytope.h"
#include "prepare_input.h"
#include "progress.h"
#include "setup.h"
#include "self_contact.h"
#include "step_replay.h"
#include "tracer.h"
#include "witness.h"

namespace kergen {

namespace {

// Several pieces and a non-empty intersection of the faces' half-spaces: a point in it sees
// every piece from inside, so it lies inside every piece: they are nested alike (a second solid
// inside the first, not a void), which no solid's surface is.
void refuse_nested_shells(const PreparedMesh& m, Error& error, std::string& message) {
  error = Error::MultipleComponents;
  message = "the mesh has " + std::to_string(m.shells) +
            " separate pieces nested with the same orientation (an inner piece faces outward: a second solid "
            "inside the first, not a void)";
}

// The witness of an empty kernel (witness.h) as input face indices, increasing and distinct (the
// triangles of a split polygon are named by the polygon).
std::vector<uint32_t> input_witness(const Setup& s) {
  std::vector<uint32_t> faces = witness_faces(s.mesh, s.lp.conflict);
  for (uint32_t f : faces)
    if (f >= s.surface_faces) return {};  // a boundary wall is no input face: no witness to name
  for (uint32_t& f : faces) f = s.mesh.input_face(f);
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  return faces;
}

// The refusal of a surface that a ray from inside its kernel crosses more than once.
void refuse_crossing(const PreparedMesh& mesh, const EmbeddingCheck& check, Error& error, std::string& message) {
  char point[96];
  std::snprintf(point, sizeof point, "(%.9g, %.9g, %.9g)", mesh.to_input(check.point[0]), mesh.to_input(check.point[1]),
                mesh.to_input(check.point[2]));
  error = Error::SelfIntersection;
  message = "the surface crosses itself: a ray from " + std::string(point) +
            ", a point every face is seen from the inside, crosses it " + std::to_string(check.crossings) +
            " times (a closed surface that does not cross itself is crossed once)";
}

// A surface whose kernel is not full-dimensional and bounded, or an open one, is answered only
// when no two of its faces meet away from the vertices and edges they share (self_contact.h):
// false, with the error set, when two do. Undecided (a polygon face that is not simple in its
// plane) leaves a warning instead: nothing was proved either way.
bool certify_no_contact(const Setup& s, Error& error, std::string& message, std::vector<Warning>& warnings) {
  const PreparedMesh& mesh = s.mesh;
  const FaceContact contact = find_face_contact(mesh, s.surface_faces);  // (walls may meet the surface)
  if (contact.outcome == FaceContact::Outcome::None) return true;
  if (contact.outcome == FaceContact::Outcome::Undecided) {
    warnings.push_back({Warning::Kind::CrossingsUnchecked, 1,
                        "a polygon face is not a simple polygon in its plane: whether the surface crosses itself "
                        "was not checked"});
    return true;
  }
  auto at = [&](uint32_t v) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.9g, %.9g, %.9g)", mesh.to_input(mesh.point(v)[0]),
                  mesh.to_input(mesh.point(v)[1]), mesh.to_input(mesh.point(v)[2]));
    return std::string(text);
  };
  error = Error::SelfIntersection;
  message = "the surface crosses or touches itself: two faces, one with a corner at " + at(contact.corner_a) +
            " and one with a corner at " + at(contact.corner_b) + ", meet away from the vertices and edges they share";
  return false;
}

// A bounded, full-dimensional kernel of a closed surface is certified by the ray degree from a
// point inside it (embedding.h); every other answer by the exact contact test.
bool certify_embedding(const Setup& s, const TraceResult& tr, Kernel& out) {
  bool full_dimensional = s.mesh.boundary_edges == 0 && tr.vertices.size() >= 4;
  for (const TracedVertex& v : tr.vertices)
    for (uint32_t p : v.tight) full_dimensional &= !s.is_box[p];  // unbounded
  if (full_dimensional) {
    const PlaneIds& tight = tr.vertices[0].tight;  // flat: a plane and its opposite hold it
    for (uint32_t p : tight) {
      const uint32_t o = s.planes->opposite(p);
      if (o != kNoPlane && std::binary_search(tight.begin(), tight.end(), o)) full_dimensional = false;
    }
  }
  if (!full_dimensional) return certify_no_contact(s, out.error, out.message, out.warnings);
  const EmbeddingCheck check = check_embedding(s.mesh, *s.planes, tr);
  if (check.outcome == EmbeddingCheck::Outcome::Embedded) return true;
  if (check.outcome == EmbeddingCheck::Outcome::Undecided)
    return certify_no_contact(s, out.error, out.message, out.warnings);
  refuse_crossing(s.mesh, check, out.error, out.message);
  return false;
}

// find_kernel_point's certificate, without a trace: the ray degree from the centroid of kernel
// vertices that LPs in more directions reach (strictly inside the kernel once they span it):
// three more, opposite the first's corner of a tetrahedron, then six along the axes; else the
// exact contact test (flat kernels, open meshes, a centroid on a facet).
bool certify_kernel_point(Setup& s, const Options& options, KernelPoint& r) {
  if (s.lp.outcome != LpResult::Outcome::Optimal || s.mesh.boundary_edges > 0)
    return certify_no_contact(s, r.error, r.message, r.warnings);
  static const double kDirections[][3] = {
      {1, -1.03125, -0.96875}, {-0.96875, 1, -1.03125}, {-1.03125, -0.96875, 1},  // tetrahedron
      {1, 0.25, 0.0625},       {-1, -0.25, -0.0625},    {0.0625, 1, 0.25},
      {-0.0625, -1, -0.25},    {0.25, 0.0625, 1},       {-0.25, -0.0625, -1}};
  std::vector<uint32_t> planes;
  for (uint32_t i = 0; i < s.planes->size(); ++i)
    if (!s.is_box[i]) planes.push_back(i);
  double sum[3] = {s.lp.vertex.x[0].v, s.lp.vertex.x[1].v, s.lp.vertex.x[2].v};
  int vertices = 1;
  for (size_t i = 0; i < std::size(kDirections); ++i) {
    const LpResult lp = solve_lp(*s.planes, s.active, kDirections[i], kLpBound, options.seed);
    if (lp.outcome == LpResult::Outcome::Optimal) {
      for (int k = 0; k < 3; ++k) sum[k] += lp.vertex.x[k].v;
      ++vertices;
    }
    if (i != 2 && i + 1 != std::size(kDirections)) continue;
    const double c[3] = {sum[0] / vertices, sum[1] / vertices, sum[2] / vertices};
    const EmbeddingCheck check = check_embedding_at(s.mesh, *s.planes, planes, c);
    if (check.outcome == EmbeddingCheck::Outcome::Embedded) return true;
    if (check.outcome == EmbeddingCheck::Outcome::CrossesItself) {
      refuse_crossing(s.mesh, check, r.error, r.message);
      return false;
    }
  }
  return certify_no_contact(s, r.error, r.message, r.warnings);
}

}  // namespace

Kernel compute_kernel(const MeshView& mesh, const Options& options) {
  auto t_total = Clock::now();
  Kernel out;
  Setup s;
  setup(mesh, options, s, out.stats);
  out.warnings = s.mesh.warnings;
  if (s.mesh.error != Error::Ok) {
    out.error = s.mesh.error;
    out.message = s.mesh.message;
    out.stats.ms_total = ms_since(t_total);
    return out;
  }
  const int unscale_exp = -s.mesh.scale_exp;  // outputs: scaled values times 2^unscale_exp
  out.shape_volume = std::ldexp(s.mesh.volume, 3 * unscale_exp);
  if (s.rejected_early) {
    out.type = KernelType::Empty;
    out.witness_faces = input_witness(s);
    out.stats.ms_total = ms_since(t_total);
    return out;
  }
  out.stats.active_planes = s.planes->size() - s.box.size();

  if (s.lp.outcome != LpResult::Outcome::Infeasible && s.mesh.shells > 1) {
    refuse_nested_shells(s.mesh, out.error, out.message);
    out.stats.ms_total = ms_since(t_total);
    return out;
  }
  if (s.lp.outcome == LpResult::Outcome::Infeasible) {
    out.type = KernelType::Empty;
    out.witness_faces = input_witness(s);
  } else if (s.lp.outcome == LpResult::Outcome::Unbounded) {
    out.type = KernelType::Unbounded;
    if (!certify_no_contact(s, out.error, out.message, out.warnings)) {
      out.type = KernelType::Empty;
      out.stats.ms_total = ms_since(t_total);
      return out;
    }
  } else {
    out.has_kernel_point = true;
    // Rounded to nearest like the output vertices (so it is one of them, bit for bit), not the
    // filter's value, whose last bits depend on which of the planes through it the LP ended on.
    double hi[3], lo[3];
    precise_coordinates(*s.planes, s.lp.vertex, hi, lo);
    for (int k = 0; k < 3; ++k) out.kernel_point[k] = std::ldexp(hi[k], unscale_exp);

    auto t = Clock::now();
    report(options, Progress::Phase::Tracing, out.stats.distinct_planes);
    // The kernel is traced without events whatever the caller asked for; the stream is then
    // replayed from the result (step_replay.h), so steps never change the algorithm.
    uint64_t steps = 0;
    TraceOptions topt;
    ReplayOptions ropt;
    ropt.on_step = &options.on_step;
    ropt.max_steps = options.max_steps;
    ropt.steps = &steps;
    ropt.unscale_exp = unscale_exp;
    if (options.has_from) {
      topt.has_from = ropt.has_from = true;
      for (int k = 0; k < 3; ++k) topt.from[k] = ropt.from[k] = s.mesh.to_scaled(options.from[k]);
    }
    std::vector<uint32_t> mesh_planes;
    mesh_planes.reserve(s.planes->size());
    for (uint32_t i = 0; i < s.planes->size(); ++i)
      if (!s.is_box[i]) mesh_planes.push_back(i);
    CulledTrace ct = trace_with_culling(*s.planes, mesh_planes, s.box, s.lp.vertex, topt, options.seed);
    TraceResult& tr = ct.trace;
    if (!tr.internal_error && !certify_embedding(s, tr, out)) return out;
    if (!tr.internal_error && (options.on_step || options.max_steps))
      replay_steps(*s.planes, ct.start_vertex, tr, ropt);
    out.stats.active_planes = 0;
    for (uint32_t p : ct.active) out.stats.active_planes += !s.is_box[p];
    out.stats.ms_trace = ms_since(t);
    out.stats.traced_lines = tr.traced_lines;
    out.complete = tr.complete;
    if (tr.internal_error) {
      out.error = Error::Internal;
      out.message = "internal error: kernel tracing could not certify a vertex (please report this mesh)";
      return out;
    }

    t = Clock::now();
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
    if (!assemble_polytope(*s.planes, tr, unscale_exp, out, emit_face, scaled_volume)) {
      out.error = Error::Internal;
      out.message = "internal error: traced kernel edges do not close into a polytope (please report this mesh)";
      return out;
    }
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
    out.volume_ratio = s.mesh.volume > 0 ? scaled_volume / s.mesh.volume : 0;
  }
  out.stats.exact_fallbacks = s.planes->exact_fallbacks;
  out.stats.ms_total = ms_since(t_total);
  return out;
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
    r.witness_faces = input_witness(s);
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
  PreparedMesh m = prepare_input(mesh, options);
  v.error = m.error;
  v.message = m.message;
  v.warnings = m.warnings;
  v.volume = std::ldexp(m.volume, -3 * m.scale_exp);
  return v;
}

}  // namespace kergen
