// Input validation: finite coordinates, valid indices, closed 2-manifold edges with consistent
// orientation, one connected piece, positive enclosed volume (flipped if negative). Zero-area
// faces are detected exactly and dropped (after the topology check, which still counts them:
// they are part of the closed surface, they only carry no plane).
#include "mesh_prep.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <sstream>
#include <utility>

#include "compiler_hints.h"
#include "exact/predicates.h"
#include "union_find.h"

namespace kergen {

namespace {

// Six times the volume enclosed by the prepared faces (their loops, CCW from outside), summed in
// double-double over fans about c, with a rigorous error bound (ApproxDD::sign decides it).
exact::ApproxDD accurate_volume6(const PreparedMesh& m, const double c[3]) {
  using exact::ApproxDD;
  auto rel = [&](uint32_t v, int k) {
    double x, y;
    exact::eft::two_sum(m.points[3 * size_t(v) + k], -c[k], x, y);
    return ApproxDD(x, y, 0);
  };
  ApproxDD vol6(0);
  for (size_t f = 0; f + 1 < m.loop_offsets.size(); ++f) {
    const uint32_t* loop = m.loops.data() + m.loop_offsets[f];
    const size_t k = m.loop_offsets[f + 1] - m.loop_offsets[f];
    for (size_t i = 1; i + 1 < k; ++i) {
      ApproxDD a[3], b[3], d[3];
      for (int j = 0; j < 3; ++j) {
        a[j] = rel(loop[0], j);
        b[j] = rel(loop[i], j);
        d[j] = rel(loop[i + 1], j);
      }
      vol6 = vol6 + (a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0]) +
                     a[2] * (b[0] * d[1] - b[1] * d[0]));
    }
  }
  return vol6;
}

Warning flipped_warning(size_t faces) {
  return {Warning::Kind::OrientationFlipped, faces,
          "faces were oriented clockwise seen from outside (negative volume); the mesh was flipped"};
}

PreparedMesh fail(PreparedMesh& m, Error e, const std::string& msg) {
  m.error = e;
  m.message = msg;
  m.rep = {};  // (its storage may hold the edge check's scratch)
  return std::move(m);
}

