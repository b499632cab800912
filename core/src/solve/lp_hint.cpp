// Seidel's LP (3D -> 2D -> 1D) in plain doubles: a fast guess at the exact LP's answer.
//
// Why: the exact LP pays for every intermediate optimum it builds (a vertex with error bounds,
// then side tests against all planes before it), and on near-degenerate input (nearly coplanar
// faces) most of those tests go past the double filter. Given the final basis first, the exact
// run builds it once and the remaining planes are one side test each at the final vertex.
//
// Planes are normalized (unit normals), so the tolerances below are distances; coordinates are
// below ~16 (scaled input, bound 8). Nothing here needs to be right: a wrong guess only costs the
// exact run the work it would have done anyway.
#include "solve/lp_hint.h"

#include <cmath>
#include <vector>

namespace kergen {

namespace {

constexpr double kTol = 1e-11;       // a plane holds a point within this distance
constexpr double kParallel = 1e-13;  // |projected normal| below this: parallel to the line/plane

struct Plane4 {
  double n[3], d;
};

double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

class FloatSeidel {
 public:
  FloatSeidel(const double dir[3], double bound, size_t n) {
    pl_.reserve(n + 3);
    in_plane_.reserve(n + 3);
    for (int k = 0; k < 3; ++k) s_[k] = dir[k] < 0 ? -1.0 : 1.0;
    const double len = std::sqrt(dot3(dir, dir));
    for (int k = 0; k < 3; ++k) c_[k] = len > 0 ? dir[k] / len : s_[k];
    // The exact LP's first tie-break direction (same sign pattern): decides where the objective
    // is perpendicular to a plane (a face facing it), as the lexicographic objective does.
    const double t[3] = {3 * s_[0], 1 * s_[1], 2 * s_[2]};
    for (int k = 0; k < 3; ++k) tie_[k] = t[k];
    bound_ = bound;
    for (int k = 0; k < 3; ++k) {
      Plane4 p{{0, 0, 0}, -bound};
      p.n[k] = s_[k];
      pl_.push_back(p);
    }
  }

  // Adds a constraint; false if its coefficients are not usable (zero or not finite).
  bool add(const double n[3], double d) {
    const double len = std::sqrt(dot3(n, n));
    if (!(len > 0) || !std::isfinite(len) || !std::isfinite(d)) return false;
    pl_.push_back({{n[0] / len, n[1] / len, n[2] / len}, d / len});
    return true;
  }

  // Runs the LP; ids of the result (plane indices in pl_, -1 for none) in `ids`.
  bool solve(int ids[4]) {
    double x[3] = {s_[0] * bound_, s_[1] * bound_, s_[2] * bound_};
    int basis[3] = {0, 1, 2};
    for (int i = 3; i < int(pl_.size()); ++i) {
      if (value(pl_[i], x) <= kTol) continue;
      if (!solve2(i, x, basis, ids)) return false;
    }
    for (int k = 0; k < 3; ++k) ids[k] = basis[k];
    ids[3] = -1;
    return true;
  }

 private:
  static double value(const Plane4& p, const double x[3]) { return dot3(p.n, x) + p.d; }

