// Certificate that a surface with a full-dimensional kernel does not cross itself.
//
// From a point p strictly inside the kernel every face is seen from its inner side, so the
// radial projection of the surface from p onto a sphere around it is a (branched) covering; it is
// one-to-one, and the surface therefore embedded and star-shaped about p, exactly when its degree
// is 1: when a ray from p in a generic direction crosses the surface once. The crossings are
// decided with exact orient3d signs; a ray that meets an edge or a vertex exactly is replaced by
// one in another direction. A surface that crosses itself away from shared vertices (overlapping
// shells exported as one mesh, a surface wound twice around a point) is otherwise accepted by
// validation, and the intersection of its face half-spaces is not its kernel.
#pragma once

#include <cstddef>
#include <vector>

#include "exact/plane_store.h"
#include "input/mesh_prep.h"
#include "solve/tracer.h"

namespace kergen {

struct EmbeddingCheck {
  enum class Outcome {
    Embedded,       // degree 1
    CrossesItself,  // degree != 1: the ray from `point` crosses the surface `crossings` times
    Undecided,      // no point strictly inside the kernel could be found in double precision
                    // (a kernel thinner than the rounding of its vertices' centroid), or every
                    // ray tried met an edge or a vertex
  };
  Outcome outcome = Outcome::Undecided;
  long crossings = 0;           // the degree: signed crossings (each +1 for a face seen from inside)
  double point[3] = {0, 0, 0};  // p, in the mesh's scaled units
};

// `kernel`: the complete trace of a bounded, full-dimensional kernel of `mesh`'s planes `ps`.
EmbeddingCheck check_embedding(const PreparedMesh& mesh, const PlaneSet& ps, const TraceResult& kernel);

// The same certificate from a point p (scaled units; snapped like the traced kernel's) that the
// caller found without a trace: Undecided unless p lies strictly inside every plane of `planes`
// (exact signs), which must then be all the kernel's planes.
EmbeddingCheck check_embedding_at(const PreparedMesh& mesh, const PlaneSet& ps, const std::vector<uint32_t>& planes,
                                  const double p[3]);

// The same from a point p (scaled units; snapped like the others) without planes: Undecided
// unless p lies strictly inside the plane of every face of `mesh` (its representative triangle,
// exact signs). For a surface whose kernel is not known yet (convex_answer.h).
EmbeddingCheck check_embedding_in_faces(const PreparedMesh& mesh, const double p[3]);

}  // namespace kergen
