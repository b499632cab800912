// The geometric phases of prepare_mesh (prep_state.h): the bounding box, the enclosed volume
// summed as fans about the box centre (with the leading run of triangles kept whole in the same
// pass), the orientation it decides (a negative volume flips the loops), the volume checked again
// once non-planar polygons are split (check_split_volume, which also issues the warnings for
// dropped and split faces), and the double-double certification of a nearly flat shape's volume.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>

#include "exact/predicates.h"
#include "input/prep_state.h"
#include "util/compiler_hints.h"
#include "util/plural.h"

namespace kergen::prep {

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

}  // namespace

// Bounding box of the used vertices (Prep::lo3, hi3). It is defined as if taken over every use in loop order: ties
// keep the held bound, so a zero bound has the sign of the first zero met. Over the used vertices
// in id order the values are the same; only a zero bound may differ (in sign). All values on that
// side are then >= 0 (<= 0 for a maximum), so the bound in loop order is the first zero
// coordinate met in loop order: it is looked up there.
void take_bounding_box(Prep& s) {
  const double* pts = s.m.points.data();
  double* lo3 = s.lo3;
  double* hi3 = s.hi3;
  bool zero[3];
  int zeros = 0;
  for (int k = 0; k < 3; ++k) zeros += zero[k] = lo3[k] == 0 || hi3[k] == 0;
  for (size_t i = 0; i < s.clean_size && zeros > 0; ++i)
    for (int k = 0; k < 3; ++k) {
      const double x = pts[3 * size_t(s.cl[i]) + k];
      if (zero[k] && x == 0) {
        if (lo3[k] == 0) lo3[k] = x;
        if (hi3[k] == 0) hi3[k] = x;
        zero[k] = false;
        --zeros;
      }
    }
}

// Four lanes of doubles (GCC and clang vector extensions: one AVX2 register in the AVX2 clone,
// two SSE2 registers otherwise); every operation is IEEE per lane, as the scalar one it
// replaces (no contraction: -ffp-contract=off), so the lanes hold the scalar code's bits.
using Lanes = double __attribute__((vector_size(32)));
using LaneBits = int64_t __attribute__((vector_size(32)));

// The triangles tri[3 j..3 j + 3), j < n, (n a multiple of 4) four at a time: d[j] is
// vol6_about_centre's term and bit j of the result is set when certainly_not_collinear does not
// certify triangle j. The arithmetic of both is the same per lane; the coordinates are loaded
// one by one into the lanes (the points are stored by vertex).
KERGEN_MULTIVERSION
uint64_t triangle_terms(const double* pts, const uint32_t* tri, size_t n, const double c[3], double* d) {
  const LaneBits abs_mask = LaneBits{} + int64_t(~(uint64_t(1) << 63));
  uint64_t uncertain = 0;
  for (size_t j = 0; j < n; j += 4) {
    const uint32_t* t = tri + 3 * j;
    Lanes a[3], bb[3], cc[3], u[3], v[3];
    for (int k = 0; k < 3; ++k) {
      const Lanes p0 = {pts[3 * size_t(t[0]) + k], pts[3 * size_t(t[3]) + k], pts[3 * size_t(t[6]) + k],
                        pts[3 * size_t(t[9]) + k]};
      const Lanes p1 = {pts[3 * size_t(t[1]) + k], pts[3 * size_t(t[4]) + k], pts[3 * size_t(t[7]) + k],
                        pts[3 * size_t(t[10]) + k]};
      const Lanes p2 = {pts[3 * size_t(t[2]) + k], pts[3 * size_t(t[5]) + k], pts[3 * size_t(t[8]) + k],
                        pts[3 * size_t(t[11]) + k]};
      a[k] = p0 - c[k];
      bb[k] = p1 - c[k];
      cc[k] = p2 - c[k];
      u[k] = p1 - p0;
      v[k] = p2 - p0;
    }
    const Lanes vol6 = a[0] * (bb[1] * cc[2] - bb[2] * cc[1]) - a[1] * (bb[0] * cc[2] - bb[2] * cc[0]) +
                       a[2] * (bb[0] * cc[1] - bb[1] * cc[0]);
    LaneBits certain = LaneBits{};
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, jj = (k + 2) % 3;
      const Lanes x = u[i] * v[jj], y = u[jj] * v[i];
      const Lanes abs_x = Lanes(LaneBits(x) & abs_mask), abs_y = Lanes(LaneBits(y) & abs_mask);
      certain |= Lanes(LaneBits(x - y) & abs_mask) > 5 * exact::kEps * (abs_x + abs_y) + exact::kUnderflowFloor;
    }
    for (int l = 0; l < 4; ++l) {
      d[j + l] = vol6[l];
      uncertain |= uint64_t(certain[l] == 0) << (j + l);
    }
  }
  return uncertain;
}

