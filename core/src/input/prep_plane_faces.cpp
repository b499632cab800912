// The faces that carry planes, built by prepare_mesh (prep_state.h) after the orientation is
// known: exact zero-area faces are dropped, planar polygons keep a representative triangle at
// their lexicographically smallest corner (and are refused if they cross themselves there),
// non-planar polygons are split into triangles by polygon_split.h; faces are renumbered from the
// first one dropped or split, and the loops and face pairs move into the result (move_loops).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <sstream>
#include <utility>
#include <vector>

#include "exact/predicates.h"
#include "input/polygon_split.h"
#include "input/prep_state.h"

namespace kergen::prep {

namespace {

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

bool lex_less(const double* a, const double* b) {
  return a[0] != b[0] ? a[0] < b[0] : (a[1] != b[1] ? a[1] < b[1] : a[2] < b[2]);
}

// As long as every face is kept whole, the plane faces are the clean faces: their loops are
// copied (and the face numbering changes) only from the first face dropped or split on, so in the
// usual case the clean loops and edge pairs are moved over as they are. Faces before f were kept
// whole.
void renumber_from(Prep& s, size_t f) {
  if (s.renumbered) return;
  s.renumbered = true;
  s.m.loops.assign(s.clean.begin(), s.clean.begin() + s.clean_offsets[f]);
  s.m.loop_offsets.assign(s.clean_offsets.begin(), s.clean_offsets.begin() + f + 1);
  s.face_of_clean.assign(s.cf, 0xffffffffu);
  std::iota(s.face_of_clean.begin(), s.face_of_clean.begin() + f, 0u);
  s.m.source_face.resize(f);
  for (size_t g = 0; g < f; ++g) s.m.source_face[g] = s.input_of_clean(g);
}

void keep_whole(Prep& s, size_t f, std::array<uint32_t, 3> rep) {
  if (s.renumbered) {
    s.face_of_clean[f] = uint32_t(s.m.rep.size());
    s.m.loops.insert(s.m.loops.end(), s.clean.begin() + s.clean_offsets[f], s.clean.begin() + s.clean_offsets[f + 1]);
    s.m.loop_offsets.push_back(uint32_t(s.m.loops.size()));
    s.m.source_face.push_back(s.input_of_clean(f));
  }
  s.m.rep.push_back(rep);
}

// Whether the polygon loop[0..k) lies in the plane of its corner rep (at position lo). The
// representative's own corners (at lo - 1, lo, lo + 1) are in its plane, and so is a corner that
// shares a coordinate with all three (an axis-aligned plane): neither needs the exact test, which
// is slow exactly when the answer is zero.
bool polygon_is_planar(const Prep& s, const uint32_t* loop, size_t k, size_t lo, const std::array<uint32_t, 3>& rep) {
  if (collinear(s.P(rep[0]), s.P(rep[1]), s.P(rep[2]), s.m.exact_shift)) return false;
  bool same[3];
  for (int c = 0; c < 3; ++c) same[c] = s.P(rep[0])[c] == s.P(rep[1])[c] && s.P(rep[1])[c] == s.P(rep[2])[c];
  auto in_axis_plane = [&](const double* q) {
    return (same[0] && q[0] == s.P(rep[0])[0]) || (same[1] && q[1] == s.P(rep[0])[1]) ||
           (same[2] && q[2] == s.P(rep[0])[2]);
  };
  for (size_t i = 0; i < k; ++i)
    if ((i + k + 1 - lo) % k > 2 && !in_axis_plane(s.P(loop[i])) &&
        orient3d(s.P(rep[0]), s.P(rep[1]), s.P(rep[2]), s.P(loop[i]), s.m.exact_shift) != 0)
      return false;
  return true;
}

// The corner at the lexicographically smallest vertex is strictly convex in a simple polygon, so
// its triangle is oriented like the polygon and gives the face's plane. In a polygon that crosses
// itself it may turn against the polygon's area, and that plane would face inward: such a face is
// refused. (Compared in a projection where the corner is not degenerate: the axes are tried from
// the one the corner's normal is largest along, which is the first unless the normal is tiny;
// some axis works, the corner is not collinear.)
bool check_planar_corner(Prep& s, const uint32_t* loop, size_t k, const std::array<uint32_t, 3>& rep) {
  const double *a = s.P(rep[0]), *b = s.P(rep[1]), *c3 = s.P(rep[2]);
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
    corner = projected_area_sign(s.m.points, rep.data(), 3, pi, pj, s.m.exact_shift);
  }
  if (corner != 0 && projected_area_sign(s.m.points, loop, k, pi, pj, s.m.exact_shift) == corner) return true;
  std::ostringstream msg;
  msg << "a polygon face crosses itself (its loop of " << k << " vertices turns against its corner at vertex " << rep[1]
      << "; the surface is not embedded there)";
  return s.fail(Error::NonManifoldEdge, msg.str());
}

// A non-planar polygon, split into triangles (polygon_split.h): in the coordinate projection
// along the Newell normal's largest axis first; a loop far from planar may cross itself in that
// projection though not seen along its normal, and is split again in the projection along the
// normal. The shape's volume came from a fan; the split may fold differently: its volume is used
// instead, and its terms' magnitudes join the rounding scale of check_split_volume. Zero-area
// triangles of the split are dropped.
bool split_nonplanar(Prep& s, size_t f, const uint32_t* loop, size_t k) {
  PreparedMesh& m = s.m;
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
    return s.fail(Error::NonManifoldEdge, msg.str());
  }
  double delta = 0;
  for (const auto& t : tris) {
    const double d = s.vol6_about_centre(t[0], t[1], t[2]);
    delta += d;
    s.split_abs += std::fabs(d);
  }
  // (that fan was over the loop before any flip: from its first corner, now the last)
  for (size_t i = 1; i + 1 < k; ++i) {
    const double d = s.flip ? s.vol6_about_centre(loop[k - 1], loop[k - 2 - i], loop[k - 1 - i])
                            : s.vol6_about_centre(loop[0], loop[i], loop[i + 1]);
    delta -= d;
    s.split_abs += std::fabs(d);
  }
  m.volume += delta / 6;
  bool any = false;
  for (const auto& tri : tris) {
    if (collinear(s.P(tri[0]), s.P(tri[1]), s.P(tri[2]), m.exact_shift)) continue;
    m.loops.insert(m.loops.end(), tri.begin(), tri.end());
    m.loop_offsets.push_back(uint32_t(m.loops.size()));
    m.rep.push_back(tri);
    m.source_face.push_back(s.input_of_clean(f));
    any = true;
  }
  if (any)
    ++s.nonplanar;
  else
    ++s.degenerate;
  return true;
}

}  // namespace

