// Cheap invariants every kernel result must satisfy, checked by the fuzz targets (and usable from
// tests). A violation prints what failed and aborts, so libFuzzer records the input as a crash.
//
// Checked for every result:
//   error != Ok: a known error code (never ParseError/IoError from compute_kernel), a non-empty
//                message, and never Error::Internal (that is a bug, not a verdict on the input).
//   error == Ok: array sizes consistent (xyz triples, edge pairs, face loops summing to the index
//                count, triangles = sum(size - 2)), every id in range, every coordinate finite,
//                per-type shape (Empty: nothing but its witness, 0 or 2 to 4 faces and walls, faces
//                increasing, in range; others: no witness; one face source per face, in range; Point: 1 vertex;
//                Segment: 2 vertices, 1 edge; Polyhedron complete: closed, V - E + F = 2, positive volume not above the
//                shape's), kernel vertices (and the kernel point) inside every input face's half-space up to output
//                rounding, and (closed input) inside the input's bounding box.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "kergen/kergen.h"

namespace kfuzz {

// What a violation does: by default print and abort (the fuzzers); tests install a handler that
// throws, so a violation becomes a test failure.
using ViolationHandler = void (*)(const std::string& what);
inline ViolationHandler violation_handler = nullptr;

[[noreturn]] inline void violated(const char* cond, const std::string& detail, const char* file, int line) {
  const std::string what = std::string(cond) + ": " + detail;
  if (violation_handler) violation_handler(what);
  std::fprintf(stderr, "\n*** kergen invariant violated at %s:%d: %s\n    %s\n", file, line, cond, detail.c_str());
  std::fflush(stderr);
  std::abort();
}
#define KFUZZ_CHECK(cond, detail)                                        \
  do {                                                                   \
    if (!(cond)) ::kfuzz::violated(#cond, (detail), __FILE__, __LINE__); \
  } while (0)

inline bool has_warning(const std::vector<kergen::Warning>& ws, kergen::Warning::Kind kind) {
  for (const auto& w : ws)
    if (w.kind == kind) return true;
  return false;
}

// Every vertex of `k` (and its kernel point) lies in the inner half-space of every face of
// `mesh`. Coordinates are scaled by one power of two first (exact), so 1e-300 and 1e300 inputs
// neither underflow nor overflow; the tolerance covers the rounding of the output coordinates
// and of this check's own arithmetic (long double), nothing scale-dependent.
inline void check_inside_halfspaces(const kergen::MeshView& mesh, const kergen::Kernel& k) {
  if (mesh.num_vertices == 0) return;
  const bool flipped = has_warning(k.warnings, kergen::Warning::Kind::OrientationFlipped);
  const bool split = has_warning(k.warnings, kergen::Warning::Kind::NonPlanarFacesSplit);
  double ext = 0;
  for (size_t i = 0; i < 3 * mesh.num_vertices; ++i) ext = std::max(ext, std::fabs(mesh.positions[i]));
  if (ext == 0) return;
  int ex = 0;
  std::frexp(ext, &ex);
  auto P = [&](uint32_t v, int c) { return (long double)std::ldexp(mesh.positions[3 * size_t(v) + c], -ex); };
  std::vector<long double> pts;
  for (size_t i = 0; i < k.vertices.size(); ++i) pts.push_back(std::ldexp(k.vertices[i], -ex));
  if (k.has_kernel_point)
    for (int c = 0; c < 3; ++c) pts.push_back(std::ldexp(k.kernel_point[c], -ex));
  const size_t np = pts.size() / 3;
  const size_t nf = mesh.face_sizes ? mesh.num_faces : mesh.num_indices / 3;
  size_t off = 0;
  for (size_t f = 0; f < nf; ++f) {
    const size_t n = mesh.face_sizes ? mesh.face_sizes[f] : 3;
    const uint32_t* loop = mesh.indices + off;
    off += n;
    if (n < 3 || (n > 3 && split)) continue;  // a split non-planar polygon: its planes are the core's choice
    // Plane normal: the polygon's area vector, the sum of its fan triangles' cross products. (One
    // fan triangle of a non-convex polygon may turn the other way: the largest one is not always
    // oriented like the polygon.) For a triangle it is the triangle's own normal.
    long double area[3] = {0, 0, 0}, area_len = 0, area_scale = 0;
    uint32_t base = loop[0];
    for (size_t i = 1; i + 1 < n; ++i) {
      long double u[3], w[3];
      for (int c = 0; c < 3; ++c) {
        u[c] = P(loop[i], c) - P(base, c);
        w[c] = P(loop[i + 1], c) - P(base, c);
      }
      const long double nn[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
      for (int c = 0; c < 3; ++c) area[c] += nn[c];
      const long double lu = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
      const long double lw = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
      area_scale += lu * lw;  // bounds the sum's rounding with the tolerance below
    }
    area_len = std::sqrt(area[0] * area[0] + area[1] * area[1] + area[2] * area[2]);
    if (area_len == 0) continue;
    const long double sign = flipped ? -1 : 1;
    for (size_t p = 0; p < np; ++p) {
      long double d = 0, lp = 0;
      for (int c = 0; c < 3; ++c) {
        long double dc = pts[3 * p + c] - P(base, c);
        d += area[c] * dc;
        lp += dc * dc;
      }
      d *= sign;
      lp = std::sqrt(lp);
      // Output rounding moves a vertex by ~2^-53 of the extent (1 here): 1e-9 is generous;
      // the second term bounds this check's own rounding for slivers.
      const long double tol = 1e-9L * area_len + 1e-15L * area_scale * (lp + 1);
      if (d > tol) {
        char buf[256];
        std::snprintf(buf, sizeof buf,
                      "%s %zu outside face %zu: signed distance %.3Le (scaled by 2^%d), tolerance %.3Le",
                      p < k.num_vertices() ? "kernel vertex" : "kernel point", p, f, (long double)(d / area_len), -ex,
                      (long double)(tol / area_len));
        violated("kernel inside every face half-space", buf, __FILE__, __LINE__);
      }
    }
  }
}

// `allow_open`: the options the result was computed with. `complete_run`: no on_step/max_steps
// stop was requested (so the result must be complete).
inline void check_kernel(const kergen::MeshView& mesh, const kergen::Kernel& k, bool allow_open, bool complete_run) {
  using kergen::Error;
  using kergen::KernelType;
  if (k.error != Error::Ok) {
    const int code = static_cast<int>(k.error);
    KFUZZ_CHECK(code > 0 && code <= static_cast<int>(Error::SelfIntersection),
                "unknown error code " + std::to_string(code));
    KFUZZ_CHECK(k.error != Error::Internal, k.message);
    KFUZZ_CHECK(k.error != Error::ParseError && k.error != Error::IoError, "compute_kernel returned a reader error");
    KFUZZ_CHECK(!k.message.empty(), std::string("error ") + kergen::error_name(k.error) + " without a message");
    return;
  }
  const std::string type = kergen::kernel_type_name(k.type);
  KFUZZ_CHECK(k.vertices.size() % 3 == 0, type);
  KFUZZ_CHECK(k.edges.size() % 2 == 0, type);
  KFUZZ_CHECK(k.triangles.size() % 3 == 0, type);
  const size_t V = k.num_vertices(), E = k.num_edges(), F = k.num_faces();
  for (double c : k.vertices) KFUZZ_CHECK(std::isfinite(c), type + ": non-finite kernel vertex coordinate");
  size_t sum = 0, tris = 0;
  for (uint32_t s : k.face_sizes) {
    KFUZZ_CHECK(s >= 3, type + ": kernel face with " + std::to_string(s) + " vertices");
    sum += s;
    tris += s - 2;
  }
  KFUZZ_CHECK(sum == k.face_indices.size(), type + ": face_sizes do not add up to face_indices");
  KFUZZ_CHECK(tris * 3 == k.triangles.size(), type + ": triangle count is not sum(size - 2)");
  for (uint32_t v : k.face_indices) KFUZZ_CHECK(v < V, type + ": face vertex id out of range");
  for (uint32_t v : k.triangles) KFUZZ_CHECK(v < V, type + ": triangle vertex id out of range");
  for (size_t e = 0; e < E; ++e) {
    KFUZZ_CHECK(k.edges[2 * e] < V && k.edges[2 * e + 1] < V, type + ": edge endpoint out of range");
    KFUZZ_CHECK(k.edges[2 * e] != k.edges[2 * e + 1], type + ": edge from a vertex to itself");
  }
  if (complete_run) KFUZZ_CHECK(k.complete, type + ": incomplete result without a stop request");
  KFUZZ_CHECK(k.type != KernelType::Unbounded || allow_open, "UNBOUNDED without allow_open");
  KFUZZ_CHECK(k.has_kernel_point == (k.type != KernelType::Empty), type + ": kernel point presence");
  if (k.has_kernel_point)
    for (double c : k.kernel_point) KFUZZ_CHECK(std::isfinite(c), type + ": non-finite kernel point");
  const size_t input_faces = mesh.face_sizes ? mesh.num_faces : mesh.num_indices / 3;
  KFUZZ_CHECK(k.witness_faces.empty() || k.type == KernelType::Empty, type + ": a witness of a non-empty kernel");
  const size_t walls = k.witness_boundary_edges.size() / 2, witness = k.witness_faces.size() + walls;
  KFUZZ_CHECK(witness != 1 && witness <= 4, type + ": " + std::to_string(witness) + " witness faces and walls");
  for (size_t i = 0; i < k.witness_faces.size(); ++i)
    KFUZZ_CHECK(k.witness_faces[i] < input_faces && (i == 0 || k.witness_faces[i - 1] < k.witness_faces[i]),
                type + ": witness faces out of range or not increasing");
  KFUZZ_CHECK(k.witness_boundary_edges.size() % 2 == 0 && (walls == 0 || k.type == KernelType::Empty),
              type + ": witness boundary edges are not pairs of an empty kernel's witness");
  for (uint32_t v : k.witness_boundary_edges)
    KFUZZ_CHECK(v < mesh.num_vertices, type + ": witness boundary edge vertex out of range");
  // One face source per face: an input face, or a mark of the box (Unbounded only) or of a wall.
  KFUZZ_CHECK(k.face_sources.size() == F, type + ": not one face source per face");
  for (int32_t s : k.face_sources)
    KFUZZ_CHECK((s >= 0 && size_t(s) < input_faces) || s == kergen::kFaceSourceWall ||
                    (s == kergen::kFaceSourceBox && k.type == KernelType::Unbounded),
                type + ": face source " + std::to_string(s) + " out of range");
  // Volumes are plain doubles: at extreme scales they may underflow to 0 or overflow to inf.
  if (!allow_open) KFUZZ_CHECK(!(k.shape_volume < 0), "negative shape volume " + std::to_string(k.shape_volume));

  switch (k.type) {
    case KernelType::Empty: KFUZZ_CHECK(V == 0 && E == 0 && F == 0, "EMPTY with geometry"); break;
    case KernelType::Point: KFUZZ_CHECK(V == 1 && E == 0 && F == 0, "POINT: V=" + std::to_string(V)); break;
    case KernelType::Segment:
      if (k.complete)
        KFUZZ_CHECK(V == 2 && E == 1 && F == 0, "SEGMENT: V=" + std::to_string(V) + " E=" + std::to_string(E));
      break;
    case KernelType::Polygon:
      if (k.complete)
        KFUZZ_CHECK(V >= 3 && V == E && F <= 1,
                    "POLYGON: V=" + std::to_string(V) + " E=" + std::to_string(E) + " F=" + std::to_string(F));
      KFUZZ_CHECK(k.volume == 0, "POLYGON with volume");
      break;
    case KernelType::Polyhedron:
      if (k.complete) {
        KFUZZ_CHECK(V >= 4 && F >= 4, "POLYHEDRON: V=" + std::to_string(V) + " F=" + std::to_string(F));
        KFUZZ_CHECK(int64_t(V) - int64_t(E) + int64_t(F) == 2,
                    "Euler: V=" + std::to_string(V) + " E=" + std::to_string(E) + " F=" + std::to_string(F));
        // Closed: every directed edge of the face loops appears once and its reverse once.
        std::map<std::pair<uint32_t, uint32_t>, int> directed;
        size_t off = 0;
        for (uint32_t s : k.face_sizes) {
          for (uint32_t i = 0; i < s; ++i) directed[{k.face_indices[off + i], k.face_indices[off + (i + 1) % s]}]++;
          off += s;
        }
        KFUZZ_CHECK(directed.size() == 2 * E, "face loops do not use each edge twice");
        for (const auto& [e, n] : directed) {
          KFUZZ_CHECK(n == 1, "a directed edge used twice (inconsistent kernel faces)");
          KFUZZ_CHECK(directed.count({e.second, e.first}) == 1, "a kernel edge with one face");
        }
        if (std::isfinite(k.shape_volume) && k.shape_volume > 0) {
          KFUZZ_CHECK(std::isfinite(k.volume) && k.volume >= 0, "volume " + std::to_string(k.volume));
          if (!allow_open)
            KFUZZ_CHECK(k.volume <= k.shape_volume * (1 + 1e-9), "kernel volume above the shape's volume");
        }
      }
      break;
    case KernelType::Unbounded: break;
  }

  check_inside_halfspaces(mesh, k);

  // A closed shape's kernel lies inside the shape, so inside its bounding box.
  if (!allow_open && mesh.num_vertices > 0) {
    double lo[3], hi[3];
    for (int c = 0; c < 3; ++c) lo[c] = hi[c] = mesh.positions[c];
    for (size_t v = 0; v < mesh.num_vertices; ++v)
      for (int c = 0; c < 3; ++c) {
        lo[c] = std::min(lo[c], mesh.positions[3 * v + c]);
        hi[c] = std::max(hi[c], mesh.positions[3 * v + c]);
      }
    for (size_t v = 0; v < V; ++v)
      for (int c = 0; c < 3; ++c) {
        const double x = k.vertices[3 * v + c];
        const double slack = 1e-9 * std::max(std::fabs(lo[c]), std::fabs(hi[c])) + 1e-9 * (hi[c] / 2 - lo[c] / 2);
        KFUZZ_CHECK(x >= lo[c] - slack && x <= hi[c] + slack, "kernel vertex outside the input's bounding box");
      }
  }
}

// Stricter checks for the kernels of well-shaped meshes (the tests'; the fuzzers skip them: on a
// degenerate kernel, rounded coordinates can make a convex corner's turn compute as 0): every
// face convex and counter-clockwise seen from outside (each turn agrees with the direction from
// the vertex centroid), and no two vertices at one position. Coordinates are scaled by one power
// of two first (exact), so huge and tiny kernels neither overflow nor underflow.
inline void check_convex_faces_and_distinct_vertices(const kergen::Kernel& k) {
  const size_t V = k.num_vertices();
  if (V == 0) return;
  double ext = 0;
  for (double c : k.vertices) ext = std::max(ext, std::fabs(c));
  int ex = 0;
  std::frexp(ext, &ex);
  std::vector<double> x(k.vertices.size());
  for (size_t i = 0; i < x.size(); ++i) x[i] = std::ldexp(k.vertices[i], -ex);
  double centre[3] = {0, 0, 0};
  for (size_t v = 0; v < V; ++v)
    for (int c = 0; c < 3; ++c) centre[c] += x[3 * v + c] / double(V);
  for (size_t f = 0, off = 0; f < k.num_faces(); off += k.face_sizes[f], ++f) {
    const size_t n = k.face_sizes[f];
    for (size_t i = 0; i < n; ++i) {
      const double* p0 = &x[3 * size_t(k.face_indices[off + i])];
      const double* p1 = &x[3 * size_t(k.face_indices[off + (i + 1) % n])];
      const double* p2 = &x[3 * size_t(k.face_indices[off + (i + 2) % n])];
      const double u[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]},
                   w[3] = {p2[0] - p1[0], p2[1] - p1[1], p2[2] - p1[2]};
      const double nn[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
      const double out = nn[0] * (p1[0] - centre[0]) + nn[1] * (p1[1] - centre[1]) + nn[2] * (p1[2] - centre[2]);
      KFUZZ_CHECK(out > 0,
                  "face " + std::to_string(f) + " not convex and counter-clockwise at corner " + std::to_string(i));
    }
  }
  std::vector<std::vector<double>> points;
  for (size_t v = 0; v < V; ++v) points.push_back({k.vertices[3 * v], k.vertices[3 * v + 1], k.vertices[3 * v + 2]});
  std::sort(points.begin(), points.end());
  KFUZZ_CHECK(std::adjacent_find(points.begin(), points.end()) == points.end(), "two kernel vertices at one position");
}

}  // namespace kfuzz
