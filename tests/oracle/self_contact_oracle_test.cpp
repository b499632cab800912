// The exact contact test (core/src/self_contact.*) against CGAL. Random pairs and small sets of
// triangles, simple polygons against triangles and against each other, with corners on a small
// integer grid (and halves), so that coplanar faces, collinear sides, a corner on a side or inside
// a face and equal positions under two ids are frequent. Faces share 0, 1 or 2 vertex ids.
//
// The reference: the exact common part of two closed triangles (CGAL::intersection on Epeck, a
// convex set given by its corners) is a contact unless every corner of it lies in the simplex
// the shared ids span: nothing (no id shared), their point, or their segment. A polygon is the
// union of the triangles of a triangulation made here (CGAL's constrained Delaunay triangulation
// of its loop, faces inside it), not the library's ear clipping. find_face_contact must answer
// Found exactly when some pair of faces is a contact, and name such a pair.
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/intersections.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "certify/self_contact.h"

namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using P3 = K::Point_3;
using Tri3 = K::Triangle_3;
using Outcome = kergen::FaceContact::Outcome;

// Deterministic draws (the same on every standard library).
struct Draw {
  std::mt19937 rng;
  explicit Draw(uint32_t seed) : rng(seed) {}
  int below(int n) { return int(rng() % uint32_t(n)); }
  int in(int lo, int hi) { return lo + below(hi - lo + 1); }
  bool chance(int percent) { return below(100) < percent; }
};

P3 point3(const std::vector<double>& pos, uint32_t v) { return P3(pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]); }

Tri3 triangle3(const std::vector<double>& pos, const std::array<uint32_t, 3>& t) {
  return Tri3(point3(pos, t[0]), point3(pos, t[1]), point3(pos, t[2]));
}

bool in_simplex(const P3& c, const std::vector<P3>& simplex) {
  if (simplex.empty()) return false;
  if (simplex.size() == 1) return c == simplex[0];
  return K::Segment_3(simplex[0], simplex[1]).has_on(c);
}

// Whether the closed triangles a and b have a common point outside `shared` (0, 1 or 2 points).
bool meet_outside(const Tri3& a, const Tri3& b, const std::vector<P3>& shared) {
  const auto common = CGAL::intersection(a, b);
  EXPECT_EQ(bool(common), CGAL::do_intersect(a, b));  // the reference agrees with itself
  if (!common) return false;
  std::vector<P3> corners;
  if (const P3* p = boost::get<P3>(&*common)) {
    corners = {*p};
  } else if (const K::Segment_3* s = boost::get<K::Segment_3>(&*common)) {
    corners = {s->source(), s->target()};
  } else if (const Tri3* t = boost::get<Tri3>(&*common)) {
    corners = {t->vertex(0), t->vertex(1), t->vertex(2)};
  } else {
    corners = boost::get<std::vector<P3>>(*common);
  }
  for (const P3& c : corners)
    if (!in_simplex(c, shared)) return true;
  return false;
}

// A face for the reference: its vertex ids and the triangles whose union it is.
struct RefFace {
  std::vector<uint32_t> ids;
  std::vector<std::array<uint32_t, 3>> pieces;
};

bool faces_meet(const std::vector<double>& pos, const RefFace& f, const RefFace& g) {
  std::vector<P3> shared;
  for (uint32_t v : f.ids)
    if (std::find(g.ids.begin(), g.ids.end(), v) != g.ids.end()) shared.push_back(point3(pos, v));
  for (const auto& a : f.pieces)
    for (const auto& b : g.pieces)
      if (meet_outside(triangle3(pos, a), triangle3(pos, b), shared)) return true;
  return false;
}

