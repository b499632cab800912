// The certificates behind the answers (certify.h; which answer each one certifies, and why, is
// listed there). The ray degree is preferred where it applies: it needs a point strictly inside a
// bounded full-dimensional kernel (embedding.h), and where there is none (flat or unbounded
// kernels, open meshes, a point that rounding puts on a facet) the exact face-face contact test
// decides instead (self_contact.h), which needs no point.
#include "certify/certify.h"

#include <algorithm>
#include <cstdio>
#include <iterator>

#include "certify/embedding.h"
#include "certify/self_contact.h"
#include "certify/witness.h"
#include "util/plural.h"

namespace kergen {

namespace {

// The refusal of a surface that a ray from inside its kernel crosses more than once.
void refuse_crossing(const PreparedMesh& mesh, const EmbeddingCheck& check, Error& error, std::string& message) {
  char point[96];
  std::snprintf(point, sizeof point, "(%.9g, %.9g, %.9g)", mesh.to_input(check.point[0]), mesh.to_input(check.point[1]),
                mesh.to_input(check.point[2]));
  error = Error::SelfIntersection;
  message = "the surface crosses itself: a ray from " + std::string(point) +
            ", a point every face is seen from the inside, crosses it " + count_of(check.crossings, "time", "times") +
            " (a closed surface that does not cross itself is crossed once)";
}

}  // namespace

void refuse_nested_shells(const PreparedMesh& m, Error& error, std::string& message) {
  error = Error::MultipleComponents;
  message = "the mesh has " + std::to_string(m.shells) +
            " separate pieces nested with the same orientation (an inner piece faces outward: a second solid "
            "inside the first, not a void)";
}

void input_witness(const Setup& s, std::vector<uint32_t>& faces, std::vector<uint32_t>& boundary_edges) {
  faces.clear();
  boundary_edges.clear();
  for (uint32_t f : witness_faces(s.mesh, s.lp.conflict)) {
    if (f < s.surface_faces) {
      faces.push_back(s.mesh.input_face(f));
    } else {  // a boundary wall (open_boundary.h): the triangle (a, b, c) of its edge a -> b
      boundary_edges.push_back(s.mesh.rep[f][0]);
      boundary_edges.push_back(s.mesh.rep[f][1]);
    }
  }
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
}

bool certify_no_contact(const Setup& s, Error& error, std::string& message, std::vector<Warning>& warnings) {
  const PreparedMesh& mesh = s.mesh;
  const FaceContact contact = find_face_contact(mesh, s.surface_faces);  // (walls may meet the surface)
  if (contact.outcome == FaceContact::Outcome::None) return true;
  if (contact.outcome == FaceContact::Outcome::Undecided) {
    warnings.push_back({Warning::Kind::CrossingsUnchecked, 1,
                        "a polygon face is not a simple polygon in its plane: whether the surface crosses itself "
                        "was not checked"});
    return true;
  }
  auto at = [&](uint32_t v) {
    char text[96];
    std::snprintf(text, sizeof text, "(%.9g, %.9g, %.9g)", mesh.to_input(mesh.point(v)[0]),
                  mesh.to_input(mesh.point(v)[1]), mesh.to_input(mesh.point(v)[2]));
    return std::string(text);
  };
  error = Error::SelfIntersection;
  message = "the surface crosses or touches itself: two faces, one with a corner at " + at(contact.corner_a) +
            " and one with a corner at " + at(contact.corner_b) + ", meet away from the vertices and edges they share";
  return false;
}

namespace {

// Whether a traced kernel of a closed surface is bounded and full-dimensional: no box plane
// holds a vertex, and no plane and its opposite both hold the first one (a flat kernel).
bool full_dimensional(const Setup& s, const TraceResult& tr) {
  if (s.mesh.boundary_edges > 0 || tr.vertices.size() < 4) return false;
  for (const TracedVertex& v : tr.vertices)
    for (uint32_t p : v.tight)
      if (s.is_box[p]) return false;
  const PlaneIds& tight = tr.vertices[0].tight;
  for (uint32_t p : tight) {
    const uint32_t o = s.planes->opposite(p);
    if (o != kNoPlane && std::binary_search(tight.begin(), tight.end(), o)) return false;
  }
  return true;
}

// The ray degree from the centroid of kernel vertices that LPs in more directions reach
// (strictly inside the kernel once they span it): three more, opposite the first's corner of a
// tetrahedron, then six along the axes. Undecided when neither centroid is strictly inside.
EmbeddingCheck degree_from_lp_vertices(const Setup& s, const Options& options) {
  static const double kDirections[][3] = {
      {1, -1.03125, -0.96875}, {-0.96875, 1, -1.03125}, {-1.03125, -0.96875, 1},  // tetrahedron
      {1, 0.25, 0.0625},       {-1, -0.25, -0.0625},    {0.0625, 1, 0.25},
      {-0.0625, -1, -0.25},    {0.25, 0.0625, 1},       {-0.25, -0.0625, -1}};
  std::vector<uint32_t> planes;
  for (uint32_t i = 0; i < s.planes->size(); ++i)
    if (!s.is_box[i]) planes.push_back(i);
  double sum[3] = {s.lp.vertex.x[0].v, s.lp.vertex.x[1].v, s.lp.vertex.x[2].v};
  int vertices = 1;
  EmbeddingCheck check;
  for (size_t i = 0; i < std::size(kDirections); ++i) {
    const LpResult lp = solve_lp(*s.planes, s.active, kDirections[i], kLpBound, options.seed);
    if (lp.outcome == LpResult::Outcome::Optimal) {
      for (int k = 0; k < 3; ++k) sum[k] += lp.vertex.x[k].v;
      ++vertices;
    }
    if (i != 2 && i + 1 != std::size(kDirections)) continue;
    const double c[3] = {sum[0] / vertices, sum[1] / vertices, sum[2] / vertices};
    check = check_embedding_at(s.mesh, *s.planes, planes, c);
    if (check.outcome != EmbeddingCheck::Outcome::Undecided) return check;
  }
  return check;
}

// The verdict of a ray degree, or of the contact test when the degree is undecided.
bool certify_by(const Setup& s, const EmbeddingCheck& check, Error& error, std::string& message,
                std::vector<Warning>& warnings) {
  if (check.outcome == EmbeddingCheck::Outcome::Embedded) return true;
  if (check.outcome == EmbeddingCheck::Outcome::Undecided) return certify_no_contact(s, error, message, warnings);
  refuse_crossing(s.mesh, check, error, message);
  return false;
}

}  // namespace

// Both entry points look for a point inside the kernel the same two ways, in the order their
// own work makes cheap (compute_kernel: its trace first; find_kernel_point: more LPs first), and
// fall back to the contact test only when both fail. The degree does not depend on the point (it
// is the surface's winding number about it, constant inside the kernel), so the two entry points
// give the same verdict on every mesh.
bool certify_embedding(const Setup& s, const Options& options, const TraceResult& tr, Kernel& out) {
  if (!full_dimensional(s, tr)) return certify_no_contact(s, out.error, out.message, out.warnings);
  EmbeddingCheck check = check_embedding(s.mesh, *s.planes, tr);
  if (check.outcome == EmbeddingCheck::Outcome::Undecided) check = degree_from_lp_vertices(s, options);
  return certify_by(s, check, out.error, out.message, out.warnings);
}

bool certify_kernel_point(Setup& s, const Options& options, KernelPoint& r) {
  if (s.lp.outcome != LpResult::Outcome::Optimal || s.mesh.boundary_edges > 0)
    return certify_no_contact(s, r.error, r.message, r.warnings);
  EmbeddingCheck check = degree_from_lp_vertices(s, options);
  if (check.outcome == EmbeddingCheck::Outcome::Undecided) {
    // The kernel traced as compute_kernel traces it (same options, no events): its point.
    const CulledTrace ct = trace_kernel(s, options);
    if (ct.trace.internal_error || !full_dimensional(s, ct.trace))
      return certify_no_contact(s, r.error, r.message, r.warnings);
    check = check_embedding(s.mesh, *s.planes, ct.trace);
  }
  return certify_by(s, check, r.error, r.message, r.warnings);
}

}  // namespace kergen
