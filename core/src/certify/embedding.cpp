// The embedding certificate (see embedding.h): a point strictly inside the kernel, then one pass
// over the faces counting signed crossings of a ray from it, with exact orient3d signs.
#include "certify/embedding.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "exact/predicates.h"
#include "util/compiler_hints.h"
#include "util/raw_vector.h"

namespace kergen {

namespace {

// Coordinates snapped to multiples of 2^-80 (scaled units, below 1 in magnitude): every product
// of three differences of them stays far above underflow, so orient3d on them is exact.
void snap(double p[3]) {
  for (int k = 0; k < 3; ++k) p[k] = std::ldexp(std::nearbyint(std::ldexp(p[k], 80)), -80);
}

// Whether p lies strictly inside every facet plane, hence in the kernel's interior (and then
// strictly inside every plane of the mesh, which all hold the kernel).
bool strictly_inside(const PlaneSet& ps, const std::vector<uint32_t>& facets, const double p[3]) {
  for (uint32_t h : facets) {
    if (ps.explicit_plane(h)) return false;  // (a bounded kernel of a closed mesh has none)
    const auto& r = ps.rep(h);
    if (orient3d(ps.point(r[0]), ps.point(r[1]), ps.point(r[2]), p, ps.exact_shift()) >= 0) return false;
  }
  return true;
}

// A point strictly inside the kernel: its vertices' centroid, else points between it and each
// vertex in turn (a thin kernel's centroid may round onto or past a facet).
bool interior_point(const PlaneSet& ps, const TraceResult& kernel, double p[3]) {
  const std::vector<uint32_t> facets = facet_planes(kernel);
  if (facets.size() < 4) return false;
  double c[3] = {0, 0, 0};
  const double n = double(kernel.vertices.size());
  for (const TracedVertex& v : kernel.vertices)
    for (int k = 0; k < 3; ++k) c[k] += v.geom.x[k].v / n;
  for (int k = 0; k < 3; ++k) p[k] = c[k];
  snap(p);
  if (strictly_inside(ps, facets, p)) return true;
  for (size_t i = 0; i < std::min<size_t>(kernel.vertices.size(), 16); ++i)
    for (double w : {0.5, 0.9}) {
      for (int k = 0; k < 3; ++k) p[k] = w * c[k] + (1 - w) * kernel.vertices[i].geom.x[k].v;
      snap(p);
      if (strictly_inside(ps, facets, p)) return true;
    }
  return false;
}

// The points' outcodes around p in the frame (e1, e2) across the ray: the sides of p, in the
// projections (s, t), a point lies on by more than the margin (bit 0: s > margin, 1: s < -margin,
// 2: t > margin, 3: t < -margin). Scaled coordinates are below 1 and |e1|, |e2| below 2 (|u| =
// 4): a projection is off by less than 1e-14; the margin is far above it. It only filters (a
// triangle skipped is far from the ray), so the vectorized clone's rounding changes no result.
constexpr double kMargin = 1e-9;
KERGEN_MULTIVERSION
void outcodes(const double* points, size_t n, const double p[3], const double e1[3], const double e2[3],
              uint8_t* code) {
  for (size_t v = 0; v < n; ++v) {
    const double* x = points + 3 * v;
    const double d0 = x[0] - p[0], d1 = x[1] - p[1], d2 = x[2] - p[2];
    const double s = d0 * e1[0] + d1 * e1[1] + d2 * e1[2];
    const double t = d0 * e2[0] + d1 * e2[1] + d2 * e2[2];
    code[v] = uint8_t((s > kMargin) | (s < -kMargin) << 1 | (t > kMargin) << 2 | (t < -kMargin) << 3);
  }
}

// Signed crossings of the segment p -> q (q outside the mesh's bounding box, so it stands for the
// ray) with the faces, each polygon fanned from its first corner (signed counts do not depend on
// how a planar polygon is split). False when the segment meets an edge or a vertex exactly.
// Most faces are far from the ray: the vertices are projected (in double) on a plane across it,
// and only triangles whose projections' box holds the ray's point, with a margin far above the
// projection's rounding, get the exact tests (a bit test of the corners' outcodes).
bool count_crossings(const PreparedMesh& mesh, const double p[3], const double q[3], long& degree) {
  const int shift = mesh.exact_shift;
  // An orthonormal-ish frame across u = q - p (exactness does not depend on it: it only filters).
  const double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
  const int m = std::fabs(u[0]) < std::fabs(u[1]) ? (std::fabs(u[0]) < std::fabs(u[2]) ? 0 : 2)
                                                  : (std::fabs(u[1]) < std::fabs(u[2]) ? 1 : 2);
  double e1[3] = {0, 0, 0};
  e1[m] = 1;  // the axis least aligned with u, made orthogonal to it
  const double uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2], ue = u[m] / uu;
  for (int k = 0; k < 3; ++k) e1[k] -= ue * u[k];
  const double e2[3] = {u[1] * e1[2] - u[2] * e1[1], u[2] * e1[0] - u[0] * e1[2], u[0] * e1[1] - u[1] * e1[0]};
  // A triangle's projections' box misses the margin around p exactly when its corners' outcodes
  // share a bit; a face whose corners all share one has no fan triangle to test.
  const size_t nv = mesh.points.size() / 3;
  RawVector<uint8_t> code(nv);
  outcodes(mesh.points.data(), nv, p, e1, e2, code.data());
  degree = 0;
  // A mesh of triangles only (the common case; every loop has at least three corners, so three
  // per face means triangles only) is scanned without its loop offsets.
  const size_t nf = mesh.loop_offsets.size() - 1;
  const bool triangles = mesh.loops.size() == 3 * nf;
  for (size_t f = 0; f < nf; ++f) {
    const uint32_t* loop = mesh.loops.data() + (triangles ? 3 * f : mesh.loop_offsets[f]);
    if (triangles && (code[loop[0]] & code[loop[1]] & code[loop[2]]) != 0) continue;
    const size_t size = triangles ? 3 : mesh.loop_offsets[f + 1] - mesh.loop_offsets[f];
    unsigned shared = 15;
    for (size_t i = 0; i < size; ++i) shared &= code[loop[i]];
    if (shared != 0) continue;
    const uint32_t ia = loop[0];
    const double* a = mesh.point(ia);
    for (size_t i = 1; i + 1 < size; ++i) {
      const uint32_t ib = loop[i], ic = loop[i + 1];
      if ((code[ia] & code[ib] & code[ic]) != 0) continue;
      const double* b = mesh.point(ib);
      const double* c = mesh.point(ic);
      const int sp = orient3d(a, b, c, p, shift), sq = orient3d(a, b, c, q, shift);
      if (sp == sq) continue;  // both on one side, or a flat fan triangle with both on its plane
      if (sp == 0 || sq == 0) return false;
      const int e1s = orient3d(p, q, a, b, shift), e2s = orient3d(p, q, b, c, shift), e3s = orient3d(p, q, c, a, shift);
      if (e1s == 0 || e2s == 0 || e3s == 0) {
        // Through an edge's line: a crossing only if the others agree (else the line misses).
        if ((e1s >= 0 && e2s >= 0 && e3s >= 0) || (e1s <= 0 && e2s <= 0 && e3s <= 0)) return false;
        continue;
      }
      if (e1s == e2s && e2s == e3s) degree += sq > 0 ? 1 : -1;  // from a face's inner side to its outer
    }
  }
  return true;
}

}  // namespace

