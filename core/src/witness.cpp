// The non-star witness (see witness.h): the conflict is checked exactly, then each of its planes
// is named by the first face lying in it with the same orientation.
#include "witness.h"

#include <algorithm>

#include "exact/predicates.h"

namespace kergen {

namespace {

constexpr uint32_t kNoFace = 0xffffffffu;

// The lowest-indexed prepared face whose plane is `plane` (exact coefficients of the triangle
// t) with the same inner side: its three representative corners on the plane (orient3d, exact),
// its normal pointing the same way (exact dot product; coplanar normals are parallel).
uint32_t first_face_on_plane(const PreparedMesh& mesh, const std::array<uint32_t, 3>& t,
                             const PlaneCoef<Expansion>& plane) {
  const double *a = mesh.point(t[0]), *b = mesh.point(t[1]), *c = mesh.point(t[2]);
  for (uint32_t f = 0; f < mesh.num_faces(); ++f) {
    const auto& r = mesh.rep[f];
    bool on = true;
    for (int k = 0; k < 3 && on; ++k) on = orient3d(a, b, c, mesh.point(r[k]), mesh.exact_shift) == 0;
    if (!on) continue;
    const PlaneCoef<Expansion> face =
        exact_plane(mesh.point(r[0]), mesh.point(r[1]), mesh.point(r[2]), mesh.exact_shift);
    const Expansion dot = plane.n[0] * face.n[0] + plane.n[1] * face.n[1] + plane.n[2] * face.n[2];
    if (dot.sign() > 0) return f;
  }
  return kNoFace;
}

}  // namespace

std::vector<uint32_t> witness_faces(const PreparedMesh& mesh, const std::vector<std::array<uint32_t, 3>>& conflict) {
  if (conflict.size() < 2 || conflict.size() > 4) return {};
  std::vector<PlaneCoef<Expansion>> planes;
  for (const auto& t : conflict)
    planes.push_back(exact_plane(mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]), mesh.exact_shift));
  if (!halfspaces_disjoint(planes.data(), planes.size())) return {};
  std::vector<uint32_t> faces;
  for (size_t i = 0; i < conflict.size(); ++i) {
    const uint32_t f = first_face_on_plane(mesh, conflict[i], planes[i]);
    if (f == kNoFace) return {};  // (never: each plane is some face's)
    faces.push_back(f);
  }
  std::sort(faces.begin(), faces.end());
  return faces;
}

}  // namespace kergen
