// Welding: merging vertices closer than a tolerance (Options::weld) before validation, so that
// a triangle soup (an unindexed STL, a three.js geometry) or a mesh whose seams were written with
// slightly different coordinates becomes the closed surface it describes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "kergen/kergen.h"

namespace kergen {

struct WeldResult {
  Mesh mesh;                          // the welded mesh: the input's positions, faces renumbered
  size_t merged_vertices = 0;         // vertices that took another's place
  size_t dropped_faces = 0;           // faces left with fewer than three distinct corners
  double tolerance = 0;               // the distance used (absolute)
  std::vector<uint32_t> source_face;  // the input face of each face of `mesh` (increasing)
  // Nothing merged and no face changed: `mesh` and `source_face` are left empty (the input is
  // the welded mesh; no copy of it is made).
  bool unchanged = false;
};

// Vertices within `tolerance` of each other (Euclidean; relative: in units of the bounding box
// diagonal) are merged transitively, each group into its lowest-indexed vertex, whose input
// position it keeps (no coordinate is computed, so exactness downstream is unaffected). Equal
// consecutive corners of a face collapse into one. `mesh` must have finite coordinates and
// indices in range (checked by the caller). O(n) expected (a grid of cells of the tolerance's
// size, searched in two levels: weld.cpp); when no vertex merges and no face changes, the result
// is `unchanged` and holds no copy of the input.
WeldResult weld_vertices(const MeshView& mesh, double tolerance, bool relative);

// The group of each of the n points (xyz), by the lowest-indexed point it is merged with (itself
// if none); `tolerance` absolute and finite, 0 for equal positions only. Two points are merged
// when their distance, computed in double, is at most the tolerance and the cubic cells of the
// tolerance's size that hold them (floor(x / tolerance) per axis) are equal or adjacent; groups
// close transitively. What weld_vertices renumbers the faces by.
std::vector<uint32_t> weld_groups(const double* positions, size_t n, double tolerance);

}  // namespace kergen
