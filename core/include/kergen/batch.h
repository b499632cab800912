// kergen batch — the kernels of many meshes, one after another (the cells of a polyhedral volume
// mesh: millions of inputs of a few dozen faces each).
//
// A KernelBatch is the per-thread state of such a loop: the place where working memory is kept
// from one call to the next. It keeps the small-input path's clipping arrays and the traced
// kernel's vertex and edge arrays, and compute(mesh, options, result) fills `result` in place,
// reusing the capacity of its arrays (vertices, edges, faces, triangles, face sources, witness,
// warnings): over many cells those stop being allocated once they have grown to the largest
// kernel seen. The input's preparation and plane classes are still allocated per call (on a
// cell, heap allocation was about 5 % of the instructions of a call; bench/README.md has the
// profile). Code that computes many kernels through it gets whatever later versions keep
// without changing.
//
// Results: KernelBatch::compute(mesh, options) returns what compute_kernel(mesh, options) returns
// — the same status, message, kernel arrays (in the canonical order of kergen.h), volume, witness,
// warnings — for every input and every option (Stats' times differ, being times). Reusing a batch
// never changes an answer: each call starts from a clean state.
//
// Threads: a KernelBatch is used by one thread at a time. Use one per thread to compute in
// parallel (the CLI's --jobs does so); different batches share nothing.
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

  // The same into `result`, whose every field is overwritten.
  void compute(const MeshView& mesh, const Options& options, Kernel& result);

  // Frees the memory the batch keeps between calls (the batch stays usable; a `result` passed
  // to compute keeps its own arrays).
  void release();

 private:
  struct Workspace;
  std::unique_ptr<Workspace> workspace_;
};

// The kernels of `count` meshes with the same options, results[i] for meshes[i] (each as
// compute_kernel(meshes[i], options) computes it; a mesh's error is its own result's, the others
// are still computed). Runs on the calling thread, one KernelBatch for all: for several threads,
// give each its own KernelBatch and share out the meshes. `results` holds `count` Kernels.
void compute_kernels(const MeshView* meshes, size_t count, const Options& options, Kernel* results);

}  // namespace kergen
