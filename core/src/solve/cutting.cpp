// Incremental plane cuts of a convex polytope with exact incidences (see cutting.h).
//
// Why a cut is exact: a vertex is removed iff side() > 0 (exact sign); an edge from a removed
// vertex to a kept one inside the plane gets the vertex (p, q, h) of its line and the plane;
// the new face's edges join the cut points (new vertices and vertices on h) two by two: the
// cut points on another plane g lie on the line g ∩ h, and a face of a convex polytope that
// lies on a line holds exactly two vertices, so every pair sharing g is an edge and more than
// two would be an inconsistency.
#include "solve/cutting.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>

#include "solve/climb.h"

namespace kergen {

namespace {

enum : int8_t { kUnseen = 0, kInside = 1, kOn = 2, kOutside = 3 };

void insert_sorted(PlaneIds& v, uint32_t x) {
  auto it = std::lower_bound(v.begin(), v.end(), x);
  if (it == v.end() || *it != x) v.insert(it, x);
}

// `out` = the sorted set `v` with x added, in one pass (a cut point's tight set: its edge's
// planes and the cutting plane).
void copy_with(const PlaneIds& v, uint32_t x, PlaneIds& out) {
  out.clear();
  out.reserve(v.size() + 1);
  const uint32_t* it = v.begin();
  for (; it != v.end() && *it < x; ++it) out.push_back(*it);
  if (it == v.end() || *it != x) out.push_back(x);
  for (; it != v.end(); ++it) out.push_back(*it);
}

class Cutter {
 public:
  // `cuts` is the number of planes to come: a cut adds a few vertices and edges, so the arrays
  // are sized once (growing them would move every vertex several times). Dense spheres add 3.3
  // (geodesic) to 4.8 (UV: the two float triangles of a quad) vertices per cut.
  Cutter(const PlaneSet& ps, const TraceResult& prev, size_t cuts) : ps_(ps) {
    const size_t V = prev.vertices.size(), room_v = V + 5 * cuts, room_e = prev.edges.size() + 6 * cuts;
    vertices_.reserve(room_v);
    vertices_ = prev.vertices;
    edges_.reserve(room_e);
    edges_ = prev.edges;
    alive_v_.reserve(room_v);
    adj_.reserve(room_v);
    xyz_.reserve(3 * room_v);
    replaced_by_.reserve(room_v);
    state_.reserve(room_v);
    alive_e_.reserve(room_e);
    alive_v_.assign(V, 1);
    alive_e_.assign(edges_.size(), 1);
    adj_.resize(V);
    xyz_.resize(3 * V);
    for (size_t v = 0; v < V; ++v) note_coordinates(v);
    for (uint32_t e = 0; e < edges_.size(); ++e) {
      adj_[edges_[e].a].push_back({e, edges_[e].b});
      adj_[edges_[e].b].push_back({e, edges_[e].a});
    }
    replaced_by_.assign(V, kNoVertex);
    state_.assign(V, kUnseen);
    alive_count_ = V;
    traced_lines_ = prev.traced_lines;
  }