namespace {

// The degree from out.point, counted along the first ray that meets no edge or vertex.
EmbeddingCheck degree_from(const PreparedMesh& mesh, EmbeddingCheck out) {
  // Directions with no simple relation to the axes or to each other; scaled coordinates are
  // below 1, so q = p + 4 u is outside the mesh.
  static const double kDirections[][3] = {{0.5773502691896258, 0.6123724356957945, 0.5400617248673217},
                                          {-0.3713906763541037, 0.5570860145311556, 0.7427813527082074},
                                          {0.8017837257372732, -0.2672612419124244, 0.5345224838248488},
                                          {-0.4364357804719848, -0.6546536707079771, 0.6172133998483676},
                                          {0.2182178902359924, 0.4364357804719848, -0.8728715609439696},
                                          {-0.7071067811865475, 0.3015113445777636, -0.6396021490668313}};
  for (const double* u : kDirections) {
    double q[3];
    for (int k = 0; k < 3; ++k) q[k] = out.point[k] + 4 * u[k];
    snap(q);
    long degree = 0;
    if (!count_crossings(mesh, out.point, q, degree)) continue;
    out.crossings = degree;
    out.outcome = degree == 1 ? EmbeddingCheck::Outcome::Embedded : EmbeddingCheck::Outcome::CrossesItself;
    return out;
  }
  return out;
}

}  // namespace

EmbeddingCheck check_embedding(const PreparedMesh& mesh, const PlaneSet& ps, const TraceResult& kernel) {
  EmbeddingCheck out;
  if (!interior_point(ps, kernel, out.point)) return out;
  return degree_from(mesh, out);
}

EmbeddingCheck check_embedding_at(const PreparedMesh& mesh, const PlaneSet& ps, const std::vector<uint32_t>& planes,
                                  const double p[3]) {
  EmbeddingCheck out;
  for (int k = 0; k < 3; ++k) out.point[k] = p[k];
  snap(out.point);
  if (planes.empty() || !strictly_inside(ps, planes, out.point)) return out;
  return degree_from(mesh, out);
}

EmbeddingCheck check_embedding_in_faces(const PreparedMesh& mesh, const double p[3]) {
  EmbeddingCheck out;
  for (int k = 0; k < 3; ++k) out.point[k] = p[k];
  snap(out.point);
  for (const auto& r : mesh.rep)
    if (orient3d(mesh.point(r[0]), mesh.point(r[1]), mesh.point(r[2]), out.point, mesh.exact_shift) >= 0) return out;
  return degree_from(mesh, out);
}

}  // namespace kergen