uint64_t triangle_block_terms(const Prep& s, const uint32_t* tri, size_t n, double* d) {
  const double* pts = s.m.points.data();
  const size_t whole = n & ~size_t(3);
  uint64_t uncertain = triangle_terms(pts, tri, whole, s.c, d);
  for (size_t j = whole; j < n; ++j) {
    const uint32_t* t = tri + 3 * j;
    d[j] = s.vol6_about_centre(t[0], t[1], t[2]);
    if (!certainly_not_collinear(pts + 3 * size_t(t[0]), pts + 3 * size_t(t[1]), pts + 3 * size_t(t[2])))
      uncertain |= uint64_t(1) << j;
  }
  return uncertain;
}

// The box into the result, its centre and largest side (for the fans' volume).
void take_centre(Prep& s) {
  s.ext = 0;
  for (int k = 0; k < 3; ++k) {
    s.m.bbox_min[k] = s.lo3[k];
    s.m.bbox_max[k] = s.hi3[k];
    s.c[k] = 0.5 * (s.m.bbox_min[k] + s.m.bbox_max[k]);
    s.ext = std::max(s.ext, s.m.bbox_max[k] - s.m.bbox_min[k]);
  }
}

// Enclosed volume (double; relative to the box centre for accuracy), as fans of the clean faces.
// The usual leading run of the plane faces is taken in the same pass (the points are read once):
// triangles that a float filter certifies as non-degenerate are kept whole with themselves as
// representatives, written in place (turned over by orient_by_volume on a flip; the filter only
// shortcuts the exact test, so the order of the corners it sees does not matter).
void sum_fan_volume(Prep& s) {
  PreparedMesh& m = s.m;
  take_centre(s);
  const size_t cf = s.cf;
  // When pair_edges summed the volume (a verdict's triangles), every face is in the leading run
  // and no shells are judged, the representatives are not written (Prep::reps_unwritten).
  if (s.volume_summed && m.shells < 2 && s.first_general == cf) {
    s.reps_unwritten = true;
    m.rep.resize(cf);  // (uninitialised: its pages are not touched)
    return;
  }
  double vol6 = 0, vol6_abs = 0;
  m.rep.resize(cf);
  std::array<uint32_t, 3>* rep_out = m.rep.data();
  const uint32_t* cl = s.cl;
  const uint32_t* off = s.clean_offsets.data();  // (read only when some face is not a triangle)
  const double* pts = m.points.data();
  // The volume term of a triangle, and whether it extends the leading run.
  auto take_triangle = [&](size_t f, uint32_t i0, uint32_t i1, uint32_t i2) KERGEN_INLINE {
    const double d = s.vol6_about_centre(i0, i1, i2);
    vol6 += d;
    vol6_abs += std::fabs(d);
    if (!certainly_not_collinear(pts + 3 * size_t(i0), pts + 3 * size_t(i1), pts + 3 * size_t(i2))) return false;
    rep_out[f] = {i0, i1, i2};
    return true;
  };
  size_t f = 0;
  if (s.clean_size == 3 * cf) {  // every clean face is a triangle: loop f starts at 3 f
    // A block of terms at a time (triangle_block_terms), taken in face order up to the first
    // triangle the filter does not certify, whose volume is counted.
    double term[kTermBlock];
    while (f < cf) {
      const size_t n = std::min(kTermBlock, cf - f);
      const uint64_t uncertain = triangle_block_terms(s, cl + 3 * f, n, term);
      const size_t stop = uncertain ? size_t(__builtin_ctzll(uncertain)) : n;
      for (size_t j = 0; j < stop; ++j) {
        vol6 += term[j];
        vol6_abs += std::fabs(term[j]);
        rep_out[f + j] = {cl[3 * (f + j)], cl[3 * (f + j) + 1], cl[3 * (f + j) + 2]};
      }
      f += stop;
      if (stop < n) {
        vol6 += term[stop];
        vol6_abs += std::fabs(term[stop]);
        break;
      }
    }
  } else {
    for (; f < cf; ++f) {
      const size_t b = off[f];
      if (off[f + 1] - b != 3 || !take_triangle(f, cl[b], cl[b + 1], cl[b + 2])) break;
    }
  }
  s.first_general = f;
  if (f < cf) {  // (build_plane_faces walks the loops from f on)
    s.own_clean();
    cl = s.cl;
    off = s.clean_offsets.data();
  }
  if (f < cf && off[f + 1] - off[f] == 3) ++f;  // (its volume is counted)
  for (; f < cf; ++f) {
    const size_t b = off[f], e = off[f + 1];
    for (size_t i = b + 1; i + 1 < e; ++i) {
      const double d = s.vol6_about_centre(cl[b], cl[i], cl[i + 1]);
      vol6 += d;
      vol6_abs += std::fabs(d);
    }
  }
  m.rep.resize(s.first_general);
  s.vol6 = vol6;
  s.vol6_abs = vol6_abs;
}

