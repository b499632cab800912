// What compute_kernel's pipeline can keep from one call to the next (KernelBatch keeps one per
// batch, kergen/batch.h; compute_kernel uses a fresh one): the small-input path's clipping
// arrays and the traced kernel's vertex and edge arrays. Their contents never carry over: each
// call overwrites them; only their capacity does.
#pragma once

#include "small/clip_polytope.h"
#include "solve/plane_culling.h"

namespace kergen {

struct KernelWorkspace {
  ClipPolytope clip;
  CulledTrace trace;
};

}  // namespace kergen
