// What stands behind each answer of compute_kernel and find_kernel_point once the LP has spoken.
// The intersection of the faces' inner half-spaces is the kernel only for a surface that bounds
// one solid, and validation cannot decide that alone (a surface may cross itself, or consist of
// pieces nested alike). So each answer has its certificate here:
// - EMPTY: input_witness names at most four input faces and boundary walls whose inner
//   half-spaces have no common point, checked exactly (witness.h), so that the answer can be
//   checked without the LP.
// - a kernel, mesh of several pieces: refuse_nested_shells. A point that sees every piece from
//   inside lies inside every piece: a second solid inside the first, which no solid's surface is.
// - a traced bounded full-dimensional kernel of a closed surface: certify_embedding, the ray
//   degree from a point inside it (embedding.h): 1 exactly when the surface is embedded. The
//   degree is the surface's winding number about the point, the same for every point inside the
//   kernel, so the point may come from the trace or from a few more LPs.
// - a flat or unbounded kernel, an open mesh, an undecided ray: certify_no_contact, the exact
//   test that no two faces meet away from the vertices and edges they share (self_contact.h);
//   there is no point strictly inside such a kernel to cast a ray from.
// - find_kernel_point's yes, which has no trace: certify_kernel_point, the ray degree from the
//   centroid of a few more LP vertices, else from the traced kernel's, else the contact test.
//   Both entry points try the same two points (in opposite orders), so they agree on every mesh.
// A failed certificate turns the answer into Error::SelfIntersection, its message saying where.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "input/mesh_prep.h"
#include "kergen/kergen.h"
#include "setup.h"
#include "solve/tracer.h"

namespace kergen {

// The witness of an empty kernel (witness.h): its faces as input face indices, increasing and
// distinct (the triangles of a split polygon are named by the polygon), and its boundary walls
// as the edges they stand on, (a, b) pairs of vertex ids (kergen.h). Both empty when there is
// no witness.
void input_witness(const Setup& s, std::vector<uint32_t>& faces, std::vector<uint32_t>& boundary_edges);

// Several pieces and a non-empty intersection of the faces' half-spaces: a point in it sees
// every piece from inside, so it lies inside every piece: they are nested alike (a second solid
// inside the first, not a void), which no solid's surface is. Sets the refusal.
void refuse_nested_shells(const PreparedMesh& m, Error& error, std::string& message);

// A surface whose kernel is not full-dimensional and bounded, or an open one, is answered only
// when no two of its faces meet away from the vertices and edges they share (self_contact.h):
// false, with the error set, when two do. Undecided (a polygon face that is not simple in its
// plane) leaves a warning instead: nothing was proved either way.
bool certify_no_contact(const Setup& s, Error& error, std::string& message, std::vector<Warning>& warnings);

// The traced kernel `tr`: a bounded, full-dimensional kernel of a closed surface by the ray
// degree from a point inside it (embedding.h; the traced kernel's, else LP vertices'), any other
// by certify_no_contact. False, with out.error and out.message set, when the surface crosses
// itself.
bool certify_embedding(const Setup& s, const Options& options, const TraceResult& tr, Kernel& out);

// find_kernel_point's certificate, without a trace (see certify.cpp). False, with r.error and
// r.message set, when the surface crosses itself.
bool certify_kernel_point(Setup& s, const Options& options, KernelPoint& r);

}  // namespace kergen