// A prepared mesh of the given faces as they are (no validation, no dropped faces, closed):
// `rep` gives each face's representative corners, in the face's orientation.
kergen::PreparedMesh prepared(const std::vector<double>& pos, const std::vector<std::vector<uint32_t>>& faces,
                              const std::vector<std::array<uint32_t, 3>>& rep) {
  kergen::PreparedMesh m;
  m.points = pos;
  m.loop_offsets.push_back(0);
  for (size_t f = 0; f < faces.size(); ++f) {
    for (uint32_t v : faces[f]) m.loops.push_back(v);
    m.loop_offsets.push_back(uint32_t(m.loops.size()));
    m.rep.push_back(rep[f]);
  }
  for (int k = 0; k < 3; ++k) {
    m.bbox_min[k] = HUGE_VAL;
    m.bbox_max[k] = -HUGE_VAL;
    for (size_t i = size_t(k); i < pos.size(); i += 3) {
      m.bbox_min[k] = std::min(m.bbox_min[k], pos[i]);
      m.bbox_max[k] = std::max(m.bbox_max[k], pos[i]);
    }
  }
  return m;
}

bool degenerate(const std::vector<double>& pos, const std::array<uint32_t, 3>& t) {
  return CGAL::collinear(point3(pos, t[0]), point3(pos, t[1]), point3(pos, t[2]));
}

// Tallies of one test: configurations compared, contacts among them, and by shared ids.
struct Tally {
  size_t compared = 0, contacts = 0, skipped = 0;
  size_t by_shared[3] = {0, 0, 0}, contacts_by_shared[3] = {0, 0, 0};
  size_t mismatches = 0;
};

// Compares the library with the reference on one configuration (a mismatch is a failure).
void compare(const std::vector<double>& pos, const std::vector<RefFace>& faces, Tally& tally, const char* what) {
  std::vector<std::vector<uint32_t>> loops;
  std::vector<std::array<uint32_t, 3>> rep;
  for (const RefFace& f : faces) {
    loops.push_back(f.ids);
    rep.push_back(f.pieces[0]);  // a triangle: itself
  }
  std::set<std::pair<uint32_t, uint32_t>> meeting;
  for (uint32_t i = 0; i < faces.size(); ++i)
    for (uint32_t j = i + 1; j < faces.size(); ++j)
      if (faces_meet(pos, faces[i], faces[j])) meeting.insert({i, j});
  const kergen::FaceContact got = kergen::find_face_contact(prepared(pos, loops, rep));
  const bool expected = !meeting.empty();
  ++tally.compared;
  tally.contacts += expected;
  bool ok = got.outcome == (expected ? Outcome::Found : Outcome::None);
  if (ok && expected) ok = meeting.count({std::min(got.face_a, got.face_b), std::max(got.face_a, got.face_b)}) > 0;
  if (!ok) {
    ++tally.mismatches;
    std::string text;
    for (size_t v = 0; v < pos.size() / 3; ++v) {
      char buf[96];
      std::snprintf(buf, sizeof buf, " v%zu=(%g,%g,%g)", v, pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]);
      text += buf;
    }
    for (const RefFace& f : faces) {
      text += " [";
      for (uint32_t v : f.ids) text += " " + std::to_string(v);
      text += " ]";
    }
    ADD_FAILURE() << what << ": CGAL says " << (expected ? "contact" : "none") << ", find_face_contact says "
                  << (got.outcome == Outcome::Found  ? "Found"
                      : got.outcome == Outcome::None ? "None"
                                                     : "Undecided")
                  << " (faces " << got.face_a << ", " << got.face_b << ");" << text;
  }
}

// A corner for the second triangle of a pair: one of the first's corners (the same position
// under a new id), a point of the first's plane (halves of its side vectors), or any grid point.
std::array<double, 3> corner_near(Draw& d, const std::vector<double>& pos, int mode) {
  const int kind = d.below(3);
  if (kind == 0) {
    const int v = d.below(3);
    return {pos[3 * v], pos[3 * v + 1], pos[3 * v + 2]};
  }
  if (kind == 1) {
    const double s = 0.5 * d.in(-2, 3), t = 0.5 * d.in(-2, 3);
    std::array<double, 3> p;
    for (int k = 0; k < 3; ++k) p[k] = pos[k] + s * (pos[3 + k] - pos[k]) + t * (pos[6 + k] - pos[k]);
    return p;
  }
  std::array<double, 3> p = {double(d.in(0, 4)), double(d.in(0, 4)), double(d.in(0, 4))};
  if (mode == 1) p[2] = 0;
  if (mode == 2) p[2] = 4 - p[0] - p[1];
  return p;
}

