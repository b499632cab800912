// Clipping a convex polytope by planes (clip_polytope.h).
#include "small/clip_polytope.h"

#include <algorithm>

#include "exact/error_bounds.h"
#include "exact/formulas.h"
#include "exact/predicates.h"
#include "exact/vertex.h"
#include "small/box_polytope.h"

namespace kergen {

namespace {

void insert_sorted(PlaneIds& v, uint32_t x) {
  auto it = std::lower_bound(v.begin(), v.end(), x);
  if (it == v.end() || *it != x) v.insert(it, x);
}

// Whether the sorted sets a and b share a plane other than h and its opposite `oh`.
bool share_other_plane(const PlaneIds& a, const PlaneIds& b, uint32_t h, uint32_t oh) {
  const uint32_t *i = a.begin(), *j = b.begin();
  while (i != a.end() && j != b.end()) {
    if (*i < *j) {
      ++i;
    } else if (*j < *i) {
      ++j;
    } else {
      if (*i != h && *i != oh) return true;
      ++i;
      ++j;
    }
  }
  return false;
}

// The vertex of planes a, b and c as a clip needs it first: filtered coordinates with rigorous
// bounds, as loose as the planes' conditioning makes them, and no input-point search (side()
// searches when its filter cannot decide). Most vertices of a clip are cut away again, and
// those of nearly coplanar planes (the triangles of a split polygon) are poorly conditioned,
// which make_vertex refines in double-double at once; finish() makes the survivors with
// make_vertex. (make_vertex itself when the determinant's sign is not certain.)
VertexGeom transient_vertex(const PlaneSet& ps, uint32_t a, uint32_t b, uint32_t c) {
  const PlaneCoef<Approx> pa = ps.approx(a), pb = ps.approx(b), pc = ps.approx(c);
  const Approx den = det3_normals(pa, pb, pc);
  if (!den.certain()) return make_vertex(ps, a, b, c, false);
  VertexGeom v;
  v.basis[0] = a;
  v.basis[1] = b;
  v.basis[2] = c;
  v.det_sign = den.sign();
  v.late_point = kPointNotSearched;
  Approx num[3];
  formula::cramer_numerators(pa, pb, pc, num);
  for (int k = 0; k < 3; ++k) v.x[k] = num[k] / den;
  return v;
}

}  // namespace

void ClipPolytope::reset(const TraceResult& start, size_t clips) {
  // Room for what the clips add (measured on the polyhedra sets: about four vertices and six
  // edges a clip), so that a first use allocates each array once instead of growing it.
  const size_t room_v = start.vertices.size() + 6 * clips, room_e = start.edges.size() + 9 * clips;
  vertices_.reserve(room_v);
  filter_.reserve(room_v);
  live_.reserve(room_v);
  side_.reserve(room_v);
  remap_.reserve(room_v);
  edges_.reserve(room_e);
  cut_points_.reserve(16);
  vertices_.clear();
  filter_.clear();
  live_.clear();
  for (const TracedVertex& v : start.vertices) add_vertex(TracedVertex(v));
  edges_.clear();
  for (const TracedEdge& e : start.edges) edges_.push_back({e.a, e.b});
}

uint32_t ClipPolytope::add_vertex(TracedVertex&& v) {
  filter_.push_back({{v.geom.x[0].v, v.geom.x[1].v, v.geom.x[2].v}, vertex_filter_terms(v.geom.x)});
  vertices_.push_back(std::move(v));
  live_.push_back(uint32_t(vertices_.size() - 1));
  return uint32_t(vertices_.size() - 1);
}

bool ClipPolytope::clip(const PlaneSet& ps, uint32_t h) {
  const size_t n = vertices_.size();
  side_.resize(n);
  bool any_in = false, any_out = false;
  // The tracer's double filter (vertex_filter.h) first, also at input points (where side()
  // goes to orient3d and the incidence lists at once): most vertices are far from most planes.
  const PlaneCoef<Approx> c = ps.approx(h);
  const double a = c.n[0].v, b = c.n[1].v, cz = c.n[2].v, d = c.d.v;
  const PlaneFilterTerms terms = plane_filter_terms(a, b, cz, d, c.n[0].e, c.n[1].e, c.n[2].e, c.d.e);
  const size_t live = live_.size();
  for (size_t i = 0; i < live; ++i) {
    const uint32_t v = live_[i];
    const Filter& fv = filter_[v];
    const double f = a * fv.x[0] + b * fv.x[1] + cz * fv.x[2] + d;
    const double bound = vertex_filter_bound(terms, fv.terms) * exact::kBoundScale;
    const int s = f < -bound ? -1 : f > bound ? 1 : side(ps, h, vertices_[v].geom);
    side_[v] = int8_t(s);
    any_in |= s < 0;
    any_out |= s > 0;
  }
  if (!any_in) return false;
  cut_points_.clear();
  for (size_t i = 0; i < live; ++i)
    if (const uint32_t v = live_[i]; side_[v] == 0) {
      insert_sorted(vertices_[v].tight, h);
      cut_points_.push_back(v);
    }
  if (!any_out) return true;  // (the plane touches at most a face: nothing is cut)

  const size_t first_new = n;
  for (auto& e : edges_) {
    const int sa = side_[e[0]], sb = side_[e[1]];
    if (sa <= 0 && sb <= 0) continue;
    if (sa >= 0 && sb >= 0) {  // outside, or from outside to a vertex on h: gone
      e[0] = kNoVertex;
      continue;
    }
    const uint32_t in = sa < 0 ? e[0] : e[1];
    const PlaneIds &ta = vertices_[e[0]].tight, &tb = vertices_[e[1]].tight;
    shared_.clear();
    std::set_intersection(ta.begin(), ta.end(), tb.begin(), tb.end(), std::back_inserter(shared_));
    uint32_t p = kNoPlane, q = kNoPlane;
    for (uint32_t x : shared_) {
      if (p == kNoPlane)
        p = x;
      else if (x != ps.opposite(p)) {
        q = x;
        break;
      }
    }
    if (q == kNoPlane) return false;
    TracedVertex nv;
    nv.geom = transient_vertex(ps, p, q, h);
    nv.tight = shared_;
    insert_sorted(nv.tight, h);
    const uint32_t id = add_vertex(std::move(nv));
    side_.push_back(0);
    cut_points_.push_back(id);
    e = {in, id};
  }
  if (!connect_cut_points(ps, h, first_new)) return false;
  // The survivors, then the cut points added after them (ids stay increasing).
  size_t kept_live = 0;
  for (size_t i = 0; i < live; ++i)
    if (side_[live_[i]] <= 0) live_[kept_live++] = live_[i];
  live_.erase(live_.begin() + kept_live, live_.begin() + live);
  size_t kept = 0;
  for (const auto& e : edges_)
    if (e[0] != kNoVertex) edges_[kept++] = e;
  edges_.resize(kept);
  return true;
}

bool ClipPolytope::connect_cut_points(const PlaneSet& ps, uint32_t h, size_t first_new) {
  const uint32_t oh = ps.opposite(h);
  const size_t c = cut_points_.size();
  for (size_t i = 0; i < c; ++i) {
    const uint32_t x = cut_points_[i];
    for (size_t j = i + 1; j < c; ++j) {
      const uint32_t y = cut_points_[j];
      if (!share_other_plane(vertices_[x].tight, vertices_[y].tight, h, oh)) continue;
      if (x < first_new && y < first_new) {
        // Two vertices that were on h already: their edge may be there (a face of the
        // polytope on h before the cut).
        bool known = false;
        for (const auto& e : edges_)
          if ((e[0] == x && e[1] == y) || (e[0] == y && e[1] == x)) known = true;
        if (known) continue;
      }
      edges_.push_back({x, y});
    }
  }
  return c >= 3;
}

bool ClipPolytope::finish(const PlaneSet& ps, TraceResult& out) {
  out.vertices.clear();  // (cleared, not replaced: a batch keeps their capacity)
  out.edges.clear();
  out.complete = true;
  out.internal_error = false;
  remap_.assign(vertices_.size(), kNoVertex);
  out.vertices.reserve(live_.size());
  for (uint32_t v : live_) {
    remap_[v] = uint32_t(out.vertices.size());
    TracedVertex& tv = vertices_[v];
    // The survivors as make_vertex makes them (with their input point, or refined
    // coordinates): the same vertices, so the same output coordinates, as the general path's.
    if (tv.geom.mesh_point == kNoPoint)
      tv.geom = make_vertex(ps, tv.geom.basis[0], tv.geom.basis[1], tv.geom.basis[2], true, tv.geom.det_sign);
    out.vertices.push_back(std::move(tv));
  }
  out.edges.resize(edges_.size());
  for (size_t i = 0; i < edges_.size(); ++i)
    if (!edge_between(ps, out, remap_[edges_[i][0]], remap_[edges_[i][1]], out.edges[i])) return false;
  out.traced_lines = edges_.size();
  return true;
}

}  // namespace kergen
