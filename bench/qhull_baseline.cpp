// The Qhull baseline of kergen_bench: halfspace intersection with libqhull_r's reentrant C API.
#include "bench_util.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#ifdef KERGEN_HAVE_QHULL
#include "libqhull_r/qhull_ra.h"
#endif

namespace kergen_bench {

#ifndef KERGEN_HAVE_QHULL

std::string qhull_version() { return "Qhull not built (libqhull-dev not found)"; }

Baseline run_qhull(const kergen::Mesh&, bool, const std::array<double, 3>&, double, int, double) {
  Baseline b;
  b.skipped = "not built (libqhull-dev not found at configure time)";
  return b;
}

#else

std::string qhull_version() { return std::string("Qhull ") + qh_version; }

namespace {

// One halfspace (nx, ny, nz, d), n·x + d <= 0 inside, per face from its first vertex triple with
// a non-zero cross product: the input a Qhull user builds (CGAL gets the same triples' planes).
// Part of the timed work.
std::vector<double> face_halfspaces(const kergen::Mesh& m, bool flip) {
  std::vector<double> hs;
  hs.reserve(4 * m.num_faces());
  const double* P = m.positions.data();
  size_t off = 0;
  for (size_t f = 0; f < m.num_faces(); ++f) {
    const size_t k = m.face_sizes.empty() ? 3 : m.face_sizes[f];
    const uint32_t* loop = m.indices.data() + off;
    off += k;
    const double* a = P + 3 * loop[0];
    for (size_t j = 1; j + 1 < k; ++j) {
      const double *b = P + 3 * loop[j], *c = P + 3 * loop[j + 1];
      const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
      double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
      if (n[0] == 0 && n[1] == 0 && n[2] == 0) continue;
      if (flip) n[0] = -n[0], n[1] = -n[1], n[2] = -n[2];
      hs.insert(hs.end(), {n[0], n[1], n[2], -(n[0] * a[0] + n[1] * a[1] + n[2] * a[2])});
      break;
    }
  }
  return hs;
}

// Qhull's messages go to a FILE*: collect them in memory for the row's note.
struct MessageStream {
  char* text = nullptr;
  size_t size = 0;
  FILE* file = open_memstream(&text, &size);
  ~MessageStream() {
    if (file) std::fclose(file);
    std::free(text);
  }
  std::string first_line() {
    std::fflush(file);
    std::string s = text ? std::string(text, size) : std::string();
    const size_t eol = s.find('\n');
    return eol == std::string::npos ? s : s.substr(0, eol);
  }
};

struct QhullRun {
  int exit_code = 0;
  std::string message;
  std::vector<double> points;  // xyz of the intersection points
};

// The timed part: the halfspaces, Qhull's intersection about the feasible point, and the
// intersection points read off its dual facets (point = feasible − normal / offset, what qhull's
// 'Fp' output and scipy's `intersections` give). Freeing Qhull's structures is not timed (nor is
// CGAL's Surface_mesh destructor).
QhullRun intersect(qhT* qh, const kergen::Mesh& m, bool flip, const char* flags, FILE* err) {
  QhullRun r;
  std::vector<double> hs = face_halfspaces(m, flip);
  qh_zero(qh, err);
  r.exit_code = qh_new_qhull(qh, 4, int(hs.size() / 4), hs.data(), False, const_cast<char*>(flags), nullptr, err);
  if (r.exit_code) return r;
  r.points.reserve(3 * size_t(qh->num_facets));
  facetT* facet;
  FORALLfacets {
    if (!(facet->offset < 0)) {  // a point at infinity: the intersection is unbounded
      r.exit_code = -1;
      r.message = "a dual facet with offset >= 0 (unbounded intersection)";
      return r;
    }
    for (int k = 0; k < 3; ++k) r.points.push_back(facet->normal[k] / -facet->offset + qh->feasible_point[k]);
  }
  return r;
}

void free_qhull(qhT* qh) {
  int curlong = 0, totlong = 0;
  qh_freeqhull(qh, !qh_ALL);
  qh_memfreeshort(qh, &curlong, &totlong);
}

// Not timed: the volume of the convex hull of the intersection points (a second Qhull run over
// the points, qh_getarea's total volume), or NaN when Qhull fails on them.
double hull_volume(std::vector<double> points) {
  MessageStream err;
  qhT qh_qh;
  qhT* qh = &qh_qh;
  qh_zero(qh, err.file);
  char flags[] = "qhull";
  double volume = std::nan("");
  if (qh_new_qhull(qh, 3, int(points.size() / 3), points.data(), False, flags, nullptr, err.file) == 0) {
    qh_getarea(qh, qh->facet_list);
    volume = qh->totvol;
  }
  free_qhull(qh);
  return volume;
}

}  // namespace

Baseline run_qhull(const kergen::Mesh& m, bool flip, const std::array<double, 3>& o, double our_volume, int runs,
                   double budget_ms) {
  Baseline b;
  // Not timed: Qhull refuses a feasible point that is not inside every halfspace (in double, as
  // it tests it), and divides by its distance to each plane.
  const std::vector<double> hs = face_halfspaces(m, flip);
  for (size_t i = 0; i < hs.size(); i += 4)
    if (!(hs[i] * o[0] + hs[i + 1] * o[1] + hs[i + 2] * o[2] + hs[i + 3] < 0)) {
      b.skipped = "feasible point not strictly inside every face plane (in double)";
      return b;
    }
  // %.17g: the feasible point Qhull parses is ours bit for bit.
  char flags[160];
  std::snprintf(flags, sizeof flags, "qhull H%.17g,%.17g,%.17g", o[0], o[1], o[2]);
  std::vector<double> times, points;
  for (int r = 0; r < runs; ++r) {
    MessageStream err;
    qhT qh_qh;
    qhT* qh = &qh_qh;
    const double t0 = now_ms();
    QhullRun run = intersect(qh, m, flip, flags, err.file);
    benchmark::DoNotOptimize(run.points.data());
    const double ms = now_ms() - t0;
    free_qhull(qh);
    if (run.exit_code) {
      b.skipped = "failed: " + (run.message.empty() ? err.first_line() : run.message);
      return b;
    }
    times.push_back(ms);
    points = std::move(run.points);
    if (ms > budget_ms) break;
  }
  b.ran = true;
  b.ms = median(times);
  b.runs = int(times.size());
  b.raw_vertices = points.size() / 3;
  b.has_volume = true;
  b.volume = hull_volume(std::move(points));
  b.volume_rel_diff = std::fabs(b.volume - our_volume) / std::fabs(our_volume);
  if (std::isnan(b.volume_rel_diff)) b.volume_rel_diff = HUGE_VAL;
  return b;
}

#endif

}  // namespace kergen_bench
