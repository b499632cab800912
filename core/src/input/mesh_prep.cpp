// Input validation: finite coordinates, valid indices, closed 2-manifold edges with consistent
// orientation, one connected piece, positive enclosed volume (flipped if negative). Zero-area
// faces are detected exactly and dropped (after the topology check, which still counts them:
// they are part of the closed surface, they only carry no plane). prepare_mesh, at the end of the
// file, runs the checks as named phases over one state (Prep), each refusing the mesh or leaving
// its part of the state for the next; non-planar polygons are split in polygon_split.cpp.
#include "input/mesh_prep.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <numeric>
#include <sstream>
#include <utility>

#include "exact/predicates.h"
#include "input/polygon_split.h"
#include "util/compiler_hints.h"
#include "util/point_table.h"
#include "util/union_find.h"

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

// Whether two used vertices have the same position (coordinates compared with ==, so -0 and +0
// are one position): a PointTable of the used vertices, expected linear time, looked up a block
// at a time with the slots prefetched (the table is larger than the caches for big meshes). The
// same pass takes the bounding box of the used vertices, in id order (complete when the answer is
// false).
bool has_shared_position(const std::vector<double>& pts, const std::vector<char>& used, size_t num_used, double lo3[3],
                         double hi3[3]) {
  PointTable table(num_used);
  const double* P = pts.data();
  for (int k = 0; k < 3; ++k) {
    lo3[k] = INFINITY;
    hi3[k] = -INFINITY;
  }
  constexpr size_t kBlock = 64;
  uint32_t ids[kBlock];
  uint64_t hashes[kBlock];
  const char* us = used.data();
  const size_t nv = used.size();
  for (size_t v0 = 0; v0 < nv;) {
    size_t n = 0;
    for (; v0 < nv && n < kBlock; ++v0) {
      if (!us[v0]) continue;
      const double* p = P + 3 * v0;
      for (int k = 0; k < 3; ++k) {
        lo3[k] = std::min(lo3[k], p[k]);
        hi3[k] = std::max(hi3[k], p[k]);
      }
      ids[n] = uint32_t(v0);
      hashes[n] = PointTable::hash(p);
      table.prefetch_slot(hashes[n]);
      ++n;
    }
    for (size_t j = 0; j < n; ++j)
      if (table.find_or_insert(P, P + 3 * size_t(ids[j]), hashes[j], ids[j]) != ids[j]) return true;
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

// The state prepare_mesh's phases share, filled in the order they run. Each phase returns false
// once it has refused the mesh (m.error and m.message set by fail()).
struct Prep {
  Prep(const MeshView& mesh_in, const Options& options_in, bool allow_shells_in)
      : mesh(mesh_in), options(options_in), allow_shells(allow_shells_in) {}
  const MeshView& mesh;
  const Options& options;
  const bool allow_shells;
  PreparedMesh m;  // the result
  size_t nv = 0, nf = 0;

  // check_coordinates: the largest magnitude (for the scale) and the smallest non-zero one (for
  // the exact shift); the scale's exponent.
  double maxabs = 0, min_nonzero_abs = INFINITY;
  int ex = 0;

  // clean_faces: the faces without repeated consecutive vertices (cf of them), the used
  // vertices, and the edge uses counted per bucket. Edge uses are bucketed by their lower vertex
  // id and direction: bucket 2 lo + 1 holds the uses running up from lo (lo -> hi, hi > lo),
  // bucket 2 lo those running down to lo. bucket[b + 1]: size of bucket b, then its end, then
  // (after the fill) its start.
  RawVector<uint32_t> clean, clean_offsets;
  size_t cf = 0;
  // The input face of each clean face, from the first face dropped on (before it: the identity).
  std::vector<uint32_t> clean_source;
  bool clean_renumbered = false;
  uint32_t input_of_clean(size_t f) const { return clean_renumbered ? clean_source[f] : uint32_t(f); }
  std::vector<char> used;
  std::vector<uint32_t> bucket;
  uint32_t total_uses = 0;

  // pair_edges: faulty edges counted, the one named the smallest (lower id, upper id); pairs of
  // faces sharing an edge; connected pieces = faces - successful unions.
  size_t open = 0, nonmanifold = 0, inconsistent = 0;
  uint64_t open_ex = UINT64_MAX, nonmanifold_ex = UINT64_MAX, inconsistent_ex = UINT64_MAX;
  UnionFind components{0};
  size_t unions = 0;
  RawVector<std::array<uint32_t, 2>> face_pairs;

  // check_shared_positions: the bounding box of the used vertices.
  double lo3[3], hi3[3];

  // sum_fan_volume: the box centre, its largest side, six times the volume of the fans about the
  // centre and the sum of its terms' magnitudes; the leading run of faces kept as they are.
  double c[3] = {0, 0, 0}, ext = 0;
  double vol6 = 0, vol6_abs = 0;
  size_t first_general = 0;
  bool fans_enclose_nothing = false, flip = false;

  // build_plane_faces
  size_t degenerate = 0, nonplanar = 0;
  double split_abs = 0;  // sum of |terms| of the split polygons' volume corrections
  bool renumbered = false;
  std::vector<uint32_t> face_of_clean;  // used once renumbered

  bool fail(Error e, const std::string& msg) {
    m.error = e;
    m.message = msg;
    m.rep = {};  // (its storage may hold the edge check's scratch)
    return false;
  }
  const double* P(uint32_t v) const { return &m.points[3 * size_t(v)]; }
  size_t face_size(size_t f) const { return mesh.face_sizes ? mesh.face_sizes[f] : 3; }

  // Six times the signed volume of the tetrahedron (c, p0, p1, p2).
  KERGEN_INLINE double vol6_about_centre(uint32_t i0, uint32_t i1, uint32_t i2) const {
    const double *p0 = P(i0), *p1 = P(i1), *p2 = P(i2);
    double a[3], bb[3], cc[3];
    for (int k = 0; k < 3; ++k) {
      a[k] = p0[k] - c[k];
      bb[k] = p1[k] - c[k];
      cc[k] = p2[k] - c[k];
    }
    return a[0] * (bb[1] * cc[2] - bb[2] * cc[1]) - a[1] * (bb[0] * cc[2] - bb[2] * cc[0]) +
           a[2] * (bb[0] * cc[1] - bb[1] * cc[0]);
  }
};

// Null arrays, empty meshes, the size limits, and face sizes that add up. (No offsets are
// stored: the faces are walked in order later.)
bool check_arrays(Prep& s) {
  const MeshView& mesh = s.mesh;
  const size_t nv = s.nv, nf = s.nf;
  if ((nv > 0 && !mesh.positions) || (mesh.num_indices > 0 && !mesh.indices) ||
      (mesh.face_sizes == nullptr && mesh.num_faces > 0 && mesh.num_faces != nf))
    return s.fail(Error::InvalidArgument, "null array with a non-zero size, or num_faces given without face_sizes");
  if (nv == 0) return s.fail(Error::EmptyInput, "the mesh has no vertices");
  if (nf == 0) return s.fail(Error::EmptyInput, "the mesh has no faces");
  if (nf > s.options.max_faces || nv > s.options.max_vertices) {
    std::ostringstream msg;
    msg << "the mesh has " << nf << " faces and " << nv << " vertices; the limit is " << s.options.max_faces
        << " faces and " << s.options.max_vertices << " vertices (Options::max_faces / Options::max_vertices)";
    return s.fail(Error::TooLarge, msg.str());
  }
  if (!mesh.face_sizes && mesh.num_indices % 3 != 0)
    return s.fail(Error::InvalidArgument,
                  "triangle indices: the count " + std::to_string(mesh.num_indices) + " is not a multiple of 3");
  if (!mesh.face_sizes) return true;
  size_t total = 0;
  for (size_t f = 0; f < nf; ++f) {
    size_t k = mesh.face_sizes[f];
    if (k < 3) {
      std::ostringstream msg;
      msg << "face " << f << " has " << k << " vertices; a face needs at least 3";
      return s.fail(Error::FaceTooSmall, msg.str());
    }
    total += k;
    if (total > mesh.num_indices)
      return s.fail(Error::InvalidArgument, "face sizes add up to more than the number of indices");
  }
  if (total != mesh.num_indices)
    return s.fail(Error::InvalidArgument, "face sizes add up to " + std::to_string(total) + " but " +
                                              std::to_string(mesh.num_indices) + " indices were given");
  return true;
}

// Finite coordinates, the largest magnitude and the smallest non-zero one in one pass
// (magnitude_extrema), and indices in range (the largest one first, a branch-free pass); the
// culprits are looked for only if needed.
bool check_coordinates_and_indices(Prep& s) {
  const double* pos = s.mesh.positions;
  uint64_t top_bits;
  int64_t low_bits;
  magnitude_extrema(pos, 3 * s.nv, top_bits, low_bits);
  if (top_bits >= 0x7ff0000000000000ull) {  // (the bits of infinity)
    size_t i = 0;
    while (std::isfinite(pos[i])) ++i;
    std::ostringstream msg;
    msg << "vertex " << i / 3 << " has a non-finite coordinate (" << pos[i] << ")";
    return s.fail(Error::NonFiniteCoordinate, msg.str());
  }
  std::memcpy(&s.maxabs, &top_bits, sizeof s.maxabs);
  if (low_bits != INT64_MAX) {
    const uint64_t min_bits = uint64_t(low_bits) + 1;
    std::memcpy(&s.min_nonzero_abs, &min_bits, sizeof s.min_nonzero_abs);
  }
  const uint32_t* indices = s.mesh.indices;
  uint32_t max_index = 0;
  for (size_t i = 0; i < s.mesh.num_indices; ++i) max_index = std::max(max_index, indices[i]);
  if (max_index < s.nv) return true;
  size_t i = 0;
  while (indices[i] < s.nv) ++i;
  size_t f = 0;
  for (size_t end = s.face_size(0); end <= i; end += s.face_size(++f)) {}
  std::ostringstream msg;
  msg << "face " << f << " refers to vertex " << indices[i] << " but the mesh has " << s.nv << " vertices";
  return s.fail(Error::IndexOutOfRange, msg.str());
}

// Scale by a power of two (exact) so that coordinates are below 1 in magnitude: keeps the exact
// arithmetic away from overflow and underflow whatever the input's units. The exact predicates
// are polynomials of degree <= 9 in the coordinates. Expansion arithmetic is exact only while no
// bit of a product falls below 2^-1074 (underflow) and no magnitude reaches ~2^996 (the splitter
// overflows): with coordinates below 1, the lowest set bit L of any coordinate must satisfy
// 9 (L + shift) >= -1074 + margin and 9 shift + 10 < 996.
bool scale_points(Prep& s) {
  PreparedMesh& m = s.m;
  const size_t n = 3 * s.nv;
  if (s.maxabs > 0) std::frexp(s.maxabs, &s.ex);
  // (As an exponent: for an input of subnormal numbers only, 2^-ex itself is not a double.)
  m.scale_exp = -s.ex;
  // When 2^scale_exp is a double, multiplying by it rounds exactly like ldexp (both give the
  // correctly rounded x 2^scale_exp, subnormal results included) at a fraction of the cost;
  // otherwise (inputs of subnormal numbers only) ldexp scales each coordinate.
  const bool exact_factor = m.scale_exp >= -1074 && m.scale_exp <= 1023;
  const double factor = exact_factor ? std::ldexp(1.0, m.scale_exp) : 0;
  const int kLowestAllowed = -112, kMaxShift = 109;
  int lowest = 0;
  // The lowest set bit of a coordinate lies at most 52 bits below its leading one: when every
  // non-zero coordinate is at least 2^(kLowestAllowed + 52), no lowest bit needs reading.
  if (exact_factor && s.min_nonzero_abs * factor >= std::ldexp(1.0, kLowestAllowed + 52)) {
    m.points = std::vector<double>(ScaledCoordinates{s.mesh.positions, factor},
                                   ScaledCoordinates{s.mesh.positions + n, factor});
  } else {
    m.points.resize(n);
    for (size_t i = 0; i < n; ++i) {
      const double x = exact_factor ? s.mesh.positions[i] * factor : m.to_scaled(s.mesh.positions[i]);
      m.points[i] = x;
      if (x != 0) lowest = std::min(lowest, lowest_bit_exponent(x));
    }
  }
  const int shift = std::max(0, kLowestAllowed - lowest);
  if (shift > kMaxShift) {
    std::ostringstream msg;
    msg << "coordinates span about " << int(-lowest * 0.30103) << " decimal orders of magnitude (largest |x| "
        << s.maxabs << ", finest bit 2^" << lowest + s.ex << "); exact evaluation supports about "
        << int((kMaxShift - kLowestAllowed) * 0.30103) << " — snap tiny coordinates to 0 or rescale";
    return s.fail(Error::CoordinateRange, msg.str());
  }
  m.exact_shift = shift;
  return true;
}

// Faces without repeated consecutive vertices; faces left with < 3 distinct vertices carry no
// area and no edges of their own (a -> b -> a pairs cancel), so they are dropped here. The same
// pass marks the used vertices and counts the edge uses per bucket (Prep::bucket). (Raw pointers
// in the loops: the stores through char would otherwise make the compiler reload every vector's
// pointers after each one.)
bool clean_faces(Prep& s) {
  const MeshView& mesh = s.mesh;
  const size_t nf = s.nf;
  s.clean.resize(mesh.num_indices);  // (written in full below)
  s.clean_offsets.resize(nf + 1);
  s.used.assign(s.nv, 0);
  s.bucket.assign(2 * s.nv + 2, 0);
  const uint32_t* in = mesh.indices;
  uint32_t* cl = s.clean.data();
  uint32_t* off = s.clean_offsets.data();
  off[0] = 0;
  char* us = s.used.data();
  uint32_t* count = s.bucket.data() + 1;
  // (bucket 2 lo + 1 < 2 hi, bucket 2 lo < 2 hi + 1: the smaller is the use's bucket)
  auto count_use = [count](uint32_t u, uint32_t v) { count[std::min(2 * size_t(u) + 1, 2 * size_t(v))]++; };
  size_t n = 0, dropped = 0, cf = 0;  // clean entries so far, faces dropped, clean faces
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
      if (s.clean_renumbered) s.clean_source.push_back(uint32_t(f));
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
      if (!s.clean_renumbered) {
        s.clean_renumbered = true;
        s.clean_source.resize(cf);
        std::iota(s.clean_source.begin(), s.clean_source.end(), 0u);
      }
      continue;
    }
    off[++cf] = uint32_t(n);
    if (s.clean_renumbered) s.clean_source.push_back(uint32_t(f));
    for (size_t i = begin; i < n; ++i) {
      const uint32_t u = cl[i], v = cl[i + 1 < n ? i + 1 : begin];
      us[u] = 1;
      count_use(u, v);
    }
  }
  s.clean.resize(n);
  s.clean_offsets.resize(cf + 1);
  s.m.dropped_faces += dropped;
  s.cf = cf;
  if (cf == 0) return s.fail(Error::DegenerateInput, "every face has fewer than 3 distinct vertices");
  return true;
}

