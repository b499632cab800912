// The first phases of prepare_mesh (prep_state.h), over the raw arrays: null and empty arrays,
// the size limits and face sizes (check_arrays); finite coordinates and indices in range, with the
// largest and smallest non-zero magnitudes taken in one branch-free pass
// (check_coordinates); and the exact power-of-two scale and shift that keep the exact
// predicates clear of overflow and underflow (scale_points, which refuses coordinate ranges too
// wide for exact evaluation).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "input/prep_state.h"
#include "util/compiler_hints.h"

namespace kergen::prep {

namespace {

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
// (magnitude_extrema); the culprit is looked for only if needed. (The indices are checked by
// clean_faces, which reads them anyway.)
bool check_coordinates(Prep& s) {
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
  return true;
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

}  // namespace kergen::prep
