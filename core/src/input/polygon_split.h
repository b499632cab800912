// Splitting a polygon face that is not exactly planar into triangles (prepare_mesh's non-planar
// faces): ear clipping in a projection, then flips of inward folds.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace kergen {

// The loop's Newell normal (its area vector, times 2), in double.
std::array<double, 3> newell_normal(const std::vector<double>& pts, const uint32_t* loop, size_t k);

// Triangles of a polygon that is not exactly planar (often: planar up to rounding, e.g. after a
// rotation). Convex polygons get a fan from their first corner; non-convex ones are ear-clipped
// in the projection along the dominant axis of n, the loop's Newell normal (along_normal: along
// n itself), which keeps every triangle oriented like the polygon (a fan would fold over a
// reflex corner and invert planes): the best-shaped ear first up to 128 corners, the first ear
// found above. What is left when no ear is found (self-overlapping input) or the work budget is
// spent is fanned, and *gave_up says so. Then, up to 128 corners, inward folds are flipped
// outward where they can be. ("Convex" and the ears are judged in the same projection.)
std::vector<std::array<uint32_t, 3>> triangulate_polygon(const std::vector<double>& pts, const uint32_t* loop, size_t k,
                                                         const std::array<double, 3>& n, int exact_shift,
                                                         bool along_normal, bool* gave_up);

// Why the split of a non-planar polygon would give a plane facing into the solid, or nullptr.
// Every triangle of the split must face like the loop's area vector n (its Newell normal), or
// stand edge-on to it: the triangles' area vectors add up to n, so one clearly against it means
// the loop crosses itself or turns back there (a bowtie, a fold), and that triangle's plane faces
// into the solid. Compared along n itself, not in a coordinate projection: a simple loop far from
// planar may cross itself seen along a coordinate axis. The dot products are in double with an
// error bound, so only a triangle certainly against n refuses the face. The planar counterpart
// is check_planar_corner in mesh_prep.cpp.
const char* split_folds_over(const std::vector<double>& pts, const std::array<double, 3>& n,
                             const std::vector<std::array<uint32_t, 3>>& tris);

}  // namespace kergen
