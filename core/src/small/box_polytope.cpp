// The box as a traced polytope (box_polytope.h).
#include "small/box_polytope.h"

#include <algorithm>

#include "exact/predicates.h"
#include "exact/vertex.h"

namespace kergen {

bool edge_between(const PlaneSet& ps, const TraceResult& tr, uint32_t a, uint32_t b, TracedEdge& e) {
  const PlaneIds &ta = tr.vertices[a].tight, &tb = tr.vertices[b].tight;
  e.a = a;
  e.b = b;
  e.planes.clear();
  std::set_intersection(ta.begin(), ta.end(), tb.begin(), tb.end(), std::back_inserter(e.planes));
  e.p = e.q = kNoPlane;
  for (uint32_t x : e.planes) {
    if (e.p == kNoPlane) {
      e.p = x;
    } else if (x != ps.opposite(e.p)) {
      e.q = x;
      break;
    }
  }
  if (e.q == kNoPlane) return false;
  // The edge's direction b - a lies along n_p x n_q: the sign of their dot product, where the
  // filtered coordinates decide it (an edge far longer than their error bounds).
  {
    const PlaneCoef<Approx> cp = ps.approx(e.p), cq = ps.approx(e.q);
    const Approx* xa = tr.vertices[a].geom.x;
    const Approx* xb = tr.vertices[b].geom.x;
    Approx dot(0);
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      dot = dot + (xb[k] - xa[k]) * (cp.n[i] * cq.n[j] - cp.n[j] * cq.n[i]);
    }
    const int s = dot.sign();
    if (s == 1 || s == -1) {
      e.sigma = s;
      return true;
    }
  }
  // Direction a -> b = sigma (n_p x n_q): for a plane r through b but not a, f_r rises to 0 at
  // b, and its rate along n_p x n_q is sign det3(n_r, n_p, n_q), so sigma is that sign.
  for (uint32_t r : tb) {
    if (std::binary_search(ta.begin(), ta.end(), r)) continue;
    const int s = sign_det3_normals(ps, r, e.p, e.q);
    if (s != 0) {
      e.sigma = s;
      return true;
    }
  }
  return false;
}

TraceResult box_polytope(const PlaneSet& ps, const std::vector<uint32_t>& box) {
  TraceResult tr;
  tr.vertices.resize(8);
  // Corner c lies at x_k = +-2 (bit k of c: the high side), on the box planes -x_k - 2 <= 0 and
  // x_k - 2 <= 0 (add_bounding_box), whose normals -+e_k have determinant the product of their
  // signs: exact without any evaluation.
  for (uint32_t c = 0; c < 8; ++c) {
    TracedVertex& v = tr.vertices[c];
    v.geom.det_sign = 1;
    for (int k = 0; k < 3; ++k) {
      const uint32_t high = (c >> k) & 1;
      v.tight.push_back(box[2 * k + high]);
      v.geom.basis[k] = box[2 * k + high];
      v.geom.x[k] = Approx(high ? 2.0 : -2.0);
      if (!high) v.geom.det_sign = -v.geom.det_sign;
    }
    std::sort(v.tight.begin(), v.tight.end());
  }
  for (uint32_t c = 0; c < 8; ++c)
    for (int k = 0; k < 3; ++k) {
      const uint32_t d = c | (1u << k);
      if (d == c) continue;
      TracedEdge e;
      edge_between(ps, tr, c, d, e);  // (box normals are axes: always decided)
      tr.edges.push_back(std::move(e));
    }
  return tr;
}

}  // namespace kergen
