// Plane culling, output-sensitive tracing: only the planes that can touch the kernel are traced
// against. Its sample kernel is K_S, the plane-subset kernel: the kernel of a random subset S of
// the distinct planes (face culling's is the face-sample kernel, of the planes of evenly spread
// faces, before planes are merged; see face_culling.h). The support test (SupportTest) serves
// both.
#pragma once

#include <vector>

#include "exact/predicates.h"
#include "solve/climb.h"
#include "solve/tracer.h"
#include "util/compiler_hints.h"

namespace kergen {

// Planes as structure of arrays: coefficients and their error bounds (as PlaneCoef<Approx>).
struct PlaneArrays {
  const double *nx, *ny, *nz, *d;
  const double *enx, *eny, *enz, *ed;
};

// Whether a plane can reach above a traced convex polytope K_S (some vertex of K_S outside it):
// a bounding-box test, then an upper bound from K_S's support function at the corners of a
// cube map of directions, then hill climbing on K_S's vertex graph (may_reach_all: a scan of
// all vertices of a small K_S instead). All in double with a margin
// far above rounding (plus the plane's coefficient error bounds and the vertices'), so a plane
// that reaches above K_S is never missed; planes that merely come close are kept too.
// `tr` must be a complete trace of a non-empty, bounded K_S (coordinates below ~2).
class SupportTest {
 public:
  // `batched`: the queries go through may_reach_all.
  SupportTest(const TraceResult& tr, size_t expected_queries, bool batched = false);
  struct Scratch {
    ClimbScratch climb;
  };
  // True when plane may hold a vertex of K_S outside (or within the margin of) its half-space;
  // `hint` is then a vertex of K_S near the plane's maximum (a start for cutting).
  bool may_reach(const PlaneCoef<Approx>& plane, Scratch& scratch, uint32_t& hint) const;
  // reaching[i] = may_reach(plane i) for n planes (hints dropped), the same tests in vectorized
  // passes over the planes (see culling.cpp).
  void may_reach_all(const PlaneArrays& planes, size_t n, Scratch& scratch, char* reaching) const;

 private:
  // Climbs from the start of `cell` (and of the cell's corners from `corner`; cell < 0: from
  // vertex 0) to the maximum of the plane's f; whether it is above -margin.
  bool climb_reaches(double a, double b, double c, double d, double margin, int32_t cell, int32_t corner,
                     Scratch& scratch, uint32_t& hint) const;

  std::vector<double> xyz_;
  std::vector<double> vertex_coord_[3];  // xyz_ as structure of arrays
  std::vector<uint32_t> adj_offset_, adj_, start_of_cell_, start_of_corner_;
  std::vector<char> cell_resolved_;
  std::vector<double> corner_support_;
  size_t cells_per_side_ = 2;
  double centre_[3] = {0, 0, 0}, half_[3] = {0, 0, 0};
  double max_abs_ = 0, coord_error_ = 0;
};

struct CulledTrace {
  TraceResult trace;             // the kernel, traced against `active` only
  std::vector<uint32_t> active;  // the planes kept (a superset of those touching the kernel)
  uint32_t start_vertex = 0;     // the vertex of `trace` at `start`
  size_t rounds = 0;
};

// Kernel of `planes` from the kernel vertex `start` (tight set computed over `planes`).
// Clarkson-style sampling: trace the kernel K_S of a subset S (S holds start's tight planes,
// `always` — e.g. bounding planes — and a random sample), find every plane some vertex of K_S
// violates, and cut K_S by them (cutting.h; retraced where the cuts do not apply): every other
// plane holds K_S, hence the result, strictly. Violation is found per plane by hill climbing on
// K_S's vertex graph in the plane's normal direction, in double with a margin far above
// rounding, so a violated plane is never missed (near-touching planes are merely kept).
// `options` must not ask for events (step_replay.h replays them from the result).
CulledTrace trace_with_culling(const PlaneSet& ps, const std::vector<uint32_t>& planes,
                               const std::vector<uint32_t>& always, const VertexGeom& start,
                               const TraceOptions& options, uint64_t seed);

}  // namespace kergen