// Mode 0: corners anywhere on the grid 0..4; mode 1: all in the plane z = 0; mode 2: all in
// the plane x + y + z = 4. The second triangle's free corners come from corner_near.
TEST(OracleSelfContact, TrianglePairs) {
  Draw d(20261127);
  Tally tally;
  size_t coplanar = 0;
  while (tally.compared < 30000) {
    const int mode = d.below(3), shared = d.below(3);
    std::vector<double> pos;
    for (int v = 0; v < 3; ++v) {
      const double x = d.in(0, 4), y = d.in(0, 4);
      const double z = mode == 0 ? d.in(0, 4) : mode == 1 ? 0 : 4 - x - y;
      pos.insert(pos.end(), {x, y, z});
    }
    std::array<uint32_t, 3> t = {0, 1, 2}, s{};
    // The first `shared` corners of s are corners of t (in random order), the others new.
    std::array<uint32_t, 3> order = {0, 1, 2};
    std::shuffle(order.begin(), order.end(), d.rng);
    for (int i = 0; i < 3; ++i) {
      if (i < shared) {
        s[i] = order[i];
        continue;
      }
      const std::array<double, 3> p = corner_near(d, pos, d.chance(50) ? mode : 0);
      s[i] = uint32_t(pos.size() / 3);
      pos.insert(pos.end(), p.begin(), p.end());
    }
    std::rotate(s.begin(), s.begin() + d.below(3), s.end());
    if (d.chance(50)) std::swap(s[1], s[2]);
    if (d.chance(50)) std::swap(t[1], t[2]);
    if (degenerate(pos, t) || degenerate(pos, s)) {
      ++tally.skipped;
      continue;
    }
    coplanar += CGAL::coplanar(point3(pos, t[0]), point3(pos, t[1]), point3(pos, t[2]), point3(pos, s[0])) &&
                CGAL::coplanar(point3(pos, t[0]), point3(pos, t[1]), point3(pos, t[2]), point3(pos, s[1])) &&
                CGAL::coplanar(point3(pos, t[0]), point3(pos, t[1]), point3(pos, t[2]), point3(pos, s[2]));
    const size_t before = tally.contacts;
    const std::vector<RefFace> faces = {{{t[0], t[1], t[2]}, {t}}, {{s[0], s[1], s[2]}, {s}}};
    compare(pos, faces, tally, "triangle pair");
    ++tally.by_shared[shared];
    tally.contacts_by_shared[shared] += tally.contacts - before;
    if (tally.mismatches > 10) break;
  }
  std::printf("triangle pairs: %zu compared (%zu coplanar), %zu contacts, %zu mismatches, %zu degenerate skipped\n",
              tally.compared, coplanar, tally.contacts, tally.mismatches, tally.skipped);
  for (int k = 0; k < 3; ++k)
    std::printf("  %d shared ids: %zu pairs, %zu contacts\n", k, tally.by_shared[k], tally.contacts_by_shared[k]);
  EXPECT_EQ(tally.mismatches, 0u);
  // Every kind is represented in both answers.
  for (int k = 0; k < 3; ++k) {
    EXPECT_GT(tally.contacts_by_shared[k], 500u) << k;
    EXPECT_GT(tally.by_shared[k] - tally.contacts_by_shared[k], 500u) << k;
  }
  EXPECT_GT(coplanar, 2000u);
}