  // Cuts by plane h, climbing from the best of the hints (dead ones stand for the cut point that
  // replaced them; invalid ones, kNoVertex, are skipped; vertex 0 when none is valid); `near`
  // gets a vertex on or nearest to h afterwards, a start for planes of similar normal. False
  // when the result is not handled (see cutting.h).
  bool cut(uint32_t h, std::initializer_list<uint32_t> hints, uint32_t& near) {
    const PlaneCoef<Approx> plane = ps_.approx(h);
    const double a = plane.n[0].v, b = plane.n[1].v, c = plane.n[2].v, d = plane.d.v;
    // The bounds of culling's support test: the climb's tie is 4 delta, the margin 16 delta.
    const double delta =
        value_error_bound(a, b, c, d, plane.n[0].e, plane.n[1].e, plane.n[2].e, plane.d.e, max_abs_, coord_error_);
    const double tie = kClimbTie * delta, margin = kReachMargin * delta;
    auto f = [&](uint32_t v) { return a * xyz_[3 * v] + b * xyz_[3 * v + 1] + c * xyz_[3 * v + 2] + d; };
    uint32_t cur = kNoVertex;
    double val = 0;
    for (uint32_t hint : hints) {
      if (hint >= alive_v_.size()) continue;
      const uint32_t start = alive(hint);
      const double start_val = f(start);
      if (cur == kNoVertex || start_val > val) {
        cur = start;
        val = start_val;
      }
    }
    if (cur == kNoVertex) {
      cur = alive(0);
      val = f(cur);
    }
    // To the maximum of f_h over the polytope: greedy ascent in double, then along edges on
    // which f_h certainly rises (in double where the values differ by more than the tie, else
    // by the exact sign of its rate). A vertex without such an edge is an exact maximum: the
    // directions of its edges span a cone holding the whole polytope.
    for (bool moved = true; moved;) {
      moved = false;
      for (const Link& link : adj_[cur]) {
        const uint32_t w = link.to;
        const double fw = f(w);
        if (fw > val) {
          cur = w;
          val = fw;
          moved = true;
          break;
        }
      }
    }
    // (Each step rises strictly, so the walk meets each vertex at most once; the count only
    // guards against an inconsistent graph, which the caller then traces instead.)
    size_t steps = 0;
    for (bool moved = true; moved;) {
      moved = false;
      if (++steps > vertices_.size()) return false;
      for (const Link& link : adj_[cur]) {
        const uint32_t w = link.to;
        const double fw = f(w);
        if (fw < val - tie) continue;  // certainly lower: each value is within delta of exact
        if (fw > val + tie || rate_sign(h, link.edge, cur) > 0) {
          cur = w;
          val = fw;
          moved = true;
          break;
        }
      }
    }
    near = cur;
    if (val <= -margin) return true;  // strictly inside at every vertex: no change
    // The exact sign where the double value is far from 0 (each value is within delta of exact),
    // else side(): a vertex certainly outside is removed without reading its record.
    auto sign_at = [&](uint32_t v, double fv) {
      return fv <= -margin ? -1 : fv > tie ? 1 : side(ps_, h, vertices_[v].geom);
    };
    const int top = sign_at(cur, val);
    if (top < 0) return true;

    // The vertices with f_h >= 0 induce a connected subgraph holding the maximum: a search
    // through them from it finds them all, and gives each of their neighbours a state.
    region_.assign(1, cur);
    out_.clear();
    on_.clear();
    auto classify = [&](uint32_t v, int s) {
      state_[v] = s > 0 ? kOutside : s == 0 ? kOn : kInside;
      if (s > 0) out_.push_back(v);
      if (s == 0) on_.push_back(v);
    };
    classify(cur, top);
    for (size_t i = 0; i < region_.size(); ++i) {
      const uint32_t v = region_[i];
      if (state_[v] == kInside) continue;
      for (const Link& link : adj_[v]) {
        const uint32_t w = link.to;
        if (state_[w] != kUnseen) continue;
        classify(w, sign_at(w, f(w)));
        region_.push_back(w);
      }
    }
    const bool ok = apply(h);
    for (uint32_t v : region_) state_[v] = kUnseen;
    if (!cut_points_.empty()) near = cut_points_[0];
    return ok;
  }

  void finish(TraceResult& out) {
    std::vector<uint32_t> id(vertices_.size(), kNoVertex);
    out = TraceResult();
    // (Sized first: growing them moved every vertex and edge of a dense kernel several times.)
    out.vertices.reserve(alive_count_);
    out.edges.reserve(size_t(std::count(alive_e_.begin(), alive_e_.end(), char(1))));
    for (uint32_t v = 0; v < vertices_.size(); ++v) {
      if (!alive_v_[v]) continue;
      id[v] = uint32_t(out.vertices.size());
      out.vertices.push_back(std::move(vertices_[v]));
    }
    for (uint32_t e = 0; e < edges_.size(); ++e) {
      if (!alive_e_[e]) continue;
      TracedEdge te = std::move(edges_[e]);
      te.a = id[te.a];
      te.b = id[te.b];
      out.edges.push_back(std::move(te));
    }
    out.traced_lines = traced_lines_;
  }

 private:
  // The live vertex standing for v: v itself, or the cut point that replaced it (recursively;
  // the chain is shortened as it is walked).
  uint32_t alive(uint32_t v) {
    uint32_t r = v;
    while (!alive_v_[r]) r = replaced_by_[r];
    while (v != r && !alive_v_[v]) {
      const uint32_t next = replaced_by_[v];
      replaced_by_[v] = r;
      v = next;
    }
    return r;
  }

  uint32_t other(uint32_t e, uint32_t v) const { return edges_[e].a == v ? edges_[e].b : edges_[e].a; }

