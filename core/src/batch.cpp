// KernelBatch and compute_kernels (batch.h): compute_kernel's pipeline, called from a per-thread
// object that keeps the pipeline's working memory (workspace.h) and fills the caller's Kernel in
// place.
#include "kergen/batch.h"

#include <utility>

#include "small/kernel_path.h"
#include "workspace.h"

namespace kergen {

struct KernelBatch::Workspace {
  KernelWorkspace kernel;
};

KernelBatch::KernelBatch() : workspace_(std::make_unique<Workspace>()) {}
KernelBatch::~KernelBatch() = default;
KernelBatch::KernelBatch(KernelBatch&&) noexcept = default;
KernelBatch& KernelBatch::operator=(KernelBatch&&) noexcept = default;

Kernel KernelBatch::compute(const MeshView& mesh, const Options& options) {
  Kernel result;
  compute(mesh, options, result);
  return result;
}

void KernelBatch::compute(const MeshView& mesh, const Options& options, Kernel& result) {
  if (!workspace_) workspace_ = std::make_unique<Workspace>();  // moved from: usable again
  compute_kernel_into(mesh, options, KernelPath::Auto, workspace_->kernel, result);
}

void KernelBatch::release() { workspace_ = std::make_unique<Workspace>(); }

void compute_kernels(const MeshView* meshes, size_t count, const Options& options, Kernel* results) {
  KernelBatch batch;
  for (size_t i = 0; i < count; ++i) batch.compute(meshes[i], options, results[i]);
}

}  // namespace kergen
