// Step replay (see step_replay.h). The tracer's order, restated on a finished vertex graph:
// each discovered vertex queues one ray per kernel edge at it that is not traced yet; rays are
// taken first in, first out (with `from`: nearest origin vertex first, then first in); taking a
// ray whose edge was traced meanwhile (from its other end) does nothing; otherwise its far end
// is discovered if new (a Vertex event) and the edge is traced (an Edge event). The tracer
// queues a vertex's rays in the order of its tight plane pairs and numbers edges as it traces
// them; a vertex's edges sorted by the plane pair a ray along them was queued under are in the
// order of its rays, whichever trace (full, cut or updated) found them.
#include "output/step_replay.h"

#include <algorithm>
#include <cmath>
#include <queue>
#include <utility>
#include <vector>

namespace kergen {

namespace {

class Replay {
 public:
  Replay(const PlaneSet& ps, TraceResult& tr, const ReplayOptions& options)
      : ps_(ps), tr_(tr), opt_(options), new_id_(tr.vertices.size(), kNoVertex), traced_(tr.edges.size(), 0) {
    // Edges at each vertex, in increasing id (a counting sort keeps the order).
    const size_t V = tr.vertices.size();
    offset_.assign(V + 1, 0);
    for (const TracedEdge& e : tr.edges) {
      ++offset_[e.a + 1];
      ++offset_[e.b + 1];
    }
    for (size_t v = 0; v < V; ++v) offset_[v + 1] += offset_[v];
    at_.resize(offset_[V]);
    std::vector<uint32_t> fill(offset_.begin(), offset_.end() - 1);
    for (uint32_t e = 0; e < tr.edges.size(); ++e) {
      at_[fill[tr.edges[e].a]++] = e;
      at_[fill[tr.edges[e].b]++] = e;
    }
    // In the tracer's ray order at each vertex (see ray_key).
    std::vector<std::pair<uint32_t, uint32_t>> key(tr.edges.size());
    for (uint32_t e = 0; e < tr.edges.size(); ++e) key[e] = ray_key(tr.edges[e]);
    for (size_t v = 0; v < V; ++v)
      std::sort(at_.begin() + offset_[v], at_.begin() + offset_[v + 1],
                [&](uint32_t x, uint32_t y) { return key[x] != key[y] ? key[x] < key[y] : x < y; });
  }

  // Emits the stream from `start`; false when a callback or max_steps stopped it.
  bool run(uint32_t start) {
    if (!discover(start)) return false;
    while (!empty()) {
      const auto [from, e] = take();
      if (traced_[e]) continue;
      const TracedEdge& te = tr_.edges[e];
      const uint32_t to = te.a == from ? te.b : te.a;
      if (new_id_[to] == kNoVertex && !discover(to)) return false;
      traced_[e] = 1;
      edge_order_.push_back(e);
      edge_from_.push_back(from);
      StepEvent ev;
      ev.kind = StepEvent::Kind::Edge;
      ev.id = uint32_t(edge_order_.size() - 1);
      ev.a = new_id_[from];
      ev.b = new_id_[to];
      if (!emit(ev)) return false;
    }
    return true;
  }

  // The trace renumbered in event order; with `complete`, also what the stream never reached
  // (nothing, for the connected graph of a polytope), so that no part of the kernel is lost.
  TraceResult result(bool complete) {
    if (complete) {
      for (uint32_t v = 0; v < tr_.vertices.size(); ++v)
        if (new_id_[v] == kNoVertex) number(v);
      for (uint32_t e = 0; e < tr_.edges.size(); ++e)
        if (!traced_[e]) {
          edge_order_.push_back(e);
          edge_from_.push_back(tr_.edges[e].a);
        }
    }
    TraceResult out;
    out.complete = complete && tr_.complete;
    out.traced_lines = tr_.traced_lines;
    out.vertices.reserve(vertex_order_.size());
    for (uint32_t v : vertex_order_) out.vertices.push_back(std::move(tr_.vertices[v]));
    out.edges.reserve(edge_order_.size());
    for (size_t i = 0; i < edge_order_.size(); ++i) {
      TracedEdge e = std::move(tr_.edges[edge_order_[i]]);
      // Oriented from the vertex it was traced from: the direction sigma (n_p x n_q) runs from
      // a to b, so reversing the edge negates sigma.
      if (e.a != edge_from_[i]) {
        std::swap(e.a, e.b);
        e.sigma = -e.sigma;
      }
      e.a = new_id_[e.a];
      e.b = new_id_[e.b];
      out.edges.push_back(std::move(e));
    }
    return out;
  }