  // Exact sign of the rate of f_h along edge e leaving its end v. The edge runs from a to b along
  // sigma (n_p x n_q), so the rate is sigma det3(n_h, n_p, n_q) (from a); it is also
  // n_h . (w - v) for the other end w. Cheapest first: the determinant's double and
  // double-double filters; where h is nearly parallel to the edge's planes (a face planar up to
  // rounding) the determinant needs expansions, while n_h . (w - v) in double-double at the
  // ends' coordinates (as known, then from their exact homogeneous coordinates, cached per
  // vertex) usually decides.
  int rate_sign(uint32_t h, uint32_t e, uint32_t v) const {
    const TracedEdge& te = edges_[e];
    const int orientation = te.a == v ? te.sigma : -te.sigma;
    const int filtered = det3_normals(ps_.approx(h), ps_.approx(te.p), ps_.approx(te.q)).sign();
    if (filtered != 2) return orientation * filtered;
    const VertexGeom &gv = vertices_[v].geom, &gw = vertices_[other(e, v)].geom;
    const PlaneCoef<exact::ApproxDD> n = ps_.dd(h);
    auto rate = [&](const exact::ApproxDD* pv, const exact::ApproxDD* pw) {
      return (n.n[0] * (pw[0] - pv[0]) + n.n[1] * (pw[1] - pv[1]) + n.n[2] * (pw[2] - pv[2])).sign();
    };
    const int dd = det3_normals(n, ps_.dd(te.p), ps_.dd(te.q)).sign();
    if (dd != 2) return orientation * dd;
    exact::ApproxDD pv[3], pw[3];
    if (dd_point(ps_, gv, pv) && dd_point(ps_, gw, pw)) {
      const int s = rate(pv, pw);
      if (s != 2) return s;
    }
    const exact::ApproxDD *xv = exact_dd_point(ps_, gv), *xw = exact_dd_point(ps_, gw);
    if (xv && xw) {
      const int s = rate(xv, xw);
      if (s != 2) return s;
    }
    return orientation * sign_det3_normals(ps_, h, te.p, te.q);
  }

  bool apply(uint32_t h) {
    // The vertices and edges on h gain it (all that changes when h only touches).
    for (uint32_t v : on_) insert_sorted(vertices_[v].tight, h);
    for (uint32_t v : on_)
      for (const Link& link : adj_[v])
        if (state_[link.to] == kOn && edges_[link.edge].a == v) insert_sorted(edges_[link.edge].planes, h);
    cut_points_.clear();
    if (out_.empty()) return true;
    if (out_.size() + on_.size() >= alive_count_) return false;  // nothing strictly inside: flat
    const uint32_t opposite = ps_.opposite(h);
    cut_points_ = on_;
    for (uint32_t v : out_) {
      // By index, re-reading adj_[v] (which the loop does not change) each time: add_vertex
      // below grows adj_, which moves v's list once a cut adds more vertices than the room
      // reserved (a plane cutting a vertex of many edges, such as a fan's apex). (A copy of the
      // list cost an allocation per removed vertex of more than four edges.)
      for (size_t i = 0; i < adj_[v].size(); ++i) {
        const Link link = adj_[v].data()[i];
        const uint32_t e = link.edge, w = link.to;
        if (!alive_e_[e]) continue;
        if (state_[w] == kOutside) {
          alive_e_[e] = 0;
        } else if (state_[w] == kOn) {
          alive_e_[e] = 0;
          auto& aw = adj_[w];
          aw.erase(std::find_if(aw.begin(), aw.end(), [e](const Link& l) { return l.edge == e; }));
        } else {
          // The edge leaves the removed part: it now ends where its line meets h.
          TracedEdge& te = edges_[e];
          TracedVertex nv;
          // Most cut vertices are later cut away again: the input-point search is left to the
          // first side test the filter cannot decide. The sign of det3(n_p, n_q, n_h) is known:
          // f_h falls strictly from v (outside) to w (inside), and its rate from te.a along the
          // edge is sigma det3(n_p, n_q, n_h), negative when v is te.a, positive when v is te.b.
          const int det_sign = te.a == v ? -te.sigma : te.sigma;
          nv.geom = make_vertex(ps_, te.p, te.q, h, false, det_sign);
          copy_with(te.planes, h, nv.tight);
          const uint32_t n = add_vertex(std::move(nv));
          (te.a == v ? te.a : te.b) = n;
          adj_[n].push_back({e, w});
          for (Link& l : adj_[w])
            if (l.edge == e) l.to = n;
          cut_points_.push_back(n);
        }
      }
      adj_[v].clear();
      alive_v_[v] = 0;
      --alive_count_;
    }
    const uint32_t any_cut_point = cut_points_.empty() ? kNoVertex : cut_points_[0];
    if (any_cut_point == kNoVertex) return false;
    for (uint32_t v : out_) replaced_by_[v] = any_cut_point;

    // The new face: cut points grouped by their other planes (one 64-bit key per pair sorts as
    // the pairs would).
    by_plane_.clear();
    for (uint32_t cpt : cut_points_)
      for (uint32_t g : vertices_[cpt].tight) {
        if (g == opposite) return false;  // flat
        if (g != h) by_plane_.push_back(uint64_t(g) << 32 | cpt);
      }
    std::sort(by_plane_.begin(), by_plane_.end());
    for (size_t i = 0; i < by_plane_.size();) {
      size_t j = i;
      const uint32_t g = uint32_t(by_plane_[i] >> 32);
      while (j < by_plane_.size() && uint32_t(by_plane_[j] >> 32) == g) ++j;
      if (j - i > 2) return false;
      if (j - i == 2 && !connect(g, h, uint32_t(by_plane_[i]), uint32_t(by_plane_[i + 1]))) return false;
      i = j;
    }
    for (uint32_t cpt : cut_points_)
      if (adj_[cpt].size() < 3) return false;
    return true;
  }

