// Pairs of triangles that meet where the mesh does not say they meet (see self_contact.h).
//
// Why the edge tests suffice: two closed triangles that meet and are not coplanar meet in a
// segment of the line of their planes whose ends lie on edges of one or the other, so an edge of
// one meets the other; coplanar ones that overlap have crossing edges or one inside the other,
// whose edges then lie in it. With a shared vertex v the common part contains v; it reaches
// beyond v only through an edge opposite v or through an edge at v that lies in the other's plane
// and points into its corner at v. With a shared edge, the common part is that edge unless the
// two triangles are coplanar and on the same side of it (folded onto each other).
#include "certify/self_contact.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "exact/predicates.h"

namespace kergen {

namespace {

struct Tri {
  uint32_t face;
  uint32_t v[3];
  int axis;  // a coordinate axis the triangle's plane is not parallel to (for in-plane tests)
};

class Geometry {
 public:
  explicit Geometry(const PreparedMesh& m) : m_(m) {}
  const double* p(uint32_t v) const { return m_.point(v); }
  int orient3(uint32_t a, uint32_t b, uint32_t c, uint32_t d) const {
    return orient3d(p(a), p(b), p(c), p(d), m_.exact_shift);
  }
  int orient2(uint32_t a, uint32_t b, uint32_t c, int axis) const {
    return orient2d(p(a), p(b), p(c), axis, m_.exact_shift);
  }
  // The axis of the largest component of (b - a) x (c - a), rounded: the exact component along
  // it is not zero for a triangle of non-zero area unless all three are tiny against rounding,
  // and then any axis the exact normal has is tried (the caller checks orient2 != 0).
  int normal_axis(uint32_t a, uint32_t b, uint32_t c) const {
    const double *x = p(a), *y = p(b), *z = p(c);
    const double u[3] = {y[0] - x[0], y[1] - x[1], y[2] - x[2]}, w[3] = {z[0] - x[0], z[1] - x[1], z[2] - x[2]};
    const double n[3] = {std::fabs(u[1] * w[2] - u[2] * w[1]), std::fabs(u[2] * w[0] - u[0] * w[2]),
                         std::fabs(u[0] * w[1] - u[1] * w[0])};
    int best = n[0] >= n[1] ? (n[0] >= n[2] ? 0 : 2) : (n[1] >= n[2] ? 1 : 2);
    for (int k = 0; k < 3 && orient2(a, b, c, best) == 0; ++k) best = k;
    return best;
  }
  // Collinear x, y, z (x != y): whether z lies on the side of x that y does, or on x (`closed`).
  bool same_ray(uint32_t x, uint32_t y, uint32_t z, bool closed) const {
    for (int k = 0; k < 3; ++k) {
      if (p(y)[k] == p(x)[k]) continue;
      const bool up = p(y)[k] > p(x)[k];
      if (p(z)[k] == p(x)[k]) return closed;
      return (p(z)[k] > p(x)[k]) == up;
    }
    return false;
  }
  // Collinear x, y, z: whether z lies on the closed segment xy.
  bool on_segment(uint32_t x, uint32_t y, uint32_t z) const {
    for (int k = 0; k < 3; ++k) {
      if (p(y)[k] == p(x)[k]) continue;
      const double lo = std::min(p(x)[k], p(y)[k]), hi = std::max(p(x)[k], p(y)[k]);
      return p(z)[k] >= lo && p(z)[k] <= hi;
    }
    return p(z)[0] == p(x)[0] && p(z)[1] == p(x)[1] && p(z)[2] == p(x)[2];
  }

