// Seidel's randomized LP, 3D -> 2D -> 1D, with every decision an exact predicate:
//  - "does the current optimum violate plane h" = side(h, vertex),
//  - "which end of the line h∩g is better" = sign of objective . (n_h x n_g), lexicographic over
//    three independent directions, so the optimum is one point even on degenerate input,
//  - "which plane cuts the line first" = side of one plane at the other's vertex on the line.
// Three bounding planes s_i x_i <= M (s = sign pattern of the objective) make every subproblem
// bounded; their corner is the optimum of the empty constraint set.
#include "solve/lp.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "solve/lp_hint.h"
#include "solve/vertex_filter.h"
#include "util/random.h"

namespace kergen {

namespace {

// Deterministic on every platform (std::shuffle's algorithm is not).
void shuffle(std::vector<uint32_t>& v, uint64_t seed) {
  SplitMix64 rng{seed ^ 0x9e3779b97f4a7c15ull};
  for (size_t i = v.size(); i > 1; --i) std::swap(v[i - 1], v[rng.next() % i]);
}

class SeidelLp {
 public:
  SeidelLp(const PlaneSet& ps, const double dir[3], const uint32_t bounds[3]) : ps_(ps) {
    for (int i = 0; i < 3; ++i) bounds_[i] = bounds[i];
    double s[3];
    for (int i = 0; i < 3; ++i) s[i] = dir[i] < 0 ? -1 : 1;
    // Tie-breaks with the same sign pattern (bounded on the orthant), independent of dir.
    const double cand[4][3] = {{3, 1, 2}, {2, 3, 1}, {1, 1, 5}, {7, 2, 1}};
    for (int i = 0; i < 3; ++i) obj_[0][i] = dir[i];
    int found = 0;
    for (int a = 0; a < 4 && found < 2; ++a)
      for (int b = a + 1; b < 4 && found < 2; ++b) {
        double c2[3], c3[3];
        for (int i = 0; i < 3; ++i) {
          c2[i] = s[i] * cand[a][i];
          c3[i] = s[i] * cand[b][i];
        }
        if (independent(dir, c2, c3)) {
          for (int i = 0; i < 3; ++i) {
            obj_[1][i] = c2[i];
            obj_[2][i] = c3[i];
          }
          found = 2;
        }
      }
    assert(found == 2);
  }

  // Whether det3(dir, c2, c3) != 0 for small integers c2, c3: their cross product w is exact in
  // doubles, so det = dir . w is within 4 eps sum |dir_i w_i| (three roundings, plus a floor for
  // subnormal products) of the exact value; only a value within that bound of 0 is decided
  // exactly. (One LP per call of a small mesh: the expansions were most of this constructor.)
  static bool independent(const double dir[3], const double c2[3], const double c3[3]) {
    const double w[3] = {c2[1] * c3[2] - c2[2] * c3[1], c2[2] * c3[0] - c2[0] * c3[2], c2[0] * c3[1] - c2[1] * c3[0]};
    const double p0 = dir[0] * w[0], p1 = dir[1] * w[1], p2 = dir[2] * w[2];
    const double det = p0 + p1 + p2;
    const double bound = 4 * exact::kEps * (std::fabs(p0) + std::fabs(p1) + std::fabs(p2)) + 1e-300;
    if (std::fabs(det) > bound) return true;
    return det3(Expansion(dir[0]), Expansion(dir[1]), Expansion(dir[2]), Expansion(c2[0]), Expansion(c2[1]),
                Expansion(c2[2]), Expansion(c3[0]), Expansion(c3[1]), Expansion(c3[2]))
               .sign() != 0;
  }

  // Infeasible: *failed_at is the first i for which cons[0..i] has no common point (cons[0..i)
  // has one, the optimum before constraint i, which it violates).
  LpResult solve(const std::vector<uint32_t>& cons, size_t* failed_at = nullptr) {
    LpResult r;
    VertexGeom v = make_vertex(ps_, cons[0], cons[1], cons[2], false);
    for (size_t i = 3; i < cons.size(); ++i) {
      uint32_t h = cons[i];
      if (side(ps_, h, v) > 0 && !solve2(h, cons.data(), i, v)) {
        r.outcome = LpResult::Outcome::Infeasible;
        if (failed_at) *failed_at = i;
        return r;
      }
    }
    r.vertex = v;
    r.outcome = LpResult::Outcome::Optimal;
    for (uint32_t b : v.basis)
      if (is_bound(b)) r.outcome = LpResult::Outcome::Unbounded;
    return r;
  }

 private:
  bool is_bound(uint32_t p) const { return p == bounds_[0] || p == bounds_[1] || p == bounds_[2]; }