// The edge check's pass over the edge uses, bucketed (Prep::bucket) by lower vertex: the uses of
// the edges of one lower vertex are tallied per upper vertex, then each edge is judged once. On a
// closed, consistently oriented 2-manifold every edge has one use each way, and its two faces
// are a pair. Pairs are listed by lower vertex id, then in the order of the faces using the edge
// upwards; each pair lists its lower face first. At most one pair per two uses; written through
// a pointer (push_back went through a stack copy, a store-forwarding stall).
class EdgePairing {
 public:
  EdgePairing(Prep& s, const uint32_t* upper, const uint32_t* use_face, size_t nv)
      : s_(s),
        upper_(upper),
        use_face_(use_face),
        tally_store_(nv),
        tally_(tally_store_.data()),
        parent_(s.components.parent.data()),
        pair_out_(s.face_pairs.data()) {}
  void pair_all(size_t nv) {
    const uint32_t* start = s_.bucket.data() + 1;
    for (size_t lo = 0; lo < nv; ++lo) pair_lower_vertex(lo, start[2 * lo], start[2 * lo + 1], start[2 * lo + 2]);
    s_.face_pairs.resize(size_t(pair_out_ - s_.face_pairs.data()));
  }

 private:
  struct Tally {
    uint32_t up = 0, down = 0, up_face = 0, down_face = 0;
  };
  // (Nine finds in ten end within one step, about half of them at once: both cases are taken
  // without a branch on which, which mispredicted often.)
  KERGEN_INLINE uint32_t find(uint32_t x) const {
    const uint32_t up = parent_[x], up2 = parent_[up];
    if (up2 == up) return up;
    x = up;
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  // (the smaller root wins, as in UnionFind::unite)
  KERGEN_INLINE void unite(uint32_t f0, uint32_t f1) {
    const uint32_t r0 = find(f0), r1 = find(f1);
    if (r0 != r1) {
      parent_[std::max(r0, r1)] = std::min(r0, r1);
      ++s_.unions;
    }
  }
  // The uses of lo's edges: [down_begin, up_begin) run down to lo, [up_begin, end) up from it.
  KERGEN_INLINE void pair_lower_vertex(size_t lo, size_t down_begin, size_t up_begin, size_t end) {
    for (size_t j = down_begin; j != up_begin; ++j) {
      Tally& t = tally_[upper_[j]];
      ++t.down;
      t.down_face = use_face_[j];
    }
    // The upward uses are paired as they are tallied, tentatively (a later use of the same edge
    // may spoil a pair). When each upward use made a pair and each downward use is in one,
    // every edge of lo has one use each way, and the pairs are the ones judge() would make, in
    // the same order: they stand, and only the tallies are cleared. (A pair never overwrites a
    // use not read yet: lo's pairs number at most its downward uses and its upward uses read.)
    const size_t downs = up_begin - down_begin, ups = end - up_begin;
    std::array<uint32_t, 2>* const pairs_before = pair_out_;
    for (size_t j = up_begin; j != end; ++j) {
      Tally& t = tally_[upper_[j]];
      ++t.up;
      t.up_face = use_face_[j];
      if (t.up == 1 && t.down == 1) {
        (*pair_out_)[0] = std::min(t.up_face, t.down_face);
        (*pair_out_)[1] = std::max(t.up_face, t.down_face);
        ++pair_out_;
      }
    }
    if (ups == downs && pair_out_ == pairs_before + ups) {
      for (size_t j = up_begin; j != end; ++j) {
        tally_[upper_[j]] = Tally{};
        const auto& pair = pairs_before[j - up_begin];
        unite(pair[0], pair[1]);
      }
      return;
    }
    pair_out_ = pairs_before;
    for (size_t j = up_begin; j != end; ++j) judge(lo, upper_[j]);
    // (as many pairs as downward uses: each pair took one, all are judged and cleared)
    if (size_t(pair_out_ - pairs_before) == downs) return;
    for (size_t j = down_begin; j != up_begin; ++j) judge(lo, upper_[j]);
  }
  // Edge (lo, hi), judged at its first upward use, or first downward use if it has none; then
  // its tally is cleared.
  void judge(size_t lo, uint32_t hi) {
    Tally& t = tally_[hi];
    if (t.up == 1 && t.down == 1) {
      const uint32_t f0 = std::min(t.up_face, t.down_face), f1 = std::max(t.up_face, t.down_face);
      (*pair_out_)[0] = f0;
      (*pair_out_)[1] = f1;
      ++pair_out_;
      unite(f0, f1);
    } else if (t.up + t.down > 0) {  // else judged already
      const uint64_t key = uint64_t(lo) << 32 | hi;
      const size_t n = size_t(t.up) + t.down;
      if (n == 1)
        note(s_.open, s_.open_ex, key);
      else if (n > 2)
        note(s_.nonmanifold, s_.nonmanifold_ex, key);
      else
        note(s_.inconsistent, s_.inconsistent_ex, key);  // two uses the same way
    }
    t = Tally{};
  }
  static void note(size_t& count, uint64_t& example, uint64_t key) {
    ++count;
    example = std::min(example, key);
  }
  Prep& s_;
  const uint32_t* upper_;
  const uint32_t* use_face_;
  std::vector<Tally> tally_store_;  // per upper vertex id; all zero between lower vertices
  Tally* tally_;
  uint32_t* parent_;
  std::array<uint32_t, 2>* pair_out_;
};

// The edge check: a counting sort of the edge uses into their buckets (no hashing and no
// comparison sort), then EdgePairing. A use is stored as its upper vertex id and its face, in two
// arrays indexed alike. No fresh memory is taken for them (first touches of fresh pages are
// costly): the faces go into the pairs' storage, which holds one face per use, and the upper ids
// into the representatives' storage (written after the check) when it holds one id per use,
// which is when every face is a triangle. The pairs written while a lower vertex's uses are
// judged end before the uses not read yet (at most one pair per two uses, and each lower
// vertex's faces are all read, by the tally, before its first pair is written).
void pair_edges(Prep& s) {
  const size_t nv = s.nv, cf = s.cf;
  std::vector<uint32_t>& bucket = s.bucket;
  uint32_t total_uses = 0;  // (the running sum stays in a register)
  for (size_t b = 1; b <= 2 * nv; ++b) bucket[b] = total_uses += bucket[b];
  bucket[2 * nv + 1] = total_uses;
  s.components = UnionFind(cf);
  s.face_pairs.resize((size_t(total_uses) + 1) / 2);
  static_assert(sizeof(std::array<uint32_t, 3>) == 3 * sizeof(uint32_t), "packed representatives");
  static_assert(sizeof(std::array<uint32_t, 2>) == 2 * sizeof(uint32_t), "packed pairs");
  RawVector<uint32_t> upper_store;
  uint32_t* upper;
  if (total_uses == 3 * cf) {
    s.m.rep.resize(cf);
    upper = reinterpret_cast<uint32_t*>(s.m.rep.data());
  } else {
    upper_store.resize(total_uses);
    upper = upper_store.data();
  }
  uint32_t* use_face = reinterpret_cast<uint32_t*>(s.face_pairs.data());
  // Filled backwards, each use at its bucket's end moved down by one: the buckets keep the uses
  // in face order, and bucket[b + 1] ends at the start of bucket b (no separate cursor array).
  // Then bucket b is [bucket[b + 1], bucket[b + 2]).
  const uint32_t* cl = s.clean.data();
  const uint32_t* off = s.clean_offsets.data();
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
  EdgePairing(s, upper, use_face, nv).pair_all(nv);
}

std::string edge_name(uint64_t k) {
  return "(" + std::to_string(uint32_t(k >> 32)) + ", " + std::to_string(uint32_t(k & 0xffffffffu)) + ")";
}

// Refuses non-manifold, inconsistently oriented and (unless allowed) open edges, in that order.
bool report_edge_faults(Prep& s) {
  if (s.nonmanifold) {
    return s.fail(Error::NonManifoldEdge,
                  std::to_string(s.nonmanifold) + " edge(s) are shared by more than two faces, e.g. edge " +
                      edge_name(s.nonmanifold_ex) + " (repeated faces? Options::repair removes them)");
  }
  if (s.inconsistent) {
    return s.fail(Error::InconsistentOrientation,
                  std::to_string(s.inconsistent) +
                      " edge(s) are traversed in the same direction by both of their faces (inconsistent "
                      "orientation), e.g. edge " +
                      edge_name(s.inconsistent_ex));
  }
  if (s.open && !s.options.allow_open) {
    return s.fail(Error::OpenMesh,
                  "the mesh is open: " + std::to_string(s.open) + " edge(s) belong to one face only, e.g. edge " +
                      edge_name(s.open_ex) +
                      " (Options::weld merges nearly coincident vertices, Options::repair also splits T-junctions; "
                      "Options::allow_open accepts open meshes)");
  }
  s.m.boundary_edges = s.open;
  return true;
}

// Connected pieces. Faces joined by boundary edges only are joined through vertices. Several
// closed pieces are the caller's to judge (shells.h) when it says so; an open one is refused.
bool count_components(Prep& s) {
  if (s.open) {
    std::vector<uint32_t> first_face(s.nv, 0xffffffffu);
    for (size_t f = 0; f < s.cf; ++f)
      for (size_t i = s.clean_offsets[f]; i < s.clean_offsets[f + 1]; ++i) {
        uint32_t v = s.clean[i];
        if (first_face[v] == 0xffffffffu)
          first_face[v] = uint32_t(f);
        else
          s.unions += s.components.unite(first_face[v], uint32_t(f));
      }
  }
  const size_t pieces = s.cf - s.unions;
  s.m.shells = pieces;
  if (pieces > 1 && (s.open || !s.allow_shells)) {
    return s.fail(Error::MultipleComponents,
                  "the mesh has " + std::to_string(pieces) +
                      " separate pieces; the kernel is defined for one closed surface (a triangle soup? "
                      "Options::weld merges its corners)");
  }
  return true;
}

// Unused vertices are a warning. Two distinct vertices of a closed surface at one position: the
// surface touches itself there (it is not embedded), and the intersection of its face
// half-spaces is then not its kernel — refused rather than answered wrongly. The same pass takes
// the bounding box of the used vertices (Prep::lo3, hi3).
bool check_shared_positions(Prep& s) {
  const size_t unused = s.nv - size_t(std::count(s.used.begin(), s.used.end(), 1));
  if (unused) s.m.warnings.push_back(unused_vertices_warning(unused));
  if (!has_shared_position(s.m.points, s.used, s.nv - unused, s.lo3, s.hi3)) return true;
  const auto pair = first_shared_position(s.m.points, s.used);
  return s.fail(Error::NonManifoldEdge,
                "vertices " + std::to_string(pair[0]) + " and " + std::to_string(pair[1]) +
                    " have the same position: the surface touches itself there (weld them, or separate the pieces)");
}

// Bounding box of the used vertices. It is defined as if taken over every use in loop order: ties
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
  for (size_t i = 0; i < s.clean.size() && zeros > 0; ++i)
    for (int k = 0; k < 3; ++k) {
      const double x = pts[3 * size_t(s.clean[i]) + k];
      if (zero[k] && x == 0) {
        if (lo3[k] == 0) lo3[k] = x;
        if (hi3[k] == 0) hi3[k] = x;
        zero[k] = false;
        --zeros;
      }
    }
  for (int k = 0; k < 3; ++k) {
    s.m.bbox_min[k] = lo3[k];
    s.m.bbox_max[k] = hi3[k];
  }
}