// Three or four triangles over a pool of six or seven grid points (some at one position under
// two ids): pairs share ids as they happen to.
TEST(OracleSelfContact, SmallSets) {
  Draw d(46);
  Tally tally;
  while (tally.compared < 8000) {
    const int points = d.in(6, 7), count = d.in(3, 4);
    const bool flat = d.chance(30);
    std::vector<double> pos;
    for (int v = 0; v < points; ++v) {
      if (v > 0 && d.chance(10)) {  // the position of an earlier point under a new id
        const int w = d.below(v);
        pos.insert(pos.end(), {pos[3 * w], pos[3 * w + 1], pos[3 * w + 2]});
        continue;
      }
      pos.insert(pos.end(), {double(d.in(0, 3)), double(d.in(0, 3)), flat ? 0.0 : double(d.in(0, 3))});
    }
    std::vector<RefFace> faces;
    bool usable = true;
    for (int f = 0; f < count && usable; ++f) {
      std::array<uint32_t, 3> t;
      do {
        for (uint32_t& v : t) v = uint32_t(d.below(points));
      } while (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]);
      usable = !degenerate(pos, t);
      for (const RefFace& g : faces) {
        int common = 0;
        for (uint32_t v : t) common += std::count(g.ids.begin(), g.ids.end(), v) > 0;
        usable &= common < 3;
      }
      faces.push_back({{t[0], t[1], t[2]}, {t}});
    }
    if (!usable) {
      ++tally.skipped;
      continue;
    }
    compare(pos, faces, tally, "small set");
    if (tally.mismatches > 10) break;
  }
  std::printf("small sets: %zu compared, %zu with a contact, %zu mismatches, %zu skipped\n", tally.compared,
              tally.contacts, tally.mismatches, tally.skipped);
  EXPECT_EQ(tally.mismatches, 0u);
  EXPECT_GT(tally.contacts, 500u);
  EXPECT_GT(tally.compared - tally.contacts, 500u);
}

// ---- polygons ------------------------------------------------------------------------------

using CDT = CGAL::Constrained_Delaunay_triangulation_2<K, CGAL::Default, CGAL::Exact_predicates_tag>;
using Polygon = CGAL::Polygon_2<K>;

// The triangles (corner indices) of a simple polygon: a constrained triangulation of its loop,
// the faces whose centroid lies inside.
std::vector<std::array<uint32_t, 3>> triangulation(const std::vector<K::Point_2>& loop) {
  CDT cdt;
  for (size_t i = 0; i < loop.size(); ++i) cdt.insert_constraint(loop[i], loop[(i + 1) % loop.size()]);
  const Polygon polygon(loop.begin(), loop.end());
  auto index = [&](const K::Point_2& p) { return uint32_t(std::find(loop.begin(), loop.end(), p) - loop.begin()); };
  std::vector<std::array<uint32_t, 3>> out;
  K::FT area = 0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    const K::Point_2 c = CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
    if (polygon.bounded_side(c) != CGAL::ON_BOUNDED_SIDE) continue;
    out.push_back({index(f->vertex(0)->point()), index(f->vertex(1)->point()), index(f->vertex(2)->point())});
    area += CGAL::area(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
  }
  EXPECT_EQ(area, CGAL::abs(polygon.area()));  // the triangles cover the polygon
  return out;
}

// A simple polygon of 4 or 5 corners on the grid 0..4 (in its own plane coordinates).
std::vector<K::Point_2> simple_polygon(Draw& d, bool& convex) {
  for (;;) {
    const int n = d.in(4, 5);
    std::vector<K::Point_2> loop;
    for (int i = 0; i < n; ++i) loop.emplace_back(d.in(0, 4), d.in(0, 4));
    const Polygon polygon(loop.begin(), loop.end());
    if (!polygon.is_simple() || polygon.area() == 0) continue;
    convex = polygon.is_convex();
    return loop;
  }
}

