// Splitting non-planar polygon faces into triangles (see polygon_split.h): ear clipping in a 2D
// projection, the best-shaped ear first for small polygons and the first ear met, found through a
// grid of corners, for large ones; then flips of diagonals that fold inward.
#include "input/polygon_split.h"

#include <algorithm>
#include <cmath>

#include "exact/predicates.h"

namespace kergen {

namespace {

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
// The projection a polygon is split in: along the dominant axis of its Newell normal n, or with
// along_normal along n itself. cross() is positive for counter-clockwise corners as the polygon
// turns (seen from the side n points to).
class Projection {
 public:
  Projection(const std::vector<double>& pts, const uint32_t* loop, const std::array<double, 3>& n, bool along_normal)
      : pts_(pts) {
    axis_ = 0;
    for (int c = 1; c < 3; ++c)
      if (std::fabs(n[c]) > std::fabs(n[axis_])) axis_ = c;
    u_ = (axis_ + 1) % 3;
    w_ = (axis_ + 2) % 3;
    orient_ = n[axis_] >= 0 ? 1 : -1;  // (u, w) is counter-clockwise when n[axis] > 0
    // The projection along n itself: the plane coordinates (p - o) . e1 and (p - o) . e2 with
    // e1, e2, n / |n| orthonormal and right-handed (counter-clockwise is positive).
    o_ = point(loop[0]);
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    along_normal_ = along_normal && len > 0 && std::isfinite(len);
    if (!along_normal_) return;
    const double nn[3] = {n[0] / len, n[1] / len, n[2] / len};
    int least = 0;  // e1 = nn x (the axis of nn's smallest part): |e1| >= sqrt(2/3) before scaling
    for (int c = 1; c < 3; ++c)
      if (std::fabs(nn[c]) < std::fabs(nn[least])) least = c;
    const int l1 = (least + 1) % 3, l2 = (least + 2) % 3;
    e1_[least] = 0;
    e1_[l1] = nn[l2];
    e1_[l2] = -nn[l1];
    const double scale = 1 / std::sqrt(e1_[l1] * e1_[l1] + e1_[l2] * e1_[l2]);
    for (int c = 0; c < 3; ++c) e1_[c] *= scale;
    for (int c = 0; c < 3; ++c) e2_[c] = nn[(c + 1) % 3] * e1_[(c + 2) % 3] - nn[(c + 2) % 3] * e1_[(c + 1) % 3];
  }
  const double* point(uint32_t v) const { return &pts_[3 * size_t(v)]; }
  void xy(uint32_t v, double& x, double& y) const {
    const double* p = point(v);
    if (!along_normal_) {
      x = p[u_];
      y = p[w_];
      return;
    }
    const double d[3] = {p[0] - o_[0], p[1] - o_[1], p[2] - o_[2]};
    x = d[0] * e1_[0] + d[1] * e1_[1] + d[2] * e1_[2];
    y = d[0] * e2_[0] + d[1] * e2_[1] + d[2] * e2_[2];
  }
  // The sign that makes a counter-clockwise turn positive in (x, y).
  double sign() const { return along_normal_ ? 1 : orient_; }
  double cross(uint32_t a, uint32_t b, uint32_t c) const {
    double ax, ay, bx, by, cx, cy;
    xy(a, ax, ay);
    xy(b, bx, by);
    xy(c, cx, cy);
    return sign() * ((bx - ax) * (cy - ay) - (by - ay) * (cx - ax));
  }
  double sq(uint32_t a, uint32_t b) const {
    double ax, ay, bx, by;
    xy(a, ax, ay);
    xy(b, bx, by);
    return (bx - ax) * (bx - ax) + (by - ay) * (by - ay);
  }