  // Optimum on plane i over pl_[0..i): a point x with its three defining constraints, or false
  // with the conflicting constraints in `witness`.
  bool solve2(int i, double x[3], int basis[3], int witness[4]) {
    const Plane4& h = pl_[i];
    // Orthonormal frame (u, w) of the plane, origin p0 = its point closest to 0.
    double e[3] = {0, 0, 0};
    const double ax = std::fabs(h.n[0]), ay = std::fabs(h.n[1]), az = std::fabs(h.n[2]);
    e[ax <= ay && ax <= az ? 0 : (ay <= az ? 1 : 2)] = 1;
    double u[3] = {h.n[1] * e[2] - h.n[2] * e[1], h.n[2] * e[0] - h.n[0] * e[2], h.n[0] * e[1] - h.n[1] * e[0]};
    const double ul = std::sqrt(dot3(u, u));
    for (double& c : u) c /= ul;
    const double w[3] = {h.n[1] * u[2] - h.n[2] * u[1], h.n[2] * u[0] - h.n[0] * u[2], h.n[0] * u[1] - h.n[1] * u[0]};
    const double p0[3] = {-h.d * h.n[0], -h.d * h.n[1], -h.d * h.n[2]};
    double cx = dot3(c_, u), cy = dot3(c_, w);
    if (std::fabs(cx) + std::fabs(cy) < 1e-12) {
      cx = dot3(tie_, u);
      cy = dot3(tie_, w);
    }
    // The constraints before i in the plane's coordinates: A . y + B <= 0.
    in_plane_.resize(i);
    for (int j = 0; j < i; ++j) in_plane_[j] = {dot3(pl_[j].n, u), dot3(pl_[j].n, w), value(pl_[j], p0)};
    // A square far beyond the box bounds every line of the plane: its sides are ids -1..-4.
    const double r = 64 * bound_;
    double y[2] = {cx >= 0 ? r : -r, cy >= 0 ? r : -r};
    int b2[2] = {-1, -1};
    for (int j = 0; j < i; ++j) {
      const double nx = in_plane_[j].ax, ny = in_plane_[j].ay, bj = in_plane_[j].b;
      if (std::fabs(nx) + std::fabs(ny) < kParallel) {
        if (bj > kTol) {
          witness[0] = i;
          witness[1] = j;
          witness[2] = witness[3] = -1;
          return false;
        }
        continue;
      }
      if (nx * y[0] + ny * y[1] + bj <= kTol) continue;
      // Optimum on the line A_j . y + B_j = 0: y0 + s t, s bounded by the constraints before j.
      const double l2 = nx * nx + ny * ny, l = std::sqrt(l2);
      double t[2] = {-ny / l, nx / l};
      if (t[0] * cx + t[1] * cy < 0) {
        t[0] = -t[0];
        t[1] = -t[1];
      }
      const double y0[2] = {-bj * nx / l2, -bj * ny / l2};
      double hi = HUGE_VAL, lo = -HUGE_VAL;
      int hi_id = -1, lo_id = -1;
      auto bound_by = [&](double ak0, double ak1, double bk, int id) {
        const double alpha = ak0 * t[0] + ak1 * t[1], beta = ak0 * y0[0] + ak1 * y0[1] + bk;
        if (alpha > kParallel) {
          const double s = -beta / alpha;
          if (s < hi) {
            hi = s;
            hi_id = id;
          }
        } else if (alpha < -kParallel) {
          const double s = -beta / alpha;
          if (s > lo) {
            lo = s;
            lo_id = id;
          }
        } else if (beta > kTol) {
          lo = HUGE_VAL;  // the line is outside a parallel constraint
          lo_id = id;
        }
      };
      bound_by(1, 0, -r, -1);
      bound_by(-1, 0, -r, -1);
      bound_by(0, 1, -r, -1);
      bound_by(0, -1, -r, -1);
      for (int k = 0; k < j; ++k) bound_by(in_plane_[k].ax, in_plane_[k].ay, in_plane_[k].b, k);
      if (lo > hi + kTol) {
        witness[0] = i;
        witness[1] = j;
        witness[2] = lo_id;
        witness[3] = hi_id;
        return false;
      }
      y[0] = y0[0] + hi * t[0];
      y[1] = y0[1] + hi * t[1];
      b2[0] = j;
      b2[1] = hi_id;
    }
    for (int k = 0; k < 3; ++k) x[k] = p0[k] + y[0] * u[k] + y[1] * w[k];
    basis[0] = i;
    basis[1] = b2[0];
    basis[2] = b2[1];
    return true;
  }

  double s_[3], c_[3], tie_[3], bound_;
  std::vector<Plane4> pl_;  // the three box planes, then the constraints
  // The constraints before the current one in its plane's frame (one array, not three: a small
  // LP's allocations cost about as much as its arithmetic).
  struct Line2 {
    double ax, ay, b;
  };
  std::vector<Line2> in_plane_;
};

}  // namespace

LpHint float_lp_hint(const PlaneSet& ps, const uint32_t* planes, size_t n, const double direction[3], double bound) {
  LpHint hint;
  FloatSeidel lp(direction, bound, n);
  for (size_t i = 0; i < n; ++i) {
    const uint32_t p = planes[i];
    const double nv[3] = {ps.nx()[p], ps.ny()[p], ps.nz()[p]};
    if (!lp.add(nv, ps.d()[p])) return hint;
  }
  int ids[4];
  hint.infeasible = !lp.solve(ids);
  for (int id : ids) {
    if (id < 3) continue;  // the box, a side of the square, or none
    const uint32_t pos = uint32_t(id - 3);
    bool seen = false;
    for (int k = 0; k < hint.count; ++k) seen |= hint.position[k] == pos;
    if (!seen) hint.position[hint.count++] = pos;
  }
  return hint;
}

}  // namespace kergen