// Enclosed volume (double; relative to the box centre for accuracy), as fans of the clean faces.
// The usual leading run of the plane faces is taken in the same pass (the points are read once):
// triangles that a float filter certifies as non-degenerate are kept whole with themselves as
// representatives, written in place (turned over by orient_by_volume on a flip; the filter only
// shortcuts the exact test, so the order of the corners it sees does not matter).
void sum_fan_volume(Prep& s) {
  PreparedMesh& m = s.m;
  for (int k = 0; k < 3; ++k) {
    s.c[k] = 0.5 * (m.bbox_min[k] + m.bbox_max[k]);
    s.ext = std::max(s.ext, m.bbox_max[k] - m.bbox_min[k]);
  }
  const size_t cf = s.cf;
  double vol6 = 0, vol6_abs = 0;
  m.rep.resize(cf);
  std::array<uint32_t, 3>* rep_out = m.rep.data();
  const uint32_t* cl = s.clean.data();
  const uint32_t* off = s.clean_offsets.data();
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
  if (s.clean.size() == 3 * cf) {  // every clean face is a triangle: loop f starts at 3 f
    for (; f < cf; ++f)
      if (!take_triangle(f, cl[3 * f], cl[3 * f + 1], cl[3 * f + 2])) break;
  } else {
    for (; f < cf; ++f) {
      const size_t b = off[f];
      if (off[f + 1] - b != 3 || !take_triangle(f, cl[b], cl[b + 1], cl[b + 2])) break;
    }
  }
  s.first_general = f;
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
    for (size_t f = 0; f < s.cf; ++f)
      std::reverse(s.clean.begin() + s.clean_offsets[f], s.clean.begin() + s.clean_offsets[f + 1]);
    for (auto& t : m.rep) std::swap(t[0], t[2]);
  }
  return true;
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