 private:
  void number(uint32_t v) {
    new_id_[v] = uint32_t(vertex_order_.size());
    vertex_order_.push_back(v);
  }

  bool discover(uint32_t v) {
    number(v);
    StepEvent ev;
    ev.kind = StepEvent::Kind::Vertex;
    ev.id = new_id_[v];
    if (opt_.on_step && *opt_.on_step) {
      // The same rounding as the result's coordinates (polytope assembly).
      double hi[3], lo[3];
      precise_coordinates(ps_, tr_.vertices[v].geom, hi, lo);
      // (+0 for a zero, as the result's vertices: polytope.cpp.)
      for (int k = 0; k < 3; ++k) ev.position[k] = std::ldexp(hi[k] + 0.0, opt_.unscale_exp);
    }
    const bool go = emit(ev);
    for (uint32_t i = offset_[v]; i < offset_[v + 1]; ++i)
      if (!traced_[at_[i]]) put(v, at_[i]);
    return go;
  }

  bool emit(const StepEvent& e) {
    if (opt_.steps) ++*opt_.steps;
    bool go = true;
    if (opt_.on_step && *opt_.on_step) go = (*opt_.on_step)(e);
    if (opt_.max_steps && opt_.steps && *opt_.steps >= opt_.max_steps) go = false;
    return go;
  }

  // The ray queue: first in, first out; with `from`, by the squared distance of the ray's
  // vertex from `from` (as the tracer computes it), then first in.
  void put(uint32_t from, uint32_t e) {
    if (!opt_.has_from) {
      fifo_.push_back({from, e});
      return;
    }
    const VertexGeom& g = tr_.vertices[from].geom;
    double prio = 0;
    for (int k = 0; k < 3; ++k) prio += (g.x[k].v - opt_.from[k]) * (g.x[k].v - opt_.from[k]);
    fifo_.push_back({from, e});
    rays_.push({prio, uint32_t(fifo_.size() - 1)});
  }
  bool empty() const { return opt_.has_from ? rays_.empty() : next_ == fifo_.size(); }
  std::pair<uint32_t, uint32_t> take() {
    if (!opt_.has_from) return fifo_[next_++];
    const uint32_t i = rays_.top().second;
    rays_.pop();
    return fifo_[i];
  }

  // The tracer queues a vertex's rays by pairs (p, q) of its sorted tight set, p before q, not
  // opposite planes, and keeps the first pair of each line: for an edge (whose planes all hold
  // the vertex) that is its first plane and the next one not opposite to it, whichever end the
  // ray leaves from. Sorting a vertex's edges by this pair restates the order of its rays.
  std::pair<uint32_t, uint32_t> ray_key(const TracedEdge& e) const {
    const uint32_t p = e.planes.empty() ? kNoPlane : e.planes[0];
    for (size_t k = 1; k < e.planes.size(); ++k)
      if (ps_.opposite(p) != e.planes[k]) return {p, e.planes[k]};
    return {p, kNoPlane};
  }

  const PlaneSet& ps_;
  TraceResult& tr_;  // moved from by result()
  const ReplayOptions& opt_;
  std::vector<uint32_t> offset_, at_;  // edges at each vertex (CSR)
  std::vector<uint32_t> new_id_;       // event id of each vertex of tr_, kNoVertex until discovered
  std::vector<char> traced_;           // per edge of tr_
  std::vector<uint32_t> vertex_order_, edge_order_, edge_from_;
  std::vector<std::pair<uint32_t, uint32_t>> fifo_;  // queued rays (vertex, edge), in order
  size_t next_ = 0;                                  // without `from`: the next ray to take
  std::priority_queue<std::pair<double, uint32_t>, std::vector<std::pair<double, uint32_t>>, std::greater<>> rays_;
};

}  // namespace

void replay_steps(const PlaneSet& ps, uint32_t start, TraceResult& tr, const ReplayOptions& options) {
  if (tr.vertices.empty() || start >= tr.vertices.size()) return;
  Replay replay(ps, tr, options);
  const bool complete = replay.run(start);
  tr = replay.result(complete);
}

}  // namespace kergen
