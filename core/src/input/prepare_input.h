// The input as the kernel sees it, before any plane: Options::weld and Options::repair (weld.h,
// repair.h) when the input allows them, then validation (mesh_prep.h), with a verdict on a mesh
// of several closed pieces (shells.h). Shared by every entry point, so that compute_kernel,
// find_kernel_point, validate_mesh and repair_mesh judge the same mesh.
#pragma once

#include "input/mesh_prep.h"
#include "kergen/kergen.h"

namespace kergen {

// prepare_mesh after Options::weld and Options::repair: the prepared mesh of the welded (and
// repaired) input, what was done reported first among its warnings and the dropped faces
// counted with the input's. `validated`, when given, receives the mesh prepare_mesh judged (the
// welded and repaired one, or a copy of the input; left empty for malformed input, which
// validation refuses). OpenBoundary::Perpendicular accepts open meshes as allow_open does.
// PrepareFor::Verdict: only the verdict is needed (mesh_prep.h; validate_mesh).
PreparedMesh prepare_input(const MeshView& mesh, const Options& options, Mesh* validated = nullptr,
                           PrepareFor purpose = PrepareFor::Faces);

// `mesh` without the vertices no face uses, the others renumbered in their order (the mesh that
// repair_mesh returns: the merged vertices of a weld are left unused).
Mesh without_unused_vertices(Mesh mesh);

}  // namespace kergen
