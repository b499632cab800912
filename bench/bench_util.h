// Pieces shared by kergen_bench's translation units (the CGAL rows, the Qhull baseline and the
// streaming rows). The Qhull code lives in its own file because qhull's C headers define macros
// (FORALLfacets, trace0, ...) that must not meet CGAL's.
#pragma once

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

#include "kergen/kergen.h"

namespace kergen_bench {

// A number with `prec` decimals, for the tables.
inline std::string fmt(double v, int prec = 2) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", prec, v);
  return buf;
}

// The clock of every timing: the wall clock, or (kergen_bench --cpu-time) the calling thread's
// CPU time, which on a machine busy with other work still says what our code and the in-process
// baselines (CGAL's halfspace_intersection_3, Qhull) cost. (CGAL 6.2 runs in its own process
// and times itself on the wall clock either way.)
inline bool& thread_cpu_clock() {
  static bool on = false;
  return on;
}
inline double now_ms() {
  if (thread_cpu_clock()) {
    timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
  }
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

inline double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct Baseline {
  bool ran = false;
  std::string skipped;  // reason when not run
  double ms = 0;        // median
  int runs = 0;
  size_t raw_vertices = 0;  // output vertices as the baseline returns them (degree-k vertices repeated)
  // Qhull only: it constructs in floating point, so its kernel is checked by volume (the volume of
  // the convex hull of its intersection points) against ours.
  bool has_volume = false;
  double volume = 0, volume_rel_diff = 0;
  bool volume_ok() const { return !has_volume || volume_rel_diff <= kVolumeTolerance; }
  static constexpr double kVolumeTolerance = 1e-6;
};

// Qhull's halfspace intersection ("qhull H" through the reentrant C API, as
// scipy.spatial.HalfspaceIntersection calls it) with `interior` as its feasible point: `runs`
// timed runs (stopping after one longer than budget_ms). `our_volume` is what its result is
// checked against. Without libqhull_r at build time the result says so in `skipped`.
Baseline run_qhull(const kergen::Mesh& m, bool flip, const std::array<double, 3>& interior, double our_volume, int runs,
                   double budget_ms);
// "Qhull 2020.2.r 2020/08/31", or a note that the bench was built without it.
std::string qhull_version();

}  // namespace kergen_bench
