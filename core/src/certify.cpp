// The certificates behind the answers (certify.h; which answer each one certifies, and why, is
// listed there). The ray degree is preferred where it applies: it needs a point strictly inside a
// bounded full-dimensional kernel (embedding.h), and where there is none (flat or unbounded
// kernels, open meshes, a point that rounding puts on a facet) the exact face-face contact test
// decides instead (self_contact.h), which needs no point.
#include "certify.h"

#include <algorithm>
#include <cstdio>
#include <iterator>

#include "embedding.h"
#include "self_contact.h"
#include "witness.h"

namespace kergen {

namespace {

// The refusal of a surface that a ray from inside its kernel crosses more than once.
void refuse_crossing(const PreparedMesh& mesh, const EmbeddingCheck& check, Error& error, std::string& message) {
  char point[96];
  std::snprintf(point, sizeof point, "(%.9g, %.9g, %.9g)", mesh.to_input(check.point[0]), mesh.to_input(check.point[1]),
                mesh.to_input(check.point[2]));
  error = Error::SelfIntersection;
  message = "the surface crosses itself: a ray from " + std::string(point) +
            ", a point every face is seen from the inside, crosses it " + std::to_string(check.crossings) +
            " times (a closed surface that does not cross itself is crossed once)";
}

}  // namespace

void refuse_nested_shells(const PreparedMesh& m, Error& error, std::string& message) {
  error = Error::MultipleComponents;
  message = "the mesh has " + std::to_string(m.shells) +
            " separate pieces nested with the same orientation (an inner piece faces outward: a second solid "
            "inside the first, not a void)";
}

std::vector<uint32_t> input_witness(const Setup& s) {
  std::vector<uint32_t> faces = witness_faces(s.mesh, s.lp.conflict);
  for (uint32_t f : faces)
    if (f >= s.surface_faces) return {};  // a boundary wall is no input face: no witness to name
  for (uint32_t& f : faces) f = s.mesh.input_face(f);
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  return faces;
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

bool certify_embedding(const Setup& s, const TraceResult& tr, Kernel& out) {
  bool full_dimensional = s.mesh.boundary_edges == 0 && tr.vertices.size() >= 4;
  for (const TracedVertex& v : tr.vertices)
    for (uint32_t p : v.tight) full_dimensional &= !s.is_box[p];  // unbounded
  if (full_dimensional) {
    const PlaneIds& tight = tr.vertices[0].tight;  // flat: a plane and its opposite hold it
    for (uint32_t p : tight) {
      const uint32_t o = s.planes->opposite(p);
      if (o != kNoPlane && std::binary_search(tight.begin(), tight.end(), o)) full_dimensional = false;
    }
  }
  if (!full_dimensional) return certify_no_contact(s, out.error, out.message, out.warnings);
  const EmbeddingCheck check = check_embedding(s.mesh, *s.planes, tr);
  if (check.outcome == EmbeddingCheck::Outcome::Embedded) return true;
  if (check.outcome == EmbeddingCheck::Outcome::Undecided)
    return certify_no_contact(s, out.error, out.message, out.warnings);
  refuse_crossing(s.mesh, check, out.error, out.message);
  return false;
}

// find_kernel_point's certificate, without a trace: the ray degree from the centroid of kernel
// vertices that LPs in more directions reach (strictly inside the kernel once they span it):
// three more, opposite the first's corner of a tetrahedron, then six along the axes; else the
// exact contact test (flat kernels, open meshes, a centroid on a facet).
bool certify_kernel_point(Setup& s, const Options& options, KernelPoint& r) {
  if (s.lp.outcome != LpResult::Outcome::Optimal || s.mesh.boundary_edges > 0)
    return certify_no_contact(s, r.error, r.message, r.warnings);
  static const double kDirections[][3] = {
      {1, -1.03125, -0.96875}, {-0.96875, 1, -1.03125}, {-1.03125, -0.96875, 1},  // tetrahedron
      {1, 0.25, 0.0625},       {-1, -0.25, -0.0625},    {0.0625, 1, 0.25},
      {-0.0625, -1, -0.25},    {0.25, 0.0625, 1},       {-0.25, -0.0625, -1}};
  std::vector<uint32_t> planes;
  for (uint32_t i = 0; i < s.planes->size(); ++i)
    if (!s.is_box[i]) planes.push_back(i);
  double sum[3] = {s.lp.vertex.x[0].v, s.lp.vertex.x[1].v, s.lp.vertex.x[2].v};
  int vertices = 1;
  for (size_t i = 0; i < std::size(kDirections); ++i) {
    const LpResult lp = solve_lp(*s.planes, s.active, kDirections[i], kLpBound, options.seed);
    if (lp.outcome == LpResult::Outcome::Optimal) {
      for (int k = 0; k < 3; ++k) sum[k] += lp.vertex.x[k].v;
      ++vertices;
    }
    if (i != 2 && i + 1 != std::size(kDirections)) continue;
    const double c[3] = {sum[0] / vertices, sum[1] / vertices, sum[2] / vertices};
    const EmbeddingCheck check = check_embedding_at(s.mesh, *s.planes, planes, c);
    if (check.outcome == EmbeddingCheck::Outcome::Embedded) return true;
    if (check.outcome == EmbeddingCheck::Outcome::CrossesItself) {
      refuse_crossing(s.mesh, check, r.error, r.message);
      return false;
    }
  }
  return certify_no_contact(s, r.error, r.message, r.warnings);
}

}  // namespace kergen
