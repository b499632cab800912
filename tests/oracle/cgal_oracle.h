// Exact reference for the kernel of a closed polygon mesh, built on CGAL only (test and benchmark
// dependency; never part of the library). It shares no code with core/src: planes, orientation,
// emptiness and dimension are decided here from the input coordinates with exact arithmetic.
//
//   planes     one per face: exact normal = sum of the fan cross products of the face (= the
//              triangle's normal for triangles, the area-weighted normal for planar polygons),
//              computed in CGAL::Gmpzf from the input doubles (no rounding). Faces with a zero
//              normal are skipped (exactly collinear). Polygons whose vertices are not exactly
//              coplanar are fan-triangulated from their first vertex, one plane per triangle.
//              Orientation: if the exact enclosed volume is negative every plane is flipped.
//   verdict    exact LP (CGAL QP solver, Gmpzf): maximize t s.t. n_i.x + d_i + t*|n_i|_1 <= 0,
//              0 <= t <= 1. Infeasible => Empty; t* > 0 => Full (x* strictly interior);
//              t* = 0 => Flat (point, segment or polygon; no volume).
//   polyhedron for Full kernels: CGAL::halfspace_intersection_3 on Epeck with x* (or its double
//              rounding when that is still strictly interior, checked exactly) as origin. Vertices
//              are deduplicated exactly (CGAL repeats a degree-k vertex k-2 times); facets are the
//              planes whose facet has >= 3 distinct vertices; the volume is summed in double from
//              the exactly computed vertices (rounded once each), relative to the interior point.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "kergen/kergen.h"

namespace kergen_oracle {

enum class Verdict { Empty, Flat, Full };
const char* verdict_name(Verdict v);

struct OracleOptions {
  bool build_polyhedron = true;  // false: LP verdict only (no halfspace_intersection_3)
  // The faces as given are only half-spaces (each face's plane, inner side behind its
  // counter-clockwise front): no topology check and no orientation flip, so an open surface and
  // extra planes (boundary walls given as triangles) can be given. Non-planar polygons are split
  // as given.
  bool half_spaces_only = false;
};

struct OracleResult {
  bool ok = false;  // false: the oracle could not run (message says why)
  std::string message;
  Verdict verdict = Verdict::Empty;
  double t_star = 0;                 // LP optimum (double approximation)
  std::array<double, 3> interior{};  // Full: a strictly interior point (double approximation)
  bool flipped = false;              // enclosed volume was negative: planes flipped
  double shape_volume = 0;           // |enclosed volume| (double approximation of the exact sum)
  size_t faces = 0, degenerate_faces = 0, non_planar_faces = 0;
  size_t planes = 0;                // planes fed to the LP (one per face or fan triangle)
  size_t distinct_planes = 0;       // after exact deduplication (same oriented plane)
  bool has_polyhedron = false;      // Full and build_polyhedron
  double volume = 0;                // kernel volume (Full)
  size_t vertices = 0, facets = 0;  // distinct kernel vertices, kernel facets (Full)
  double ms_planes = 0, ms_lp = 0, ms_hull = 0;
};

OracleResult oracle_kernel(const kergen::Mesh& mesh, const OracleOptions& options = {});

// A non-star witness checked here, independently of the library: `faces` (indices into the
// mesh's faces) are at most four, the inner half-spaces of their planes have no common point
// (exact LP: infeasible), and without any one of the faces the others' have one (minimal).
// Planes as above: a planar face's exact normal, a non-planar face's split (it stands for one of
// its triangles' planes: some choice must pass), oriented by the exact enclosed volume.
struct WitnessCheck {
  bool ok = false;  // all of the above holds
  std::string message;
  size_t planes = 0;            // planes of the witness faces (all triangles of non-planar ones)
  size_t non_planar_faces = 0;  // witness faces that stand for their split's planes
};
WitnessCheck check_witness(const kergen::Mesh& mesh, const std::vector<uint32_t>& faces);

// Axis-aligned bounding-box diagonal of the mesh's vertices.
double bbox_diagonal(const kergen::Mesh& mesh);

}  // namespace kergen_oracle