  // Lexicographic sign of the objective along n_p x n_q (never 0 for non-parallel p, q).
  int objective_sign(uint32_t p, uint32_t q) const {
    for (const auto& c : obj_) {
      int s = sign_det3_vector(ps_, c, p, q);
      if (s != 0) return s;
    }
    return 0;
  }

  // Optimum on the line h∩g over cons[0..n). Along D = sigma (n_h x n_g) plane m crosses the
  // line at t_m = -f_m(P0) / (n_m . D) for a point P0 of it; the planes m with n_m . D > 0 bound
  // t from above (the first one binds), the others from below. Whether m cuts before the current
  // best a is side(m, vertex(h, g, a)) > 0; a filtered comparison of the crossings decides that
  // without building the vertex, so one is built per change only where the filter cannot tell.
  bool solve1(uint32_t h, uint32_t g, const uint32_t* cons, size_t n, VertexGeom& out) {
    int sigma = objective_sign(h, g);
    assert(sigma != 0);
    const LineDirection line(ps_, h, g);
    const CrossingFilter filter(ps_.approx(h), ps_.approx(g), line.u, sigma);
    Best ahead, behind;
    parallel_.clear();
    for (size_t i = 0; i < n; ++i) {
      uint32_t m = cons[i];
      if (m == h || m == g) continue;
      const PlaneCoef<Approx> pm = ps_.approx(m);
      const Approx rate = filter.rate(pm);
      int r = rate.sign();
      if (r == 2)
        r = sign_det3_normals(ps_, m, h, g) * sigma;  // rate_sign's exact fallback (its filter is the one above)
      if (r == 0) {
        parallel_.push_back(m);
        continue;
      }
      Best& best = r > 0 ? ahead : behind;
      const Approx offset = filter.offset(pm);
      bool take = best.plane == kNoPlane;
      if (!take) {
        // s (f_b(P0) a_m - f_m(P0) a_b) with s > 0: its sign orders the crossings t_m, t_b (the
        // product of the two rates is positive on either side). m cuts first when it is < 0
        // ahead, > 0 behind.
        const int q = best.certain && rate.certain() ? (best.offset * rate - offset * best.rate).sign() : 2;
        if (q != 2)
          take = r > 0 ? q < 0 : q > 0;
        else
          take = side(ps_, m, best.vertex(ps_, h, g)) > 0;
      }
      if (take) best.set(m, rate, offset);
    }
    if (ahead.plane == kNoPlane) return false;  // unreachable: the bounding planes bound the objective
    const VertexGeom& va = ahead.vertex(ps_, h, g);
    if (behind.plane != kNoPlane && side(ps_, behind.plane, va) > 0) return false;
    for (uint32_t m : parallel_)
      if (side(ps_, m, va) > 0) return false;
    out = va;
    return true;
  }

  // P0 = (d_g n_h - d_h n_g) x c / s with c = n_h x n_g and s = c . c > 0 (h, g not parallel),
  // kept homogeneous: offset(m) = s f_m(P0) = n_m . W + d_m s, rate(m) = n_m . D, D = sigma c.
  struct CrossingFilter {
    CrossingFilter(const PlaneCoef<Approx>& ph, const PlaneCoef<Approx>& pg, const Approx c[3], int sigma) {
      Approx w[3];
      for (int k = 0; k < 3; ++k) w[k] = pg.d * ph.n[k] - ph.d * pg.n[k];
      W[0] = w[1] * c[2] - w[2] * c[1];
      W[1] = w[2] * c[0] - w[0] * c[2];
      W[2] = w[0] * c[1] - w[1] * c[0];
      s = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
      for (int k = 0; k < 3; ++k) D[k] = sigma > 0 ? c[k] : -c[k];
    }
    Approx rate(const PlaneCoef<Approx>& pm) const { return pm.n[0] * D[0] + pm.n[1] * D[1] + pm.n[2] * D[2]; }
    Approx offset(const PlaneCoef<Approx>& pm) const {
      return pm.n[0] * W[0] + pm.n[1] * W[1] + pm.n[2] * W[2] + pm.d * s;
    }
    Approx W[3], s, D[3];
  };

  // The binding plane on one side of the line so far, its filter values, and its vertex once built.
  struct Best {
    uint32_t plane = kNoPlane;
    Approx rate, offset;
    bool certain = false;  // rate certain: the crossing comparison is usable
    bool built = false;
    VertexGeom v;
    void set(uint32_t m, const Approx& r, const Approx& o) {
      plane = m;
      rate = r;
      offset = o;
      certain = r.certain();
      built = false;
    }
    const VertexGeom& vertex(const PlaneSet& ps, uint32_t h, uint32_t g) {
      if (!built) {
        v = make_vertex(ps, h, g, plane, false);
        built = true;
      }
      return v;
    }
  };