 private:
  const std::vector<double>& pts_;
  int axis_, u_, w_;
  double orient_;
  bool along_normal_;
  const double* o_;
  double e1_[3] = {0, 0, 0}, e2_[3] = {0, 0, 0};
};

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
class OutwardFolder {
 public:
  OutwardFolder(const Projection& proj, size_t k, int exact_shift) : proj_(proj), k_(k), exact_shift_(exact_shift) {}
  void fold(std::vector<std::array<uint32_t, 3>>& out) {
    if (k_ > 128) return;
    size_t flips = 0;
    const size_t cap = 4 * k_ * k_;
    bool changed = true;
    while (changed && flips < cap) {
      changed = false;
      for (size_t i = 0; i < out.size() && flips < cap; ++i) {
        for (int e = 0; e < 3; ++e) {
          if (!flip_if_inward(out, i, e)) continue;
          ++flips;
          changed = true;
          break;  // this triangle changed: its edges are looked at again on the next sweep
        }
      }
    }
  }

 private:
  // Flips the diagonal at edge e of triangle i when it folds inward and the flip is clean.
  bool flip_if_inward(std::vector<std::array<uint32_t, 3>>& out, size_t i, int e) {
    const uint32_t x = out[i][e], y = out[i][(e + 1) % 3], p = out[i][(e + 2) % 3];
    size_t j = 0;
    int g = 0;
    for (; j < out.size(); ++j) {
      if (j == i) continue;
      for (g = 0; g < 3; ++g)
        if (out[j][g] == y && out[j][(g + 1) % 3] == x) break;
      if (g < 3) break;
    }
    if (j == out.size()) return false;
    const uint32_t q = out[j][(g + 2) % 3];
    if (!folds_inward(x, y, p, q)) return false;
    const double tol = 1e-12 * (proj_.sq(x, q) + proj_.sq(q, p) + proj_.sq(p, x) + proj_.sq(q, y) + proj_.sq(y, p));
    if (!(proj_.cross(x, q, p) > tol && proj_.cross(q, y, p) > tol)) return false;
    out[i] = {x, q, p};
    out[j] = {q, y, p};
    return true;
  }
  bool folds_inward(uint32_t x, uint32_t y, uint32_t p, uint32_t q) {
    for (const auto& d : tested_)
      if ((d[0] == x && d[1] == y && d[2] == p && d[3] == q) || (d[0] == y && d[1] == x && d[2] == q && d[3] == p))
        return d[4] != 0;
    const bool inward = orient3d(proj_.point(x), proj_.point(y), proj_.point(p), proj_.point(q), exact_shift_) > 0;
    if (tested_.empty()) tested_.reserve(4 * k_);
    tested_.push_back({x, y, p, q, inward});
    return inward;
  }
  const Projection& proj_;
  size_t k_;
  int exact_shift_;
  std::vector<std::array<uint32_t, 5>> tested_;  // x, y, p, q, whether it folds inward
};

// Up to 128 corners: the best-shaped ear first (area over squared edge lengths): a sliver's plane
// is poorly determined by its points, so slivers are avoided whenever the polygon allows it.
// Each corner's ear is judged once and again only when it may have changed: when a neighbour
// is clipped (its triangle changes) or when the corner that blocked it is (the others only
// lose a corner, which cannot block an ear). Quadratic instead of cubic in the corners, with
// the same choices. idx holds the corners left (vertex ids) and keeps what no ear could take.
void clip_best_ears(const Projection& proj, std::vector<uint32_t>& idx, std::vector<std::array<uint32_t, 3>>& out) {
  constexpr uint32_t kNoBlocker = 0xffffffffu, kUnjudged = 0xfffffffeu;
  const size_t k = idx.size();
  std::vector<double> quality;    // per position in idx: the ear's quality, 0 if not an ear
  std::vector<uint32_t> blocker;  // the corner inside the ear, kNoBlocker, or kUnjudged
  auto judge = [&](size_t i) {
    const size_t r = idx.size();
    const uint32_t a = idx[(i + r - 1) % r], b = idx[i], c = idx[(i + 1) % r];
    quality[i] = 0;
    blocker[i] = kNoBlocker;
    const double area2 = proj.cross(a, b, c);
    if (!(area2 > 0)) return;  // reflex or flat corner
    // A corner on or within rounding distance of the ear's border blocks it too (a polygon
    // that is non-planar by rounding has its collinear corners off by an ulp either way).
    const double size2 = proj.sq(a, b) + proj.sq(b, c) + proj.sq(c, a);
    const double tol = -1e-9 * size2;
    for (size_t j = 0; j < r; ++j) {
      const uint32_t q = idx[j];
      if (q == a || q == b || q == c) continue;
      if (proj.cross(a, b, q) >= tol && proj.cross(b, c, q) >= tol && proj.cross(c, a, q) >= tol) {
        blocker[i] = q;
        return;
      }
    }
    quality[i] = area2 / size2;
  };
  if (k > 3) {
    quality.assign(k, 0);
    blocker.assign(k, kUnjudged);
  }
  while (idx.size() > 3) {
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
}

// Larger polygons: the first ear met walking around the loop (stepping back after each ear to
// the corner before it), with the same ear test, on plane coordinates computed once. The corners
// that could block an ear are looked up in a grid of cells, over the rows and columns that the
// region of ear_region reaches (it holds every corner the test can accept, so the answer is the
// one a scan of every corner gives), unless the ear is too thin for that region or it reaches
// more cells than corners are left: then every corner is scanned. A work budget bounds
// pathological loops (kBudgetPerScan); what is left is fanned (gave_up), and the fold check
// judges the result.
class LargePolygonClipper {
 public:
  LargePolygonClipper(const Projection& proj, const uint32_t* loop, size_t k)
      : loop_(loop), k_(k), xs_(k), ys_(k), next_(k), prev_(k), alive_(k, 1), sign_(proj.sign()) {
    for (size_t t = 0; t < k; ++t) proj.xy(loop[t], xs_[t], ys_[t]);
    // The corners left, as a ring of positions in loop.
    for (size_t t = 0; t < k; ++t) {
      next_[t] = uint32_t((t + 1) % k);
      prev_[t] = uint32_t((t + k - 1) % k);
    }
  }
  // Clips ears into out; idx gets the corners left (vertex ids).
  void clip(std::vector<uint32_t>& idx, std::vector<std::array<uint32_t, 3>>& out) {
    const CornerGrid grid(xs_, ys_);
    const bool charge_scans = k_ <= kBudgetPerScan;
    size_t budget = charge_scans ? 8 * k_ * k_ : std::min(kEarWorkPerCorner * k_, 8 * kBudgetPerScan * kBudgetPerScan);
    size_t r = k_;   // corners left
    uint32_t i = 0;  // the corner whose ear is tried next
    while (r > 3 && budget > 0) {
      bool clipped = false;
      for (size_t tries = 0; tries < r && budget > 0 && !clipped; ++tries, i = next_[i]) {
        const uint32_t a = prev_[i], b = i, c = next_[i];
        if (!charge_scans) --budget;  // (a walk over reflex or flat corners is work too)
        const double area2 = cr(a, b, c);
        if (!(area2 > 0)) continue;  // reflex or flat corner
        size_t work = 1;
        const bool empty = ear_is_empty(grid, a, b, c, area2, r, work);
        budget -= std::min(budget, charge_scans ? r : work);
        if (!empty) continue;
        out.push_back({loop_[a], loop_[b], loop_[c]});
        alive_[b] = 0;
        next_[a] = c;
        prev_[c] = a;
        --r;
        i = a;  // the corner before the ear, whose own ear just changed
        clipped = true;
        break;
      }
      if (!clipped) break;
    }
    idx.clear();
    for (uint32_t t = 0; t < k_; ++t)
      if (alive_[t]) idx.push_back(loop_[t]);
  }

 private:
  double cr(uint32_t a, uint32_t b, uint32_t c) const {
    return sign_ * ((xs_[b] - xs_[a]) * (ys_[c] - ys_[a]) - (ys_[b] - ys_[a]) * (xs_[c] - xs_[a]));
  }
  double sq2(uint32_t a, uint32_t b) const {
    return (xs_[b] - xs_[a]) * (xs_[b] - xs_[a]) + (ys_[b] - ys_[a]) * (ys_[b] - ys_[a]);
  }
  // Whether no corner left blocks the ear (a, b, c) of r corners left; work counts what was looked at.
  bool ear_is_empty(const CornerGrid& grid, uint32_t a, uint32_t b, uint32_t c, double area2, size_t r, size_t& work) {
    const double tol = -1e-9 * (sq2(a, b) + sq2(b, c) + sq2(c, a));
    auto blocks = [&](uint32_t q) {
      return loop_[q] != loop_[a] && loop_[q] != loop_[b] && loop_[q] != loop_[c] && cr(a, b, q) >= tol &&
             cr(b, c, q) >= tol && cr(c, a, q) >= tol;
    };
    // The region's rows of cells, each cut to the columns the region reaches in it.
    EarRegion region;
    size_t box_cells[4], cells = 0;
    bool use_grid = ear_region(xs_, ys_, a, b, c, tol, area2, region) && grid.cells_of(region.box, box_cells) <= 4 * r;
    if (use_grid) {
      rows_.clear();
      for (size_t cy = box_cells[2]; cy <= box_cells[3] && cells <= r; ++cy) {
        double lo, hi, xlo, xhi;
        grid.row_band(cy, lo, hi);
        ++work;
        if (!region_x_range(region, lo, hi, xlo, xhi)) continue;
        const size_t c0 = std::max(box_cells[0], grid.column(xlo)), c1 = std::min(box_cells[1], grid.column(xhi));
        if (c0 > c1) continue;
        rows_.push_back({cy, c0, c1});
        cells += c1 - c0 + 1;
      }
      use_grid = cells <= r;
    }
    if (!use_grid) {
      for (uint32_t q = next_[c]; q != a; q = next_[q], ++work)
        if (blocks(q)) {
          ++work;  // (the corner that blocks counts as looked at, like every other)
          return false;
        }
      return true;
    }
    for (size_t w = 0; w < rows_.size(); ++w)
      for (size_t cx = rows_[w][1]; cx <= rows_[w][2]; ++cx) {
        const uint32_t* items = grid.items(cx, rows_[w][0]);
        const size_t n = grid.count(cx, rows_[w][0]);
        work += 1 + n;
        for (size_t j = 0; j < n; ++j)
          if (alive_[items[j]] && blocks(items[j])) return false;
      }
    return true;
  }
  const uint32_t* loop_;
  size_t k_;
  std::vector<double> xs_, ys_;
  std::vector<uint32_t> next_, prev_;
  std::vector<char> alive_;
  double sign_;
  std::vector<std::array<size_t, 3>> rows_;  // an ear's rows of cells: row, first and last column
};

}  // namespace

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
std::vector<std::array<uint32_t, 3>> triangulate_polygon(const std::vector<double>& pts, const uint32_t* loop, size_t k,
                                                         const std::array<double, 3>& n, int exact_shift,
                                                         bool along_normal, bool* gave_up) {
  if (gave_up) *gave_up = false;
  std::vector<std::array<uint32_t, 3>> out;
  out.reserve(k - 2);
  const Projection proj(pts, loop, n, along_normal);
  OutwardFolder folder(proj, k, exact_shift);
  // A convex polygon (every corner turns the same way in the projection) keeps the simple rule:
  // a fan from its first corner.
  bool convex = true;
  for (size_t i = 0; i < k && convex; ++i)
    if (proj.cross(loop[(i + k - 1) % k], loop[i], loop[(i + 1) % k]) < 0) convex = false;
  if (convex) {
    for (size_t i = 1; i + 1 < k; ++i) out.push_back({loop[0], loop[i], loop[i + 1]});
    folder.fold(out);
    return out;
  }
  std::vector<uint32_t> idx(loop, loop + k);
  if (k <= 128)
    clip_best_ears(proj, idx, out);
  else
    LargePolygonClipper(proj, loop, k).clip(idx, out);
  if (gave_up) *gave_up = idx.size() > 3;
  for (size_t i = 1; i + 1 < idx.size(); ++i) out.push_back({idx[0], idx[i], idx[i + 1]});
  folder.fold(out);
  return out;
}

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
}  // namespace kergen