 private:
  const PreparedMesh& m_;
};

// z in the closed triangle abc of in-plane orientation o (all coplanar).
bool in_closed_triangle(const Geometry& g, uint32_t a, uint32_t b, uint32_t c, int o, uint32_t z, int axis) {
  return g.orient2(a, b, z, axis) != -o && g.orient2(b, c, z, axis) != -o && g.orient2(c, a, z, axis) != -o;
}

// Closed segments xy and uw in one plane meet.
bool segments_meet(const Geometry& g, uint32_t x, uint32_t y, uint32_t u, uint32_t w, int axis) {
  const int d1 = g.orient2(x, y, u, axis), d2 = g.orient2(x, y, w, axis);
  const int d3 = g.orient2(u, w, x, axis), d4 = g.orient2(u, w, y, axis);
  if (d1 * d2 < 0 && d3 * d4 < 0) return true;
  return (d1 == 0 && g.on_segment(x, y, u)) || (d2 == 0 && g.on_segment(x, y, w)) ||
         (d3 == 0 && g.on_segment(u, w, x)) || (d4 == 0 && g.on_segment(u, w, y));
}

// The closed segment xy meets the closed triangle t.
bool segment_meets_triangle(const Geometry& g, uint32_t x, uint32_t y, const Tri& t) {
  const uint32_t a = t.v[0], b = t.v[1], c = t.v[2];
  const int sx = g.orient3(a, b, c, x), sy = g.orient3(a, b, c, y);
  if (sx == sy && sx != 0) return false;
  if (sx == 0 && sy == 0) {
    const int o = g.orient2(a, b, c, t.axis);
    if (in_closed_triangle(g, a, b, c, o, x, t.axis) || in_closed_triangle(g, a, b, c, o, y, t.axis)) return true;
    return segments_meet(g, x, y, a, b, t.axis) || segments_meet(g, x, y, b, c, t.axis) ||
           segments_meet(g, x, y, c, a, t.axis);
  }
  // One common point with the plane: inside the closed triangle when the line xy passes every
  // edge on the same side (or on it).
  const int e1 = g.orient3(x, y, a, b), e2 = g.orient3(x, y, b, c), e3 = g.orient3(x, y, c, a);
  return (e1 >= 0 && e2 >= 0 && e3 >= 0) || (e1 <= 0 && e2 <= 0 && e3 <= 0);
}

// The edge v->z, with z in the plane of t = (v, d, e), enters t's closed corner at v.
bool enters_corner(const Geometry& g, uint32_t v, uint32_t d, uint32_t e, uint32_t z, int axis) {
  const int o = g.orient2(v, d, e, axis), s1 = g.orient2(v, d, z, axis), s2 = g.orient2(v, z, e, axis);
  if (s1 == o && s2 == o) return true;
  return (s1 == 0 && g.same_ray(v, d, z, false)) || (s2 == 0 && g.same_ray(v, e, z, false));
}

// t rotated so that its vertex `v` comes first (orientation kept).
Tri rotated_to(const Tri& t, uint32_t v) {
  Tri r = t;
  while (r.v[0] != v) r = {r.face, {r.v[1], r.v[2], r.v[0]}, r.axis};
  return r;
}

bool meet_beyond_vertex(const Geometry& g, const Tri& t0, const Tri& s0, uint32_t v) {
  const Tri t = rotated_to(t0, v), s = rotated_to(s0, v);
  if (segment_meets_triangle(g, t.v[1], t.v[2], s) || segment_meets_triangle(g, s.v[1], s.v[2], t)) return true;
  for (int i = 1; i < 3; ++i) {
    if (g.orient3(s.v[0], s.v[1], s.v[2], t.v[i]) == 0 && enters_corner(g, v, s.v[1], s.v[2], t.v[i], s.axis))
      return true;
    if (g.orient3(t.v[0], t.v[1], t.v[2], s.v[i]) == 0 && enters_corner(g, v, t.v[1], t.v[2], s.v[i], t.axis))
      return true;
  }
  return false;
}

// Triangles sharing the edge uw (and third corners a, b): folded onto each other.
bool folded(const Geometry& g, uint32_t u, uint32_t w, uint32_t a, uint32_t b, int axis) {
  return g.orient3(u, w, a, b) == 0 && g.orient2(u, w, a, axis) == g.orient2(u, w, b, axis);
}

// Whether the corners of r other than `except` lie strictly on one side of t's plane (then r
// meets that plane at most at `except`): most pairs the grid proposes end here.
bool off_plane(const Geometry& g, const Tri& t, const Tri& r, uint32_t except) {
  int side = 0;
  for (uint32_t x : r.v) {
    if (x == except) continue;
    const int o = g.orient3(t.v[0], t.v[1], t.v[2], x);
    if (o == 0 || (side != 0 && o != side)) return false;
    side = o;
  }
  return true;
}

bool triangles_meet(const Geometry& g, const Tri& t, const Tri& s) {
  uint32_t shared[3], n = 0;
  for (uint32_t x : t.v)
    if (x == s.v[0] || x == s.v[1] || x == s.v[2]) shared[n++] = x;
  if (n <= 1) {
    const uint32_t except = n == 1 ? shared[0] : UINT32_MAX;
    if (off_plane(g, t, s, except) || off_plane(g, s, t, except)) return false;
  }
  if (n == 3) return true;  // the same corners twice
  if (n == 2) {
    auto third = [&](const Tri& r) {
      for (uint32_t x : r.v)
        if (x != shared[0] && x != shared[1]) return x;
      return r.v[0];
    };
    return folded(g, shared[0], shared[1], third(t), third(s), t.axis);
  }
  if (n == 1) return meet_beyond_vertex(g, t, s, shared[0]);
  for (int i = 0; i < 3; ++i) {
    if (segment_meets_triangle(g, t.v[i], t.v[(i + 1) % 3], s)) return true;
    if (segment_meets_triangle(g, s.v[i], s.v[(i + 1) % 3], t)) return true;
  }
  return false;
}

// Ear clipping of face f, whose corners are `ring`, in its plane (exact in-plane signs). False
// when no ear is left before the polygon is used up: it is not a simple polygon (a repeated
// corner, crossing sides).
bool triangulate_face(const Geometry& g, const PreparedMesh& m, uint32_t f, std::vector<uint32_t> ring,
                      std::vector<Tri>& out) {
  const auto& rep = m.rep[f];
  const int axis = g.normal_axis(rep[0], rep[1], rep[2]);
  const int o = g.orient2(rep[0], rep[1], rep[2], axis);
  while (ring.size() > 3) {
    const size_t n = ring.size();
    size_t ear = n;
    for (size_t i = 0; i < n && ear == n; ++i) {
      const uint32_t a = ring[(i + n - 1) % n], b = ring[i], c = ring[(i + 1) % n];
      if (g.orient2(a, b, c, axis) != o) continue;  // reflex or straight corner
      bool empty = true;
      for (size_t j = 0; j < n && empty; ++j) {
        const uint32_t z = ring[j];
        if (j == i || j == (i + 1) % n || j == (i + n - 1) % n) continue;
        empty = z != a && z != b && z != c && !in_closed_triangle(g, a, b, c, o, z, axis);
      }
      if (empty) ear = i;
    }
    if (ear == n) break;
    out.push_back({f, {ring[(ear + n - 1) % n], ring[ear], ring[(ear + 1) % n]}, axis});
    ring.erase(ring.begin() + ptrdiff_t(ear));
  }
  // What is left is the last triangle, or corners on one line (covered by the triangles' sides).
  bool straight = true;
  for (size_t i = 0; i < ring.size() && straight; ++i)
    straight = g.orient2(ring[i], ring[(i + 1) % ring.size()], ring[(i + 2) % ring.size()], axis) == 0;
  if (straight) return true;
  if (ring.size() != 3 || g.orient2(ring[0], ring[1], ring[2], axis) != o) return false;
  out.push_back({f, {ring[0], ring[1], ring[2]}, axis});
  return true;
}

struct Box {
  double lo[3], hi[3];
};

Box box_of(const Geometry& g, const Tri& t) {
  Box b;
  for (int k = 0; k < 3; ++k) {
    b.lo[k] = std::min({g.p(t.v[0])[k], g.p(t.v[1])[k], g.p(t.v[2])[k]});
    b.hi[k] = std::max({g.p(t.v[0])[k], g.p(t.v[1])[k], g.p(t.v[2])[k]});
  }
  return b;
}

// A uniform grid over the mesh's box with cells twice the mean side of the faces' bounding boxes:
// a triangle then covers at most 8 cells and a cell holds a few triangles, for meshes whose faces
// are of similar sizes.
struct Grid {
  template <class Fn>
  void visit(const Box& b, Fn&& fn) const {
    for (uint64_t i = index(b.lo[0], 0); i <= index(b.hi[0], 0); ++i)
      for (uint64_t j = index(b.lo[1], 1); j <= index(b.hi[1], 1); ++j)
        for (uint64_t l = index(b.lo[2], 2); l <= index(b.hi[2], 2); ++l) fn(key(i, j, l));
  }
  double lo[3], cell;
  uint64_t n;
  Grid(const PreparedMesh& m, size_t num_faces) {
    for (int k = 0; k < 3; ++k) lo[k] = m.bbox_min[k];
    double sides = 0;
    for (uint32_t f = 0; f < num_faces; ++f) {
      double flo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, fhi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
      for (uint32_t i = m.loop_offsets[f]; i < m.loop_offsets[f + 1]; ++i)
        for (int k = 0; k < 3; ++k) {
          flo[k] = std::min(flo[k], m.point(m.loops[i])[k]);
          fhi[k] = std::max(fhi[k], m.point(m.loops[i])[k]);
        }
      sides += std::max({fhi[0] - flo[0], fhi[1] - flo[1], fhi[2] - flo[2]});
    }
    const double side = m.extent(), mean = num_faces ? sides / double(num_faces) : side;
    n = side > 0 && mean > 0 ? uint64_t(std::clamp(side / mean, 1.0, double(1u << 20))) : 1;
    cell = side > 0 ? side / double(n) * (1 + 1e-9) : 1;
  }
  uint64_t index(double x, int k) const {
    return std::min<uint64_t>(uint64_t(std::max(0.0, (x - lo[k]) / cell)), n - 1);
  }
  uint64_t key(uint64_t i, uint64_t j, uint64_t l) const { return (i * n + j) * n + l; }
};

Box box_of_side(const Geometry& g, uint32_t u, uint32_t w) {
  Box b;
  for (int k = 0; k < 3; ++k) {
    b.lo[k] = std::min(g.p(u)[k], g.p(w)[k]);
    b.hi[k] = std::max(g.p(u)[k], g.p(w)[k]);
  }
  return b;
}

// The vertices lying exactly inside the side u -> w (not at its ends), in order from u to w.
std::vector<uint32_t> vertices_inside_side(const Geometry& g, const Grid& grid,
                                           const std::vector<std::pair<uint64_t, uint32_t>>& vertex_cells, uint32_t u,
                                           uint32_t w, int shift) {
  std::vector<uint32_t> inside;
  const Box b = box_of_side(g, u, w);
  grid.visit(b, [&](uint64_t key) {
    auto it = std::lower_bound(vertex_cells.begin(), vertex_cells.end(), std::make_pair(key, uint32_t(0)));
    for (; it != vertex_cells.end() && it->first == key; ++it) {
      const uint32_t z = it->second;
      const double* pz = g.p(z);
      bool in_box = true;
      for (int k = 0; k < 3; ++k) in_box &= pz[k] >= b.lo[k] && pz[k] <= b.hi[k];
      if (!in_box || z == u || z == w || !collinear(g.p(u), g.p(w), pz, shift)) continue;
      const bool at_end = (pz[0] == g.p(u)[0] && pz[1] == g.p(u)[1] && pz[2] == g.p(u)[2]) ||
                          (pz[0] == g.p(w)[0] && pz[1] == g.p(w)[1] && pz[2] == g.p(w)[2]);
      if (!at_end) inside.push_back(z);
    }
  });
  int k = 0;  // the axis along which the side is longest orders the points on it
  for (int i = 1; i < 3; ++i)
    if (b.hi[i] - b.lo[i] > b.hi[k] - b.lo[k]) k = i;
  const bool up = g.p(w)[k] > g.p(u)[k];
  std::sort(inside.begin(), inside.end(), [&](uint32_t x, uint32_t y) { return (g.p(x)[k] < g.p(y)[k]) == up; });
  inside.erase(std::unique(inside.begin(), inside.end()), inside.end());
  return inside;
}

// Face f's corners with every vertex lying exactly inside one of its sides inserted there. Such a
// vertex is where a zero-area face was dropped (its middle corner lies on the side of the face
// across its long edge), or a T-junction: the neighbours meet the side at that vertex, as the mesh
// says, and the contact tests then see them share it.
std::vector<uint32_t> ring_with_side_vertices(const Geometry& g, const PreparedMesh& m, const Grid& grid,
                                              const std::vector<std::pair<uint64_t, uint32_t>>& vertex_cells,
                                              uint32_t f) {
  std::vector<uint32_t> ring;
  const uint32_t begin = m.loop_offsets[f], end = m.loop_offsets[f + 1];
  for (uint32_t i = begin; i < end; ++i) {
    const uint32_t u = m.loops[i], w = m.loops[i + 1 < end ? i + 1 : begin];
    ring.push_back(u);
    if (vertex_cells.empty()) continue;
    const std::vector<uint32_t> inside = vertices_inside_side(g, grid, vertex_cells, u, w, m.exact_shift);
    ring.insert(ring.end(), inside.begin(), inside.end());
  }
  return ring;
}

}  // namespace

FaceContact find_face_contact(const PreparedMesh& m, size_t num_faces) {
  FaceContact out;
  const Geometry g(m);
  const Grid grid(m, num_faces);
  // (cell, vertex) of every face corner, when a vertex may lie inside a side as the mesh says:
  // where zero-area faces were dropped, or at the holes of an open mesh (T-junctions). Elsewhere
  // such a vertex is a touch, found by the pair tests.
  std::vector<std::pair<uint64_t, uint32_t>> vertex_cells;
  if (m.dropped_faces > 0 || m.boundary_edges > 0) {
    vertex_cells.reserve(m.loops.size());
    for (uint32_t i = 0; i < m.loop_offsets[num_faces]; ++i) {
      const uint32_t v = m.loops[i];
      const double* p = g.p(v);
      vertex_cells.push_back({grid.key(grid.index(p[0], 0), grid.index(p[1], 1), grid.index(p[2], 2)), v});
    }
    std::sort(vertex_cells.begin(), vertex_cells.end());
    vertex_cells.erase(std::unique(vertex_cells.begin(), vertex_cells.end()), vertex_cells.end());
  }
  std::vector<Tri> tris;
  tris.reserve(m.loops.size());
  for (uint32_t f = 0; f < num_faces; ++f)
    if (!triangulate_face(g, m, f, ring_with_side_vertices(g, m, grid, vertex_cells, f), tris)) {
      out.outcome = FaceContact::Outcome::Undecided;
      out.face_a = out.face_b = f;
      return out;
    }
  std::vector<Box> boxes(tris.size());
  std::vector<std::pair<uint64_t, uint32_t>> cells;  // (cell, triangle), one per cell a box covers
  cells.reserve(2 * tris.size());
  for (uint32_t t = 0; t < tris.size(); ++t) {
    const Box& b = boxes[t] = box_of(g, tris[t]);
    grid.visit(b, [&](uint64_t key) { cells.push_back({key, t}); });
  }
  std::sort(cells.begin(), cells.end());
  for (size_t begin = 0, end; begin < cells.size(); begin = end) {
    for (end = begin + 1; end < cells.size() && cells[end].first == cells[begin].first;) ++end;
    for (size_t x = begin; x < end; ++x)
      for (size_t y = x + 1; y < end; ++y) {
        const uint32_t t = cells[x].second, s = cells[y].second;
        const Box &a = boxes[t], &b = boxes[s];
        double corner[3];  // the overlap's low corner: its cell is the one place the pair is tested
        bool overlap = true;
        for (int k = 0; k < 3; ++k) {
          overlap &= a.lo[k] <= b.hi[k] && b.lo[k] <= a.hi[k];
          corner[k] = std::max(a.lo[k], b.lo[k]);
        }
        if (!overlap ||
            grid.key(grid.index(corner[0], 0), grid.index(corner[1], 1), grid.index(corner[2], 2)) != cells[x].first)
          continue;
        if (triangles_meet(g, tris[t], tris[s])) {
          out = {FaceContact::Outcome::Found, tris[t].face, tris[s].face, tris[t].v[0], tris[s].v[0]};
          return out;
        }
      }
  }
  return out;
}

}  // namespace kergen