// Plane-carrying faces after the leading run: exact zero-area ones are dropped; planar polygons
// keep one representative triangle at their lexicographically smallest vertex (a strictly convex
// corner, so the triangle has the polygon's orientation); non-planar polygons are split.
bool build_plane_faces(Prep& s) {
  if (s.first_general < s.cf) s.own_clean();  // (done by sum_fan_volume already)
  for (size_t f = s.first_general; f < s.cf; ++f) {
    const uint32_t* loop = &s.clean[s.clean_offsets[f]];
    const size_t k = s.clean_offsets[f + 1] - s.clean_offsets[f];
    if (k == 3) {
      if (collinear(s.P(loop[0]), s.P(loop[1]), s.P(loop[2]), s.m.exact_shift)) {
        renumber_from(s, f);
        ++s.degenerate;
        continue;
      }
      keep_whole(s, f, {loop[0], loop[1], loop[2]});
      continue;
    }
    size_t lo = 0;
    for (size_t i = 1; i < k; ++i)
      if (lex_less(s.P(loop[i]), s.P(loop[lo]))) lo = i;
    const std::array<uint32_t, 3> rep = {loop[(lo + k - 1) % k], loop[lo], loop[(lo + 1) % k]};
    if (polygon_is_planar(s, loop, k, lo, rep)) {
      if (!check_planar_corner(s, loop, k, rep)) return false;
      keep_whole(s, f, rep);
      continue;
    }
    renumber_from(s, f);
    if (!split_nonplanar(s, f, loop, k)) return false;
  }
  return true;
}

// The loops and the pairs of neighbouring faces, renumbered if faces were dropped or split.
// A verdict needs no loops, unless several shells are judged (judge_shells) or a thin shape's
// volume is certified; the input's faces are then not copied.
void move_loops(Prep& s) {
  PreparedMesh& m = s.m;
  if (!s.renumbered) {
    if (s.clean_viewed && s.verdict_only && m.shells < 2 && !needs_thin_certificate(s)) {
      m.adjacent = std::move(s.face_pairs);
      return;
    }
    s.own_clean();
    if (s.clean_renumbered) m.source_face = std::move(s.clean_source);
    m.loops = std::move(s.clean);
    m.loop_offsets = std::move(s.clean_offsets);
    m.adjacent = std::move(s.face_pairs);
    return;
  }
  m.adjacent.reserve(s.face_pairs.size());
  for (const auto& pr : s.face_pairs) {
    uint32_t a = s.face_of_clean[pr[0]], b = s.face_of_clean[pr[1]];
    if (a != 0xffffffffu && b != 0xffffffffu) m.adjacent.push_back({a, b});
  }
}

}  // namespace kergen::prep
