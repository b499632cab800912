// Exact CGAL reference for the mesh kernel; see cgal_oracle.h for what it decides and how.
#include "cgal_oracle.h"

#include <CGAL/Convex_hull_3/dual/halfspace_intersection_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Gmpzf.h>
#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <unordered_map>

namespace kergen_oracle {
namespace {

using NT = CGAL::Gmpzf;  // exact for + - * on doubles
using Vec = std::array<NT, 3>;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using EFT = Epeck::FT;
using EET = EFT::ET;

double ms_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
NT dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
bool is_zero(const Vec& a) { return CGAL::is_zero(a[0]) && CGAL::is_zero(a[1]) && CGAL::is_zero(a[2]); }

CGAL::Gmpq to_gmpq(const NT& x) {
  CGAL::Gmpq q(CGAL::Gmpz(x.man()));
  if (x.exp() > 0) mpq_mul_2exp(q.mpq(), q.mpq(), static_cast<mp_bitcnt_t>(x.exp()));
  if (x.exp() < 0) mpq_div_2exp(q.mpq(), q.mpq(), static_cast<mp_bitcnt_t>(-x.exp()));
  return q;
}
CGAL::Gmpq to_gmpq(const CGAL::Quotient<NT>& x) { return to_gmpq(x.numerator()) / to_gmpq(x.denominator()); }
EFT to_eft(const CGAL::Gmpq& q) { return EFT(EET(q.mpq())); }

struct Plane {
  Vec n;
  NT d;
};

using Triangle = std::array<uint32_t, 3>;

// The core's split of a non-planar convex polygon (loop oriented outward), restated here: a fan
// from the first corner, then every diagonal where the surface folds inward (the far corner of
// the neighbouring triangle strictly outside a triangle's plane, decided here in exact
// arithmetic) is flipped when both new triangles have clearly positive area in the projection
// along the dominant axis of the Newell normal (the same double-precision rule as the core, so
// both sides split alike), sweeping the triangles in the same order until nothing changes.
// Non-convex polygons (which the core ear-clips) keep a plain fan here: no shared mesh has one.
std::vector<Triangle> split_like_core(const std::vector<Vec>& P, const double* pos, const std::vector<uint32_t>& loop) {
  const size_t k = loop.size();
  auto D = [&](uint32_t v) { return pos + 3 * size_t(v); };
  double n[3] = {0, 0, 0};
  for (size_t i = 0; i < k; ++i) {
    const double *a = D(loop[i]), *b = D(loop[(i + 1) % k]);
    n[0] += (a[1] - b[1]) * (a[2] + b[2]);
    n[1] += (a[2] - b[2]) * (a[0] + b[0]);
    n[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  int axis = 0;
  for (int c = 1; c < 3; ++c)
    if (std::fabs(n[c]) > std::fabs(n[axis])) axis = c;
  const int u = (axis + 1) % 3, w = (axis + 2) % 3;
  const double orient = n[axis] >= 0 ? 1 : -1;
  auto area2 = [&](uint32_t a, uint32_t b, uint32_t c) {
    const double *pa = D(a), *pb = D(b), *pc = D(c);
    return orient * ((pb[u] - pa[u]) * (pc[w] - pa[w]) - (pb[w] - pa[w]) * (pc[u] - pa[u]));
  };
  auto sq = [&](uint32_t a, uint32_t b) {
    const double *pa = D(a), *pb = D(b);
    return (pb[u] - pa[u]) * (pb[u] - pa[u]) + (pb[w] - pa[w]) * (pb[w] - pa[w]);
  };
  std::vector<Triangle> out;
  for (size_t i = 1; i + 1 < k; ++i) out.push_back({loop[0], loop[i], loop[i + 1]});
  bool convex = true;
  for (size_t i = 0; i < k && convex; ++i)
    if (area2(loop[(i + k - 1) % k], loop[i], loop[(i + 1) % k]) < 0) convex = false;
  if (!convex || k > 128) return out;
  bool changed = true;
  size_t flips = 0;
  const size_t cap = 4 * k * k;
  while (changed && flips < cap) {
    changed = false;
    for (size_t i = 0; i < out.size() && flips < cap; ++i) {
      for (int e = 0; e < 3; ++e) {
        const uint32_t x = out[i][e], y = out[i][(e + 1) % 3], p = out[i][(e + 2) % 3];
        size_t j = 0;
        int g = 0;
        for (; j < out.size(); ++j) {
          if (j == i) continue;
          for (g = 0; g < 3; ++g)
            if (out[j][g] == y && out[j][(g + 1) % 3] == x) break;
          if (g < 3) break;
        }
        if (j == out.size()) continue;
        const uint32_t q = out[j][(g + 2) % 3];
        if (!CGAL::is_positive(dot(cross(sub(P[y], P[x]), sub(P[p], P[x])), sub(P[q], P[x])))) continue;
        const double tol = 1e-12 * (sq(x, q) + sq(q, p) + sq(p, x) + sq(q, y) + sq(y, p));
        if (!(area2(x, q, p) > tol && area2(q, y, p) > tol)) continue;
        out[i] = {x, q, p};
        out[j] = {q, y, p};
        ++flips;
        changed = true;
        break;
      }
    }
  }
  return out;
}

// Whether the half-spaces n . x + d <= 0 have a common point (exact LP, free variables, no
// objective).
bool have_common_point(const std::vector<Plane>& planes) {
  CGAL::Quadratic_program<NT> lp(CGAL::SMALLER, false, NT(0), false, NT(0));
  for (size_t i = 0; i < planes.size(); ++i) {
    for (int a = 0; a < 3; ++a) lp.set_a(a, static_cast<int>(i), planes[i].n[a]);
    lp.set_b(static_cast<int>(i), -planes[i].d);
  }
  return !CGAL::solve_linear_program(lp, NT()).is_infeasible();
}

}  // namespace

WitnessCheck check_witness(const kergen::Mesh& mesh, const std::vector<uint32_t>& faces) {
  WitnessCheck r;
  const size_t nf = mesh.num_faces();
  if (faces.empty() || faces.size() > 4) {
    r.message = std::to_string(faces.size()) + " witness faces (expected 1 to 4)";
    return r;
  }
  std::vector<Vec> P(mesh.num_vertices());
  for (size_t v = 0; v < P.size(); ++v)
    for (int k = 0; k < 3; ++k) P[v][k] = NT(mesh.positions[3 * v + k]);
  std::vector<size_t> offset(nf + 1, 0);
  for (size_t f = 0; f < nf; ++f) offset[f + 1] = offset[f] + (mesh.face_sizes.empty() ? 3 : mesh.face_sizes[f]);
  NT vol6 = 0;  // the orientation, as oracle_kernel decides it
  for (size_t f = 0; f < nf; ++f) {
    const uint32_t* loop = mesh.indices.data() + offset[f];
    for (size_t j = 1; j + 2 <= offset[f + 1] - offset[f]; ++j)
      vol6 = vol6 + dot(P[loop[0]], cross(P[loop[j]], P[loop[j + 1]]));
  }
  const bool flipped = CGAL::is_negative(vol6);
  std::vector<std::vector<Plane>> face_planes;
  for (uint32_t f : faces) {
    if (f >= nf) {
      r.message = "witness face " + std::to_string(f) + " does not exist";
      return r;
    }
    std::vector<uint32_t> loop(mesh.indices.begin() + long(offset[f]), mesh.indices.begin() + long(offset[f + 1]));
    if (flipped) std::reverse(loop.begin(), loop.end());
    const Vec& p0 = P[loop[0]];
    Vec n{NT(0), NT(0), NT(0)};
    for (size_t j = 1; j + 1 < loop.size(); ++j) {
      const Vec c = cross(sub(P[loop[j]], p0), sub(P[loop[j + 1]], p0));
      for (int a = 0; a < 3; ++a) n[a] = n[a] + c[a];
    }
    bool planar = !is_zero(n);
    for (size_t j = 3; planar && j < loop.size(); ++j) planar = CGAL::is_zero(dot(n, sub(P[loop[j]], p0)));
    std::vector<Plane> planes;
    if (planar) {
      planes.push_back({n, -dot(n, p0)});
    } else {
      ++r.non_planar_faces;
      for (const Triangle& t : split_like_core(P, mesh.positions.data(), loop)) {
        const Vec c = cross(sub(P[t[1]], P[t[0]]), sub(P[t[2]], P[t[0]]));
        if (!is_zero(c)) planes.push_back({c, -dot(c, P[t[0]])});
      }
    }
    if (planes.empty()) {
      r.message = "witness face " + std::to_string(f) + " has no plane (zero area)";
      return r;
    }
    r.planes += planes.size();
    face_planes.push_back(std::move(planes));
  }
  // One plane per face (a non-planar face stands for one of its triangles' planes): some choice
  // must be disjoint, and minimal.
  size_t choices = 1;
  for (const auto& planes : face_planes) choices *= planes.size();
  std::string why = "the witness faces' half-spaces have a common point";
  for (size_t choice = 0; choice < choices && choices <= 4096; ++choice) {
    std::vector<Plane> chosen;
    for (size_t i = 0, c = choice; i < face_planes.size(); c /= face_planes[i].size(), ++i)
      chosen.push_back(face_planes[i][c % face_planes[i].size()]);
    if (have_common_point(chosen)) continue;
    bool minimal = true;
    for (size_t i = 0; i < chosen.size() && minimal; ++i) {
      std::vector<Plane> others = chosen;
      others.erase(others.begin() + long(i));
      if (!have_common_point(others)) {
        minimal = false;
        why = "not minimal: the half-spaces are disjoint without face " + std::to_string(faces[i]);
      }
    }
    if (minimal) {
      r.ok = true;
      return r;
    }
  }
  r.message = why;
  return r;
}

const char* verdict_name(Verdict v) {
  switch (v) {
    case Verdict::Empty: return "EMPTY";
    case Verdict::Flat: return "FLAT";
    case Verdict::Full: return "FULL";
  }
  return "?";
}

double bbox_diagonal(const kergen::Mesh& mesh) {
  const size_t nv = mesh.num_vertices();
  if (nv == 0) return 0;
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k) lo[k] = hi[k] = mesh.positions[k];
  for (size_t v = 0; v < nv; ++v)
    for (int k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], mesh.positions[3 * v + k]);
      hi[k] = std::max(hi[k], mesh.positions[3 * v + k]);
    }
  return std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                   (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

OracleResult oracle_kernel(const kergen::Mesh& mesh, const OracleOptions& options) {
  OracleResult r;
  auto t0 = std::chrono::steady_clock::now();
  const size_t nv = mesh.num_vertices();
  const size_t nf = mesh.num_faces();
  r.faces = nf;
  if (nv == 0 || nf == 0) {
    r.message = "empty mesh";
    return r;
  }
  std::vector<Vec> P(nv);
  for (size_t v = 0; v < nv; ++v)
    for (int k = 0; k < 3; ++k) {
      const double c = mesh.positions[3 * v + k];
      if (!std::isfinite(c)) {
        r.message = "non-finite coordinate";
        return r;
      }
      P[v][k] = NT(c);
    }

  // ---- topology: every directed edge once, its reverse once; one connected piece -----------
  if (!options.half_spaces_only) {
    std::unordered_map<uint64_t, uint32_t> directed;
    std::vector<uint32_t> parent(nv);
    for (uint32_t v = 0; v < nv; ++v) parent[v] = v;
    auto find = [&](uint32_t v) {
      while (parent[v] != v) v = parent[v] = parent[parent[v]];
      return v;
    };
    std::vector<char> used(nv, 0);
    size_t off = 0;
    for (size_t f = 0; f < nf; ++f) {
      const size_t k = mesh.face_sizes.empty() ? 3 : mesh.face_sizes[f];
      if (k < 3 || off + k > mesh.indices.size()) {
        r.message = "face " + std::to_string(f) + " has fewer than 3 vertices or runs past the index array";
        return r;
      }
      for (size_t j = 0; j < k; ++j) {
        const uint32_t a = mesh.indices[off + j], b = mesh.indices[off + (j + 1) % k];
        if (a >= nv || b >= nv) {
          r.message = "face " + std::to_string(f) + " refers to a missing vertex";
          return r;
        }
        ++directed[(uint64_t(a) << 32) | b];
        used[a] = 1;
        parent[find(a)] = find(b);
      }
      off += k;
    }
    for (const auto& [key, count] : directed) {
      const uint64_t rev = (key << 32) | (key >> 32);
      auto it = directed.find(rev);
      if (count != 1 || it == directed.end() || it->second != 1 || (key >> 32) == (key & 0xffffffffu)) {
        r.message = "not closed, manifold and consistently oriented (directed edge used " + std::to_string(count) +
                    "x, reverse " + std::to_string(it == directed.end() ? 0u : it->second) + "x)";
        return r;
      }
    }
    size_t roots = 0;
    for (uint32_t v = 0; v < nv; ++v) roots += used[v] && find(v) == v;
    if (roots != 1) {
      r.message = std::to_string(roots) + " connected components";
      return r;
    }
  }

  // ---- planes and the exact enclosed volume (x6) --------------------------------------------
  std::vector<Plane> planes;
  planes.reserve(nf);
  std::vector<std::vector<uint32_t>> non_planar;
  NT vol6 = 0;
  size_t offset = 0;
  for (size_t f = 0; f < nf; ++f) {
    const size_t k = mesh.face_sizes.empty() ? 3 : mesh.face_sizes[f];
    if (k < 3 || offset + k > mesh.indices.size()) {
      r.message = "face " + std::to_string(f) + " has fewer than 3 vertices or runs past the index array";
      return r;
    }
    const uint32_t* loop = mesh.indices.data() + offset;
    offset += k;
    for (size_t j = 0; j < k; ++j)
      if (loop[j] >= nv) {
        r.message = "face " + std::to_string(f) + " refers to a missing vertex";
        return r;
      }
    const Vec& p0 = P[loop[0]];
    Vec n{NT(0), NT(0), NT(0)};
    for (size_t j = 1; j + 1 < k; ++j) {
      const Vec c = cross(sub(P[loop[j]], p0), sub(P[loop[j + 1]], p0));
      for (int a = 0; a < 3; ++a) n[a] = n[a] + c[a];
      vol6 = vol6 + dot(p0, cross(P[loop[j]], P[loop[j + 1]]));
    }
    bool planar = !is_zero(n);
    for (size_t j = 3; planar && j < k; ++j) planar = CGAL::is_zero(dot(n, sub(P[loop[j]], p0)));
    if (planar) {
      planes.push_back({n, -dot(n, p0)});
    } else if (k == 3) {
      ++r.degenerate_faces;  // exactly collinear triangle
    } else {
      // Split once the orientation is known (the fold test depends on it).
      non_planar.emplace_back(loop, loop + k);
    }
  }
  if (CGAL::is_zero(vol6) && !options.half_spaces_only) {
    r.message = "the mesh encloses no volume";
    return r;
  }
  r.flipped = CGAL::is_negative(vol6) && !options.half_spaces_only;
  r.shape_volume = std::abs(CGAL::to_double(vol6)) / 6.0;
  if (r.flipped)
    for (Plane& p : planes) {
      for (int a = 0; a < 3; ++a) p.n[a] = -p.n[a];
      p.d = -p.d;
    }
  for (std::vector<uint32_t>& loop : non_planar) {
    if (r.flipped) std::reverse(loop.begin(), loop.end());
    bool any = false;
    for (const Triangle& t : split_like_core(P, mesh.positions.data(), loop)) {
      const Vec c = cross(sub(P[t[1]], P[t[0]]), sub(P[t[2]], P[t[0]]));
      if (is_zero(c)) continue;
      planes.push_back({c, -dot(c, P[t[0]])});
      any = true;
    }
    if (any)
      ++r.non_planar_faces;
    else
      ++r.degenerate_faces;
  }
  r.planes = planes.size();

  // Exact deduplication of oriented planes: scale so the first non-zero normal component is +-1.
  {
    std::map<std::array<CGAL::Gmpq, 4>, size_t> seen;
    std::vector<Plane> unique;
    for (const Plane& p : planes) {
      int lead = 0;
      while (CGAL::is_zero(p.n[lead])) ++lead;
      CGAL::Gmpq s = to_gmpq(p.n[lead]);
      s = CGAL::abs(s);
      std::array<CGAL::Gmpq, 4> key{to_gmpq(p.n[0]) / s, to_gmpq(p.n[1]) / s, to_gmpq(p.n[2]) / s, to_gmpq(p.d) / s};
      if (seen.emplace(std::move(key), unique.size()).second) unique.push_back(p);
    }
    planes.swap(unique);
  }
  r.distinct_planes = planes.size();
  r.ms_planes = ms_since(t0);

  // ---- exact LP: maximize t s.t. n_i.x + t*|n_i|_1 <= -d_i, 0 <= t <= 1 ----------------------
  t0 = std::chrono::steady_clock::now();
  CGAL::Quadratic_program<NT> lp(CGAL::SMALLER, false, NT(0), false, NT(0));
  for (size_t i = 0; i < planes.size(); ++i) {
    const Plane& p = planes[i];
    const int row = static_cast<int>(i);
    for (int a = 0; a < 3; ++a) lp.set_a(a, row, p.n[a]);
    lp.set_a(3, row, CGAL::abs(p.n[0]) + CGAL::abs(p.n[1]) + CGAL::abs(p.n[2]));
    lp.set_b(row, -p.d);
  }
  lp.set_l(3, true, NT(0));
  lp.set_u(3, true, NT(1));
  lp.set_c(3, NT(-1));
  CGAL::Quadratic_program_solution<NT> sol = CGAL::solve_linear_program(lp, NT());
  r.ms_lp = ms_since(t0);
  if (sol.is_infeasible()) {
    r.ok = true;
    r.verdict = Verdict::Empty;
    return r;
  }
  if (!sol.is_optimal()) {
    r.message = "LP neither infeasible nor optimal";
    return r;
  }
  const CGAL::Gmpq t_star = -to_gmpq(sol.objective_value());
  r.t_star = CGAL::to_double(t_star);
  std::array<CGAL::Gmpq, 3> x;
  {
    auto it = sol.variable_values_begin();
    for (int a = 0; a < 3; ++a, ++it) {
      x[a] = to_gmpq(*it);
      r.interior[a] = CGAL::to_double(x[a]);
    }
  }
  r.ok = true;
  if (CGAL::is_zero(t_star)) {
    r.verdict = Verdict::Flat;
    return r;
  }
  r.verdict = Verdict::Full;
  if (!options.build_polyhedron) return r;

  // ---- the kernel polyhedron: halfspace_intersection_3 on Epeck -----------------------------
  t0 = std::chrono::steady_clock::now();
  // Prefer the double rounding of x* as origin (short coordinates) when it is still strictly
  // inside every plane (checked exactly); else the exact rational x*.
  bool rounded_inside = true;
  {
    Vec xr{NT(r.interior[0]), NT(r.interior[1]), NT(r.interior[2])};
    for (const Plane& p : planes)
      if (!CGAL::is_negative(dot(p.n, xr) + p.d)) {
        rounded_inside = false;
        break;
      }
  }
  Epeck::Point_3 origin = rounded_inside ? Epeck::Point_3(r.interior[0], r.interior[1], r.interior[2])
                                         : Epeck::Point_3(to_eft(x[0]), to_eft(x[1]), to_eft(x[2]));
  std::vector<Epeck::Plane_3> eplanes;
  eplanes.reserve(planes.size());
  for (const Plane& p : planes)
    eplanes.emplace_back(to_eft(to_gmpq(p.n[0])), to_eft(to_gmpq(p.n[1])), to_eft(to_gmpq(p.n[2])),
                         to_eft(to_gmpq(p.d)));
  CGAL::Surface_mesh<Epeck::Point_3> K;
  CGAL::halfspace_intersection_3(eplanes.begin(), eplanes.end(), K, boost::optional<Epeck::Point_3>(origin));

  // Distinct vertices (exact comparison).
  using VI = CGAL::Surface_mesh<Epeck::Point_3>::Vertex_index;
  std::vector<VI> order(K.vertices().begin(), K.vertices().end());
  std::sort(order.begin(), order.end(),
            [&](VI a, VI b) { return CGAL::compare_xyz(K.point(a), K.point(b)) == CGAL::SMALLER; });
  std::vector<size_t> id(K.number_of_vertices() + 1, 0);
  std::vector<std::array<double, 3>> pos;
  for (size_t i = 0; i < order.size(); ++i) {
    if (i == 0 || CGAL::compare_xyz(K.point(order[i - 1]), K.point(order[i])) != CGAL::EQUAL) {
      const Epeck::Point_3& p = K.point(order[i]);
      pos.push_back({CGAL::to_double(CGAL::exact(p.x())), CGAL::to_double(CGAL::exact(p.y())),
                     CGAL::to_double(CGAL::exact(p.z()))});
    }
    id[order[i].idx()] = pos.size() - 1;
  }
  r.vertices = pos.size();

  // Facets with >= 3 distinct vertices; volume = sum of fan tetrahedra apexed at the origin.
  const std::array<double, 3> o = r.interior;
  double vol6k = 0;
  for (auto f : K.faces()) {
    std::vector<size_t> loop;
    for (auto v : CGAL::vertices_around_face(K.halfedge(f), K)) {
      const size_t i = id[v.idx()];
      if (loop.empty() || loop.back() != i) loop.push_back(i);
    }
    while (loop.size() > 1 && loop.front() == loop.back()) loop.pop_back();
    std::vector<size_t> sorted = loop;
    std::sort(sorted.begin(), sorted.end());
    if (std::unique(sorted.begin(), sorted.end()) - sorted.begin() >= 3) ++r.facets;
    for (size_t j = 1; j + 1 < loop.size(); ++j) {
      const auto& a = pos[loop[0]];
      const auto& b = pos[loop[j]];
      const auto& c = pos[loop[j + 1]];
      const double ax = a[0] - o[0], ay = a[1] - o[1], az = a[2] - o[2];
      const double bx = b[0] - o[0], by = b[1] - o[1], bz = b[2] - o[2];
      const double cx = c[0] - o[0], cy = c[1] - o[1], cz = c[2] - o[2];
      vol6k += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
    }
  }
  r.volume = vol6k / 6.0;
  r.has_polyhedron = true;
  r.ms_hull = ms_since(t0);
  return r;
}

}  // namespace kergen_oracle
