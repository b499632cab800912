// The convex answer (convex_answer.h): the certificate in one pass over the face pairs and two
// over the faces, then the solid's vertices and edges read off the mesh.
#include "solve/convex_answer.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "certify/embedding.h"
#include "exact/expansion.h"
#include "exact/predicates.h"

namespace kergen {

namespace {

struct Loop {
  const uint32_t* v;
  size_t k;
  bool has(uint32_t x) const { return std::find(v, v + k, x) != v + k; }
};

Loop loop_of(const PreparedMesh& m, uint32_t f) {
  return {m.loops.data() + m.loop_offsets[f], size_t(m.loop_offsets[f + 1] - m.loop_offsets[f])};
}

// Whether every corner of `b` off `a` lies on the inner side of a's plane, or on it.
bool inside_plane_of(const PreparedMesh& m, uint32_t a, const Loop& la, const Loop& lb) {
  const auto& r = m.rep[a];
  for (size_t i = 0; i < lb.k; ++i)
    if (!la.has(lb.v[i]) && orient3d(m.point(r[0]), m.point(r[1]), m.point(r[2]), m.point(lb.v[i]), m.exact_shift) > 0)
      return false;
  return true;
}

// Faces a and b (neighbours) meet at a convex or flat edge. Two triangles: the corner of b off
// the shared edge is not outside a's plane (the sign is the same tetrahedron's seen from b).
// Polygons: each lies on the inner side of the other's plane, corner by corner (what every pair
// of faces of a convex solid does; for a polygon that is not convex in its plane the corners
// next to the edge would not tell the side near it).
bool convex_pair(const PreparedMesh& m, uint32_t a, uint32_t b) {
  const Loop la = loop_of(m, a), lb = loop_of(m, b);
  if (la.k == 3 && lb.k == 3) return inside_plane_of(m, a, la, lb);
  if (la.k * lb.k > 4096) return false;  // (a large polygon: the quadratic scans would not pay)
  return inside_plane_of(m, a, la, lb) && inside_plane_of(m, b, lb, la);
}

// Candidate points inside the solid: the mean of the faces' corners (a convex combination of
// every vertex with positive weights: inside the solid, if the rounding lets it), then points
// between it and a few corners (a thin solid's mean may round onto or past a face).
bool embedded_about_interior_point(const PreparedMesh& m) {
  double c[3] = {0, 0, 0};
  const double n = double(m.loops.size());
  for (uint32_t v : m.loops)
    for (int k = 0; k < 3; ++k) c[k] += m.point(v)[k] / n;
  if (check_embedding_in_faces(m, c).outcome == EmbeddingCheck::Outcome::Embedded) return true;
  for (size_t i = 0; i < std::min<size_t>(m.loops.size(), 16); ++i)
    for (double w : {0.5, 0.9}) {
      double p[3];
      for (int k = 0; k < 3; ++k) p[k] = w * c[k] + (1 - w) * m.point(m.loops[i])[k];
      const EmbeddingCheck e = check_embedding_in_faces(m, p);
      if (e.outcome == EmbeddingCheck::Outcome::Embedded) return true;
      if (e.outcome == EmbeddingCheck::Outcome::CrossesItself) return false;
    }
  return false;
}

// A mesh edge between two distinct planes, directed as the faces of the lower plane p run along it.
struct BoundaryLink {
  uint32_t from, to, p, q;
  bool operator<(const BoundaryLink& o) const {
    return from != o.from ? from < o.from : (to != o.to ? to < o.to : (p != o.p ? p < o.p : q < o.q));
  }
  bool operator==(const BoundaryLink& o) const { return from == o.from && to == o.to && p == o.p && q == o.q; }
};

// The mesh edges between faces on distinct planes, grouped by their first vertex (each once,
// though a pair of polygons sharing two edges is listed twice).
std::vector<BoundaryLink> boundary_links(const PreparedMesh& m, const std::vector<uint32_t>& face_plane) {
  std::vector<BoundaryLink> links;
  for (const auto& [a, b] : m.adjacent) {
    const uint32_t pa = face_plane[a], pb = face_plane[b];
    if (pa == pb) continue;
    const Loop la = loop_of(m, a), lb = loop_of(m, b);
    for (size_t i = 0; i < la.k; ++i) {
      const uint32_t u = la.v[i], v = la.v[(i + 1) % la.k];
      for (size_t j = 0; j < lb.k; ++j)
        if (lb.v[j] == v && lb.v[(j + 1) % lb.k] == u)
          links.push_back(pa < pb ? BoundaryLink{u, v, pa, pb} : BoundaryLink{v, u, pb, pa});
    }
  }
  std::sort(links.begin(), links.end());
  links.erase(std::unique(links.begin(), links.end()), links.end());
  return links;
}

// Per mesh vertex, the sorted distinct planes of the faces around it: [start[v], start[v] + count[v]).
struct VertexPlanes {
  std::vector<uint32_t> start, count, planes;
};

VertexPlanes planes_around_vertices(const PreparedMesh& m, const std::vector<uint32_t>& face_plane) {
  const size_t nv = m.points.size() / 3, nf = m.num_faces();
  VertexPlanes vp;
  vp.start.assign(nv + 1, 0);
  for (uint32_t v : m.loops) ++vp.start[v + 1];
  for (size_t v = 0; v < nv; ++v) vp.start[v + 1] += vp.start[v];
  vp.planes.resize(m.loops.size());
  std::vector<uint32_t> fill(vp.start.begin(), vp.start.end() - 1);
  for (uint32_t f = 0; f < nf; ++f) {
    const Loop l = loop_of(m, f);
    for (size_t i = 0; i < l.k; ++i) vp.planes[fill[l.v[i]]++] = face_plane[f];
  }
  vp.count.resize(nv);
  for (size_t v = 0; v < nv; ++v) {
    uint32_t* b = vp.planes.data() + vp.start[v];
    uint32_t* e = vp.planes.data() + vp.start[v + 1];
    std::sort(b, e);
    vp.count[v] = uint32_t(std::unique(b, e) - b);
  }
  return vp;
}

}  // namespace

bool convex_solid(const PreparedMesh& m) {
  if (m.error != Error::Ok || m.boundary_edges > 0 || m.shells != 1 || m.num_faces() < 4) return false;
  // Every edge is one face pair: nothing was dropped or split (those pairs are not listed).
  if (2 * m.adjacent.size() != m.loops.size()) return false;
  for (const auto& [a, b] : m.adjacent)
    if (!convex_pair(m, a, b)) return false;
  return embedded_about_interior_point(m);
}

bool convex_trace(const Setup& s, TraceResult& out) {
  const PreparedMesh& m = s.mesh;
  const std::vector<uint32_t>& face_plane = s.face_plane;
  const size_t nv = m.points.size() / 3;
  const VertexPlanes vp = planes_around_vertices(m, face_plane);
  std::vector<uint32_t> id(nv, kNoVertex);
  for (uint32_t v = 0; v < nv; ++v) {
    if (vp.count[v] < 3) continue;
    id[v] = uint32_t(out.vertices.size());
    TracedVertex tv;
    tv.geom.mesh_point = int32_t(v);
    for (int k = 0; k < 3; ++k) {
      tv.geom.x[k] = Approx(m.point(v)[k]);
      tv.geom.basis[k] = vp.planes[vp.start[v] + k];
    }
    tv.tight.assign(vp.planes.data() + vp.start[v], vp.planes.data() + vp.start[v] + vp.count[v]);
    out.vertices.push_back(std::move(tv));
  }
  const std::vector<BoundaryLink> links = boundary_links(m, face_plane);
  std::vector<uint32_t> first(nv + 1, 0);
  for (const BoundaryLink& l : links) ++first[l.from + 1];
  for (size_t v = 0; v < nv; ++v) first[v + 1] += first[v];
  // From each vertex of the solid, each chain of links on the same two planes to the next one
  // (the corners between lie inside the solid's edge, on those two planes only).
  for (const BoundaryLink& start : links) {
    if (id[start.from] == kNoVertex) continue;
    uint32_t at = start.to;
    for (size_t steps = 0; id[at] == kNoVertex; ++steps) {
      const BoundaryLink* next = nullptr;
      for (uint32_t i = first[at]; i < first[at + 1]; ++i)
        if (links[i].p == start.p && links[i].q == start.q) next = &links[i];
      if (!next || steps > links.size() || vp.count[at] != 2) return false;
      at = next->to;
    }
    TracedEdge e;
    e.a = id[start.from];
    e.b = id[at];
    e.p = start.p;  // the faces of p run from a to b: the edge's direction is n_p x n_q
    e.q = start.q;
    e.sigma = 1;
    e.planes.push_back(start.p);
    e.planes.push_back(start.q);
    out.edges.push_back(std::move(e));
  }
  return out.vertices.size() >= 4;
}

uint32_t extreme_vertex(const TraceResult& tr, const PlaneSet& ps, const double dir[3]) {
  using exact::Expansion;
  // Each dot product in double is within 3 eps of the sum of its terms' magnitudes: a
  // difference beyond 1e-14 of both sums decides; closer ones are compared exactly.
  auto dot = [&](uint32_t i, double& magnitude) {
    const double* x = ps.point(uint32_t(tr.vertices[i].geom.mesh_point));
    magnitude = std::fabs(dir[0] * x[0]) + std::fabs(dir[1] * x[1]) + std::fabs(dir[2] * x[2]);
    return dir[0] * x[0] + dir[1] * x[1] + dir[2] * x[2];
  };
  auto exact_greater = [&](uint32_t i, uint32_t j) {
    const double* x = ps.point(uint32_t(tr.vertices[i].geom.mesh_point));
    const double* y = ps.point(uint32_t(tr.vertices[j].geom.mesh_point));
    Expansion d;
    for (int k = 0; k < 3; ++k) d = d + (Expansion::product(dir[k], x[k]) - Expansion::product(dir[k], y[k]));
    return d.sign() > 0;
  };
  uint32_t best = 0;
  double best_mag = 0, best_dot = tr.vertices.empty() ? 0 : dot(0, best_mag);
  for (uint32_t i = 1; i < tr.vertices.size(); ++i) {
    double mag = 0;
    const double d = dot(i, mag);
    const bool certain = std::fabs(d - best_dot) > 1e-14 * (mag + best_mag);
    if (certain ? d > best_dot : exact_greater(i, best)) {
      best = i;
      best_dot = d;
      best_mag = mag;
    }
  }
  return best;
}

}  // namespace kergen