// Plane-carrying faces after the leading run: exact zero-area ones are dropped; planar polygons
// keep one representative triangle at their lexicographically smallest vertex (a strictly convex
// corner, so the triangle has the polygon's orientation); non-planar polygons are split.
bool build_plane_faces(Prep& s) {
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
                          std::to_string(m.dropped_faces) + " zero-area faces were ignored"});
  if (s.nonplanar)
    m.warnings.push_back({Warning::Kind::NonPlanarFacesSplit, s.nonplanar,
                          std::to_string(s.nonplanar) + " non-planar polygons were split into triangles"});
  if (m.rep.empty()) return s.fail(Error::DegenerateInput, "every face has zero area");
  return true;
}

// The loops and the pairs of neighbouring faces, renumbered if faces were dropped or split.
void move_loops(Prep& s) {
  PreparedMesh& m = s.m;
  if (!s.renumbered) {
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

// A nearly flat shape's volume is far below the rounding of its terms (the points' offsets from
// the centre, rounded, span its thickness): summed again in double-double once the loops are
// final, for shapes thinner than 1e-6 of their bounding cube (rare). The orientation was chosen
// by the double sum. check_split_volume scales its rounding by the terms' magnitudes, but a
// term's own rounding scales with the products inside it, far larger when its cross product
// cancels (or the term is pure noise: a face folded back onto itself). So the accurate sum, with
// its error bound, must certify that the surface as oriented encloses a positive volume; when it
// cannot, the volume was lost in the double sum's rounding and no orientation can be trusted
// (fuzzed: folded shapes with scaled coordinates from 1e-18 to 1, a single face a b b a c).
bool certify_thin_volume(Prep& s) {
  PreparedMesh& m = s.m;
  if (s.open || !(m.volume < 1e-6 * s.ext * s.ext * s.ext)) return true;
  const exact::ApproxDD vol6_dd = accurate_volume6(m, s.c);
  m.volume = (vol6_dd.hi + vol6_dd.lo) / 6;
  if (vol6_dd.sign() == 1) return true;
  return s.fail(Error::DegenerateInput,
                "the mesh encloses almost no volume and its orientation cannot be decided reliably (flat or folded "
                "onto itself)");
}

}  // namespace

Warning unused_vertices_warning(size_t count) {
  return {Warning::Kind::UnusedVertices, count, std::to_string(count) + " vertices are not used by any face"};
}

// The phases in order; each refuses the mesh or leaves its part of the state for the next.
PreparedMesh prepare_mesh(const MeshView& mesh, const Options& options, bool allow_shells) {
  Prep s(mesh, options, allow_shells);
  s.nv = mesh.num_vertices;
  s.nf = mesh.face_sizes ? mesh.num_faces : mesh.num_indices / 3;
  s.m.input_faces = s.nf;
  // (A phase that refuses the mesh has set m.error and m.message; m is returned as it stands.)
  if (!check_arrays(s) || !check_coordinates_and_indices(s) || !scale_points(s) || !clean_faces(s))
    return std::move(s.m);
  pair_edges(s);
  if (!report_edge_faults(s) || !count_components(s) || !check_shared_positions(s)) return std::move(s.m);
  take_bounding_box(s);
  sum_fan_volume(s);
  if (!orient_by_volume(s) || !build_plane_faces(s) || !check_split_volume(s)) return std::move(s.m);
  move_loops(s);
  certify_thin_volume(s);
  return std::move(s.m);
}

}  // namespace kergen
