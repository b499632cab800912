// libFuzzer target, differential: the small-input path (core/src/small/small_kernel.h: the kernel
// clipped from a box) against the general path (plane culling and tracing) on inputs decoded as
// fuzz_kernel decodes them (see fuzz_kernel.cpp for the byte layout). The small path is forced
// whatever the number of planes; both answers must pass kfuzz::check_kernel and agree: status,
// message, type, the kernel's vertices, edges, faces and their sources in the canonical order,
// the witness, and the volume and area (to the resolution of the vertex coordinates, ~2^-100 of
// their magnitude: their last bits may follow the planes a vertex was found on, see kergen.h).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "kernel_input.h"
#include "small/kernel_path.h"

namespace {

bool close(double a, double b, double resolution) {
  if (a == b || (std::isnan(a) && std::isnan(b))) return true;  // (an overflowing shape's NaN volumes)
  if (!std::isfinite(a) || !std::isfinite(b)) return false;
  return std::fabs(a - b) <= 1e-12 * std::max(std::fabs(a), std::fabs(b)) + resolution;
}

// The first field where the two paths' answers differ ("" when none).
std::string first_difference(const kergen::Kernel& a, const kergen::Kernel& b) {
  if (a.error != b.error || a.message != b.message) return "error";
  if (a.type != b.type || a.complete != b.complete) return "type";
  if (a.vertices != b.vertices || a.edges != b.edges) return "vertices or edges";
  if (a.face_indices != b.face_indices || a.face_sizes != b.face_sizes || a.triangles != b.triangles) return "faces";
  if (a.face_sources != b.face_sources) return "face sources";
  if (a.witness_faces != b.witness_faces || a.witness_boundary_edges != b.witness_boundary_edges) return "witness";
  if (a.has_kernel_point != b.has_kernel_point || a.kernel_point != b.kernel_point) return "kernel point";
  if (a.warnings.size() != b.warnings.size()) return "warnings";
  double extent = 0, magnitude = 0;
  for (size_t i = 0; i < a.vertices.size(); ++i) {
    magnitude = std::max(magnitude, std::fabs(a.vertices[i]));
    extent = std::max(extent, std::fabs(a.vertices[i] - a.vertices[i % 3]));
  }
  const double resolution = 1e-27 * double(a.triangles.size() / 3 + 1) * magnitude * 3 * extent * extent;
  if (!close(a.volume, b.volume, resolution) || !close(a.area, b.area, 1e-27 * magnitude * extent * 1e3) ||
      !close(a.shape_volume, b.shape_volume, 0))
    return "volume or area";
  return "";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  kfuzz::kernel_input::Bytes in{data, size};
  const kfuzz::DecodedInput d = kfuzz::decode_kernel_input(in);
  const kergen::MeshView view = d.mesh.view();
  if (std::getenv("KFUZZ_DUMP"))  // KFUZZ_DUMP=1 build-fuzz/fuzz/fuzz_small_path FILE: the decoded input as OFF
    std::fprintf(stderr, "# allow_open %d deepest %d from %d max_steps %llu\n%s", d.options.allow_open,
                 d.options.deepest_point, d.options.has_from, (unsigned long long)d.options.max_steps,
                 kergen::write_off(d.mesh).c_str());
  const kergen::Kernel small = kergen::compute_kernel_on_path(view, d.options, kergen::KernelPath::Small);
  kfuzz::check_kernel(view, small, d.options.allow_open, !d.stop_early);
  const kergen::Kernel general = kergen::compute_kernel_on_path(view, d.options, kergen::KernelPath::General);
  const std::string diff = first_difference(small, general);
  KFUZZ_CHECK(diff.empty(), "the small path differs from the general path in " + diff + " (" +
                                std::to_string(small.num_vertices()) + " vs " + std::to_string(general.num_vertices()) +
                                " vertices, types " + kergen::kernel_type_name(small.type) + " vs " +
                                kergen::kernel_type_name(general.type) + ")");
  return 0;
}
