// Decoder and checks of the fuzz_kernel target, shared with tests/core/regression_test.cpp (which
// replays crash inputs found by the fuzzer).
#pragma once

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "fixtures.h"
#include "invariants.h"
#include "kergen/io.h"
#include "kergen/kergen.h"

namespace kfuzz {
namespace kernel_input {

using kergen::Mesh;
using namespace kergen_test;

struct Bytes {
  const uint8_t* data;
  size_t size;
  size_t pos = 0;
  uint8_t u8() { return pos < size ? data[pos++] : 0; }
  bool empty() const { return pos >= size; }
};

inline Mesh octahedron() {
  Mesh m;
  add_point(m, 1, 0, 0);
  add_point(m, -1, 0, 0);
  add_point(m, 0, 1, 0);
  add_point(m, 0, -1, 0);
  add_point(m, 0, 0, 1);
  add_point(m, 0, 0, -1);
  const uint32_t f[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (const auto& t : f) add_face(m, {t[0], t[1], t[2]});
  return m;
}

// Star-shaped bumpy sphere (radius 1 + 0.25 sin(3 theta) cos(2 phi)): a small UV sphere.
inline Mesh bumpy_sphere(int nu, int nv) {
  Mesh m;
  const double pi = 3.14159265358979323846;
  const uint32_t north = add_point(m, 0, 0, 1), south = add_point(m, 0, 0, -1);
  for (int j = 1; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      double th = pi * j / nv, ph = 2 * pi * i / nu;
      double r = 1 + 0.25 * std::sin(3 * th) * std::cos(2 * ph);
      add_point(m, r * std::sin(th) * std::cos(ph), r * std::sin(th) * std::sin(ph), r * std::cos(th));
    }
  auto id = [&](int j, int i) { return uint32_t(2 + (j - 1) * nu + (i % nu)); };
  for (int i = 0; i < nu; ++i) {
    add_face(m, {north, id(1, i), id(1, i + 1)});
    add_face(m, {south, id(nv - 1, i + 1), id(nv - 1, i)});
  }
  for (int j = 1; j + 1 < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      add_face(m, {id(j, i), id(j + 1, i), id(j + 1, i + 1)});
      add_face(m, {id(j, i), id(j + 1, i + 1), id(j, i + 1)});
    }
  return m;
}

inline Mesh concat(const Mesh& a, const Mesh& b) {
  Mesh m = a;
  const uint32_t base = uint32_t(a.num_vertices());
  m.positions.insert(m.positions.end(), b.positions.begin(), b.positions.end());
  if (!a.face_sizes.empty() || !b.face_sizes.empty()) {
    if (m.face_sizes.empty()) m.face_sizes.assign(a.indices.size() / 3, 3);
    if (b.face_sizes.empty())
      m.face_sizes.insert(m.face_sizes.end(), b.indices.size() / 3, 3);
    else
      m.face_sizes.insert(m.face_sizes.end(), b.face_sizes.begin(), b.face_sizes.end());
  }
  for (uint32_t v : b.indices) m.indices.push_back(v + base);
  return m;
}

inline Mesh raw_mesh(Bytes& in) {
  Mesh m;
  const int nv = 3 + in.u8() % 14;
  const int nf = 1 + in.u8() % 28;
  // (Each byte read in its own statement: the order of evaluation of function arguments is
  // unspecified, and g++ and clang++ differ, so a crash input found by the clang fuzzer would
  // decode to another mesh in the g++ regression tests.)
  for (int v = 0; v < nv; ++v) {
    const int x = int8_t(in.u8()) % 5, y = int8_t(in.u8()) % 5, z = int8_t(in.u8()) % 5;
    add_point(m, x, y, z);
  }
  const bool polygons = in.u8() & 1;
  for (int f = 0; f < nf; ++f) {
    const uint32_t n = polygons ? 1 + in.u8() % 6 : 3;
    if (polygons) m.face_sizes.push_back(n);
    for (uint32_t i = 0; i < n; ++i) m.indices.push_back(in.u8() % (nv + 1));  // nv: out of range
  }
  return m;
}

inline Mesh base_mesh(Bytes& in, uint8_t which) {
  switch (which % 24) {
    case 0: return unit_cube();
    case 1: return tessellated_cube(2);
    case 2: return octahedron();
    case 3: return dented_cube();
    case 4: return l_prism();
    case 5: return plus_prism(0.3);
    case 6: return s_prism();         // kernel: a polygon
    case 7: return pinwheel_prism();  // kernel: a segment
    case 8: return u_prism();         // not star-shaped
    case 9: return pyramid(5);
    case 10: return pyramid(7, 1, 1e-3);  // flat pyramid: near-coplanar faces
    case 11: return bumpy_sphere(8, 6);
    case 12: return bumpy_sphere(5, 4);
    case 13: {
      const uint8_t seed = in.u8(), points = uint8_t(4 + in.u8() % 10);  // (in this order: see raw_mesh)
      return random_convex(seed, points).mesh;
    }
    case 14: return torus(6, 4);
    case 15: return open_cube();
    case 16: return cubes_sharing_edge();
    case 17: return concat(unit_cube(), box(3, 0, 0, 4, 1, 1));  // two components
    case 18: {                                                   // flat: a square used from both sides
      Mesh m;
      add_point(m, 0, 0, 0);
      add_point(m, 1, 0, 0);
      add_point(m, 1, 1, 0);
      add_point(m, 0, 1, 0);
      add_face(m, {0, 1, 2});
      add_face(m, {0, 2, 3});
      add_face(m, {0, 2, 1});
      add_face(m, {0, 3, 2});
      return m;
    }
    case 19: return box(0, 0, 0, 1, 1e-9, 1);  // sliver box
    case 20: return plus_prism(1e-7);          // tiny kernel
    default: return raw_mesh(in);
  }
}

inline double special(uint8_t b) {
  switch (b % 10) {
    case 0: return 0.0;
    case 1: return -0.0;
    case 2: return std::numeric_limits<double>::denorm_min();
    case 3: return DBL_MIN;
    case 4: return DBL_MAX;
    case 5: return -DBL_MAX / 4;
    case 6: return std::numeric_limits<double>::quiet_NaN();
    case 7: return std::numeric_limits<double>::infinity();
    case 8: return 1e-300;
    default: return 1e300;
  }
}

inline void perturb(Mesh& m, Bytes& in, int max_ops) {
  const size_t nv = m.num_vertices();
  if (nv == 0) return;
  double ext = 0;
  for (double c : m.positions) ext = std::max(ext, std::fabs(c));
  if (!(ext > 0) || !std::isfinite(ext)) ext = 1;
  for (int op_i = 0; op_i < max_ops && !in.empty(); ++op_i) {
    const uint8_t op = in.u8(), v = in.u8(), a = in.u8(), b = in.u8();
    double* p = &m.positions[3 * (v % nv)];
    const int axis = a % 3;
    switch (op % 9) {
      case 0: {  // a few ulps
        const double to = (b & 0x80) ? INFINITY : -INFINITY;
        for (int i = 0; i <= (b & 7); ++i) p[axis] = std::nextafter(p[axis], to);
        break;
      }
      case 1:  // 2^-k of the extent
        p[axis] += ((b & 0x80) ? -1 : 1) * std::ldexp(ext, -int(b % 64));
        break;
      case 2:  // copy one coordinate from another vertex: new coplanarities
        p[axis] = m.positions[3 * (b % nv) + axis];
        break;
      case 3: {  // midpoint of two vertices: slivers and collinear corners
        const double* q = &m.positions[3 * (a % nv)];
        const double* r = &m.positions[3 * (b % nv)];
        for (int c = 0; c < 3; ++c) p[c] = q[c] / 2 + r[c] / 2;
        break;
      }
      case 4:  // onto another vertex: zero-area faces
        std::memcpy(p, &m.positions[3 * (b % nv)], 3 * sizeof(double));
        break;
      case 5:
        if ((b & 0x0f) == 0) p[axis] = special(b >> 4);  // rare: special values
        break;
      case 6: {  // swap two corners of a face: inconsistent orientation
        if (m.indices.size() < 2) break;
        size_t i = (size_t(a) << 8 | b) % m.indices.size();
        size_t j = i + 1 < m.indices.size() ? i + 1 : i - 1;
        std::swap(m.indices[i], m.indices[j]);
        break;
      }
      case 7: {  // overwrite an index (sometimes out of range)
        if (m.indices.empty()) break;
        m.indices[(size_t(v) << 8 | a) % m.indices.size()] = b % (nv + 2);
        break;
      }
      default: {  // relative jitter of the whole vertex by ~2^-40 (near-coplanar, generic)
        for (int c = 0; c < 3; ++c) p[c] += std::ldexp(ext, -40 - int((a >> (2 * c)) & 3)) * (((b >> c) & 1) ? 1 : -1);
        break;
      }
    }
  }
}

inline void scale_translate(Mesh& m, uint8_t sb, uint8_t tb) {
  double s = 1;
  switch (sb % 8) {
    case 0: s = 1; break;
    case 1: s = 1e-300; break;
    case 2: s = 1e300; break;
    case 3: s = 1e-150; break;
    case 4: s = 1e150; break;
    case 5: s = 1e-6; break;
    case 6: s = 1e6; break;
    default: s = std::ldexp(1.0, int(int8_t(sb)) * 4); break;
  }
  double t[3] = {0, 0, 0};
  switch (tb % 8) {
    case 0: break;
    case 1:
      t[0] = 1e6;
      t[1] = -1e6;
      t[2] = 3e6;
      break;
    case 2: t[0] = t[1] = t[2] = 1e-300; break;
    case 3:
      t[0] = 0.5;
      t[1] = 0.25;
      t[2] = -0.125;
      break;
    case 4: t[2] = 1e15; break;
    case 5: t[0] = -1e6; break;
    default: break;
  }
  for (size_t i = 0; i < m.positions.size(); ++i) m.positions[i] = m.positions[i] * s + t[i % 3] * s;
}

inline void flip_all(Mesh& m) {
  size_t off = 0;
  for (size_t f = 0; f < m.num_faces(); ++f) {
    size_t k = m.face_sizes.empty() ? 3 : m.face_sizes[f];
    std::reverse(m.indices.begin() + off, m.indices.begin() + off + k);
    off += k;
  }
}

// Reorders faces by a byte-driven permutation and rotates each loop's start.
inline void shuffle(Mesh& m, Bytes& in, bool rotate) {
  std::vector<std::vector<uint32_t>> loops;
  size_t off = 0;
  for (size_t f = 0; f < m.num_faces(); ++f) {
    size_t k = m.face_sizes.empty() ? 3 : m.face_sizes[f];
    loops.emplace_back(m.indices.begin() + off, m.indices.begin() + off + k);
    off += k;
  }
  uint32_t state = 0x9e3779b9u ^ in.u8();
  for (size_t i = loops.size(); i > 1; --i) {
    state = state * 1664525u + 1013904223u;
    std::swap(loops[i - 1], loops[(state >> 8) % i]);
  }
  const bool polygons = !m.face_sizes.empty();
  m.indices.clear();
  m.face_sizes.clear();
  for (auto& l : loops) {
    if (rotate && !l.empty()) {
      state = state * 1664525u + 1013904223u;
      std::rotate(l.begin(), l.begin() + (state >> 8) % l.size(), l.end());
    }
    m.indices.insert(m.indices.end(), l.begin(), l.end());
    if (polygons) m.face_sizes.push_back(uint32_t(l.size()));
  }
}

}  // namespace kernel_input

// One decoded input: the mesh, the options, and the bytes that chose them.
struct DecodedInput {
  kergen::Mesh mesh;
  kergen::Options options;
  uint8_t which = 0, flags = 0;  // the base mesh, the option bits
  bool stop_early = false;       // options.max_steps is set
};

// Decodes the mesh and options of one input from `in` (see the top of fuzz/fuzz_kernel.cpp for
// the byte layout), consuming the bytes it reads.
inline DecodedInput decode_kernel_input(kernel_input::Bytes& in) {
  using namespace kernel_input;
  DecodedInput d;
  const uint8_t which = in.u8(), flags = in.u8(), sb = in.u8(), tb = in.u8();
  d.which = which;
  d.flags = flags;
  kergen::Mesh& m = d.mesh;
  m = base_mesh(in, which);
  const bool scale_first = !(flags & 0x80);
  if (scale_first) scale_translate(m, sb, tb);
  perturb(m, in, 24);
  if (!scale_first) scale_translate(m, sb, tb);
  if (flags & 1) flip_all(m);
  if (flags & 2) shuffle(m, in, flags & 4);

  kergen::Options& o = d.options;
  o.max_faces = 5000;
  o.allow_open = flags & 8;
  o.deepest_point = flags & 16;
  if ((flags & 32) && m.num_vertices() > 0) {
    o.has_from = true;
    const size_t v = in.u8() % m.num_vertices();
    for (int c = 0; c < 3; ++c) o.from[c] = m.positions[3 * v + c] * 2;
  }
  d.stop_early = flags & 64;
  if (d.stop_early) o.max_steps = 1 + in.u8() % 16;
  return d;
}

// Decodes one fuzz input, computes its kernel and checks every invariant (see the top of
// fuzz/fuzz_kernel.cpp for the byte layout). Violations go to kfuzz::violated.
inline void run_kernel_input(const uint8_t* data, size_t size) {
  kernel_input::Bytes in{data, size};
  DecodedInput d = decode_kernel_input(in);
  const kergen::Mesh& m = d.mesh;
  const kergen::Options& o = d.options;
  const uint8_t which = d.which;
  const bool stop_early = d.stop_early;
  const uint8_t flags = d.flags;

  if (std::getenv("KFUZZ_DUMP")) {  // KFUZZ_DUMP=1 build-fuzz/fuzz/fuzz_kernel FILE: the decoded input as OFF
    std::fprintf(stderr, "# flags %d allow_open %d deepest %d from %d max_steps %llu\n%s", flags, o.allow_open,
                 o.deepest_point, o.has_from, (unsigned long long)o.max_steps, kergen::write_off(m).c_str());
  }
  const kergen::MeshView view = m.view();
  const kergen::Kernel k = kergen::compute_kernel(view, o);
  kfuzz::check_kernel(view, k, o.allow_open, !stop_early);
  if (k.ok() && k.has_deepest_point) {
    for (double c : k.deepest_point) KFUZZ_CHECK(std::isfinite(c), "non-finite deepest point");
    KFUZZ_CHECK(std::isfinite(k.inscribed_radius) ? k.inscribed_radius >= 0 : true, "negative inscribed radius");
  }
  if (stop_early) return;

  // Repair (welding at equal positions, repeated faces, T-junctions) never fails inside; where it
  // finds nothing to repair (no repair warning) the answer is the one without it.
  {
    kergen::Options o3 = o;
    o3.repair = true;
    o3.deepest_point = false;
    const kergen::Kernel k3 = kergen::compute_kernel(view, o3);
    KFUZZ_CHECK(k3.error != kergen::Error::Internal, k3.message);
    bool repaired = false;
    for (const kergen::Warning& w : k3.warnings)
      repaired |=
          w.kind == kergen::Warning::Kind::VerticesWelded || w.kind == kergen::Warning::Kind::DuplicateFacesRemoved ||
          w.kind == kergen::Warning::Kind::CancellingFacesRemoved || w.kind == kergen::Warning::Kind::TJunctionsSplit;
    if (!repaired) {
      KFUZZ_CHECK(k3.error == k.error, std::string("repair changed an input it did not repair: ") +
                                           kergen::error_name(k.error) + " vs " + kergen::error_name(k3.error));
      if (k.ok())
        KFUZZ_CHECK(k3.type == k.type && k3.num_vertices() == k.num_vertices(),
                    "repair changed the kernel of an input it did not repair");
    }
  }

  // The LP seed only orders constraints: the kernel must not depend on it.
  kergen::Options o2 = o;
  o2.seed = 0x1234567u + which;
  o2.deepest_point = false;
  const kergen::Kernel k2 = kergen::compute_kernel(view, o2);
  KFUZZ_CHECK(k2.error == k.error, std::string("error depends on the seed: ") + kergen::error_name(k.error) + " vs " +
                                       kergen::error_name(k2.error));
  if (k.ok()) {
    KFUZZ_CHECK(k2.type == k.type, std::string("type depends on the seed: ") + kergen::kernel_type_name(k.type) +
                                       " vs " + kergen::kernel_type_name(k2.type));
    KFUZZ_CHECK(
        k2.num_vertices() == k.num_vertices() && k2.num_edges() == k.num_edges() && k2.num_faces() == k.num_faces(),
        "kernel size depends on the seed: V " + std::to_string(k.num_vertices()) + " vs " +
            std::to_string(k2.num_vertices()));
    // The volume comes from vertex coordinates known to ~2^-100 of their magnitude M (double-double,
    // see assemble_polytope), so each of its T triangle terms can be off by ~3 2^-100 M L^2 (L the
    // kernel's extent): a kernel below that resolution (three vertices within 1e-30 of each other
    // and a far apex) has a volume of pure rounding, which the seed's vertex order changes.
    double extent = 0, magnitude = 0;
    for (size_t i = 0; i < k.vertices.size(); ++i) {
      magnitude = std::max(magnitude, std::fabs(k.vertices[i]));
      extent = std::max(extent, std::fabs(k.vertices[i] - k.vertices[i % 3]));
    }
    const double resolution = 1e-27 * double(k.triangles.size() / 3) * magnitude * 3 * extent * extent;
    if (std::isfinite(k.volume) && std::isfinite(k2.volume))
      KFUZZ_CHECK(
          std::fabs(k.volume - k2.volume) <= 1e-9 * std::max(std::fabs(k.volume), std::fabs(k2.volume)) + resolution,
          "volume depends on the seed");
  }
  const kergen::KernelPoint kp = kergen::find_kernel_point(view, o);
  KFUZZ_CHECK(kp.error == k.error, std::string("find_kernel_point error ") + kergen::error_name(kp.error) + " vs " +
                                       kergen::error_name(k.error));
  if (k.ok())
    KFUZZ_CHECK(kp.star_shaped == (k.type != kergen::KernelType::Empty), "find_kernel_point disagrees on emptiness");
}

}  // namespace kfuzz