  // The double coordinates of vertex v, and the bounds on them the margins are made of.
  void note_coordinates(size_t v) {
    for (int k = 0; k < 3; ++k) {
      const Approx& x = vertices_[v].geom.x[k];
      xyz_[3 * v + k] = x.v;
      max_abs_ = std::max(max_abs_, std::fabs(x.v));
      coord_error_ = std::max(coord_error_, x.e);
    }
  }

  uint32_t add_vertex(TracedVertex&& v) {
    const uint32_t id = uint32_t(vertices_.size());
    for (int k = 0; k < 3; ++k) xyz_.push_back(0);  // (set below; within the reserved room)
    vertices_.push_back(std::move(v));
    note_coordinates(id);
    alive_v_.push_back(1);
    adj_.emplace_back();
    replaced_by_.push_back(kNoVertex);
    state_.push_back(kUnseen);
    ++alive_count_;
    return id;
  }

  // sign det3(n_r, n_g, n_h) when it is the determinant of v's basis up to the order of r and g
  // (a cut point made on the edge of planes r and g, or g and r, by h): its exact sign is known
  // from make_vertex. 2 otherwise.
  static int basis_det_sign(const VertexGeom& v, uint32_t r, uint32_t g, uint32_t h) {
    if (v.basis[2] != h || v.det_sign == 0) return 2;
    if (v.basis[0] == r && v.basis[1] == g) return v.det_sign;
    if (v.basis[0] == g && v.basis[1] == r) return -v.det_sign;
    return 2;
  }

  // Edge between cut points u and w on the line of planes g and h (unless it exists).
  bool connect(uint32_t g, uint32_t h, uint32_t u, uint32_t w) {
    for (const Link& l : adj_[u])
      if (l.to == w) return true;
    const auto &tu = vertices_[u].tight, &tw = vertices_[w].tight;
    // Direction u -> w = sigma (n_g x n_h): for a plane r through u but not w, f_r drops from 0
    // at u, and its rate along n_g x n_h is sign det3(n_r, n_g, n_h), so sigma is minus that.
    int sigma = 0;
    for (uint32_t r : tu) {
      if (std::binary_search(tw.begin(), tw.end(), r)) continue;
      const int known = basis_det_sign(vertices_[u].geom, r, g, h);
      const int s = known != 2 ? known : sign_det3_normals(ps_, r, g, h);
      if (s != 0) {
        sigma = -s;
        break;
      }
    }
    if (sigma == 0) return false;
    TracedEdge te;
    te.a = u;
    te.b = w;
    te.p = g;
    te.q = h;
    te.sigma = sigma;
    std::set_intersection(tu.begin(), tu.end(), tw.begin(), tw.end(), std::back_inserter(te.planes));
    const uint32_t id = uint32_t(edges_.size());
    edges_.push_back(std::move(te));
    alive_e_.push_back(1);
    adj_[u].push_back({id, w});
    adj_[w].push_back({id, u});
    return true;
  }