// The loop's Newell normal (its area vector, times 2), in double.
std::array<double, 3> newell_normal(const std::vector<double>& pts, const uint32_t* loop, size_t k) {
  std::array<double, 3> n = {0, 0, 0};
  for (size_t t = 0; t < k; ++t) {
    const double* a = &pts[3 * size_t(loop[t])];
    const double* b = &pts[3 * size_t(loop[(t + 1) % k])];
    n[0] += (a[1] - b[1]) * (a[2] + b[2]);
    n[1] += (a[2] - b[2]) * (a[0] + b[0]);
    n[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  return n;
}

// Ear clipping of polygons over 128 corners (the first ear met) has a work budget: up to this
// many corners, 8 k^2 with every ear test charged as a scan of the corners left (the budget of
// the plain quadratic search it replaces, so the same polygons are split the same way); above,
// kEarWorkPerCorner per corner (at most 8 kBudgetPerScan^2, the most a smaller polygon gets),
// charged with the work actually done: steps of the walk, cells and corners looked at.
constexpr size_t kBudgetPerScan = 4096;
constexpr size_t kEarWorkPerCorner = 4096;

// The corners of a polygon in a uniform grid over their box in its plane (about four cells per
// corner, shaped like the box), listed per cell: the corners near a small ear are a few cells'
// worth. A coordinate's cell is monotone in it, so a box's cells hold every corner in the box.
class CornerGrid {
 public:
  CornerGrid(const std::vector<double>& xs, const std::vector<double>& ys) {
    const size_t k = xs.size();
    x0_ = *std::min_element(xs.begin(), xs.end());
    y0_ = *std::min_element(ys.begin(), ys.end());
    const double ex = *std::max_element(xs.begin(), xs.end()) - x0_, ey = *std::max_element(ys.begin(), ys.end()) - y0_;
    const size_t cells = 4 * k;
    if (ex > 0 && ey > 0) {
      const double g = std::sqrt(double(cells) * (ex / ey));  // (ex / ey first: no overflow to inf * 0)
      gx_ = g >= double(cells) ? cells : std::max<size_t>(1, size_t(g));
      gy_ = std::max<size_t>(1, cells / gx_);
    } else {
      gx_ = ex > 0 ? cells : 1;
      gy_ = ey > 0 ? cells : 1;
    }
    ix_ = ex > 0 ? double(gx_) / ex : 0;
    iy_ = ey > 0 ? double(gy_) / ey : 0;
    start_.assign(gx_ * gy_ + 1, 0);
    std::vector<uint32_t> cell(k);
    for (size_t t = 0; t < k; ++t) {
      cell[t] = uint32_t(to_cell(ys[t], y0_, iy_, gy_) * gx_ + to_cell(xs[t], x0_, ix_, gx_));
      ++start_[cell[t] + 1];
    }
    for (size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    items_.resize(k);
    std::vector<uint32_t> fill(start_.begin(), start_.end() - 1);
    for (size_t t = 0; t < k; ++t) items_[fill[cell[t]]++] = uint32_t(t);
  }
  // The cell ranges [x0, x1] and [y0, y1] covering box (xlo, xhi, ylo, yhi), and their count.
  size_t cells_of(const double box[4], size_t range[4]) const {
    range[0] = to_cell(box[0], x0_, ix_, gx_);
    range[1] = to_cell(box[1], x0_, ix_, gx_);
    range[2] = to_cell(box[2], y0_, iy_, gy_);
    range[3] = to_cell(box[3], y0_, iy_, gy_);
    return (range[1] - range[0] + 1) * (range[3] - range[2] + 1);
  }
  // A band of y holding every corner of row cy (the rows' ends open; a little wider than the row
  // for the rounding of the cell computation).
  void row_band(size_t cy, double& lo, double& hi) const {
    if (iy_ == 0) {
      lo = -INFINITY;
      hi = INFINITY;
      return;
    }
    const double slack = 1e-14 * (std::fabs(y0_) + double(gy_) / iy_);
    lo = cy == 0 ? -INFINITY : y0_ + (double(cy) - 0.01) / iy_ - slack;
    hi = cy + 1 == gy_ ? INFINITY : y0_ + (double(cy) + 1.01) / iy_ + slack;
  }
  size_t column(double x) const { return to_cell(x, x0_, ix_, gx_); }
  const uint32_t* items(size_t cx, size_t cy) const { return items_.data() + start_[cy * gx_ + cx]; }
  size_t count(size_t cx, size_t cy) const { return start_[cy * gx_ + cx + 1] - start_[cy * gx_ + cx]; }

 private:
  // Monotone in v (rounded subtraction and multiplication by inv >= 0 are), clamped to [0, g).
  static size_t to_cell(double v, double origin, double inv, size_t g) {
    const double t = (v - origin) * inv;
    if (!(t > 0)) return 0;  // (also NaN: 0 * inf for v at the origin)
    if (t >= double(g - 1)) return g - 1;
    return size_t(t);
  }
  double x0_, y0_, ix_, iy_;
  size_t gx_, gy_;
  std::vector<uint32_t> start_, items_;
};

// A region holding every point q that the ear test accepts for the ear (a, b, c) of positive area
// area2 = cr(a, b, c) (cr(a, b, q), cr(b, c, q), cr(c, a, q) >= tol as computed, tol <= 0): the
// points within margin (in each coordinate) of the triangle corner[0..3), and its box. False when
// the ear is too thin for the bound (then every corner is scanned). Why it holds: in exact
// arithmetic the accepted points form the triangle T' whose sides lie -tol / |e| outside the ear's
// sides e, which is the ear scaled about its centroid by 1 + 3 mu, mu = -tol / area2 (a side moves
// by 3 mu times the centroid's distance area2 / (3 |e|)): its corner at b is b + mu (2b - a - c).
// A point at distance D from T' is beyond one of its sides by at least D sin(angle / 2) >= D s / 2
// (s the smallest sine of the ear's angles, which T' shares), so its exact cr for that side is
// below tol by |e| D s / 2, while cr's rounding is below 4.01 eps |e| |q - p| (p that side's first
// corner, |q - p| <= D + diameter of T'). The margin, 1e-12 / s + 1e-6 of T's diameter plus 1e-14
// of the coordinates' size for the rounding of the corners computed here, keeps every point that
// the rounded test accepts inside with a factor of 1000 to spare. Sines below 1e-10 and sides
// below 1e-80 (no subnormal products) are refused.
struct EarRegion {
  double corner[3][2];
  double margin;
  double box[4];  // xlo, xhi, ylo, yhi
};
bool ear_region(const std::vector<double>& xs, const std::vector<double>& ys, uint32_t a, uint32_t b, uint32_t c,
                double tol, double area2, EarRegion& region) {
  auto len = [&](uint32_t p, uint32_t q) {
    return std::sqrt((xs[q] - xs[p]) * (xs[q] - xs[p]) + (ys[q] - ys[p]) * (ys[q] - ys[p]));
  };
  const double ab = len(a, b), bc = len(b, c), ca = len(c, a);
  const double shortest = std::min(ab, std::min(bc, ca)), longest = std::max(ab, std::max(bc, ca));
  if (!(shortest >= 1e-80)) return false;
  const double s = std::min(area2 / (ab * ca), std::min(area2 / (ab * bc), area2 / (bc * ca)));
  if (!(s >= 1e-10)) return false;
  const double mu = -tol / area2, diameter = (1 + 3 * mu) * longest;
  const double margin = diameter * (1e-12 / s + 1e-6) + 1e-14 * (std::fabs(xs[a]) + std::fabs(ys[a]) + 2 * diameter);
  region.margin = margin;
  double* box = region.box;
  box[0] = box[2] = INFINITY;
  box[1] = box[3] = -INFINITY;
  const uint32_t ear[3] = {a, b, c};
  for (int i = 0; i < 3; ++i) {
    const uint32_t p = ear[i], q = ear[(i + 1) % 3], r = ear[(i + 2) % 3];
    const double x = xs[p] + mu * ((xs[p] - xs[q]) + (xs[p] - xs[r])),
                 y = ys[p] + mu * ((ys[p] - ys[q]) + (ys[p] - ys[r]));
    region.corner[i][0] = x;
    region.corner[i][1] = y;
    box[0] = std::min(box[0], x - margin);
    box[1] = std::max(box[1], x + margin);
    box[2] = std::min(box[2], y - margin);
    box[3] = std::max(box[3], y + margin);
  }
  return true;
}

// The range of x over the region's points with lo <= y <= hi, widened for rounding; false if
// there are none. The triangle's part in the band widened by the margin is bounded by the parts
// of its sides there: each side's is found from where it crosses the band's lines (well
// conditioned unless the side is nearly level, which then counts whole where its y range meets
// the band).
bool region_x_range(const EarRegion& region, double lo, double hi, double& xlo, double& xhi) {
  lo -= region.margin;
  hi += region.margin;
  xlo = INFINITY;
  xhi = -INFINITY;
  double size = 0;
  for (int i = 0; i < 3; ++i) size = std::max(size, std::fabs(region.corner[i][0]) + std::fabs(region.corner[i][1]));
  for (int i = 0; i < 3; ++i) {
    const double *p = region.corner[i], *q = region.corner[(i + 1) % 3];
    const double dx = q[0] - p[0], dy = q[1] - p[1];
    if (std::max(p[1], q[1]) < lo || std::min(p[1], q[1]) > hi) continue;
    double t0 = 0, t1 = 1;
    if (std::fabs(dy) >= 1e-3 * std::fabs(dx)) {
      const double ta = (lo - p[1]) / dy, tb = (hi - p[1]) / dy;
      t0 = std::max(0.0, std::min(ta, tb));
      t1 = std::min(1.0, std::max(ta, tb));
      if (!(t0 <= t1)) continue;
    }
    const double x0 = p[0] + t0 * dx, x1 = p[0] + t1 * dx;
    xlo = std::min(xlo, std::min(x0, x1));
    xhi = std::max(xhi, std::max(x0, x1));
  }
  if (!(xlo <= xhi)) return false;
  const double slack = region.margin + 1e-10 * size;
  xlo -= slack;
  xhi += slack;
  return true;
}

// Triangles of a polygon that is not exactly planar (often: planar up to rounding, e.g. after a
// rotation). Convex polygons get a fan from their first corner; non-convex ones are ear-clipped
// in the projection along the dominant axis of n, the loop's Newell normal (along_normal: along
// n itself), which keeps every triangle oriented like the polygon (a fan would fold over a
// reflex corner and invert planes): the best-shaped ear first up to 128 corners, the first ear
// found above. What is left when no ear is found (self-overlapping input) or the work budget is
// spent is fanned, and *gave_up says so. Then, up to 128 corners, inward folds are flipped
// outward where they can be. ("Convex" and the ears are judged in the same projection.)
std::vector<std::array<uint32_t, 3>> triangulate_polygon(const std::vector<double>& pts, const uint32_t* loop, size_t k,
                                                         const std::array<double, 3>& n, int exact_shift,
                                                         bool along_normal, bool* gave_up) {
  if (gave_up) *gave_up = false;
  std::vector<std::array<uint32_t, 3>> out;
  out.reserve(k - 2);
  auto P = [&](uint32_t v) { return &pts[3 * size_t(v)]; };
  int axis = 0;
  for (int c = 1; c < 3; ++c)
    if (std::fabs(n[c]) > std::fabs(n[axis])) axis = c;
  const int u = (axis + 1) % 3, w = (axis + 2) % 3;
  const double orient = n[axis] >= 0 ? 1 : -1;  // (u, w) is counter-clockwise when n[axis] > 0
  // The projection along n itself, for along_normal: the plane coordinates (p - o) . e1 and
  // (p - o) . e2 with e1, e2, n / |n| orthonormal and right-handed (counter-clockwise is positive).
  double e1[3], e2[3];
  const double* o = P(loop[0]);
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  along_normal = along_normal && len > 0 && std::isfinite(len);
  if (along_normal) {
    const double nn[3] = {n[0] / len, n[1] / len, n[2] / len};
    int least = 0;  // e1 = nn x (the axis of nn's smallest part): |e1| >= sqrt(2/3) before scaling
    for (int c = 1; c < 3; ++c)
      if (std::fabs(nn[c]) < std::fabs(nn[least])) least = c;
    const int l1 = (least + 1) % 3, l2 = (least + 2) % 3;
    e1[least] = 0;
    e1[l1] = nn[l2];
    e1[l2] = -nn[l1];
    const double scale = 1 / std::sqrt(e1[l1] * e1[l1] + e1[l2] * e1[l2]);
    for (int c = 0; c < 3; ++c) e1[c] *= scale;
    for (int c = 0; c < 3; ++c) e2[c] = nn[(c + 1) % 3] * e1[(c + 2) % 3] - nn[(c + 2) % 3] * e1[(c + 1) % 3];
  }
  auto plane_xy = [&](uint32_t v, double& x, double& y) {
    const double* p = P(v);
    if (!along_normal) {
      x = p[u];
      y = p[w];
      return;
    }
    const double d[3] = {p[0] - o[0], p[1] - o[1], p[2] - o[2]};
    x = d[0] * e1[0] + d[1] * e1[1] + d[2] * e1[2];
    y = d[0] * e2[0] + d[1] * e2[1] + d[2] * e2[2];
  };
  auto cross = [&](uint32_t a, uint32_t b, uint32_t c) {
    double ax, ay, bx, by, cx, cy;
    plane_xy(a, ax, ay);
    plane_xy(b, bx, by);
    plane_xy(c, cx, cy);
    return (along_normal ? 1 : orient) * ((bx - ax) * (cy - ay) - (by - ay) * (cx - ax));
  };
  auto sq = [&](uint32_t a, uint32_t b) {
    double ax, ay, bx, by;
    plane_xy(a, ax, ay);
    plane_xy(b, bx, by);
    return (bx - ax) * (bx - ax) + (by - ay) * (by - ay);
  };
  std::vector<uint32_t> idx(loop, loop + k);
  // A convex polygon (every corner turns the same way in the projection) keeps the simple rule:
  // a fan from its first corner.
  bool convex = true;
  for (size_t i = 0; i < k && convex; ++i)
    if (cross(loop[(i + k - 1) % k], loop[i], loop[(i + 1) % k]) < 0) convex = false;
  // Where two triangles of the split meet along a diagonal (x, y), the far corner q of the
  // second may lie strictly outside the plane of the first (x, y, p): the surface folds inward,
  // and both planes cut into the solid. A polygon that is non-planar by rounding then loses
  // slivers of rounding size to the kernel, each corner of them a vertex of nearly coplanar
  // planes whose side tests need exact arithmetic. Flipping the diagonal to (p, q) folds it
  // outward; it is done only when both new triangles have clearly positive area in the
  // projection (their planes keep the polygon's orientation). For a convex polygon every corner
  // is extreme in the projection, so the flips reach the outward-folded split (the upper convex
  // hull of the corners): near the polygon the triangles' half-spaces meet in the solid itself.
  // Each flip moves the surface strictly outward, so none is undone; the cap only guards the loop.
  // The side tests are exact and costly on such nearly coplanar corners, and the sweeps meet
  // each diagonal from both of its triangles and again on every later sweep: their results are
  // kept. orient3d(x, y, p, q) = orient3d(y, x, q, p) (two swaps), which is how the other
  // triangle sees the same diagonal.
  std::vector<std::array<uint32_t, 5>> tested;  // x, y, p, q, whether it folds inward
  auto folds_inward = [&](uint32_t x, uint32_t y, uint32_t p, uint32_t q) {
    for (const auto& d : tested)
      if ((d[0] == x && d[1] == y && d[2] == p && d[3] == q) || (d[0] == y && d[1] == x && d[2] == q && d[3] == p))
        return d[4] != 0;
    const bool inward = orient3d(P(x), P(y), P(p), P(q), exact_shift) > 0;
    if (tested.empty()) tested.reserve(4 * k);
    tested.push_back({x, y, p, q, inward});
    return inward;
  };
  auto fold_outward = [&]() {
    if (k > 128) return;
    size_t flips = 0;
    const size_t cap = 4 * k * k;
    bool changed = true;
    while (changed && flips < cap) {
      changed = false;
      for (size_t i = 0; i < out.size() && flips < cap; ++i) {
        for (int e = 0; e < 3; ++e) {
          const uint32_t x = out[i][e], y = out[i][(e + 1) % 3], p = out[i][(e + 2) % 3];
          size_t j = 0;
          int g = 0;
          for (; j < out.size(); ++j) {
            if (j == i) continue;
            for (g = 0; g < 3; ++g)
              if (out[j][g] == y && out[j][(g + 1) % 3] == x) break;
            if (g < 3) break;
          }
          if (j == out.size()) continue;
          const uint32_t q = out[j][(g + 2) % 3];
          if (!folds_inward(x, y, p, q)) continue;
          const double tol = 1e-12 * (sq(x, q) + sq(q, p) + sq(p, x) + sq(q, y) + sq(y, p));
          if (!(cross(x, q, p) > tol && cross(q, y, p) > tol)) continue;
          out[i] = {x, q, p};
          out[j] = {q, y, p};
          ++flips;
          changed = true;
          break;  // this triangle changed: its edges are looked at again on the next sweep
        }
      }
    }
  };
  if (convex) {
    for (size_t i = 1; i + 1 < k; ++i) out.push_back({loop[0], loop[i], loop[i + 1]});
    fold_outward();
    return out;
  }
  // The best-shaped ear first (area over squared edge lengths): a sliver's plane is poorly
  // determined by its points, so slivers are avoided whenever the polygon allows it.
  // Each corner's ear is judged once and again only when it may have changed: when a neighbour
  // is clipped (its triangle changes) or when the corner that blocked it is (the others only
  // lose a corner, which cannot block an ear). Quadratic instead of cubic in the corners, with
  // the same choices.
  constexpr uint32_t kNoBlocker = 0xffffffffu, kUnjudged = 0xfffffffeu;
  std::vector<double> quality;    // per position in idx: the ear's quality, 0 if not an ear
  std::vector<uint32_t> blocker;  // the corner inside the ear, kNoBlocker, or kUnjudged
  auto judge = [&](size_t i) {
    const size_t r = idx.size();
    const uint32_t a = idx[(i + r - 1) % r], b = idx[i], c = idx[(i + 1) % r];
    quality[i] = 0;
    blocker[i] = kNoBlocker;
    const double area2 = cross(a, b, c);
    if (!(area2 > 0)) return;  // reflex or flat corner
    // A corner on or within rounding distance of the ear's border blocks it too (a polygon
    // that is non-planar by rounding has its collinear corners off by an ulp either way).
    const double size2 = sq(a, b) + sq(b, c) + sq(c, a);
    const double tol = -1e-9 * size2;
    for (size_t j = 0; j < r; ++j) {
      const uint32_t q = idx[j];
      if (q == a || q == b || q == c) continue;
      if (cross(a, b, q) >= tol && cross(b, c, q) >= tol && cross(c, a, q) >= tol) {
        blocker[i] = q;
        return;
      }
    }
    quality[i] = area2 / size2;
  };
  if (idx.size() > 3 && k <= 128) {
    quality.assign(k, 0);
    blocker.assign(k, kUnjudged);
  }
  while (idx.size() > 3 && k <= 128) {
    const size_t r = idx.size();
    size_t best = r;
    double best_quality = 0;
    for (size_t i = 0; i < r; ++i) {
      if (blocker[i] == kUnjudged) judge(i);
      if (quality[i] > best_quality) {
        best_quality = quality[i];
        best = i;
      }
    }
    if (best == r) break;
    const uint32_t clipped = idx[best];
    out.push_back({idx[(best + r - 1) % r], clipped, idx[(best + 1) % r]});
    idx.erase(idx.begin() + long(best));
    quality.erase(quality.begin() + long(best));
    blocker.erase(blocker.begin() + long(best));
    const size_t m = r - 1;
    blocker[(best + m - 1) % m] = kUnjudged;  // the neighbours
    blocker[best % m] = kUnjudged;
    for (size_t i = 0; i < m; ++i)
      if (blocker[i] == clipped) blocker[i] = kUnjudged;
  }
  // Larger polygons: the first ear met walking around the loop (stepping back after each ear to
  // the corner before it), with the same ear test, on plane coordinates computed once. The corners
  // that could block an ear are looked up in a grid of cells, over the rows and columns that the
  // region of ear_region reaches (it holds every corner the test can accept, so the answer is the
  // one a scan of every corner gives), unless the ear is too thin for that region or it reaches
  // more cells than corners are left: then every corner is scanned. A work budget bounds
  // pathological loops (kBudgetPerScan); what is left is fanned (gave_up), and the fold check
  // judges the result.
  if (k > 128) {
    std::vector<double> xs(k), ys(k);
    for (size_t t = 0; t < k; ++t) plane_xy(loop[t], xs[t], ys[t]);
    const double sign = along_normal ? 1 : orient;
    auto cr = [&](uint32_t a, uint32_t b, uint32_t c) {
      return sign * ((xs[b] - xs[a]) * (ys[c] - ys[a]) - (ys[b] - ys[a]) * (xs[c] - xs[a]));
    };
    auto sq2 = [&](uint32_t a, uint32_t b) {
      return (xs[b] - xs[a]) * (xs[b] - xs[a]) + (ys[b] - ys[a]) * (ys[b] - ys[a]);
    };
    // The corners left, as a ring of positions in loop.
    std::vector<uint32_t> next(k), prev(k);
    std::vector<char> alive(k, 1);
    for (size_t t = 0; t < k; ++t) {
      next[t] = uint32_t((t + 1) % k);
      prev[t] = uint32_t((t + k - 1) % k);
    }
    const CornerGrid grid(xs, ys);
    std::vector<std::array<size_t, 3>> rows;  // an ear's rows of cells: row, first and last column
    const bool charge_scans = k <= kBudgetPerScan;
    size_t budget = charge_scans ? 8 * k * k : std::min(kEarWorkPerCorner * k, 8 * kBudgetPerScan * kBudgetPerScan);
    size_t r = k;    // corners left
    uint32_t i = 0;  // the corner whose ear is tried next
    while (r > 3 && budget > 0) {
      bool clipped = false;
      for (size_t tries = 0; tries < r && budget > 0 && !clipped; ++tries, i = next[i]) {
        const uint32_t a = prev[i], b = i, c = next[i];
        if (!charge_scans) --budget;  // (a walk over reflex or flat corners is work too)
        const double area2 = cr(a, b, c);
        if (!(area2 > 0)) continue;  // reflex or flat corner
        const double tol = -1e-9 * (sq2(a, b) + sq2(b, c) + sq2(c, a));
        auto blocks = [&](uint32_t q) {
          return loop[q] != loop[a] && loop[q] != loop[b] && loop[q] != loop[c] && cr(a, b, q) >= tol &&
                 cr(b, c, q) >= tol && cr(c, a, q) >= tol;
        };
        bool empty = true;
        size_t work = 1;
        // The region's rows of cells, each cut to the columns the region reaches in it.
        EarRegion region;
        size_t box_cells[4], cells = 0;
        bool use_grid =
            ear_region(xs, ys, a, b, c, tol, area2, region) && grid.cells_of(region.box, box_cells) <= 4 * r;
        if (use_grid) {
          rows.clear();
          for (size_t cy = box_cells[2]; cy <= box_cells[3] && cells <= r; ++cy) {
            double lo, hi, xlo, xhi;
            grid.row_band(cy, lo, hi);
            ++work;
            if (!region_x_range(region, lo, hi, xlo, xhi)) continue;
            const size_t c0 = std::max(box_cells[0], grid.column(xlo)), c1 = std::min(box_cells[1], grid.column(xhi));
            if (c0 > c1) continue;
            rows.push_back({cy, c0, c1});
            cells += c1 - c0 + 1;
          }
          use_grid = cells <= r;
        }
        if (use_grid) {
          for (size_t w = 0; w < rows.size() && empty; ++w)
            for (size_t cx = rows[w][1]; cx <= rows[w][2] && empty; ++cx) {
              const uint32_t* items = grid.items(cx, rows[w][0]);
              const size_t n = grid.count(cx, rows[w][0]);
              work += 1 + n;
              for (size_t j = 0; j < n && empty; ++j)
                if (alive[items[j]] && blocks(items[j])) empty = false;
            }
        } else {
          for (uint32_t q = next[c]; q != a && empty; q = next[q], ++work)
            if (blocks(q)) empty = false;
        }
        budget -= std::min(budget, charge_scans ? r : work);
        if (!empty) continue;
        out.push_back({loop[a], loop[b], loop[c]});
        alive[b] = 0;
        next[a] = c;
        prev[c] = a;
        --r;
        i = a;  // the corner before the ear, whose own ear just changed
        clipped = true;
        break;
      }
      if (!clipped) break;
    }
    idx.clear();
    for (uint32_t t = 0; t < k; ++t)
      if (alive[t]) idx.push_back(loop[t]);
  }
  if (gave_up) *gave_up = idx.size() > 3;
  for (size_t i = 1; i + 1 < idx.size(); ++i) out.push_back({idx[0], idx[i], idx[i + 1]});
  fold_outward();
  return out;
}

// The number of trailing zero bits of a non-zero 64-bit integer.
inline int count_trailing_zeros(uint64_t x) {
#if defined(__GNUC__) || defined(__clang__)
  return __builtin_ctzll(x);
#else
  int n = 0;
  while (!(x & 1)) {
    x >>= 1;
    ++n;
  }
  return n;
#endif
}

// The exponent of the lowest set bit of a finite non-zero double, read from its bits:
// x = mant 2^(biased - 1075), with the implicit leading bit for normal numbers, and
// x = mant 2^-1074 for subnormal ones.
int lowest_bit_exponent(double x) {
  uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  uint64_t mant = bits & ((uint64_t(1) << 52) - 1);
  int biased = int((bits >> 52) & 0x7ff);
  if (biased)
    mant |= uint64_t(1) << 52;
  else
    biased = 1;
  return biased - 1075 + count_trailing_zeros(mant);  // mant != 0 for x != 0
}

// Whether two used vertices have the same position (coordinates compared with ==, so -0 and
// +0 are one position): a hash table of the used vertices, expected linear time. The table is
// larger than the caches for big meshes, so slots are hashed a block ahead and prefetched.
// The same pass takes the bounding box of the used vertices, in id order (complete when the
// answer is false).
bool has_shared_position(const std::vector<double>& pts, const std::vector<char>& used, size_t num_used, double lo3[3],
                         double hi3[3]) {
  size_t bits = 1;
  while ((size_t(1) << bits) < 2 * num_used) ++bits;  // load factor <= 1/2
  const uint32_t kEmpty = 0xffffffffu;
  std::vector<uint32_t> table_store(size_t(1) << bits, kEmpty);
  uint32_t* table = table_store.data();
  const size_t mask = table_store.size() - 1;
  const double* P = pts.data();
  for (int k = 0; k < 3; ++k) {
    lo3[k] = INFINITY;
    hi3[k] = -INFINITY;
  }
  auto home = [&](uint32_t v) {
    const double* p = P + 3 * size_t(v);
    uint64_t h = 0;
    for (int k = 0; k < 3; ++k) {
      lo3[k] = std::min(lo3[k], p[k]);
      hi3[k] = std::max(hi3[k], p[k]);
      const double x = p[k] + 0.0;  // -0 + 0 = +0: equal coordinates hash alike
      uint64_t b;
      std::memcpy(&b, &x, sizeof b);
      h = (h ^ b ^ (b >> 29)) * 0x9e3779b97f4a7c15ull;  // the high bits depend on every input bit
    }
    return size_t(h >> (64 - bits));
  };
  constexpr size_t kBlock = 16;
  uint32_t ids[kBlock];
  size_t slots[kBlock];
  const char* us = used.data();
  const size_t nv = used.size();
  for (size_t v0 = 0; v0 < nv;) {
    size_t n = 0;
    for (; v0 < nv && n < kBlock; ++v0) {
      if (!us[v0]) continue;
      ids[n] = uint32_t(v0);
      slots[n] = home(uint32_t(v0));
      prefetch(table + slots[n]);
      ++n;
    }
    for (size_t j = 0; j < n; ++j) {
      const double* p = P + 3 * size_t(ids[j]);
      for (size_t slot = slots[j];; slot = (slot + 1) & mask) {
        if (table[slot] == kEmpty) {
          table[slot] = ids[j];
          break;
        }
        const double* q = P + 3 * size_t(table[slot]);
        if (p[0] == q[0] && p[1] == q[1] && p[2] == q[2]) return true;
      }
    }
  }
  return false;
}

// The pair reported when used vertices share a position: the two lowest ids at the
// lexicographically smallest shared position (a sort, run only once a pair is known to exist).
std::array<uint32_t, 2> first_shared_position(const std::vector<double>& pts, const std::vector<char>& used) {
  std::vector<uint32_t> order;
  for (uint32_t v = 0; v < used.size(); ++v)
    if (used[v]) order.push_back(v);
  auto at = [&](uint32_t v) { return &pts[3 * size_t(v)]; };
  std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
    const double *p = at(a), *q = at(b);
    return p[0] != q[0] ? p[0] < q[0] : (p[1] != q[1] ? p[1] < q[1] : (p[2] != q[2] ? p[2] < q[2] : a < b));
  });
  for (size_t i = 1; i < order.size(); ++i) {
    const double *p = at(order[i - 1]), *q = at(order[i]);
    if (p[0] == q[0] && p[1] == q[1] && p[2] == q[2]) return {order[i - 1], order[i]};
  }
  return {0, 0};  // not reached: called only when a shared position exists
}

// Sign of the signed area of the polygon loop[0..k) projected onto coordinates (i, j): the sum of
// its fan triangles' 2D orientations about loop[0] (for k = 3, the triangle's orientation).
// Exact: a double filter, then expansions over the coordinates times 2^shift (exact, and clear of
// underflow like the other exact predicates).
int projected_area_sign(const std::vector<double>& pts, const uint32_t* loop, size_t k, int i, int j, int shift) {
  auto at = [&](size_t t, int c) { return pts[3 * size_t(loop[t]) + c]; };
  double sum = 0, magnitude = 0;
  for (size_t t = 1; t + 1 < k; ++t) {
    const double ux = at(t, i) - at(0, i), uy = at(t, j) - at(0, j);
    const double vx = at(t + 1, i) - at(0, i), vy = at(t + 1, j) - at(0, j);
    const double p = ux * vy, q = uy * vx;
    sum += p - q;
    magnitude += std::fabs(p) + std::fabs(q);
  }
  // Each term is off by at most ~4 eps of its products (differences, products, subtraction), the
  // sum by k eps of the magnitudes more; the factor 2 and the floor keep clear of the edge cases.
  const double bound = 2 * (double(k) + 8) * exact::kEps * magnitude + 1e-300;
  if (sum > bound) return 1;
  if (sum < -bound) return -1;
  using exact::Expansion;
  auto scaled = [&](size_t t, int c) { return std::ldexp(at(t, c), shift); };
  Expansion total;
  for (size_t t = 1; t + 1 < k; ++t) {
    const Expansion ux = Expansion::difference(scaled(t, i), scaled(0, i)),
                    uy = Expansion::difference(scaled(t, j), scaled(0, j));
    const Expansion vx = Expansion::difference(scaled(t + 1, i), scaled(0, i)),
                    vy = Expansion::difference(scaled(t + 1, j), scaled(0, j));
    total = total + (ux * vy - uy * vx);
  }
  return total.sign();
}

// Why the split of a non-planar polygon would give a plane facing into the solid, or nullptr.
// Every triangle of the split must face like the loop's area vector n (its Newell normal), or
// stand edge-on to it: the triangles' area vectors add up to n, so one clearly against it means
// the loop crosses itself or turns back there (a bowtie, a fold), and that triangle's plane faces
// into the solid. Compared along n itself, not in a coordinate projection: a simple loop far from
// planar may cross itself seen along a coordinate axis. The dot products are in double with an
// error bound, so only a triangle certainly against n refuses the face. The planar counterpart
// is the corner test in prepare_mesh.
const char* split_folds_over(const std::vector<double>& pts, const std::array<double, 3>& n,
                             const std::vector<std::array<uint32_t, 3>>& tris) {
  if (n[0] == 0 && n[1] == 0 && n[2] == 0) return "its loop encloses no area";
  for (const auto& tri : tris) {
    const double *a = &pts[3 * size_t(tri[0])], *b = &pts[3 * size_t(tri[1])], *c = &pts[3 * size_t(tri[2])];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, w[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    double dot = 0, magnitude = 0;
    for (int x = 0; x < 3; ++x) {
      const int y = (x + 1) % 3, z = (x + 2) % 3;
      const double p = u[y] * w[z], q = u[z] * w[y];
      dot += (p - q) * n[x];
      magnitude += (std::fabs(p) + std::fabs(q)) * std::fabs(n[x]);
    }
    // Differences, products, the subtraction and the sum: each off by a few eps of the magnitudes.
    if (dot < -16 * exact::kEps * magnitude)
      return "a triangle of its split faces against the loop's area vector (the loop crosses itself or turns back)";
  }
  return nullptr;
}

// Coordinates times a factor, read as a range: a vector assigned from it is filled once (a
// resize would first write zeros over it).
struct ScaledCoordinates {
  using iterator_category = std::random_access_iterator_tag;
  using value_type = double;
  using difference_type = std::ptrdiff_t;
  using pointer = const double*;
  using reference = double;
  const double* at;
  double factor;
  double operator*() const { return *at * factor; }
  ScaledCoordinates& operator++() {
    ++at;
    return *this;
  }
  ScaledCoordinates operator++(int) {
    ScaledCoordinates old = *this;
    ++at;
    return old;
  }
  difference_type operator-(const ScaledCoordinates& o) const { return at - o.at; }
  bool operator==(const ScaledCoordinates& o) const { return at == o.at; }
  bool operator!=(const ScaledCoordinates& o) const { return at != o.at; }
};

bool lex_less(const double* a, const double* b) {
  return a[0] != b[0] ? a[0] < b[0] : (a[1] != b[1] ? a[1] < b[1] : a[2] < b[2]);
}

// The bits of the largest magnitude among x[0..n) (top) and of the smallest non-zero one minus
// one (low; INT64_MAX when every value is zero), in one branch-free pass: without the sign bit,
// doubles order like their bit patterns, and every NaN or infinity lies at or above infinity.
// The bits are below 2^63, so signed extrema order them: SIMD units compare signed 64-bit
// integers (SSE4.2, AVX2, wasm's i64x2), not unsigned ones. A zero's magnitude minus one wraps
// and, masked to 63 bits, becomes the largest value. Four chains: the extrema do not wait on
// each other.
KERGEN_MULTIVERSION
void magnitude_extrema(const double* x, size_t n, uint64_t& top_bits, int64_t& low_bits) {
  constexpr uint64_t kAbs = ~(uint64_t(1) << 63);
  int64_t top[4] = {0, 0, 0, 0}, low[4] = {INT64_MAX, INT64_MAX, INT64_MAX, INT64_MAX};
  auto take = [](const double* p, int64_t& t, int64_t& l) KERGEN_INLINE {
    uint64_t b;
    std::memcpy(&b, p, sizeof b);
    t = std::max(t, int64_t(b & kAbs));
    l = std::min(l, int64_t(((b & kAbs) - 1) & kAbs));
  };
  size_t i = 0;
  for (; i + 4 <= n; i += 4)
    for (int j = 0; j < 4; ++j) take(x + i + j, top[j], low[j]);
  for (; i < n; ++i) take(x + i, top[0], low[0]);
  top_bits = uint64_t(std::max(std::max(top[0], top[1]), std::max(top[2], top[3])));
  low_bits = std::min(std::min(low[0], low[1]), std::min(low[2], low[3]));
}

}  // namespace

Warning unused_vertices_warning(size_t count) {
  return {Warning::Kind::UnusedVertices, count, std::to_string(count) + " vertices are not used by any face"};
}

PreparedMesh prepare_mesh(const MeshView& mesh, const Options& options, bool allow_shells) {
  PreparedMesh m;
  const size_t nv = mesh.num_vertices;
  const size_t nf = mesh.face_sizes ? mesh.num_faces : mesh.num_indices / 3;
  m.input_faces = nf;

  if ((nv > 0 && !mesh.positions) || (mesh.num_indices > 0 && !mesh.indices) ||
      (mesh.face_sizes == nullptr && mesh.num_faces > 0 && mesh.num_faces != nf))
    return fail(m, Error::InvalidArgument, "null array with a non-zero size, or num_faces given without face_sizes");
  if (nv == 0) return fail(m, Error::EmptyInput, "the mesh has no vertices");
  if (nf == 0) return fail(m, Error::EmptyInput, "the mesh has no faces");
  if (nf > options.max_faces || nv > options.max_vertices) {
    std::ostringstream s;
    s << "the mesh has " << nf << " faces and " << nv << " vertices; the limit is " << options.max_faces
      << " faces and " << options.max_vertices << " vertices (Options::max_faces / Options::max_vertices)";
    return fail(m, Error::TooLarge, s.str());
  }
  if (!mesh.face_sizes && mesh.num_indices % 3 != 0)
    return fail(m, Error::InvalidArgument,
                "triangle indices: the count " + std::to_string(mesh.num_indices) + " is not a multiple of 3");

  // Face sizes must add up. (No offsets are stored: the faces are walked in order below.)
  if (mesh.face_sizes) {
    size_t total = 0;
    for (size_t f = 0; f < nf; ++f) {
      size_t k = mesh.face_sizes[f];
      if (k < 3) {
        std::ostringstream s;
        s << "face " << f << " has " << k << " vertices; a face needs at least 3";
        return fail(m, Error::FaceTooSmall, s.str());
      }
      total += k;
      if (total > mesh.num_indices)
        return fail(m, Error::InvalidArgument, "face sizes add up to more than the number of indices");
    }
    if (total != mesh.num_indices)
      return fail(m, Error::InvalidArgument,
                  "face sizes add up to " + std::to_string(total) + " but " + std::to_string(mesh.num_indices) +
                      " indices were given");
  }
  auto face_size = [&](size_t f) -> size_t { return mesh.face_sizes ? mesh.face_sizes[f] : 3; };

  // Finite coordinates, the largest magnitude (for the scale below) and the smallest non-zero
  // one (for the exact shift below) in one pass (magnitude_extrema); the culprit is looked for
  // only if needed.
  double maxabs = 0, min_nonzero_abs = INFINITY;
  {
    const double* pos = mesh.positions;
    uint64_t top_bits;
    int64_t low_bits;
    magnitude_extrema(pos, 3 * nv, top_bits, low_bits);
    if (top_bits >= 0x7ff0000000000000ull) {  // (the bits of infinity)
      size_t i = 0;
      while (std::isfinite(pos[i])) ++i;
      std::ostringstream s;
      s << "vertex " << i / 3 << " has a non-finite coordinate (" << pos[i] << ")";
      return fail(m, Error::NonFiniteCoordinate, s.str());
    }
    std::memcpy(&maxabs, &top_bits, sizeof maxabs);
    if (low_bits != INT64_MAX) {
      const uint64_t min_bits = uint64_t(low_bits) + 1;
      std::memcpy(&min_nonzero_abs, &min_bits, sizeof min_nonzero_abs);
    }
  }
  // Indices in range: the largest one first (a branch-free pass), the culprit only if needed.
  uint32_t max_index = 0;
  for (size_t i = 0; i < mesh.num_indices; ++i) max_index = std::max(max_index, mesh.indices[i]);
  if (max_index >= nv) {
    size_t i = 0;
    while (mesh.indices[i] < nv) ++i;
    size_t f = 0;
    for (size_t end = face_size(0); end <= i; end += face_size(++f)) {}
    std::ostringstream s;
    s << "face " << f << " refers to vertex " << mesh.indices[i] << " but the mesh has " << nv << " vertices";
    return fail(m, Error::IndexOutOfRange, s.str());
  }

  // Scale by a power of two (exact) so that coordinates are below 1 in magnitude: keeps the
  // exact arithmetic away from overflow and underflow whatever the input's units.
  int ex = 0;
  if (maxabs > 0) std::frexp(maxabs, &ex);
  // (As an exponent: for an input of subnormal numbers only, 2^-ex itself is not a double.)
  m.scale_exp = -ex;
  // The exact predicates are polynomials of degree <= 9 in the coordinates. Expansion
  // arithmetic is exact only while no bit of a product falls below 2^-1074 (underflow) and no
  // magnitude reaches ~2^996 (the splitter overflows): with coordinates below 1 (scaled above),
  // the lowest set bit L of any coordinate must satisfy 9 (L + shift) >= -1074 + margin and
  // 9 shift + 10 < 996.
  {
    // When 2^scale_exp is a double, multiplying by it rounds exactly like ldexp (both give the
    // correctly rounded x 2^scale_exp, subnormal results included) at a fraction of the cost;
    // otherwise (inputs of subnormal numbers only) ldexp scales each coordinate.
    const bool exact_factor = m.scale_exp >= -1074 && m.scale_exp <= 1023;
    const double factor = exact_factor ? std::ldexp(1.0, m.scale_exp) : 0;
    const int kLowestAllowed = -112, kMaxShift = 109;
    int lowest = 0;
    // The lowest set bit of a coordinate lies at most 52 bits below its leading one: when every
    // non-zero coordinate is at least 2^(kLowestAllowed + 52), no lowest bit needs reading.
    if (exact_factor && min_nonzero_abs * factor >= std::ldexp(1.0, kLowestAllowed + 52)) {
      m.points = std::vector<double>(ScaledCoordinates{mesh.positions, factor},
                                     ScaledCoordinates{mesh.positions + 3 * nv, factor});
    } else {
      m.points.resize(3 * nv);
      for (size_t i = 0; i < 3 * nv; ++i) {
        const double x = exact_factor ? mesh.positions[i] * factor : m.to_scaled(mesh.positions[i]);
        m.points[i] = x;
        if (x != 0) lowest = std::min(lowest, lowest_bit_exponent(x));
      }
    }
    int shift = std::max(0, kLowestAllowed - lowest);
    if (shift > kMaxShift) {
      std::ostringstream s;
      s << "coordinates span about " << int(-lowest * 0.30103) << " decimal orders of magnitude (largest |x| " << maxabs
        << ", finest bit 2^" << lowest + ex << "); exact evaluation supports about "
        << int((kMaxShift - kLowestAllowed) * 0.30103) << " — snap tiny coordinates to 0 or rescale";
      return fail(m, Error::CoordinateRange, s.str());
    }
    m.exact_shift = shift;
  }

  // Faces without repeated consecutive vertices; faces left with < 3 distinct vertices carry
  // no area and no edges of their own (a -> b -> a pairs cancel), so they are dropped here.
  // The same pass marks the used vertices and counts the edge uses per bucket of the edge
  // check below. (Raw pointers in the loops: the stores through char would otherwise make the
  // compiler reload every vector's pointers after each one.)
  RawVector<uint32_t> clean(mesh.num_indices), clean_offsets(nf + 1);  // (written in full below)
  std::vector<char> used(nv, 0);
  // Edge uses are bucketed by their lower vertex id and direction: bucket 2 lo + 1 holds the
  // uses running up from lo (lo -> hi, hi > lo), bucket 2 lo those running down to lo.
  // bucket[b + 1]: size of bucket b, then its end, then (after the fill) its start.
  std::vector<uint32_t> bucket(2 * nv + 2, 0);
  size_t cf = 0;  // clean faces
  // The input face of each clean face, from the first face dropped on (before it: the identity).
  std::vector<uint32_t> clean_source;
  bool clean_renumbered = false;
  {
    const uint32_t* in = mesh.indices;
    uint32_t* cl = clean.data();
    uint32_t* off = clean_offsets.data();
    off[0] = 0;
    char* us = used.data();
    uint32_t* count = bucket.data() + 1;
    // (bucket 2 lo + 1 < 2 hi, bucket 2 lo < 2 hi + 1: the smaller is the use's bucket)
    auto count_use = [count](uint32_t u, uint32_t v) { count[std::min(2 * size_t(u) + 1, 2 * size_t(v))]++; };
    size_t n = 0, dropped = 0;  // clean entries so far, faces dropped
    size_t f = 0;
    if (!mesh.face_sizes) {
      // The usual leading run of a triangle mesh: face f is at 3 f (the offsets are written after).
      for (; f < nf; ++f, in += 3) {
        const uint32_t a = in[0], b = in[1], c = in[2];
        if (a == b || b == c || c == a) break;
        cl[3 * f] = a;
        cl[3 * f + 1] = b;
        cl[3 * f + 2] = c;
        us[a] = us[b] = us[c] = 1;
        count_use(a, b);
        count_use(b, c);
        count_use(c, a);
      }
      for (size_t g = 1; g <= f; ++g) off[g] = uint32_t(3 * g);
      n = 3 * f;
      cf = f;
    }
    for (; f < nf; ++f) {
      const size_t begin = n, k = mesh.face_sizes ? mesh.face_sizes[f] : 3;
      if (k == 3 && in[0] != in[1] && in[1] != in[2] && in[2] != in[0]) {  // the usual case
        const uint32_t a = in[0], b = in[1], c = in[2];
        cl[n] = a;
        cl[n + 1] = b;
        cl[n + 2] = c;
        n += 3;
        in += 3;
        off[++cf] = uint32_t(n);
        if (clean_renumbered) clean_source.push_back(uint32_t(f));
        us[a] = us[b] = us[c] = 1;
        count_use(a, b);
        count_use(b, c);
        count_use(c, a);
        continue;
      }
      for (size_t i = 0; i < k; ++i)
        if (n == begin || cl[n - 1] != in[i]) cl[n++] = in[i];
      while (n - begin > 1 && cl[n - 1] == cl[begin]) --n;
      in += k;
      if (n - begin < 3) {
        n = begin;
        ++dropped;
        if (!clean_renumbered) {
          clean_renumbered = true;
          clean_source.resize(cf);
          std::iota(clean_source.begin(), clean_source.end(), 0u);
        }
        continue;
      }
      off[++cf] = uint32_t(n);
      if (clean_renumbered) clean_source.push_back(uint32_t(f));
      for (size_t i = begin; i < n; ++i) {
        const uint32_t u = cl[i], v = cl[i + 1 < n ? i + 1 : begin];
        us[u] = 1;
        count_use(u, v);
      }
    }
    clean.resize(n);
    clean_offsets.resize(cf + 1);
    m.dropped_faces += dropped;
  }
  if (cf == 0) return fail(m, Error::DegenerateInput, "every face has fewer than 3 distinct vertices");

  // Edge check (counting sort into the buckets, no hashing and no comparison sort). The uses of
  // the edges of one lower vertex are tallied per upper vertex, then each edge is judged once:
  // on a closed, consistently oriented 2-manifold every edge has one use each way, and its two
  // faces are a pair.
  uint32_t total_uses = 0;  // (the running sum stays in a register)
  for (size_t b = 1; b <= 2 * nv; ++b) bucket[b] = total_uses += bucket[b];
  bucket[2 * nv + 1] = total_uses;
  // Faulty edges are counted; the one named is the smallest (lower id, upper id).
  size_t open = 0, nonmanifold = 0, inconsistent = 0;
  uint64_t open_ex = UINT64_MAX, nonmanifold_ex = UINT64_MAX, inconsistent_ex = UINT64_MAX;
  auto note = [](size_t& count, uint64_t& example, uint64_t key) {
    ++count;
    example = std::min(example, key);
  };
  // Connected pieces = faces - successful unions (no pass over the classes afterwards).
  UnionFind components(cf);
  size_t unions = 0;
  // Pairs of faces sharing an edge, by lower vertex id, then in the order of the faces using
  // the edge upwards; each pair lists its lower face first. At most one pair per two uses;
  // written through a pointer (push_back went through a stack copy, a store-forwarding stall).
  RawVector<std::array<uint32_t, 2>> face_pairs((size_t(total_uses) + 1) / 2);
  {
    // A use is stored as its upper vertex id and its face, in two arrays indexed alike. No
    // fresh memory is taken for them (first touches of fresh pages are costly): the faces go
    // into the pairs' storage, which holds one face per use, and the upper ids into the
    // representatives' storage (written after the check) when it holds one id per use, which
    // is when every face is a triangle. The pairs written while a lower vertex's uses are
    // judged end before the uses not read yet (at most one pair per two uses, and each lower
    // vertex's faces are all read, by the tally, before its first pair is written).
    static_assert(sizeof(std::array<uint32_t, 3>) == 3 * sizeof(uint32_t), "packed representatives");
    static_assert(sizeof(std::array<uint32_t, 2>) == 2 * sizeof(uint32_t), "packed pairs");
    RawVector<uint32_t> upper_store;
    uint32_t* upper;
    if (total_uses == 3 * cf) {
      m.rep.resize(cf);
      upper = reinterpret_cast<uint32_t*>(m.rep.data());
    } else {
      upper_store.resize(total_uses);
      upper = upper_store.data();
    }
    uint32_t* use_face = reinterpret_cast<uint32_t*>(face_pairs.data());
    {
      // Filled backwards, each use at its bucket's end moved down by one: the buckets keep the
      // uses in face order, and bucket[b + 1] ends at the start of bucket b (no separate cursor
      // array). Then bucket b is [bucket[b + 1], bucket[b + 2]).
      const uint32_t* cl = clean.data();
      const uint32_t* off = clean_offsets.data();
      uint32_t* cursor = bucket.data() + 1;
      auto put = [&](uint32_t u, uint32_t v, uint32_t f) {
        const uint32_t slot = --cursor[std::min(2 * size_t(u) + 1, 2 * size_t(v))];
        upper[slot] = std::max(u, v);
        use_face[slot] = f;
      };
      if (total_uses == 3 * cf) {
        for (size_t f = cf; f-- > 0;) {
          const uint32_t a = cl[3 * f], b = cl[3 * f + 1], c = cl[3 * f + 2];
          put(c, a, uint32_t(f));
          put(b, c, uint32_t(f));
          put(a, b, uint32_t(f));
        }
      } else {
        for (size_t f = cf; f-- > 0;) {
          const size_t b = off[f], e = off[f + 1];
          for (size_t i = e; i-- > b;) put(cl[i], cl[i + 1 < e ? i + 1 : b], uint32_t(f));
        }
      }
    }
    struct Tally {
      uint32_t up = 0, down = 0, up_face = 0, down_face = 0;
    };
    std::vector<Tally> tally_store(nv);  // per upper vertex id; all zero between lower vertices
    Tally* tally = tally_store.data();
    uint32_t* parent = components.parent.data();
    // (Nine finds in ten end within one step, about half of them at once: both cases are
    // taken without a branch on which, which mispredicted often.)
    auto find = [parent](uint32_t x) {
      const uint32_t up = parent[x], up2 = parent[up];
      if (up2 == up) return up;
      x = up;
      while (parent[x] != x) x = parent[x] = parent[parent[x]];
      return x;
    };
    std::array<uint32_t, 2>* pair_out = face_pairs.data();
    const uint32_t* start = bucket.data() + 1;
    for (size_t lo = 0; lo < nv; ++lo) {
      const size_t down_begin = start[2 * lo], up_begin = start[2 * lo + 1], end = start[2 * lo + 2];
      for (size_t j = down_begin; j != up_begin; ++j) {
        Tally& t = tally[upper[j]];
        ++t.down;
        t.down_face = use_face[j];
      }
      // (the smaller root wins, as in UnionFind::unite)
      auto unite = [&](uint32_t f0, uint32_t f1) KERGEN_INLINE {
        const uint32_t r0 = find(f0), r1 = find(f1);
        if (r0 != r1) {
          parent[std::max(r0, r1)] = std::min(r0, r1);
          ++unions;
        }
      };
      // The upward uses are paired as they are tallied, tentatively (a later use of the same edge
      // may spoil a pair). When each upward use made a pair and each downward use is in one,
      // every edge of lo has one use each way, and the pairs are the ones judged below, in the
      // same order: they stand, and only the tallies are cleared. (A pair never overwrites a
      // use not read yet: lo's pairs number at most its downward uses and its upward uses read.)
      const size_t downs = up_begin - down_begin, ups = end - up_begin;
      std::array<uint32_t, 2>* const pairs_before = pair_out;
      for (size_t j = up_begin; j != end; ++j) {
        Tally& t = tally[upper[j]];
        ++t.up;
        t.up_face = use_face[j];
        if (t.up == 1 && t.down == 1) {
          (*pair_out)[0] = std::min(t.up_face, t.down_face);
          (*pair_out)[1] = std::max(t.up_face, t.down_face);
          ++pair_out;
        }
      }
      if (ups == downs && pair_out == pairs_before + ups) {
        for (size_t j = up_begin; j != end; ++j) {
          tally[upper[j]] = Tally{};
          const auto& pair = pairs_before[j - up_begin];
          unite(pair[0], pair[1]);
        }
        continue;
      }
      pair_out = pairs_before;
      // Judged at its first upward use, or first downward use if it has none; then cleared.
      auto judge = [&](uint32_t hi) KERGEN_INLINE {
        Tally& t = tally[hi];
        if (t.up == 1 && t.down == 1) {
          const uint32_t f0 = std::min(t.up_face, t.down_face), f1 = std::max(t.up_face, t.down_face);
          (*pair_out)[0] = f0;
          (*pair_out)[1] = f1;
          ++pair_out;
          unite(f0, f1);
        } else if (t.up + t.down > 0) {  // else judged already
          const uint64_t key = uint64_t(lo) << 32 | hi;
          const size_t n = size_t(t.up) + t.down;
          if (n == 1)
            note(open, open_ex, key);
          else if (n > 2)
            note(nonmanifold, nonmanifold_ex, key);
          else
            note(inconsistent, inconsistent_ex, key);  // two uses the same way
        }
        t = Tally{};
      };
      for (size_t j = up_begin; j != end; ++j) judge(upper[j]);
      // (as many pairs as downward uses: each pair took one, all are judged and cleared)
      if (size_t(pair_out - pairs_before) == downs) continue;
      for (size_t j = down_begin; j != up_begin; ++j) judge(upper[j]);
    }
    face_pairs.resize(size_t(pair_out - face_pairs.data()));
  }
  auto edge_name = [](uint64_t k) {
    return "(" + std::to_string(uint32_t(k >> 32)) + ", " + std::to_string(uint32_t(k & 0xffffffffu)) + ")";
  };
  if (nonmanifold) {
    return fail(m, Error::NonManifoldEdge,
                std::to_string(nonmanifold) + " edge(s) are shared by more than two faces, e.g. edge " +
                    edge_name(nonmanifold_ex) + " (repeated faces? Options::repair removes them)");
  }
  if (inconsistent) {
    return fail(m, Error::InconsistentOrientation,
                std::to_string(inconsistent) +
                    " edge(s) are traversed in the same direction by both of their faces (inconsistent orientation), "
                    "e.g. edge " +
                    edge_name(inconsistent_ex));
  }
  if (open && !options.allow_open) {
    return fail(m, Error::OpenMesh,
                "the mesh is open: " + std::to_string(open) + " edge(s) belong to one face only, e.g. edge " +
                    edge_name(open_ex) +
                    " (Options::weld merges nearly coincident vertices, Options::repair also splits T-junctions; "
                    "Options::allow_open accepts open meshes)");
  }
  m.boundary_edges = open;
  // Faces joined by boundary edges only are joined through vertices for the component count.
  {
    if (open) {
      std::vector<uint32_t> first_face(nv, 0xffffffffu);
      for (size_t f = 0; f < cf; ++f)
        for (size_t i = clean_offsets[f]; i < clean_offsets[f + 1]; ++i) {
          uint32_t v = clean[i];
          if (first_face[v] == 0xffffffffu)
            first_face[v] = uint32_t(f);
          else
            unions += components.unite(first_face[v], uint32_t(f));
        }
    }
    const size_t pieces = cf - unions;
    m.shells = pieces;
    // Several closed pieces are the caller's to judge (shells.h) when it says so; an open one is
    // refused as before.
    if (pieces > 1 && (open || !allow_shells)) {
      return fail(m, Error::MultipleComponents,
                  "the mesh has " + std::to_string(pieces) +
                      " separate pieces; the kernel is defined for one closed surface (a triangle soup? Options::weld "
                      "merges its corners)");
    }
  }
  double lo3[3], hi3[3];  // bounding box of the used vertices, taken with the check below
  {
    const size_t unused = nv - size_t(std::count(used.begin(), used.end(), 1));
    if (unused) m.warnings.push_back(unused_vertices_warning(unused));
    // Two distinct vertices of a closed surface at one position: the surface touches itself
    // there (it is not embedded), and the intersection of its face half-spaces is then not its
    // kernel — refused rather than answered wrongly.
    if (has_shared_position(m.points, used, nv - unused, lo3, hi3)) {
      const auto pair = first_shared_position(m.points, used);
      return fail(m, Error::NonManifoldEdge,
                  "vertices " + std::to_string(pair[0]) + " and " + std::to_string(pair[1]) +
                      " have the same position: the surface touches itself there (weld them, or separate the pieces)");
    }
  }

  // Bounding box of the used vertices. It is defined as if taken over every use in loop order:
  // ties keep the held bound, so a zero bound has the sign of the first zero met. Over the used
  // vertices in id order the values are the same; only a zero bound may differ (in sign). All
  // values on that side are then >= 0 (<= 0 for a maximum), so the bound in loop order is the
  // first zero coordinate met in loop order: it is looked up there.
  {
    const double* pts = m.points.data();
    bool zero[3];
    int zeros = 0;
    for (int k = 0; k < 3; ++k) zeros += zero[k] = lo3[k] == 0 || hi3[k] == 0;
    for (size_t i = 0; i < clean.size() && zeros > 0; ++i)
      for (int k = 0; k < 3; ++k) {
        const double x = pts[3 * size_t(clean[i]) + k];
        if (zero[k] && x == 0) {
          if (lo3[k] == 0) lo3[k] = x;
          if (hi3[k] == 0) hi3[k] = x;
          zero[k] = false;
          --zeros;
        }
      }
    for (int k = 0; k < 3; ++k) {
      m.bbox_min[k] = lo3[k];
      m.bbox_max[k] = hi3[k];
    }
  }

  // Enclosed volume (double; relative to the box centre for accuracy).
  double c[3], ext = 0;
  for (int k = 0; k < 3; ++k) {
    c[k] = 0.5 * (m.bbox_min[k] + m.bbox_max[k]);
    ext = std::max(ext, m.bbox_max[k] - m.bbox_min[k]);
  }
  // Six times the signed volume of the tetrahedron (c, p0, p1, p2).
  auto vol6_about_centre = [&](uint32_t i0, uint32_t i1, uint32_t i2) KERGEN_INLINE {
    const double *p0 = &m.points[3 * size_t(i0)], *p1 = &m.points[3 * size_t(i1)], *p2 = &m.points[3 * size_t(i2)];
    double a[3], bb[3], cc[3];
    for (int k = 0; k < 3; ++k) {
      a[k] = p0[k] - c[k];
      bb[k] = p1[k] - c[k];
      cc[k] = p2[k] - c[k];
    }
    return a[0] * (bb[1] * cc[2] - bb[2] * cc[1]) - a[1] * (bb[0] * cc[2] - bb[2] * cc[0]) +
           a[2] * (bb[0] * cc[1] - bb[1] * cc[0]);
  };
  // The usual leading run of the plane faces below is taken in the same pass (the points are
  // read once): triangles that a float filter certifies as non-degenerate are kept whole with
  // themselves as representatives, written in place (turned over below on a flip; the filter
  // only shortcuts the exact test, so the order of the corners it sees does not matter).
  double vol6 = 0, vol6_abs = 0;
  m.rep.resize(cf);
  size_t first_general = 0;  // where the leading run ends
  {
    std::array<uint32_t, 3>* rep_out = m.rep.data();
    const uint32_t* cl = clean.data();
    const uint32_t* off = clean_offsets.data();
    const double* pts = m.points.data();
    // The volume term of a triangle, and whether it extends the leading run.
    auto take_triangle = [&](size_t f, uint32_t i0, uint32_t i1, uint32_t i2) KERGEN_INLINE {
      const double d = vol6_about_centre(i0, i1, i2);
      vol6 += d;
      vol6_abs += std::fabs(d);
      if (!certainly_not_collinear(pts + 3 * size_t(i0), pts + 3 * size_t(i1), pts + 3 * size_t(i2))) return false;
      rep_out[f] = {i0, i1, i2};
      return true;
    };
    size_t f = 0;
    if (clean.size() == 3 * cf) {  // every clean face is a triangle: loop f starts at 3 f
      for (; f < cf; ++f)
        if (!take_triangle(f, cl[3 * f], cl[3 * f + 1], cl[3 * f + 2])) break;
    } else {
      for (; f < cf; ++f) {
        const size_t b = off[f];
        if (off[f + 1] - b != 3 || !take_triangle(f, cl[b], cl[b + 1], cl[b + 2])) break;
      }
    }
    first_general = f;
    if (f < cf && off[f + 1] - off[f] == 3) ++f;  // (its volume is counted)
    for (; f < cf; ++f) {
      const size_t b = off[f], e = off[f + 1];
      for (size_t i = b + 1; i + 1 < e; ++i) {
        const double d = vol6_about_centre(cl[b], cl[i], cl[i + 1]);
        vol6 += d;
        vol6_abs += std::fabs(d);
      }
    }
    m.rep.resize(first_general);
  }
  // A closed surface enclosing nothing sums to zero up to rounding; anything at the rounding
  // level of the terms' magnitudes is treated as zero. The fans of non-planar polygons may enclose
  // nothing where their splits below do (two quads over a tetrahedron's corners whose fans take
  // the same diagonal): then the split surface decides, below.
  if (!open && ext == 0)
    return fail(m, Error::DegenerateInput, "the mesh encloses no volume (flat or folded onto itself)");
  const bool fans_enclose_nothing = !open && !(std::fabs(vol6) > 1e-12 * vol6_abs);
  const bool flip = vol6 < 0 && !open && !fans_enclose_nothing;
  m.volume = flip ? -vol6 / 6 : vol6 / 6;
  if (flip) {
    m.warnings.push_back(flipped_warning(cf));
    for (size_t f = 0; f < cf; ++f)
      std::reverse(clean.begin() + clean_offsets[f], clean.begin() + clean_offsets[f + 1]);
    for (auto& t : m.rep) std::swap(t[0], t[2]);
  }

  // Plane-carrying faces: drop exact zero-area ones; planar polygons keep one representative
  // triangle at their lexicographically smallest vertex (a strictly convex corner, so the
  // triangle has the polygon's orientation); non-planar polygons are split into triangles
  // (triangulate_polygon). As long as every face is kept whole, the plane faces are the clean
  // faces: their loops are copied (and the face numbering changes) only from the first face
  // dropped or split on, so in the usual case the clean loops and edge pairs are moved over as
  // they are.
  size_t degenerate = 0, nonplanar = 0;
  double split_abs = 0;  // sum of |terms| of the split polygons' volume corrections
  bool renumbered = false;
  std::vector<uint32_t> face_of_clean;  // used once renumbered
  auto input_of_clean = [&](size_t f) { return clean_renumbered ? clean_source[f] : uint32_t(f); };
  auto renumber = [&](size_t f) {  // faces before f were kept whole
    if (renumbered) return;
    renumbered = true;
    m.loops.assign(clean.begin(), clean.begin() + clean_offsets[f]);
    m.loop_offsets.assign(clean_offsets.begin(), clean_offsets.begin() + f + 1);
    face_of_clean.assign(cf, 0xffffffffu);
    std::iota(face_of_clean.begin(), face_of_clean.begin() + f, 0u);
    m.source_face.resize(f);
    for (size_t g = 0; g < f; ++g) m.source_face[g] = input_of_clean(g);
  };
  auto keep_whole = [&](size_t f, std::array<uint32_t, 3> rep) {
    if (renumbered) {
      face_of_clean[f] = uint32_t(m.rep.size());
      m.loops.insert(m.loops.end(), clean.begin() + clean_offsets[f], clean.begin() + clean_offsets[f + 1]);
      m.loop_offsets.push_back(uint32_t(m.loops.size()));
      m.source_face.push_back(input_of_clean(f));
    }
    m.rep.push_back(rep);
  };
  for (size_t f = first_general; f < cf; ++f) {
    const uint32_t* loop = &clean[clean_offsets[f]];
    size_t k = clean_offsets[f + 1] - clean_offsets[f];
    auto P = [&](uint32_t v) { return &m.points[3 * size_t(v)]; };
    if (k == 3) {
      if (collinear(P(loop[0]), P(loop[1]), P(loop[2]), m.exact_shift)) {
        renumber(f);
        ++degenerate;
        continue;
      }
      keep_whole(f, {loop[0], loop[1], loop[2]});
      continue;
    }
    size_t lo = 0;
    for (size_t i = 1; i < k; ++i)
      if (lex_less(P(loop[i]), P(loop[lo]))) lo = i;
    std::array<uint32_t, 3> rep = {loop[(lo + k - 1) % k], loop[lo], loop[(lo + 1) % k]};
    bool planar = !collinear(P(rep[0]), P(rep[1]), P(rep[2]), m.exact_shift);
    // The representative's own corners (at lo - 1, lo, lo + 1) are in its plane, and so is a
    // corner that shares a coordinate with all three (an axis-aligned plane): neither needs the
    // exact test, which is slow exactly when the answer is zero.
    bool same[3];
    for (int c = 0; c < 3; ++c) same[c] = P(rep[0])[c] == P(rep[1])[c] && P(rep[1])[c] == P(rep[2])[c];
    auto in_axis_plane = [&](const double* q) {
      return (same[0] && q[0] == P(rep[0])[0]) || (same[1] && q[1] == P(rep[0])[1]) ||
             (same[2] && q[2] == P(rep[0])[2]);
    };
    for (size_t i = 0; i < k && planar; ++i)
      if ((i + k + 1 - lo) % k > 2 && !in_axis_plane(P(loop[i])) &&
          orient3d(P(rep[0]), P(rep[1]), P(rep[2]), P(loop[i]), m.exact_shift) != 0)
        planar = false;
    if (planar) {
      // The corner at the lexicographically smallest vertex is strictly convex in a simple
      // polygon, so its triangle is oriented like the polygon and gives the face's plane. In a
      // polygon that crosses itself it may turn against the polygon's area, and that plane would
      // face inward: such a face is refused. (Compared in a projection where the corner is not
      // degenerate: the axes are tried from the one the corner's normal is largest along, which
      // is the first unless the normal is tiny; some axis works, the corner is not collinear.)
      const double *a = P(rep[0]), *b = P(rep[1]), *c3 = P(rep[2]);
      double nrm[3];
      for (int c = 0; c < 3; ++c) {
        const int i = (c + 1) % 3, j = (c + 2) % 3;
        nrm[c] = std::fabs((b[i] - a[i]) * (c3[j] - a[j]) - (b[j] - a[j]) * (c3[i] - a[i]));
      }
      int axes[3] = {0, 1, 2};
      std::sort(axes, axes + 3, [&](int x, int y) { return nrm[x] > nrm[y]; });
      int corner = 0, pi = 0, pj = 0;
      for (int t = 0; t < 3 && corner == 0; ++t) {
        pi = (axes[t] + 1) % 3;
        pj = (axes[t] + 2) % 3;
        corner = projected_area_sign(m.points, rep.data(), 3, pi, pj, m.exact_shift);
      }
      if (corner == 0 || projected_area_sign(m.points, loop, k, pi, pj, m.exact_shift) != corner) {
        std::ostringstream msg;
        msg << "a polygon face crosses itself (its loop of " << k << " vertices turns against its corner at vertex "
            << rep[1] << "; the surface is not embedded there)";
        return fail(m, Error::NonManifoldEdge, msg.str());
      }
      keep_whole(f, rep);
      continue;
    }
    renumber(f);
    bool any = false;
    // Split in the coordinate projection along the Newell normal's largest axis first; a loop
    // far from planar may cross itself in that projection though not seen along its normal, and
    // is split again in the projection along the normal.
    const std::array<double, 3> n = newell_normal(m.points, loop, k);
    bool gave_up = false;
    auto tris = triangulate_polygon(m.points, loop, k, n, m.exact_shift, false, &gave_up);
    const char* why = split_folds_over(m.points, n, tris);
    if (why) {
      tris = triangulate_polygon(m.points, loop, k, n, m.exact_shift, true, &gave_up);
      why = split_folds_over(m.points, n, tris);
    }
    if (why) {
      std::ostringstream msg;
      msg << "a non-planar polygon face of " << k << " vertices (first vertex " << loop[0]
          << ") folds over itself: " << why;
      if (gave_up)
        msg << "; its ear clipping found no more ears (the loop overlaps itself) or spent its work budget, and the "
               "rest was"
               " split as a fan (split such a face before, if it is simple)";
      else
        msg << "; the surface is not embedded there";
      return fail(m, Error::NonManifoldEdge, msg.str());
    }
    {
      // The shape's volume above came from a fan; the split may fold differently: use its volume.
      // Its terms' magnitudes join the rounding scale of the volume test below.
      double delta = 0;
      for (const auto& t : tris) {
        const double d = vol6_about_centre(t[0], t[1], t[2]);
        delta += d;
        split_abs += std::fabs(d);
      }
      // (that fan was over the loop before any flip: from its first corner, now the last)
      for (size_t i = 1; i + 1 < k; ++i) {
        const double d = flip ? vol6_about_centre(loop[k - 1], loop[k - 2 - i], loop[k - 1 - i])
                              : vol6_about_centre(loop[0], loop[i], loop[i + 1]);
        delta -= d;
        split_abs += std::fabs(d);
      }
      m.volume += delta / 6;
    }
    for (const auto& tri : tris) {
      if (collinear(P(tri[0]), P(tri[1]), P(tri[2]), m.exact_shift)) continue;
      m.loops.insert(m.loops.end(), tri.begin(), tri.end());
      m.loop_offsets.push_back(uint32_t(m.loops.size()));
      m.rep.push_back(tri);
      m.source_face.push_back(input_of_clean(f));
      any = true;
    }
    if (any)
      ++nonplanar;
    else
      ++degenerate;
  }
  // The fans' volume chose the orientation and the splits then fold outward for it; polygons far
  // from planar can fold into a surface that encloses a negative volume (two quads closing a
  // tetrahedron, each folded outward after a flip). The split surface is what the planes come
  // from: it is turned over once more, as a whole, when its own volume says so.
  if (!open && nonplanar > 0 && m.volume < 0) {
    for (size_t f = 0; f + 1 < m.loop_offsets.size(); ++f)
      std::reverse(m.loops.begin() + m.loop_offsets[f], m.loops.begin() + m.loop_offsets[f + 1]);
    for (auto& t : m.rep) std::swap(t[0], t[2]);
    m.volume = -m.volume;
    auto flipped = std::find_if(m.warnings.begin(), m.warnings.end(),
                                [](const Warning& w) { return w.kind == Warning::Kind::OrientationFlipped; });
    if (flipped != m.warnings.end())
      m.warnings.erase(flipped);
    else
      m.warnings.push_back(flipped_warning(cf));
  }
  if (!open && (nonplanar > 0 || fans_enclose_nothing) && !(m.volume > 1e-12 * (vol6_abs + split_abs) / 6))
    return fail(m, Error::DegenerateInput,
                nonplanar > 0 ? "the mesh encloses no volume once its non-planar polygons are split"
                              : "the mesh encloses no volume (flat or folded onto itself)");
  m.dropped_faces += degenerate;
  if (m.dropped_faces)
    m.warnings.push_back({Warning::Kind::DegenerateFacesDropped, m.dropped_faces,
                          std::to_string(m.dropped_faces) + " zero-area faces were ignored"});
  if (nonplanar)
    m.warnings.push_back({Warning::Kind::NonPlanarFacesSplit, nonplanar,
                          std::to_string(nonplanar) + " non-planar polygons were split into triangles"});
  if (m.rep.empty()) return fail(m, Error::DegenerateInput, "every face has zero area");
  // A nearly flat shape's volume is far below the rounding of its terms (the points' offsets
  // from the centre, rounded, span its thickness): summed again in double-double once the loops
  // are final, for shapes thinner than 1e-6 of their bounding cube (rare).
  // The orientation was chosen by the double sum. The test above scales its rounding by the
  // terms' magnitudes, but a term's own rounding scales with the products inside it, far larger
  // when its cross product cancels (or the term is pure noise: a face folded back onto itself).
  // So the accurate sum, with its error bound, must certify that the surface as oriented
  // encloses a positive volume; when it cannot, the volume was lost in the double sum's rounding
  // and no orientation can be trusted (fuzzed: folded shapes with scaled coordinates from 1e-18
  // to 1, a single face a b b a c).
  auto finish = [&]() {
    if (!open && m.volume < 1e-6 * ext * ext * ext) {
      const exact::ApproxDD vol6_dd = accurate_volume6(m, c);
      m.volume = (vol6_dd.hi + vol6_dd.lo) / 6;
      if (vol6_dd.sign() != 1)
        return fail(m, Error::DegenerateInput,
                    "the mesh encloses almost no volume and its orientation cannot be decided reliably (flat or folded "
                    "onto itself)");
    }
    return std::move(m);
  };
  if (!renumbered) {
    if (clean_renumbered) m.source_face = std::move(clean_source);
    m.loops = std::move(clean);
    m.loop_offsets = std::move(clean_offsets);
    m.adjacent = std::move(face_pairs);
    return finish();
  }
  m.adjacent.reserve(face_pairs.size());
  for (const auto& pr : face_pairs) {
    uint32_t a = face_of_clean[pr[0]], b = face_of_clean[pr[1]];
    if (a != 0xffffffffu && b != 0xffffffffu) m.adjacent.push_back({a, b});
  }
  return finish();
}

}  // namespace kergen
