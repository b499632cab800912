// Public entry points: validation -> exact planes -> LP start vertex -> tracing -> polytope.
#include "kergen/kergen.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <memory>

#include "culling.h"
#include "lp.h"
#include "mesh_prep.h"
#include "plane_classes.h"
#include "planes.h"
#include "polytope.h"
#include "step_replay.h"
#include "tracer.h"

namespace kergen {

const char* error_name(Error e) {
  switch (e) {
    case Error::Ok: return "OK";
    case Error::EmptyInput: return "EMPTY_INPUT";
    case Error::NonFiniteCoordinate: return "NON_FINITE_COORDINATE";
    case Error::IndexOutOfRange: return "INDEX_OUT_OF_RANGE";
    case Error::FaceTooSmall: return "FACE_TOO_SMALL";
    case Error::OpenMesh: return "OPEN_MESH";
    case Error::NonManifoldEdge: return "NON_MANIFOLD_EDGE";
    case Error::InconsistentOrientation: return "INCONSISTENT_ORIENTATION";
    case Error::MultipleComponents: return "MULTIPLE_COMPONENTS";
    case Error::DegenerateInput: return "DEGENERATE_INPUT";
    case Error::TooLarge: return "TOO_LARGE";
    case Error::ParseError: return "PARSE_ERROR";
    case Error::IoError: return "IO_ERROR";
    case Error::InvalidArgument: return "INVALID_ARGUMENT";
    case Error::CoordinateRange: return "COORDINATE_RANGE";
  }
  return "UNKNOWN";
}

const char* kernel_type_name(KernelType t) {
  switch (t) {
    case KernelType::Empty: return "EMPTY";
    case KernelType::Point: return "POINT";
    case KernelType::Segment: return "SEGMENT";
    case KernelType::Polygon: return "POLYGON";
    case KernelType::Polyhedron: return "POLYHEDRON";
    case KernelType::Unbounded: return "UNBOUNDED";
  }
  return "UNKNOWN";
}

const char* progress_phase_name(Progress::Phase p) {
  switch (p) {
    case Progress::Phase::Validating: return "validating";
    case Progress::Phase::Planes: return "planes";
    case Progress::Phase::Lp: return "lp";
    case Progress::Phase::Tracing: return "tracing";
    case Progress::Phase::Assembling: return "assembling";
  }
  return "unknown";
}

namespace {

void report(const Options& options, Progress::Phase phase, size_t count) {
  if (options.on_progress) options.on_progress(Progress{phase, count});
}

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

// Everything up to and including the LP, shared by compute_kernel and find_kernel_point.
struct Setup {
  PreparedMesh mesh;
  std::unique_ptr<PlaneSet> planes;
  std::vector<uint32_t> active;  // the LP's constraints: the mesh planes (+ the box for open meshes)
  std::vector<uint32_t> box;
  std::vector<char> is_box;
  LpResult lp;
  bool rejected_early = false;  // empty kernel proven before the plane classes were built
  double center[3] = {0, 0, 0};
};

// Generic objective for the LP (ties are broken lexicographically anyway).
constexpr double kDefaultDirection[3] = {0.5773502691896258, 0.5773502691896257, 0.5773502691896256};
// Below this many faces the sample kernel would cost about as much as the plane classes it saves.
constexpr size_t kFaceCullingMinFaces = 700;
constexpr double kLpBound = 8;  // scaled coordinates are below 1; the open-mesh box is within 4

// A box twice the size of the data (scaled coordinates are below 1): it bounds what an open
// surface leaves unbounded, and the subset kernels of culling. A closed mesh's kernel never
// reaches it.
void add_box(PlaneSet& ps, std::vector<uint32_t>& box) {
  for (int k = 0; k < 3; ++k)
    for (int sgn = -1; sgn <= 1; sgn += 2) {
      double n[3] = {0, 0, 0};
      n[k] = sgn;
      box.push_back(ps.add_explicit(n[0], n[1], n[2], -2.0));
    }
}

// The planes of the representative triangles of faces first, ..., first + n - 1 (n <= kFaceBlock),
// as structure of arrays: the points are gathered first, then approx_plane runs over the block
// in one vectorized loop (the same operations per lane, so the same bounds as one at a time).
constexpr size_t kFaceBlock = 64;
struct FacePlanes {
  double nx[kFaceBlock], ny[kFaceBlock], nz[kFaceBlock], d[kFaceBlock];
  double enx[kFaceBlock], eny[kFaceBlock], enz[kFaceBlock], ed[kFaceBlock];
  PlaneArrays arrays() const { return {nx, ny, nz, d, enx, eny, enz, ed}; }
};

KERGEN_MULTIVERSION
void face_planes(const PreparedMesh& mesh, uint32_t first, size_t n, FacePlanes& out) {
  double xyz[9][kFaceBlock];
  for (size_t j = 0; j < n; ++j) {
    const auto& r = mesh.rep[first + j];
    for (int t = 0; t < 3; ++t) {
      const double* q = mesh.point(r[t]);
      for (int k = 0; k < 3; ++k) xyz[3 * t + k][j] = q[k];
    }
  }
  for (size_t j = 0; j < n; ++j) {
    const double a[3] = {xyz[0][j], xyz[1][j], xyz[2][j]}, b[3] = {xyz[3][j], xyz[4][j], xyz[5][j]},
                 c[3] = {xyz[6][j], xyz[7][j], xyz[8][j]};
    const PlaneCoef<Approx> p = approx_plane(a, b, c);
    out.nx[j] = p.n[0].v; out.enx[j] = p.n[0].e;
    out.ny[j] = p.n[1].v; out.eny[j] = p.n[1].e;
    out.nz[j] = p.n[2].v; out.enz[j] = p.n[2].e;
    out.d[j] = p.d.v; out.ed[j] = p.d.e;
  }
}

// The faces whose planes may reach above K_R (traced in `sample_kernel`), with the sample's
// own faces, in increasing order; false when more than half the faces may (a convex shape: all of
// them; a finely tessellated flat part of the kernel's boundary): the classes of all faces then
// cost less than those of a renumbered subset. Evenly spread probes tell before the full scan.
// (Out of line, called once: profiles show the scan as one entry.)
[[gnu::noinline]] bool faces_reaching(const PreparedMesh& mesh, const TraceResult& sample_kernel,
                                      const std::vector<uint32_t>& sample, std::vector<uint32_t>& kept) {
  const size_t nf = mesh.num_faces();
  const SupportTest support(sample_kernel, nf, true);
  SupportTest::Scratch scratch;
  auto reaches = [&](uint32_t f) {
    const auto& r = mesh.rep[f];
    uint32_t hint = 0;
    return support.may_reach(approx_plane(mesh.point(r[0]), mesh.point(r[1]), mesh.point(r[2])), scratch, hint);
  };
  constexpr size_t kProbes = 256;
  size_t probes_reaching = 0;
  for (size_t i = 0; i < kProbes; ++i) probes_reaching += reaches(uint32_t(((2 * i + 1) * nf) / (2 * kProbes)));
  if (2 * probes_reaching > kProbes) return false;
  kept.reserve(2 * sample.size());
  size_t next_sample = 0;
  FacePlanes block;
  char reaching[kFaceBlock];
  for (size_t first = 0; first < nf; first += kFaceBlock) {
    const size_t n = std::min(kFaceBlock, nf - first);
    face_planes(mesh, uint32_t(first), n, block);
    support.may_reach_all(block.arrays(), n, scratch, reaching);
    // Runs of faces up to the next sample face (kept whatever the test says) or the block's end.
    for (size_t j = 0;; ++j) {
      const size_t run_end =
          next_sample < sample.size() && sample[next_sample] < first + n ? sample[next_sample] - first : n;
      for (; j < run_end; ++j)
        if (reaching[j]) {
          kept.push_back(uint32_t(first + j));
          if (kept.size() > nf / 2) return false;  // the probes were wrong: not worth it either
        }
      if (j == n) break;
      kept.push_back(uint32_t(first + j));
      ++next_sample;
    }
  }
  return true;
}

void setup(const MeshView& mesh, const Options& options, Setup& s, Stats& stats) {
  auto t = Clock::now();
  report(options, Progress::Phase::Validating, mesh.face_sizes ? mesh.num_faces : mesh.num_indices / 3);
  s.mesh = prepare_mesh(mesh, options);
  stats.input_vertices = mesh.num_vertices;
  stats.input_faces = s.mesh.input_faces;
  stats.dropped_faces = s.mesh.dropped_faces;
  stats.ms_validate = ms_since(t);
  if (s.mesh.error != Error::Ok) return;

  // Faces before planes: on a large closed mesh, the kernel K_R of the planes of an evenly
  // spread sample R of faces bounds the kernel K (K is inside K_R). K is empty when K_R is (one
  // small exact LP, before any plane classes of the whole mesh are built); otherwise only the
  // faces whose planes reach above K_R can touch K, and the exact plane classes are built for
  // them and R alone. (K_R from a feasible sample proves nothing about K's emptiness: the LP
  // over the kept planes decides it.)
  std::vector<uint32_t> kept_faces;
  bool culled = false;
  const size_t nf = s.mesh.num_faces();
  report(options, Progress::Phase::Planes, nf);
  if (s.mesh.boundary_edges == 0 && nf > kFaceCullingMinFaces) {
    t = Clock::now();
    std::vector<uint32_t> sample;
    const size_t k = std::min(nf, size_t(3 * std::sqrt(double(nf))) + 32);
    for (size_t i = 0; i < k; ++i) sample.push_back(uint32_t((i * nf) / k));  // increasing
    PlaneSet sp(&s.mesh.points, s.mesh.exact_shift);
    sp.set_extent(s.mesh.extent());
    std::vector<uint32_t> sample_plane;
    build_planes(s.mesh, sample, sp, sample_plane);
    std::vector<uint32_t> sample_planes(sp.size()), sample_box;
    for (uint32_t i = 0; i < sp.size(); ++i) sample_planes[i] = i;
    add_box(sp, sample_box);
    std::vector<uint32_t> lp_planes = sample_planes;
    lp_planes.insert(lp_planes.end(), sample_box.begin(), sample_box.end());
    const auto t_lp = Clock::now();
    LpResult quick = solve_lp(sp, lp_planes, kDefaultDirection, kLpBound, options.seed);
    stats.ms_lp = ms_since(t_lp);
    if (quick.outcome == LpResult::Outcome::Infeasible) {
      s.lp = quick;
      s.rejected_early = true;
      stats.ms_planes = ms_since(t) - stats.ms_lp;
      return;
    }
    if (options.cull_faces && quick.outcome == LpResult::Outcome::Optimal) {
      TraceOptions quiet;
      CulledTrace kr = trace_with_culling(sp, sample_planes, sample_box, quick.vertex, quiet, options.seed);
      if (!kr.trace.internal_error && kr.trace.complete && !kr.trace.vertices.empty()) {
        culled = faces_reaching(s.mesh, kr.trace, sample, kept_faces);
        if (culled) stats.culled_faces = nf - kept_faces.size();
      }
    }
    stats.ms_planes = ms_since(t) - stats.ms_lp;
  }

  t = Clock::now();
  s.planes = std::make_unique<PlaneSet>(&s.mesh.points, s.mesh.exact_shift);
  s.planes->set_extent(s.mesh.extent());
  std::vector<uint32_t> face_plane;
  if (culled) build_planes(s.mesh, kept_faces, *s.planes, face_plane);
  else build_planes(s.mesh, *s.planes, face_plane);
  stats.distinct_planes = s.planes->size();
  s.active.reserve(s.planes->size() + 6);
  for (uint32_t i = 0; i < s.planes->size(); ++i) s.active.push_back(i);
  for (int k = 0; k < 3; ++k) s.center[k] = 0.5 * (s.mesh.bbox_min[k] + s.mesh.bbox_max[k]);
  add_box(*s.planes, s.box);
  if (s.mesh.boundary_edges > 0) s.active.insert(s.active.end(), s.box.begin(), s.box.end());
  s.is_box.assign(s.planes->size(), 0);
  for (uint32_t i = 0; i < s.planes->size(); ++i) s.is_box[i] = s.planes->explicit_plane(i);
  stats.ms_planes += ms_since(t);

  t = Clock::now();
  report(options, Progress::Phase::Lp, stats.distinct_planes);
  double dir[3] = {kDefaultDirection[0], kDefaultDirection[1], kDefaultDirection[2]};
  if (options.has_from) {
    double len = 0;
    for (int k = 0; k < 3; ++k) {
      double d = s.mesh.to_scaled(options.from[k]) - s.center[k];
      len += d * d;
    }
    if (len > 0 && std::isfinite(len))
      for (int k = 0; k < 3; ++k) dir[k] = s.mesh.to_scaled(options.from[k]) - s.center[k];
  }
  s.lp = solve_lp(*s.planes, s.active, dir, kLpBound, options.seed);
  stats.ms_lp += ms_since(t);
}

// Centre of the largest ball inside the kernel: bisection on the inward offset r of the facet
// planes (unit normals, double coefficients taken as exact), each step one exact LP that says
// whether the offset polytope is non-empty. The last feasible LP vertex is within the bisection
// tolerance of a centre (any point of the final offset polytope is one when it is not unique).
bool deepest_point(const PlaneSet& ps, const std::vector<uint32_t>& facets, const double bbox_min[3],
                   const double bbox_max[3], double point[3], double& radius) {
  if (facets.size() < 4) return false;
  std::vector<double> no_points;
  std::vector<std::array<double, 4>> unit;
  for (uint32_t h : facets) {
    double n[3] = {ps.nx()[h], ps.ny()[h], ps.nz()[h]};
    double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 0)) return false;
    unit.push_back({n[0] / len, n[1] / len, n[2] / len, ps.d()[h] / len});
  }
  double hi = 0;
  for (int k = 0; k < 3; ++k) hi = std::max(hi, 0.5 * (bbox_max[k] - bbox_min[k]));
  double lo = 0;
  bool found = false;
  for (int it = 0; it < 60 && hi - lo > 1e-15 * std::max(hi, 1e-300); ++it) {
    double r = 0.5 * (lo + hi);
    PlaneSet shrunk(&no_points);
    std::vector<uint32_t> ids;
    for (const auto& u : unit) ids.push_back(shrunk.add_explicit(u[0], u[1], u[2], u[3] + r));
    LpResult lp = solve_lp(shrunk, ids, kDefaultDirection, kLpBound, 7);
    if (lp.outcome == LpResult::Outcome::Optimal) {
      lo = r;
      for (int k = 0; k < 3; ++k) point[k] = lp.vertex.x[k].v;
      found = true;
    } else {
      hi = r;
    }
  }
  radius = lo;
  return found;
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
    out.stats.ms_total = ms_since(t_total);
    return out;
  }
  out.stats.active_planes = s.planes->size() - s.box.size();

  if (s.lp.outcome == LpResult::Outcome::Infeasible) {
    out.type = KernelType::Empty;
  } else if (s.lp.outcome == LpResult::Outcome::Unbounded) {
    out.type = KernelType::Unbounded;
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
    if (!tr.internal_error && (options.on_step || options.max_steps)) replay_steps(*s.planes, ct.start_vertex, tr, ropt);
    out.stats.active_planes = 0;
    for (uint32_t p : ct.active) out.stats.active_planes += !s.is_box[p];
    out.stats.ms_trace = ms_since(t);
    out.stats.traced_lines = tr.traced_lines;
    out.complete = tr.complete;
    if (tr.internal_error) {
      out.error = Error::InvalidArgument;
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
      if (!go) { stopped = true; out.complete = false; }
      return go;
    };
    double scaled_volume = 0;
    if (!assemble_polytope(*s.planes, tr, unscale_exp, out, emit_face, scaled_volume)) {
      out.error = Error::InvalidArgument;
      out.message = "internal error: traced kernel edges do not close into a polytope (please report this mesh)";
      return out;
    }
    for (const auto& v : tr.vertices)
      for (uint32_t p : v.tight)
        if (s.is_box[p]) out.type = KernelType::Unbounded;
    if (options.deepest_point && out.type == KernelType::Polyhedron && out.complete) {
      std::vector<uint32_t> facets;
      for (const auto& e : tr.edges)
        for (uint32_t h : e.planes) facets.push_back(h);
      std::sort(facets.begin(), facets.end());
      std::vector<uint32_t> counted;
      for (size_t i = 0; i < facets.size();) {
        size_t j = i;
        while (j < facets.size() && facets[j] == facets[i]) ++j;
        if (j - i >= 3) counted.push_back(facets[i]);
        i = j;
      }
      double p[3] = {0, 0, 0}, r = 0;
      if (deepest_point(*s.planes, counted, s.mesh.bbox_min, s.mesh.bbox_max, p, r)) {
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
  if (s.lp.outcome == LpResult::Outcome::Optimal) {
    r.star_shaped = true;
    double hi[3], lo[3];
    precise_coordinates(*s.planes, s.lp.vertex, hi, lo);  // rounded to nearest, as compute_kernel's
    for (int k = 0; k < 3; ++k) r.point[k] = s.mesh.to_input(hi[k]);
  } else if (s.lp.outcome == LpResult::Outcome::Unbounded) {
    r.star_shaped = true;  // non-empty but unbounded (open input)
  }
  return r;
}

Validation validate_mesh(const MeshView& mesh, const Options& options) {
  Validation v;
  PreparedMesh m = prepare_mesh(mesh, options);
  v.error = m.error;
  v.message = m.message;
  v.warnings = m.warnings;
  v.volume = std::ldexp(m.volume, -3 * m.scale_exp);
  return v;
}

}  // namespace kergen
