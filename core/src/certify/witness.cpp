// The non-star witness (see witness.h): the conflict is checked exactly, then each of its planes
// is named by the first face lying in it with the same orientation.
#include "certify/witness.h"

#include <algorithm>
#include <cmath>

#include "exact/error_bounds.h"
#include "exact/predicates.h"

namespace kergen {

namespace {

constexpr uint32_t kNoFace = 0xffffffffu;

// Whether prepared face f lies in the plane of triangle t (exact coefficients `plane`) with the
// same inner side: its three representative corners on the plane (orient3d, exact) and its normal
// pointing the same way (exact dot product; coplanar normals are parallel).
bool face_in_plane(const PreparedMesh& mesh, uint32_t f, const std::array<uint32_t, 3>& t,
                   const PlaneCoef<Expansion>& plane) {
  const auto& r = mesh.rep[f];
  for (int k = 0; k < 3; ++k)
    if (orient3d(mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]), mesh.point(r[k]), mesh.exact_shift) != 0)
      return false;
  const PlaneCoef<Expansion> face = exact_plane(mesh.point(r[0]), mesh.point(r[1]), mesh.point(r[2]), mesh.exact_shift);
  return (plane.n[0] * face.n[0] + plane.n[1] * face.n[1] + plane.n[2] * face.n[2]).sign() > 0;
}

// For each plane of the conflict, the lowest-indexed prepared face lying in it (face_in_plane), in
// one pass over the faces. Most faces are told apart by a double filter: the plane's value at
// their first corner, certainly non-zero (value_error_bound; scaled points are below 1).
std::vector<uint32_t> first_faces_in_planes(const PreparedMesh& mesh,
                                            const std::vector<std::array<uint32_t, 3>>& conflict,
                                            const std::vector<PlaneCoef<Expansion>>& planes) {
  const size_t n = conflict.size();
  std::vector<PlaneCoef<Approx>> approx(n);
  std::vector<double> bound(n);
  for (size_t i = 0; i < n; ++i) {
    const auto& t = conflict[i];
    const PlaneCoef<Approx>& p = approx[i] = approx_plane(mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]));
    bound[i] = value_error_bound(p.n[0].v, p.n[1].v, p.n[2].v, p.d.v, p.n[0].e, p.n[1].e, p.n[2].e, p.d.e, 1, 0) *
               exact::kBoundScale;
  }
  std::vector<uint32_t> first(n, kNoFace);
  size_t missing = n;
  for (uint32_t f = 0; f < mesh.num_faces() && missing > 0; ++f) {
    const double* q = mesh.point(mesh.rep[f][0]);
    for (size_t i = 0; i < n; ++i) {
      if (first[i] != kNoFace) continue;
      const PlaneCoef<Approx>& p = approx[i];
      const double value = p.n[0].v * q[0] + p.n[1].v * q[1] + p.n[2].v * q[2] + p.d.v;
      if (std::fabs(value) > bound[i] || !face_in_plane(mesh, f, conflict[i], planes[i])) continue;
      first[i] = f;
      --missing;
    }
  }
  return first;
}

}  // namespace

std::vector<uint32_t> witness_faces(const PreparedMesh& mesh, const std::vector<std::array<uint32_t, 3>>& conflict) {
  if (conflict.size() < 2 || conflict.size() > 4) return {};
  std::vector<PlaneCoef<Expansion>> planes;
  for (const auto& t : conflict)
    planes.push_back(exact_plane(mesh.point(t[0]), mesh.point(t[1]), mesh.point(t[2]), mesh.exact_shift));
  if (!halfspaces_disjoint(planes.data(), planes.size())) return {};
  std::vector<uint32_t> faces = first_faces_in_planes(mesh, conflict, planes);
  if (std::find(faces.begin(), faces.end(), kNoFace) != faces.end()) return {};  // (never: each plane is a face's)
  std::sort(faces.begin(), faces.end());
  return faces;
}

}  // namespace kergen