// A closed surface enclosing nothing sums to zero up to rounding; anything at the rounding level
// of the terms' magnitudes is treated as zero. The fans of non-planar polygons may enclose
// nothing where their splits do (two quads over a tetrahedron's corners whose fans take the same
// diagonal): then the split surface decides, in check_split_volume. A negative volume turns the
// loops over.
bool orient_by_volume(Prep& s) {
  PreparedMesh& m = s.m;
  const bool open = s.open != 0;
  if (!open && s.ext == 0)
    return s.fail(Error::DegenerateInput, "the mesh encloses no volume (flat or folded onto itself)");
  s.fans_enclose_nothing = !open && !(std::fabs(s.vol6) > 1e-12 * s.vol6_abs);
  s.flip = s.vol6 < 0 && !open && !s.fans_enclose_nothing;
  m.volume = s.flip ? -s.vol6 / 6 : s.vol6 / 6;
  if (s.flip) {
    m.warnings.push_back(flipped_warning(s.cf));
    s.own_clean();
    for (size_t f = 0; f < s.cf; ++f)
      std::reverse(s.clean.begin() + s.clean_offsets[f], s.clean.begin() + s.clean_offsets[f + 1]);
    if (!s.reps_unwritten)
      for (auto& t : m.rep) std::swap(t[0], t[2]);
  }
  return true;
}

// The fans' volume chose the orientation and the splits then fold outward for it; polygons far
// from planar can fold into a surface that encloses a negative volume (two quads closing a
// tetrahedron, each folded outward after a flip). The split surface is what the planes come from:
// it is turned over once more, as a whole, when its own volume says so. Then the warnings.
bool check_split_volume(Prep& s) {
  PreparedMesh& m = s.m;
  const bool open = s.open != 0;
  if (!open && s.nonplanar > 0 && m.volume < 0) {
    for (size_t f = 0; f + 1 < m.loop_offsets.size(); ++f)
      std::reverse(m.loops.begin() + m.loop_offsets[f], m.loops.begin() + m.loop_offsets[f + 1]);
    if (!s.reps_unwritten)
      for (auto& t : m.rep) std::swap(t[0], t[2]);
    m.volume = -m.volume;
    auto flipped = std::find_if(m.warnings.begin(), m.warnings.end(),
                                [](const Warning& w) { return w.kind == Warning::Kind::OrientationFlipped; });
    if (flipped != m.warnings.end())
      m.warnings.erase(flipped);
    else
      m.warnings.push_back(flipped_warning(s.cf));
  }
  if (!open && (s.nonplanar > 0 || s.fans_enclose_nothing) && !(m.volume > 1e-12 * (s.vol6_abs + s.split_abs) / 6))
    return s.fail(Error::DegenerateInput, s.nonplanar > 0
                                              ? "the mesh encloses no volume once its non-planar polygons are split"
                                              : "the mesh encloses no volume (flat or folded onto itself)");
  m.dropped_faces += s.degenerate;
  if (m.dropped_faces)
    m.warnings.push_back({Warning::Kind::DegenerateFacesDropped, m.dropped_faces,
                          count_of(m.dropped_faces, "zero-area face", "zero-area faces") +
                              verb_for(m.dropped_faces, " was", " were") + " ignored"});
  if (s.nonplanar)
    m.warnings.push_back({Warning::Kind::NonPlanarFacesSplit, s.nonplanar,
                          count_of(s.nonplanar, "non-planar polygon", "non-planar polygons") +
                              verb_for(s.nonplanar, " was", " were") + " split into triangles"});
  if (m.rep.empty()) return s.fail(Error::DegenerateInput, "every face has zero area");
  return true;
}

// A nearly flat shape's volume is far below the rounding of its terms (the points' offsets from
// the centre, rounded, span its thickness): summed again in double-double once the loops are
// final, for shapes thinner than 1e-6 of their bounding cube (rare). The orientation was chosen
// by the double sum. check_split_volume scales its rounding by the terms' magnitudes, but a
// term's own rounding scales with the products inside it, far larger when its cross product
// cancels (or the term is pure noise: a face folded back onto itself). So the accurate sum, with
// its error bound, must certify that the surface as oriented encloses a positive volume; when it
// cannot, the volume was lost in the double sum's rounding and no orientation can be trusted
// (fuzzed: folded shapes with scaled coordinates from 1e-18 to 1, a single face a b b a c).
bool needs_thin_certificate(const Prep& s) { return !s.open && s.m.volume < 1e-6 * s.ext * s.ext * s.ext; }

bool certify_thin_volume(Prep& s) {
  PreparedMesh& m = s.m;
  if (!needs_thin_certificate(s)) return true;
  const exact::ApproxDD vol6_dd = accurate_volume6(m, s.c);
  m.volume = (vol6_dd.hi + vol6_dd.lo) / 6;
  if (vol6_dd.sign() == 1) return true;
  return s.fail(Error::DegenerateInput,
                "the mesh encloses almost no volume and its orientation cannot be decided reliably (flat or folded "
                "onto itself)");
}

}  // namespace kergen::prep