// A simple polygon (4 or 5 corners, convex or not) in a plane O + a U + b V (integer O, U, V)
// against a triangle that shares 0, 1 or 2 (adjacent) of its corners; the triangle's other
// corners are polygon corners (the position under a new id), points of the polygon's plane, or
// grid points.
TEST(OracleSelfContact, PolygonAgainstTriangle) {
  Draw d(5);
  Tally tally;
  size_t non_convex = 0;
  while (tally.compared < 12000) {
    bool convex = false;
    const std::vector<K::Point_2> loop = simple_polygon(d, convex);
    const uint32_t n = uint32_t(loop.size());
    int o[3], u[3], v[3];
    do {
      for (int k = 0; k < 3; ++k) {
        o[k] = d.in(0, 2);
        u[k] = d.in(-1, 1);
        v[k] = d.in(-1, 1);
      }
    } while (u[1] * v[2] - u[2] * v[1] == 0 && u[2] * v[0] - u[0] * v[2] == 0 && u[0] * v[1] - u[1] * v[0] == 0);
    auto embed = [&](double a, double b) {
      return std::array<double, 3>{o[0] + a * u[0] + b * v[0], o[1] + a * u[1] + b * v[1], o[2] + a * u[2] + b * v[2]};
    };
    std::vector<double> pos;
    for (const auto& p : loop) {
      const std::array<double, 3> q = embed(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
      pos.insert(pos.end(), q.begin(), q.end());
    }
    // The polygon's representative corners: its lowest corner (x, then y) and its neighbours, a
    // convex corner in the loop's orientation.
    const uint32_t low = uint32_t(std::min_element(loop.begin(), loop.end()) - loop.begin());
    const std::array<uint32_t, 3> rep = {(low + n - 1) % n, low, (low + 1) % n};
    RefFace polygon{{}, triangulation(loop)};
    for (uint32_t i = 0; i < n; ++i) polygon.ids.push_back(i);

    const int shared = d.below(3);
    std::array<uint32_t, 3> s{};
    const uint32_t first = uint32_t(d.below(int(n)));
    for (int i = 0; i < 3; ++i) {
      if (i < shared) {
        s[i] = (first + uint32_t(i)) % n;
        continue;
      }
      std::array<double, 3> p;
      const int kind = d.below(3);
      if (kind == 0) {
        const int c = d.below(int(n));
        p = {pos[3 * c], pos[3 * c + 1], pos[3 * c + 2]};
      } else if (kind == 1) {
        p = embed(0.5 * d.in(0, 8), 0.5 * d.in(0, 8));
      } else {
        p = {double(d.in(-1, 5)), double(d.in(-1, 5)), double(d.in(-1, 5))};
      }
      s[i] = uint32_t(pos.size() / 3);
      pos.insert(pos.end(), p.begin(), p.end());
    }
    std::rotate(s.begin(), s.begin() + d.below(3), s.end());
    if (d.chance(50)) std::swap(s[1], s[2]);
    if (degenerate(pos, s)) {
      ++tally.skipped;
      continue;
    }
    const RefFace triangle{{s[0], s[1], s[2]}, {s}};
    const size_t before = tally.contacts;
    const bool expected = faces_meet(pos, polygon, triangle);
    const kergen::FaceContact got = kergen::find_face_contact(prepared(pos, {polygon.ids, triangle.ids}, {rep, s}));
    ++tally.compared;
    tally.contacts += expected;
    ++tally.by_shared[shared];
    tally.contacts_by_shared[shared] += tally.contacts - before;
    non_convex += !convex;
    if (got.outcome != (expected ? Outcome::Found : Outcome::None)) {
      ++tally.mismatches;
      std::string text;
      for (size_t w = 0; w < pos.size() / 3; ++w) {
        char buf[96];
        std::snprintf(buf, sizeof buf, " v%zu=(%g,%g,%g)", w, pos[3 * w], pos[3 * w + 1], pos[3 * w + 2]);
        text += buf;
      }
      ADD_FAILURE() << "polygon of " << n << " corners against a triangle (" << s[0] << ", " << s[1] << ", " << s[2]
                    << "): CGAL says " << (expected ? "contact" : "none") << ", find_face_contact says "
                    << (got.outcome == Outcome::Found  ? "Found"
                        : got.outcome == Outcome::None ? "None"
                                                       : "Undecided")
                    << ";" << text;
      if (tally.mismatches > 10) break;
    }
  }
  std::printf("polygon against triangle: %zu compared (%zu non-convex polygons), %zu contacts, %zu mismatches\n",
              tally.compared, non_convex, tally.contacts, tally.mismatches);
  for (int k = 0; k < 3; ++k)
    std::printf("  %d shared ids: %zu pairs, %zu contacts\n", k, tally.by_shared[k], tally.contacts_by_shared[k]);
  EXPECT_EQ(tally.mismatches, 0u);
  EXPECT_GT(non_convex, 1000u);
  for (int k = 0; k < 3; ++k) {
    EXPECT_GT(tally.contacts_by_shared[k], 200u) << k;
    EXPECT_GT(tally.by_shared[k] - tally.contacts_by_shared[k], 200u) << k;
  }
}

// Two simple polygons (4 or 5 corners each): the second in the first's plane or in another plane
// through the corners they share (0, 1, or 2 adjacent corners of the first, adjacent in the
// second too), its other corners on the grid -2..4 of its plane.
TEST(OracleSelfContact, PolygonPairs) {
  Draw d(7);
  Tally tally;
  size_t same_plane = 0;
  while (tally.compared < 6000) {
    bool convex = false;
    const std::vector<K::Point_2> a = simple_polygon(d, convex);
    const uint32_t n = uint32_t(a.size());
    std::array<double, 3> o, u, v;
    do {
      for (int k = 0; k < 3; ++k) {
        o[k] = d.in(0, 2);
        u[k] = d.in(-1, 1);
        v[k] = d.in(-1, 1);
      }
    } while (u[1] * v[2] - u[2] * v[1] == 0 && u[2] * v[0] - u[0] * v[2] == 0 && u[0] * v[1] - u[1] * v[0] == 0);
    std::vector<double> pos;
    auto embed = [](const std::array<double, 3>& o, const std::array<double, 3>& u, const std::array<double, 3>& v,
                    const K::Point_2& p) {
      const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y());
      return std::array<double, 3>{o[0] + x * u[0] + y * v[0], o[1] + x * u[1] + y * v[1], o[2] + x * u[2] + y * v[2]};
    };
    for (const K::Point_2& p : a) {
      const std::array<double, 3> q = embed(o, u, v, p);
      pos.insert(pos.end(), q.begin(), q.end());
    }
    // The second polygon's frame and the shared corners in it.
    const int shared = d.below(3);
    const uint32_t first = uint32_t(d.below(int(n))), second = (first + 1) % n;
    const bool flat = d.chance(50);
    std::array<double, 3> o2 = o, u2 = u, v2 = v;
    std::vector<K::Point_2> b;
    std::vector<uint32_t> b_ids;
    if (flat) {
      if (shared >= 1) b = {a[first]};
      if (shared == 2) b.push_back(a[second]);
    } else {
      o2 = {pos[3 * first], pos[3 * first + 1], pos[3 * first + 2]};
      do {
        for (int k = 0; k < 3; ++k) {
          u2[k] = shared == 2 ? pos[3 * second + k] - o2[k] : d.in(-1, 1);
          v2[k] = d.in(-1, 1);
        }
      } while (u2[1] * v2[2] - u2[2] * v2[1] == 0 && u2[2] * v2[0] - u2[0] * v2[2] == 0 &&
               u2[0] * v2[1] - u2[1] * v2[0] == 0);
      if (shared >= 1) b = {K::Point_2(0, 0)};
      if (shared == 2) b.push_back(K::Point_2(1, 0));
    }
    if (shared >= 1) b_ids.push_back(first);
    if (shared == 2) b_ids.push_back(second);
    const int m = d.in(4, 5);
    while (int(b.size()) < m) b.emplace_back(d.in(-2, 4), d.in(-2, 4));
    const Polygon b_polygon(b.begin(), b.end());
    if (!b_polygon.is_simple() || b_polygon.area() == 0) {
      ++tally.skipped;
      continue;
    }
    for (size_t i = b_ids.size(); i < b.size(); ++i) {
      b_ids.push_back(uint32_t(pos.size() / 3));
      const std::array<double, 3> q = embed(o2, u2, v2, b[i]);
      pos.insert(pos.end(), q.begin(), q.end());
    }
    if (d.chance(50)) {  // the second loop the other way round (the shared corners stay adjacent)
      std::reverse(b.begin(), b.end());
      std::reverse(b_ids.begin(), b_ids.end());
    }
    RefFace first_face{{}, triangulation(a)}, second_face{b_ids, {}};
    for (uint32_t i = 0; i < n; ++i) first_face.ids.push_back(i);
    for (const auto& t : triangulation(b)) second_face.pieces.push_back({b_ids[t[0]], b_ids[t[1]], b_ids[t[2]]});
    // Representative corners: the lowest corner of each loop (x, then y) and its neighbours.
    const uint32_t la = uint32_t(std::min_element(a.begin(), a.end()) - a.begin());
    const uint32_t lb = uint32_t(std::min_element(b.begin(), b.end()) - b.begin()), k = uint32_t(b.size());
    const std::array<uint32_t, 3> rep_a = {(la + n - 1) % n, la, (la + 1) % n};
    const std::array<uint32_t, 3> rep_b = {b_ids[(lb + k - 1) % k], b_ids[lb], b_ids[(lb + 1) % k]};
    const size_t before = tally.contacts;
    const bool expected = faces_meet(pos, first_face, second_face);
    const kergen::FaceContact got =
        kergen::find_face_contact(prepared(pos, {first_face.ids, second_face.ids}, {rep_a, rep_b}));
    ++tally.compared;
    tally.contacts += expected;
    ++tally.by_shared[shared];
    tally.contacts_by_shared[shared] += tally.contacts - before;
    same_plane += flat;
    if (got.outcome != (expected ? Outcome::Found : Outcome::None)) {
      ++tally.mismatches;
      std::string text;
      for (size_t w = 0; w < pos.size() / 3; ++w) {
        char buf[96];
        std::snprintf(buf, sizeof buf, " v%zu=(%g,%g,%g)", w, pos[3 * w], pos[3 * w + 1], pos[3 * w + 2]);
        text += buf;
      }
      text += " second [";
      for (uint32_t w : b_ids) text += " " + std::to_string(w);
      ADD_FAILURE() << "polygon pair: CGAL says " << (expected ? "contact" : "none") << ", find_face_contact says "
                    << (got.outcome == Outcome::Found  ? "Found"
                        : got.outcome == Outcome::None ? "None"
                                                       : "Undecided")
                    << ";" << text << " ]";
      if (tally.mismatches > 10) break;
    }
  }
  std::printf("polygon pairs: %zu compared (%zu in one plane), %zu contacts, %zu mismatches\n", tally.compared,
              same_plane, tally.contacts, tally.mismatches);
  for (int k = 0; k < 3; ++k)
    std::printf("  %d shared ids: %zu pairs, %zu contacts\n", k, tally.by_shared[k], tally.contacts_by_shared[k]);
  EXPECT_EQ(tally.mismatches, 0u);
  EXPECT_GT(same_plane, 2000u);
  for (int k = 0; k < 3; ++k) {
    EXPECT_GT(tally.contacts_by_shared[k], 200u) << k;
    EXPECT_GT(tally.by_shared[k] - tally.contacts_by_shared[k], 200u) << k;
  }
}

}  // namespace
