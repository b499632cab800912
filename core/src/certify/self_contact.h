// Exact test that a surface does not cross or touch itself, for the answers the embedding
// certificate (embedding.h) cannot give: flat kernels, unbounded kernels, open meshes (no kernel
// point sees every face strictly from its inner side) and find_kernel_point (which never has a
// point strictly inside the kernel).
//
// Every face is triangulated (a triangle as it is; a planar polygon by ear clipping in its plane,
// with exact in-plane orientations), a grid of the triangles' bounding boxes narrows the pairs,
// and each pair is decided with exact orient3d / orient2d signs. Two triangles may meet only where
// the mesh says they do: at a vertex id they share (and nowhere else), along an edge they share
// (and not folded onto each other). Any other common point, a crossing or a touch, is a contact.
// Positions that are equal under two vertex ids count as a touch: such a surface is not embedded.
#pragma once

#include <cstddef>
#include <cstdint>

#include "input/mesh_prep.h"

namespace kergen {

struct FaceContact {
  enum class Outcome {
    None,       // no two faces meet except at the vertices and edges they share
    Found,      // faces face_a and face_b (prepared faces) cross or touch
    Undecided,  // a polygon face could not be triangulated (not a simple polygon in its plane):
                // the test does not answer
  };
  Outcome outcome = Outcome::None;
  uint32_t face_a = 0, face_b = 0;
  uint32_t corner_a = 0, corner_b = 0;  // a vertex id of each of the two triangles that meet
};

// The first `num_faces` faces of `mesh` (all by default; boundary walls that follow a surface's own
// faces are left out). Expected O(faces) for well-spread meshes (each grid cell holds a few
// triangles); a polygon of k corners costs O(k^2) to triangulate.
FaceContact find_face_contact(const PreparedMesh& mesh, size_t num_faces);
inline FaceContact find_face_contact(const PreparedMesh& mesh) { return find_face_contact(mesh, mesh.num_faces()); }

}  // namespace kergen