  // Optimum on plane h over cons[0..n) (cons starts with the three bounding planes).
  bool solve2(uint32_t h, const uint32_t* cons, size_t n, VertexGeom& out) {
    VertexGeom w;
    bool have = false;
    // The optimum over the bounding planes alone: the feasible, locally optimal corner.
    for (int x = 0; x < 3 && !have; ++x)
      for (int y = x + 1; y < 3 && !have; ++y) {
        uint32_t bx = bounds_[x], by = bounds_[y], bz = bounds_[3 - x - y];
        if (sign_det3_normals(ps_, h, bx, by) == 0) continue;
        VertexGeom c = make_vertex(ps_, h, bx, by, false);
        int sz = side(ps_, bz, c);
        if (sz > 0) continue;
        uint32_t tight[3] = {bx, by, bz};
        int nt = sz == 0 ? 3 : 2;
        bool optimal = true;
        for (int a = 0; a < nt && optimal; ++a) {
          if (normals_parallel(ps_, h, tight[a])) continue;
          for (int sigma = -1; sigma <= 1 && optimal; sigma += 2) {
            bool feasible = true;
            for (int b = 0; b < nt; ++b)
              if (b != a && sigma * sign_det3_normals(ps_, tight[b], h, tight[a]) > 0) feasible = false;
            if (feasible && sigma * objective_sign(h, tight[a]) > 0) optimal = false;
          }
        }
        if (optimal) {
          w = c;
          have = true;
        }
      }
    assert(have && "no optimal corner of the bounding planes on h");
    if (!have) return false;
    for (size_t i = 0; i < n; ++i) {
      uint32_t g = cons[i];
      if (is_bound(g)) continue;
      if (side(ps_, g, w) > 0) {
        if (normals_parallel(ps_, h, g)) return false;  // g excludes all of h
        if (!solve1(h, g, cons, i, w)) return false;
      }
    }
    out = w;
    return true;
  }

