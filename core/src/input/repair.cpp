// Repair (see repair.h): duplicate and cancelling faces by their canonical corner cycles, then
// T-junctions on the edges only one face uses, with exact collinearity and exact betweenness.
#include "input/repair.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "exact/predicates.h"

namespace kergen {

namespace {

using Loop = std::vector<uint32_t>;

std::vector<Loop> loops_of(const Mesh& m) {
  std::vector<Loop> loops;
  for (size_t f = 0, at = 0; f < m.num_faces(); ++f) {
    const size_t n = m.face_sizes.empty() ? 3 : m.face_sizes[f];
    loops.emplace_back(m.indices.begin() + long(at), m.indices.begin() + long(at + n));
    at += n;
  }
  return loops;
}

void set_loops(Mesh& m, const std::vector<Loop>& loops) {
  m.indices.clear();
  m.face_sizes.clear();
  bool triangles = true;
  for (const Loop& l : loops) {
    m.indices.insert(m.indices.end(), l.begin(), l.end());
    m.face_sizes.push_back(uint32_t(l.size()));
    triangles &= l.size() == 3;
  }
  if (triangles) m.face_sizes.clear();
}

// The loop rotated to start at its smallest vertex (the same cycle gives the same key).
Loop canonical(const Loop& l) {
  const size_t s = size_t(std::min_element(l.begin(), l.end()) - l.begin());
  Loop c(l.begin() + long(s), l.end());
  c.insert(c.end(), l.begin(), l.begin() + long(s));
  return c;
}

// Removes faces repeating another's cycle: copies of one orientation keep one, and a cycle
// present in both orientations goes entirely.
void remove_repeated_faces(std::vector<Loop>& loops, RepairCounts& counts, std::vector<uint32_t>& kept_faces) {
  std::map<Loop, std::vector<size_t>> by_cycle;
  for (size_t f = 0; f < loops.size(); ++f) by_cycle[canonical(loops[f])].push_back(f);
  std::vector<char> removed(loops.size(), 0);
  for (auto& [cycle, faces] : by_cycle) {
    for (size_t i = 1; i < faces.size(); ++i) removed[faces[i]] = 1;
    counts.duplicate_faces += faces.size() - 1;
  }
  for (const auto& [cycle, faces] : by_cycle) {
    if (removed[faces[0]]) continue;
    const Loop reversed = canonical(Loop(cycle.rbegin(), cycle.rend()));
    const auto other = by_cycle.find(reversed);
    if (other == by_cycle.end() || other->second[0] == faces[0] || removed[other->second[0]]) continue;
    removed[faces[0]] = removed[other->second[0]] = 1;
    counts.cancelling_faces += 2;
  }
  std::vector<Loop> kept;
  kept_faces.clear();
  for (size_t f = 0; f < loops.size(); ++f)
    if (!removed[f]) {
      kept.push_back(std::move(loops[f]));
      kept_faces.push_back(uint32_t(f));
    }
  loops = std::move(kept);
}

// Splits T-junctions: every vertex lying exactly inside an edge that one face uses and no face
// uses the other way is inserted into that face's loop, in order along the edge. Candidates are
// the vertices of such edges (a T-junction's vertex ends the halves, which are such edges too).
// The tests run on the positions scaled by a power of two (exact), so no product underflows.
void split_t_junctions(const std::vector<double>& positions, std::vector<Loop>& loops, RepairCounts& counts) {
  std::set<std::pair<uint32_t, uint32_t>> uses;
  for (const Loop& l : loops)
    for (size_t i = 0; i < l.size(); ++i) uses.insert({l[i], l[(i + 1) % l.size()]});
  std::vector<uint32_t> candidates;
  for (const auto& [a, b] : uses)
    if (!uses.count({b, a})) candidates.insert(candidates.end(), {a, b});
  if (candidates.empty()) return;
  double ext = 0;
  for (double c : positions) ext = std::max(ext, std::fabs(c));
  int ex = 0;
  std::frexp(ext, &ex);
  std::vector<double> x(positions.size());
  for (size_t i = 0; i < x.size(); ++i) x[i] = std::ldexp(positions[i], -ex);
  auto p = [&](uint32_t v) { return &x[3 * size_t(v)]; };
  std::sort(candidates.begin(), candidates.end(),
            [&](uint32_t a, uint32_t b) { return p(a)[0] < p(b)[0] || (p(a)[0] == p(b)[0] && a < b); });
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  for (Loop& l : loops) {
    Loop out;
    for (size_t i = 0; i < l.size(); ++i) {
      const uint32_t a = l[i], b = l[(i + 1) % l.size()];
      out.push_back(a);
      if (uses.count({b, a})) continue;
      const double *pa = p(a), *pb = p(b);
      int axis = 0;  // the edge's dominant axis: betweenness along it is exact for collinear points
      for (int k = 1; k < 3; ++k)
        if (std::fabs(pb[k] - pa[k]) > std::fabs(pb[axis] - pa[axis])) axis = k;
      const double lo = std::min(pa[0], pb[0]), hi = std::max(pa[0], pb[0]);
      auto first =
          std::lower_bound(candidates.begin(), candidates.end(), lo, [&](uint32_t v, double t) { return p(v)[0] < t; });
      std::vector<std::pair<double, uint32_t>> inside;
      for (auto it = first; it != candidates.end() && p(*it)[0] <= hi; ++it) {
        const uint32_t v = *it;
        if (v == a || v == b || std::find(l.begin(), l.end(), v) != l.end()) continue;
        const double t = p(v)[axis];
        if (!((pa[axis] < t && t < pb[axis]) || (pb[axis] < t && t < pa[axis]))) continue;
        if (!collinear(pa, pb, p(v))) continue;
        inside.push_back({pb[axis] > pa[axis] ? t : -t, v});  // (exact order along the edge)
      }
      std::sort(inside.begin(), inside.end());
      for (const auto& [d, v] : inside) out.push_back(v);
      counts.t_junctions += inside.size();
    }
    l = std::move(out);
  }
}

}  // namespace

RepairCounts repair_mesh(Mesh& mesh, std::vector<uint32_t>* kept_faces) {
  RepairCounts counts;
  std::vector<Loop> loops = loops_of(mesh);
  std::vector<uint32_t> kept;
  remove_repeated_faces(loops, counts, kept);
  if (kept_faces) *kept_faces = std::move(kept);
  split_t_junctions(mesh.positions, loops, counts);
  set_loops(mesh, loops);
  return counts;
}

}  // namespace kergen
