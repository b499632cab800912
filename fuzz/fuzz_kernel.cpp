// libFuzzer target: compute_kernel on positions/indices decoded from the fuzz bytes.
//
// Input layout (every byte optional; missing bytes read as 0):
//   [0]    base mesh: one of a small generated set (convex, star-shaped non-convex, polygon/segment
//          kernels, not star-shaped, open, non-manifold, two components, flat, genus 1), or "raw":
//          vertices and faces read directly from the bytes (small-integer coordinates, so exact
//          coplanarity and degeneracy are common)
//   [1]    flags: flip orientation, shuffle faces, rotate loops, allow_open, deepest_point, from,
//          max_steps, scale after (instead of before) the perturbations
//   [2]    scale: 1, 1e-300, 1e300, 1e-150, 1e150, 1e-6, 1e6, or 2^(int8)
//   [3]    translation: 0, +-1e6, 1e-300, 0.5, 1e15, ...
//   [4..]  perturbations, 4 bytes each: (op, vertex, a, b): nudge a coordinate by a few ulps or by
//          2^-k of the extent, copy a coordinate from another vertex (coplanar faces), move a
//          vertex to the midpoint of two others (slivers, collinear corners) or onto another
//          (zero-area faces), set a coordinate to a special value (0, -0, subnormal, huge, NaN,
//          inf), swap two corners of a face, overwrite an index
// Every result must pass kfuzz::check_kernel. A complete run is repeated with another LP seed
// (the result must not depend on it) and compared with find_kernel_point.
#include <cstddef>
#include <cstdint>

#include "kernel_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  kfuzz::run_kernel_input(data, size);
  return 0;
}
