// Embind bindings of kergen/batch.h for batch.js (computeKernels): a KernelBatch kept in the heap
// between the calls of one computeKernels run, and the kernels of a range of meshes per call.
// Registration and conversion only, as bindings.cpp; the meshes arrive as a table of addresses
// into heap blocks batch.js writes, the results leave as bindings.cpp's result blocks.
//
// Mesh table, u32 words per mesh (kMeshWords): positions address, number of position values,
// indices address, number of indices, face sizes address, number of face sizes (0: triangles),
// and the word the result block's address is written into (0: the block could not be allocated).
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cstdint>

#include "blocks.h"
#include "kergen/batch.h"

namespace {

// clang-format off
#define KERGEN_BATCH_ROW(X) \
  X(positions) X(numValues) X(indices) X(numIndices) X(faceSizes) X(numFaceSizes) X(result)
// clang-format on
enum MeshWord : uint32_t {
#define KERGEN_ENUM(name) k_##name,
  KERGEN_BATCH_ROW(KERGEN_ENUM)
#undef KERGEN_ENUM
      kMeshWords
};

kergen::MeshView table_view(const uint32_t* row) {
  kergen::MeshView m;
  m.positions = reinterpret_cast<const double*>(static_cast<uintptr_t>(row[k_positions]));
  m.num_vertices = row[k_numValues] / 3;
  m.indices = reinterpret_cast<const uint32_t*>(static_cast<uintptr_t>(row[k_indices]));
  m.num_indices = row[k_numIndices];
  if (row[k_numFaceSizes]) {
    m.face_sizes = reinterpret_cast<const uint32_t*>(static_cast<uintptr_t>(row[k_faceSizes]));
    m.num_faces = row[k_numFaceSizes];
  }
  return m;
}

// batchOpen() → the address of a new KernelBatch (0: out of memory).
uintptr_t batch_open() {
  auto* batch = new (std::nothrow) kergen::KernelBatch;
  return reinterpret_cast<uintptr_t>(batch);
}

void batch_close(uintptr_t batch) { delete reinterpret_cast<kergen::KernelBatch*>(batch); }

// batchCompute(batch, options, table, count): the kernel of each of the `count` meshes of the
// table with the options in the option slots at `options`, each result block's address written
// into its row (each mesh's error is its own block; the others are still computed).
void batch_compute(uintptr_t batch_address, uintptr_t options_address, uintptr_t table, uint32_t count) {
  auto& batch = *reinterpret_cast<kergen::KernelBatch*>(batch_address);
  const kergen::Options options = kergen_wasm::read_options(options_address);
  kergen::Kernel kernel;  // reused: KernelBatch::compute overwrites every field
  for (uint32_t i = 0; i < count; ++i) {
    uint32_t* row = reinterpret_cast<uint32_t*>(table) + i * kMeshWords;
    row[k_result] = static_cast<uint32_t>(kergen_wasm::guarded([&]() -> uintptr_t {
      batch.compute(table_view(row), options, kernel);
      return kergen_wasm::kernel_block(kernel);
    }));
  }
}

// The row layout batch.js reads: each word's index by name, and the words per row.
emscripten::val batch_wire_format() {
  emscripten::val w = emscripten::val::object();
#define KERGEN_PAIR(name) w.set(#name, static_cast<uint32_t>(k_##name));
  KERGEN_BATCH_ROW(KERGEN_PAIR)
#undef KERGEN_PAIR
  w.set("words", static_cast<uint32_t>(kMeshWords));
  return w;
}

}  // namespace

EMSCRIPTEN_BINDINGS(kergen_batch) {
  emscripten::function("batchOpen", &batch_open);
  emscripten::function("batchClose", &batch_close);
  emscripten::function("batchCompute", &batch_compute);
  emscripten::function("batchWireFormat", &batch_wire_format);
}
