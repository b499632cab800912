// libFuzzer target: KernelBatch (kergen/batch.h) on a sequence of up to four inputs decoded as
// fuzz_kernel decodes one, each computed by one batch into one reused Kernel, forwards and then
// backwards: every result must pass kfuzz::check_kernel and equal compute_kernel's field by field
// (Stats' times aside), whatever the batch computed before.
//
// Input layout: [0] the number of inputs (1 + byte % 4); the rest split into that many equal
// parts, each one fuzz_kernel input (see fuzz_kernel.cpp).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "kergen/batch.h"
#include "kernel_input.h"

namespace {

// The first field where a and b differ ("" when none).
std::string first_difference(const kergen::Kernel& a, const kergen::Kernel& b) {
  if (a.error != b.error || a.message != b.message) return "error";
  if (a.type != b.type || a.complete != b.complete) return "type";
  if (a.vertices != b.vertices || a.edges != b.edges) return "vertices or edges";
  if (a.face_indices != b.face_indices || a.face_sizes != b.face_sizes || a.triangles != b.triangles) return "faces";
  if (a.face_sources != b.face_sources) return "face sources";
  if (a.witness_faces != b.witness_faces || a.witness_boundary_edges != b.witness_boundary_edges) return "witness";
  if (a.volume != b.volume || a.area != b.area || a.shape_volume != b.shape_volume || a.volume_ratio != b.volume_ratio)
    return "volume or area";
  if (a.has_kernel_point != b.has_kernel_point || a.kernel_point != b.kernel_point) return "kernel point";
  if (a.has_deepest_point != b.has_deepest_point || a.deepest_point != b.deepest_point ||
      a.inscribed_radius != b.inscribed_radius)
    return "deepest point";
  if (a.warnings.size() != b.warnings.size()) return "warnings";
  for (size_t i = 0; i < a.warnings.size(); ++i)
    if (a.warnings[i].kind != b.warnings[i].kind || a.warnings[i].count != b.warnings[i].count ||
        a.warnings[i].message != b.warnings[i].message)
      return "warnings";
  if (a.stats.distinct_planes != b.stats.distinct_planes || a.stats.active_planes != b.stats.active_planes)
    return "plane counts";
  return "";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const size_t count = 1 + data[0] % 4, part = (size - 1) / count;
  std::vector<kfuzz::DecodedInput> inputs;
  for (size_t i = 0; i < count; ++i) {
    kfuzz::kernel_input::Bytes in{data + 1 + i * part, part};
    inputs.push_back(kfuzz::decode_kernel_input(in));
  }
  std::vector<kergen::Kernel> expected;
  for (const auto& d : inputs) expected.push_back(kergen::compute_kernel(d.mesh.view(), d.options));
  kergen::KernelBatch batch;
  kergen::Kernel reused;
  for (int round = 0; round < 2; ++round)
    for (size_t j = 0; j < count; ++j) {
      const size_t i = round == 0 ? j : count - 1 - j;
      const kfuzz::DecodedInput& d = inputs[i];
      batch.compute(d.mesh.view(), d.options, reused);
      kfuzz::check_kernel(d.mesh.view(), reused, d.options.allow_open, !d.stop_early);
      const std::string diff = first_difference(reused, expected[i]);
      KFUZZ_CHECK(diff.empty(), "KernelBatch differs from compute_kernel in " + diff + " (input " + std::to_string(i) +
                                    ", round " + std::to_string(round) + ")");
    }
  return 0;
}
