// The certainly extreme vertex (extreme_vertex.h).
#include "small/extreme_vertex.h"

#include "exact/expansion.h"

namespace kergen {

uint32_t certainly_extreme_vertex(const TraceResult& tr, const double dir[3]) {
  auto value = [&](uint32_t i) {
    const VertexGeom& g = tr.vertices[i].geom;
    return Approx(dir[0]) * g.x[0] + Approx(dir[1]) * g.x[1] + Approx(dir[2]) * g.x[2];
  };
  const size_t n = tr.vertices.size();
  if (n == 0) return kNoVertex;
  uint32_t top = 0;
  Approx top_value = value(0);
  for (uint32_t i = 1; i < n; ++i) {
    const Approx v = value(i);
    if (v.v > top_value.v) {
      top = i;
      top_value = v;
    }
  }
  for (uint32_t i = 0; i < n; ++i)
    if (i != top && (top_value - value(i)).sign() != 1) return kNoVertex;
  return top;
}

}  // namespace kergen
