// Polytope assembly. Edge (v, w) lies on plane h iff h contains the edge's line; a plane holding
// three or more edges is a facet (a supporting plane through two non-collinear edges touches a
// 2D face). Each facet's edges are oriented exactly: along edge e with direction sigma (n_p x n_q),
// facet h is counter-clockwise seen from outside iff sigma (n_p x n_q) . (n_h x n_s) > 0 for any
// other plane s through e that is not h or its opposite (the projection of n_s on h points out
// of the facet).
#include "output/polytope.h"

#include <algorithm>
#include <cmath>

namespace kergen {

namespace {

// The vertices' coordinates: hi + lo to ~1e-30 relative (so the output is rounded once, from
// nearly exact values), and local + local_lo, the same relative to the first vertex, for area
// and volume: far from the origin (offset >> size) the differences keep their accuracy. (One
// allocation for the four arrays: on a small kernel the allocations are a visible part of the
// assembly.)
struct VertexCoordinates {
  explicit VertexCoordinates(size_t V) : storage(12 * V) {
    hi = storage.data();
    lo = hi + 3 * V;
    local = lo + 3 * V;
    local_lo = local + 3 * V;
  }
  std::vector<double> storage;
  double *hi, *lo, *local, *local_lo;
};

// The output position of each traced vertex: its id in the output (`rank`) and the traced
// vertex at each output id (`order`).
struct VertexNumbering {
  std::vector<uint32_t> rank, order;
};

// The order of coordinate k of vertices a and b (-1, 0, 1) whose coordinates round to the same
// doubles: from their low parts (`ta`, `tb`: hi[3], lo[3]) where those differ by far more than
// their accuracy (~1e-30 relative, precise_coordinates), else exactly (num / den of the exact
// homogeneous coordinates, computed on demand): the low parts follow the planes a vertex was
// found on, so the order would otherwise depend on the path that found it.
int compare_exact_coordinate(const PlaneSet& ps, const VertexGeom& a, const double* ta, const VertexGeom& b,
                             const double* tb, int k) {
  const double lo_a = ta[3 + k], lo_b = tb[3 + k];
  const double accuracy = std::ldexp(std::max(std::fabs(ta[k]), 0x1p-1022), -90);
  if (std::fabs(lo_a - lo_b) > accuracy) return lo_a < lo_b ? -1 : 1;
  if (a.mesh_point != kNoPoint && b.mesh_point != kNoPoint) return 0;  // exact: hi, lo = 0
  const ExactHomogeneous &ha = exact_homogeneous(ps, a), &hb = exact_homogeneous(ps, b);
  // num_a / den_a - num_b / den_b has the sign of (num_a den_b - num_b den_a) den_a den_b.
  const int s = (ha.num[k] * hb.den - hb.num[k] * ha.den).sign() * ha.den.sign() * hb.den.sign();
  return s;
}

// Numbers the vertices canonically, in lexicographic order of their rounded coordinates, and of
// their exact ones where those are equal (compare_exact_coordinate; exactly equal ones keep
// their traced order, which the tracer never produces: a vertex is found once), and fills `c` in that
// order: area and volume are summed in it, whatever the output numbering. Fills the output
// vertices (rounded once, to nearest), with `canonical` in that order, else in traced order.
void round_vertices(const PlaneSet& ps, const TraceResult& trace, int unscale_exp, bool canonical, VertexCoordinates& c,
                    VertexNumbering& numbering, Kernel& out) {
  const size_t V = trace.vertices.size();
  std::vector<double> traced(6 * V);  // hi[3], lo[3] per traced vertex
  for (size_t i = 0; i < V; ++i) precise_coordinates(ps, trace.vertices[i].geom, &traced[6 * i], &traced[6 * i + 3]);
  // A zero's sign depends on the planes that happened to define the vertex: +0 always (x + 0 is
  // +0 for x = -0 and x otherwise).
  for (double& x : traced) x += 0.0;
  numbering.order.resize(V);
  numbering.rank.resize(V);
  for (uint32_t i = 0; i < V; ++i) numbering.order[i] = i;
  const double* t = traced.data();
  std::stable_sort(numbering.order.begin(), numbering.order.end(), [&](uint32_t a, uint32_t b) {
    for (int k = 0; k < 3; ++k)  // the rounded coordinates
      if (t[6 * a + k] != t[6 * b + k]) return t[6 * a + k] < t[6 * b + k];
    for (int k = 0; k < 3; ++k) {  // then the exact ones
      const int c =
          compare_exact_coordinate(ps, trace.vertices[a].geom, t + 6 * a, trace.vertices[b].geom, t + 6 * b, k);
      if (c != 0) return c < 0;
    }
    return false;
  });
  for (uint32_t i = 0; i < V; ++i) {
    const uint32_t from = numbering.order[i];
    numbering.rank[from] = i;
    for (int k = 0; k < 3; ++k) {
      c.hi[3 * i + k] = traced[6 * from + k];
      c.lo[3 * i + k] = traced[6 * from + 3 + k];
    }
  }
  out.vertices.resize(3 * V);
  for (size_t i = 0; i < V; ++i) {
    const size_t at = canonical ? i : numbering.rank[i];
    for (int k = 0; k < 3; ++k) out.vertices[3 * i + k] = std::ldexp(c.hi[3 * at + k], unscale_exp);
  }
  for (size_t i = 0; i < V; ++i)
    for (int k = 0; k < 3; ++k) {
      // Knuth's two-sum of a = hi_i and b = -hi_0: s + err == a + b exactly.
      const double a = c.hi[3 * i + k], b = -c.hi[k];
      const double s = a + b, bb = s - a, err = (a - (s - bb)) + (b - bb);
      // local + local_lo: the difference to ~1e-30 (the volume of a nearly flat kernel cancels
      // far below the rounding of one double).
      const double tail = err + (c.lo[3 * i + k] - c.lo[k]);
      c.local[3 * i + k] = s + tail;
      c.local_lo[3 * i + k] = tail - (c.local[3 * i + k] - s);
    }
}

// The output edges: with `canonical`, (low, high) canonical id pairs in increasing order; else in
// traced order, numbering and orientation (the step events').
void number_edges(const TraceResult& trace, const VertexNumbering& numbering, bool canonical, Kernel& out) {
  const size_t E = trace.edges.size();
  out.edges.resize(2 * E);
  if (!canonical) {
    for (size_t i = 0; i < E; ++i) {
      out.edges[2 * i] = trace.edges[i].a;
      out.edges[2 * i + 1] = trace.edges[i].b;
    }
    return;
  }
  std::vector<uint64_t> keys(E);
  for (size_t i = 0; i < E; ++i) {
    const uint64_t a = numbering.rank[trace.edges[i].a], b = numbering.rank[trace.edges[i].b];
    keys[i] = a < b ? (a << 32 | b) : (b << 32 | a);
  }
  std::sort(keys.begin(), keys.end());
  for (size_t i = 0; i < E; ++i) {
    out.edges[2 * i] = uint32_t(keys[i] >> 32);
    out.edges[2 * i + 1] = uint32_t(keys[i]);
  }
}

// Flat: some opposite pair is tight at a vertex (then it is tight everywhere); the lower of the
// two, or kNoPlane.
uint32_t flat_plane_of(const PlaneSet& ps, const TraceResult& trace) {
  const PlaneIds& tight = trace.vertices[0].tight;
  for (uint32_t p : tight) {
    uint32_t o = ps.opposite(p);
    if (o != kNoPlane && std::binary_search(tight.begin(), tight.end(), o)) return std::min(p, o);
  }
  return kNoPlane;
}

struct PlaneEdge {
  uint32_t h, e, s;
};

// (plane, edge) pairs grouped by plane, edges increasing within a group, each with another
// plane s through the edge, not h or its opposite: found in this pass over the edges in order,
// since per facet their plane lists are scattered reads. The grouping is a counting sort over
// plane ids when the pairs are numerous enough to pay for one count per plane, a sort otherwise
// (a small kernel of a large mesh stays output-sized).
std::vector<PlaneEdge> plane_edges_by_plane(const PlaneSet& ps, const TraceResult& trace) {
  const size_t E = trace.edges.size();
  auto pair_at = [&](uint32_t e, uint32_t h) {
    uint32_t s = kNoPlane;
    for (uint32_t c : trace.edges[e].planes)
      if (c != h && c != ps.opposite(h)) {
        s = c;
        break;
      }
    return PlaneEdge{h, e, s};
  };
  size_t num_pairs = 0;
  for (const TracedEdge& te : trace.edges) num_pairs += te.planes.size();
  std::vector<PlaneEdge> grouped;
  if (8 * num_pairs >= ps.size()) {
    std::vector<uint32_t> fill(ps.size() + 1, 0);
    for (const TracedEdge& te : trace.edges)
      for (uint32_t h : te.planes) ++fill[h + 1];
    for (size_t h = 0; h < ps.size(); ++h) fill[h + 1] += fill[h];
    grouped.resize(num_pairs);
    for (uint32_t e = 0; e < E; ++e)
      for (uint32_t h : trace.edges[e].planes) grouped[fill[h]++] = pair_at(e, h);
  } else {
    grouped.reserve(num_pairs);
    for (uint32_t e = 0; e < E; ++e)
      for (uint32_t h : trace.edges[e].planes) grouped.push_back(pair_at(e, h));
    std::stable_sort(grouped.begin(), grouped.end(), [](const PlaneEdge& x, const PlaneEdge& y) { return x.h < y.h; });
  }
  return grouped;
}

// Facets: planes holding three or more edges (the flat plane alone for a polygon), increasing,
// as [begin, end) ranges of `grouped`; `corners` counts their edges.
std::vector<std::pair<uint32_t, uint32_t>> facet_ranges(const std::vector<PlaneEdge>& grouped, uint32_t flat_plane,
                                                        size_t& corners) {
  std::vector<std::pair<uint32_t, uint32_t>> facets;
  facets.reserve(grouped.size() / 3 + 1);  // (each has three edges or more)
  corners = 0;
  for (uint32_t i = 0, j; i < grouped.size(); i = j) {
    for (j = i; j < grouped.size() && grouped[j].h == grouped[i].h; ++j) {}
    if (flat_plane != kNoPlane ? grouped[i].h == flat_plane : j - i >= 3) {
      facets.push_back({i, j});
      corners += j - i;
    }
  }
  return facets;
}

// One facet's loop, in output ids, started at its lowest vertex: [begin, begin + size) of the
// collected corners, on plane h.
struct FacetLoop {
  uint32_t begin, size, h;
};

// The facets' loops (canonical ids, each started at its lowest vertex) sorted in increasing
// order of their vertex sequences (two facets never share one), appended to the output faces
// and triangles (each face's fan from its first corner) in output ids (`output_id` of a canonical
// id, or the canonical id itself when null) and announced in that order while `emit_face` wants
// more. Each face's plane goes to `face_planes` when given.
void emit_sorted_facets(std::vector<FacetLoop>& loops, std::vector<uint32_t>& corners, const uint32_t* output_id,
                        const std::function<bool(const StepEvent&)>& emit_face, Kernel& out,
                        std::vector<uint32_t>* face_planes) {
  const uint32_t* cs = corners.data();
  std::sort(loops.begin(), loops.end(), [cs](const FacetLoop& x, const FacetLoop& y) {
    return std::lexicographical_compare(cs + x.begin, cs + x.begin + x.size, cs + y.begin, cs + y.begin + y.size);
  });
  if (output_id)
    for (uint32_t& v : corners) v = output_id[v];
  bool announce = true;
  for (const FacetLoop& f : loops) {
    const uint32_t* loop = cs + f.begin;
    const uint32_t fid = uint32_t(out.face_sizes.size());
    if (face_planes) face_planes->push_back(f.h);
    out.face_sizes.push_back(f.size);
    out.face_indices.insert(out.face_indices.end(), loop, loop + f.size);
    for (size_t i = 1; i + 1 < f.size; ++i) {
      out.triangles.push_back(loop[0]);
      out.triangles.push_back(loop[i]);
      out.triangles.push_back(loop[i + 1]);
    }
    if (announce && emit_face) {
      StepEvent ev;
      ev.kind = StepEvent::Kind::Face;
      ev.id = fid;
      ev.loop = out.face_indices.data() + (out.face_indices.size() - f.size);
      ev.loop_size = f.size;
      announce = emit_face(ev);
    }
  }
}

// Each facet's edges oriented exactly and walked into one CCW loop, its vertices renumbered by
// `rank` and started at the lowest, collected in `loops` / `corners`. False when a complete
// trace leaves a facet that is not one closed loop (a stopped run leaves facets open).
bool walk_facets(const PlaneSet& ps, const TraceResult& trace, const std::vector<PlaneEdge>& grouped,
                 const std::vector<std::pair<uint32_t, uint32_t>>& facets, const std::vector<uint32_t>& rank,
                 std::vector<FacetLoop>& loops, std::vector<uint32_t>& corners) {
  const size_t V = trace.vertices.size();
  bool ok = true;
  // Per vertex: the next one along the facet being walked; the facet's tails (at most V) and
  // its loop (at most V + 1: a walk that misses its start stops one step past the tails), in
  // one allocation.
  std::vector<uint32_t> walk(3 * V + 1, kNoVertex);
  uint32_t *next = walk.data(), *touched = next + V, *loop = touched + V;
  for (const auto& [begin, end] : facets) {
    const uint32_t h = grouped[begin].h;
    size_t num_touched = 0, loop_size = 0;
    bool valid = true;
    for (uint32_t i = begin; i < end; ++i) {
      const TracedEdge& te = trace.edges[grouped[i].e];
      const uint32_t s = grouped[i].s;
      if (s == kNoPlane) {
        valid = false;
        break;
      }
      int sg = te.sigma * sign_edge_in_facet(ps, te.p, te.q, h, s);
      uint32_t from = sg > 0 ? te.a : te.b, to = sg > 0 ? te.b : te.a;
      if (sg == 0 || next[from] != kNoVertex) {
        valid = false;
        break;
      }
      next[from] = to;
      touched[num_touched++] = from;  // (no vertex twice: next[from] was unset)
    }
    if (valid) {
      uint32_t start = touched[0], v = start;
      do {
        loop[loop_size++] = v;
        v = next[v];
      } while (v != kNoVertex && v != start && loop_size <= num_touched);
      valid = v == start && loop_size == num_touched;
    }
    for (size_t t = 0; t < num_touched; ++t) next[touched[t]] = kNoVertex;
    if (!valid) {
      if (trace.complete) ok = false;
      continue;
    }
    size_t first = 0;
    for (size_t i = 0; i < loop_size; ++i) {
      loop[i] = rank[loop[i]];
      if (loop[i] < loop[first]) first = i;
    }
    loops.push_back({uint32_t(corners.size()), uint32_t(loop_size), h});
    corners.insert(corners.end(), loop + first, loop + loop_size);
    corners.insert(corners.end(), loop, loop + first);
  }
  return ok;
}

// Six times the volume summed again in double-double, from the local coordinates to ~1e-30, about
// vertex 0 (the local origin, exactly). Every term is then the volume of a tetrahedron spanned by
// a kernel vertex and a face triangle, not negative in exact arithmetic (the kernel is convex),
// so a negative computed term is rounding and counts as 0: the sum is never negative.
double vol6_double_double(const VertexCoordinates& c, const std::vector<uint32_t>& triangles) {
  using exact::ApproxDD;
  auto PD = [&](uint32_t v, int k) { return ApproxDD(c.local[3 * size_t(v) + k], c.local_lo[3 * size_t(v) + k], 0); };
  ApproxDD sum(0);
  for (size_t t = 0; t < triangles.size(); t += 3) {
    uint32_t a = triangles[t], b = triangles[t + 1], d = triangles[t + 2];
    if (a == 0 || b == 0 || d == 0) continue;  // (a face through vertex 0: volume 0)
    ApproxDD u[3], w[3], r[3];
    for (int k = 0; k < 3; ++k) {
      u[k] = PD(b, k) - PD(a, k);
      w[k] = PD(d, k) - PD(a, k);
      r[k] = PD(a, k);
    }
    const ApproxDD n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    const ApproxDD term = n[0] * r[0] + n[1] * r[1] + n[2] * r[2];
    if (term.hi + term.lo > 0) sum = sum + term;
  }
  return sum.hi + sum.lo;
}

// Area and six times the volume (divergence theorem about the vertex centroid), in the scaled
// units of the plane set so that huge or tiny inputs neither overflow nor underflow before the
// ratio.
void area_and_vol6(const VertexCoordinates& c, size_t V, const std::vector<uint32_t>& triangles, double& area,
                   double& vol6) {
  auto P = [&](uint32_t v, int k) { return c.local[3 * size_t(v) + k]; };
  double centre[3] = {0, 0, 0};
  for (uint32_t i = 0; i < V; ++i)
    for (int k = 0; k < 3; ++k) centre[k] += P(i, k) / double(V);
  // The double pass's error, over eps: the rounding of the terms (vol6_abs) and the rounding of
  // the local coordinates themselves (below eps max|local| = eps reach each), which the edge
  // vectors u, w and the arm r inherit: a kernel far thinner than its distance from vertex 0
  // (a needle under a far apex) has edges below that rounding, and terms of no correct digit.
  double reach = 0;
  for (size_t i = 0; i < 3 * V; ++i) reach = std::max(reach, std::fabs(c.local[i]));
  double vol6_abs = 0, coordinate_error = 0;
  area = vol6 = 0;
  for (size_t t = 0; t < triangles.size(); t += 3) {
    uint32_t a = triangles[t], b = triangles[t + 1], d = triangles[t + 2];
    double u[3], w[3], r[3];
    for (int k = 0; k < 3; ++k) {
      u[k] = P(b, k) - P(a, k);
      w[k] = P(d, k) - P(a, k);
      r[k] = P(a, k) - centre[k];
    }
    double n[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    area += 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const double term = n[0] * r[0] + n[1] * r[1] + n[2] * r[2];
    vol6 += term;
    vol6_abs += std::fabs(n[0] * r[0]) + std::fabs(n[1] * r[1]) + std::fabs(n[2] * r[2]);
    const double u1 = std::fabs(u[0]) + std::fabs(u[1]) + std::fabs(u[2]),
                 w1 = std::fabs(w[0]) + std::fabs(w[1]) + std::fabs(w[2]);
    const double r1 = std::fabs(r[0]) + std::fabs(r[1]) + std::fabs(r[2]),
                 n1 = std::fabs(n[0]) + std::fabs(n[1]) + std::fabs(n[2]);
    coordinate_error += reach * (4 * (u1 + w1) * r1 + 2 * n1);
  }
  // A nearly flat kernel's volume is far below the rounding of its terms (a tetrahedron of volume
  // 1e-17 with unit edges came out negative): then it is summed again in double-double. (A kernel
  // smaller than the coordinates' resolution, e.g. three vertices within 1e-30 of each other, had
  // volume -1e-68 against a true ~1e-83; a needle of base 1e-10 under an apex 1e6 away, whose
  // terms cancel in no sum, had volume 1.4e-3 against a true 3.1e-18 before the coordinates'
  // rounding counted.)
  if (!(vol6 > 1e-6 * (vol6_abs + coordinate_error))) vol6 = vol6_double_double(c, triangles);
}

}  // namespace

bool assemble_polytope(const PlaneSet& ps, const TraceResult& trace, int unscale_exp, Kernel& out,
                       const std::function<bool(const StepEvent&)>& emit_face, double& scaled_volume,
                       std::vector<uint32_t>* face_planes, VertexOrder vertex_order) {
  scaled_volume = 0;
  const size_t V = trace.vertices.size(), E = trace.edges.size();
  const bool canonical = vertex_order == VertexOrder::Canonical;
  VertexCoordinates coords(V);
  VertexNumbering numbering;
  round_vertices(ps, trace, unscale_exp, canonical, coords, numbering, out);
  number_edges(trace, numbering, canonical, out);
  if (V == 0) {
    out.type = KernelType::Empty;
    return true;
  }
  if (V == 1) {
    out.type = KernelType::Point;
    return true;
  }
  if (V == 2 && E <= 1) {
    out.type = KernelType::Segment;
    return true;
  }
  const uint32_t flat_plane = flat_plane_of(ps, trace);
  out.type = flat_plane != kNoPlane ? KernelType::Polygon : KernelType::Polyhedron;

  const std::vector<PlaneEdge> grouped = plane_edges_by_plane(ps, trace);
  size_t num_corners = 0;
  const auto facets = facet_ranges(grouped, flat_plane, num_corners);
  std::vector<FacetLoop> loops;
  std::vector<uint32_t> corners;
  loops.reserve(facets.size());
  corners.reserve(num_corners);
  bool ok = walk_facets(ps, trace, grouped, facets, numbering.rank, loops, corners);
  out.face_sizes.reserve(loops.size());
  out.face_indices.reserve(corners.size());
  out.triangles.reserve(3 * (corners.size() - std::min(corners.size(), 2 * loops.size())));
  if (face_planes) face_planes->reserve(loops.size());
  emit_sorted_facets(loops, corners, canonical ? nullptr : numbering.order.data(), emit_face, out, face_planes);

  // Area and volume from the canonical numbering, whatever the output's.
  std::vector<uint32_t> canonical_triangles;
  if (!canonical) {
    canonical_triangles.reserve(out.triangles.size());
    for (uint32_t v : out.triangles) canonical_triangles.push_back(numbering.rank[v]);
  }
  double area = 0, vol6 = 0;
  area_and_vol6(coords, V, canonical ? out.triangles : canonical_triangles, area, vol6);
  scaled_volume = (out.type == KernelType::Polyhedron && trace.complete) ? vol6 / 6 : 0;
  out.area = std::ldexp(area, 2 * unscale_exp);
  out.volume = std::ldexp(scaled_volume, 3 * unscale_exp);
  if (out.type == KernelType::Polyhedron && trace.complete && V + out.face_sizes.size() != E + 2) ok = false;
  return ok;
}

}  // namespace kergen
