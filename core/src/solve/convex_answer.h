// The convex answer: a closed surface that bounds a convex solid is its own kernel (every face
// plane holds the solid on its inner side, and the kernel lies inside the solid), so its
// kernel needs no LP and no trace, only the solid's own vertices, edges and faces: O(n).
//
// The certificate, all exact: every edge of the surface is convex or flat (orient3d of the
// neighbouring faces' corners against each face's plane), a point lies strictly inside every
// face's plane, and the ray degree from it is 1 (embedding.h: the surface is embedded and
// star-shaped about it). An embedded closed surface that is locally convex along every edge is
// locally convex everywhere, and a connected, closed, locally convex set is convex (Tietze,
// Nakajima). A surface wound twice around the point, or folded flat onto itself, fails the
// degree or the strict test, and goes the traced way, which explains its refusal.
#pragma once

#include <cstdint>

#include "input/mesh_prep.h"
#include "setup.h"
#include "solve/tracer.h"

namespace kergen {

// Whether `mesh` (closed, one piece, validated) passes the certificate above. Cheap to refuse:
// the first reflex edge ends it. Conservative: a mesh whose faces were split or dropped (its
// face pairs then miss edges), or with a polygon pair too large to compare corner by corner,
// takes the traced way.
bool convex_solid(const PreparedMesh& mesh);

// The kernel of a mesh that passed convex_solid, as the trace would give it: its vertices are
// the mesh's corners on three or more distinct face planes (input points, exact), its edges the
// chains of mesh edges between two distinct planes, each with its two planes (s.face_plane holds
// every prepared face's plane class: coplanar neighbours are one face). Tight sets hold exactly
// the planes through each vertex, edges are oriented like the tracer's (direction n_p x n_q, p
// the plane whose faces run along it from a to b). False when the surface does not have that
// structure (not expected after the certificate: reported as an internal error).
bool convex_trace(const Setup& s, TraceResult& out);

// The vertex of `tr` extreme in direction `dir` (exact comparisons; the first of exact ties):
// the vertex the LP would start from, so compute_kernel's kernel_point is the same either way.
uint32_t extreme_vertex(const TraceResult& tr, const PlaneSet& ps, const double dir[3]);

}  // namespace kergen
