// Which path compute_kernel takes to the traced kernel: an internal switch, so that tests and
// the differential fuzzer can run the small-input path (small_kernel.h) and the general path
// (plane culling and tracing) on the same input and compare their answers. The answer never
// depends on it: only the time does.
#pragma once

#include "kergen/kergen.h"

namespace kergen {

enum class KernelPath {
  Auto,     // the small path up to kSmallPlaneLimit planes, the general one above (compute_kernel)
  General,  // always trace (plane culling, tracer)
  Small,    // clip whatever the number of planes (still never with step events, nor flat kernels)
};

struct KernelWorkspace;  // workspace.h

// compute_kernel(mesh, options) on `path`.
Kernel compute_kernel_on_path(const MeshView& mesh, const Options& options, KernelPath path);

// The same into `out` (every field overwritten, its arrays' capacity kept), with the working
// memory of `ws` (whose capacity is kept too): KernelBatch's call.
void compute_kernel_into(const MeshView& mesh, const Options& options, KernelPath path, KernelWorkspace& ws,
                         Kernel& out);

}  // namespace kergen
