// kergen batch — the kernels of many meshes, one after another, without paying each call's set-up.
//
// compute_kernel (kergen.h) allocates its working memory afresh on every call. On a small input
// (a polyhedral cell of a volume mesh, a few dozen faces) that set-up is a large part of the
// call. A KernelBatch keeps its working memory between calls, so that computing the kernels of
// a million cells costs their computation, not a million set-ups.
//
// Results: KernelBatch::compute(mesh, options) returns what compute_kernel(mesh, options) returns
// — the same status, message, kernel arrays in the same order, volume, witness, warnings — for
// every input and every option (Stats' times differ, being times). Reusing a batch never changes
// an answer: each call starts from a clean state; only memory capacity is carried over.
//
// Threads: a KernelBatch is used by one thread at a time (it is its working memory). Use one per
// thread to compute in parallel (the CLI's --jobs does so); different batches share nothing.
//
// Memory: a batch keeps about what its largest input needed until it is destroyed or release()d.
#pragma once

#include <cstddef>
#include <memory>

#include "kergen/kergen.h"

namespace kergen {

class KernelBatch {
 public:
  KernelBatch();
  ~KernelBatch();
  KernelBatch(KernelBatch&&) noexcept;
  KernelBatch& operator=(KernelBatch&&) noexcept;
  KernelBatch(const KernelBatch&) = delete;
  KernelBatch& operator=(const KernelBatch&) = delete;

  // The kernel of `mesh`, as compute_kernel(mesh, options) computes it.
  Kernel compute(const MeshView& mesh, const Options& options = {});

  // The same into `result`, whose every field is overwritten; its arrays keep their capacity, so
  // a caller that reuses one Kernel per batch allocates nothing for them after the first calls.
  void compute(const MeshView& mesh, const Options& options, Kernel& result);

  // Frees the memory kept between calls (the batch stays usable).
  void release();

 private:
  struct Workspace;
  std::unique_ptr<Workspace> workspace_;
};

// The kernels of `count` meshes with the same options, results[i] for meshes[i] (each as
// compute_kernel(meshes[i], options) computes it; a mesh's error is its own result's, the others
// are still computed). Runs on the calling thread, one KernelBatch for all: for several threads,
// give each its own KernelBatch and share out the meshes. `results` holds `count` Kernels
// (their arrays' capacity is reused).
void compute_kernels(const MeshView* meshes, size_t count, const Options& options, Kernel* results);

}  // namespace kergen