  const PlaneSet& ps_;
  uint32_t bounds_[3];
  double obj_[3][3];
  std::vector<uint32_t> parallel_;
};

}  // namespace

namespace {

// Bounds of the conflict search, far beyond the LP's: the planes of a small conflict can meet
// far from the mesh (nearly parallel ones at about the gap between them over their angle: two
// faces of a torus's top and bottom rings, antiparallel up to rounding, meet ~1e15 away), and a
// conflict must not need the bounds. A power of two, exact like the LP's; its cube, in the
// homogeneous coordinates of a corner of the bounds, stays far from overflow.
const double kConflictBound = std::ldexp(1.0, 100);

// A minimal conflict among the face planes of cons[3..failed] (cons[0..failed] infeasible:
// solve's failed_at), by the additive method (Chinneck, "Feasibility and Infeasibility in
// Optimization", 2008): the planes are taken in order until they have no common point; the last
// one taken belongs to the conflict and goes first, and the planes before it are taken again,
// until the conflict found so far has no common point by itself. Each plane added was needed
// (the planes before it, with the conflict found before it, have a common point), so the result
// is minimal and, by Helly's theorem, at most four planes. Explicit planes (the LP's bounds, a
// bounding box) are left out, and the search runs inside far wider bounds of its own; when that
// makes cons[3..failed] feasible (it needed the box), every face plane of cons is searched
// instead. Each round is one exact LP over the planes left; solve_lp put the float run's
// conflict first, so failed is small in practice. Empty when no conflict of face planes is found
// within the wide bounds.
std::vector<uint32_t> minimal_conflict(PlaneSet& ps, const double direction[3], const std::vector<uint32_t>& cons,
                                       size_t failed) {
  // (The search's exact evaluations are not counted: Stats::exact_fallbacks stays the kernel's.)
  const size_t exact_fallbacks = ps.exact_fallbacks;
  uint32_t bounds[3];
  for (int i = 0; i < 3; ++i) {
    double n[3] = {0, 0, 0};
    n[i] = direction[i] < 0 ? -1 : 1;
    bounds[i] = ps.add_explicit(n[0], n[1], n[2], -kConflictBound);
  }
  auto face_planes = [&](size_t end) {
    std::vector<uint32_t> out;
    for (size_t i = 3; i < end; ++i)
      if (!ps.explicit_plane(cons[i])) out.push_back(cons[i]);
    return out;
  };
  std::vector<uint32_t> found, rest = face_planes(failed + 1), order;
  {
    SeidelLp lp(ps, direction, bounds);
    // The planes are taken in this order (the bounds first), and `at` is where they first have
    // no common point.
    auto infeasible_at = [&](size_t& at) {
      order.assign(bounds, bounds + 3);
      order.insert(order.end(), found.begin(), found.end());
      order.insert(order.end(), rest.begin(), rest.end());
      return lp.solve(order, &at).outcome == LpResult::Outcome::Infeasible;
    };
    size_t at = 0;
    bool done = !infeasible_at(at);
    if (done) {
      rest = face_planes(cons.size());
      done = !infeasible_at(at);
    }
    for (int round = 0; round < 5 && !done; ++round) {
      const size_t fixed = 3 + found.size();
      if (at < fixed) break;  // found has no common point by itself (at == fixed - 1)
      found.push_back(order[at]);
      rest.resize(at - fixed);
      done = !infeasible_at(at);  // (never: the previous round's order with the same prefix failed)
    }
    if (done || found.size() > 4) found.clear();
  }
  for (int i = 0; i < 3; ++i) ps.pop_last();
  ps.exact_fallbacks = exact_fallbacks;
  return found;
}

// Planes of `planes` outside `skip` that the vertex violates: a double pass with a rigorous
// per-plane error bound, the exact predicate only where that is undecided.
void violated_planes(const PlaneSet& ps, const std::vector<uint32_t>& planes, const std::vector<char>& skip,
                     const VertexGeom& v, std::vector<uint32_t>& out) {
  out.clear();
  const VertexFilter filter(v);
  for (uint32_t l : planes) {
    if (skip[l]) continue;
    const int s = filter.sign(ps.approx(l));
    if (s > 0 || (s == 0 && side(ps, l, v) > 0)) out.push_back(l);
  }
}

constexpr size_t kSamplingThreshold = 2000;

}  // namespace

LpResult solve_lp(PlaneSet& ps, const std::vector<uint32_t>& planes, const double direction[3], double bound,
                  uint64_t seed) {
  uint32_t bounds[3];
  for (int i = 0; i < 3; ++i) {
    double n[3] = {0, 0, 0};
    n[i] = direction[i] < 0 ? -1 : 1;
    bounds[i] = ps.add_explicit(n[0], n[1], n[2], -bound);
  }
  LpResult r;
  {
    SeidelLp lp(ps, direction, bounds);
    auto run = [&](const std::vector<uint32_t>& subset, uint64_t s) {
      std::vector<uint32_t> cons;
      cons.reserve(subset.size() + 3);
      cons.assign(bounds, bounds + 3);
      std::vector<uint32_t> order = subset;
      shuffle(order, s);
      // A double-precision run's basis (or conflict) goes first: the exact run then builds the
      // optimum about once instead of once per violation. The rest keep their shuffled order,
      // and with it the expected linear time whatever the guess.
      const LpHint hint = float_lp_hint(ps, order.data(), order.size(), direction, bound);
      for (int k = 0; k < hint.count; ++k) cons.push_back(order[hint.position[k]]);
      // (The moved positions are at most four: looked up in the hint, not marked in an array.)
      auto moved = [&](size_t i) {
        for (int k = 0; k < hint.count; ++k)
          if (hint.position[k] == i) return true;
        return false;
      };
      for (size_t i = 0; i < order.size(); ++i)
        if (!moved(i)) cons.push_back(order[i]);
      size_t failed = 0;
      LpResult result = lp.solve(cons, &failed);
      if (result.outcome == LpResult::Outcome::Infeasible)
        for (uint32_t p : minimal_conflict(ps, direction, cons, failed)) result.conflict.push_back(ps.rep(p));
      return result;
    };
    if (planes.size() <= kSamplingThreshold) {
      r = run(planes, seed);
    } else {
      // Clarkson's sampling: solve exactly on a random subset plus the planes its optimum
      // violated so far; when the optimum violates nothing it is the optimum of all planes.
      std::vector<char> in_subset(ps.size(), 0);
      std::vector<uint32_t> subset, violated;
      std::vector<uint32_t> pool = planes;
      shuffle(pool, seed ^ 0x5eed);
      size_t sample = std::min(planes.size(), size_t(6 * std::sqrt(double(planes.size()))));
      for (size_t i = 0; i < sample; ++i) {
        subset.push_back(pool[i]);
        in_subset[pool[i]] = 1;
      }
      for (uint64_t round = 0;; ++round) {
        r = run(subset, seed + round);
        if (r.outcome == LpResult::Outcome::Infeasible) break;  // a subset is already infeasible
        violated_planes(ps, planes, in_subset, r.vertex, violated);
        if (violated.empty()) break;
        for (uint32_t l : violated) {
          subset.push_back(l);
          in_subset[l] = 1;
        }
      }
    }
  }
  for (int i = 0; i < 3; ++i) ps.pop_last();
  // The optimum is kept (it starts the tracing): rebuilt with input-point recognition.
  if (r.outcome == LpResult::Outcome::Optimal)
    r.vertex = make_vertex(ps, r.vertex.basis[0], r.vertex.basis[1], r.vertex.basis[2]);
  return r;
}

}  // namespace kergen