  const PlaneSet& ps_;
  std::vector<TracedVertex> vertices_;
  std::vector<TracedEdge> edges_;
  std::vector<char> alive_v_, alive_e_;
  // Per vertex, its edges and the vertex at their other end (three at a simple vertex): the
  // climbs and the region search step to neighbours without reading the edges. Room for six
  // inside the list: the input points of a triangulated surface (a geodesic sphere's kernel
  // vertices) have five or six, and a list on the heap costs the climbs a second random read.
  struct Link {
    uint32_t edge, to;
  };
  std::vector<SmallVector<Link, 6>> adj_;
  std::vector<double> xyz_;
  std::vector<uint32_t> replaced_by_;  // a cut point of the cut that removed the vertex
  std::vector<int8_t> state_;
  size_t alive_count_ = 0, traced_lines_ = 0;
  double max_abs_ = 0, coord_error_ = 0;  // over every vertex so far (upper bounds for the live ones)
  std::vector<uint32_t> region_, out_, on_, cut_points_;
  std::vector<uint64_t> by_plane_;  // (plane << 32 | cut point): sorted, the pairs' order
};

}  // namespace

namespace {

// A biased randomized insertion order (Amenta, Choi & Rote 2003): the random order cut into
// rounds doubling in size from 64, each round sorted along a cube map of the plane normals
// (64 x 64 cells per side, rows in serpentine order). Consecutive cuts then fall near each other
// on the polytope, so the climbs and the region search find its records in cache, while each
// round is still a random sample of the rest: the expected total change stays that of the
// random order.
void bias_for_locality(const PlaneSet& ps, const std::vector<uint32_t>& added, std::vector<uint32_t>& order) {
  constexpr size_t kSide = 64, kFirstRound = 64;
  std::vector<uint64_t> keyed(order.size());
  for (size_t i = 0; i < order.size(); ++i) {
    const uint32_t h = added[order[i]];
    size_t cell = cube_cell(kSide, ps.nx()[h], ps.ny()[h], ps.nz()[h]);
    if (cell == kNoCell) cell = 0;
    const size_t row = cell / kSide, col = cell % kSide;  // (row counts the cube's faces' rows)
    keyed[i] = uint64_t(row * kSide + (row & 1 ? kSide - 1 - col : col)) << 32 | order[i];
  }
  for (size_t begin = 0, size = kFirstRound; begin < keyed.size(); begin += size, size *= 2)
    std::sort(keyed.begin() + begin, keyed.begin() + std::min(keyed.size(), begin + size));
  for (size_t i = 0; i < order.size(); ++i) order[i] = uint32_t(keyed[i]);
}

}  // namespace

bool cut_kernel_trace(const PlaneSet& ps, const TraceResult& prev, const std::vector<uint32_t>& added,
                      const std::vector<uint32_t>& hints, uint64_t seed, TraceResult& out) {
  if (prev.vertices.empty() || !prev.complete || prev.internal_error) return false;
  std::vector<uint32_t> order(added.size());
  for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  // Random order: the expected total change of incremental half-space intersection is small
  // in random order, while input order (spatially coherent) can rebuild the same region often.
  for (size_t i = order.size(); i > 1; --i) {
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    std::swap(order[i - 1], order[size_t((seed >> 33) % i)]);
  }
  bias_for_locality(ps, added, order);
  Cutter cutter(ps, prev, added.size());
  // The hints come from prev; once cuts have refined the polytope near a direction, the last
  // vertex found for a plane of similar normal is usually closer. Two cube maps of the normals:
  // a fine one (about two planes per cell) and a coarse one for cells not visited yet.
  const size_t cells_per_side =
      std::min<size_t>(128, std::max<size_t>(1, size_t(std::sqrt(double(added.size()) / 12))));
  const size_t coarse_per_side = std::max<size_t>(1, cells_per_side / 4);
  std::vector<uint32_t> recent(6 * cells_per_side * cells_per_side, kNoVertex),
      recent_coarse(6 * coarse_per_side * coarse_per_side, kNoVertex);
  for (uint32_t i : order) {
    const uint32_t h = added[i];
    const size_t cell = cube_cell(cells_per_side, ps.nx()[h], ps.ny()[h], ps.nz()[h]);
    const size_t coarse = cube_cell(coarse_per_side, ps.nx()[h], ps.ny()[h], ps.nz()[h]);
    uint32_t near = kNoVertex;
    if (!cutter.cut(h,
                    {i < hints.size() ? hints[i] : 0, cell == kNoCell ? kNoVertex : recent[cell],
                     coarse == kNoCell ? kNoVertex : recent_coarse[coarse]},
                    near))
      return false;
    if (cell != kNoCell) recent[cell] = near;
    if (coarse != kNoCell) recent_coarse[coarse] = near;
  }
  cutter.finish(out);
  return true;
}

}  // namespace kergen
