// cell_kernels.cpp — the kernel of each cell of a volume mesh (volume.h: compute_cell_kernels,
// cell_status_code): each cell's surface (cell_surface) through one KernelBatch (batch.h: the
// results of compute_kernel, without each call's set-up), one cell at a time, with the cell's
// diameter and the numbers derived from the kernel.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "kergen/batch.h"
#include "kergen/volume.h"

namespace kergen {

namespace {

// h: the largest distance between two of the cell's vertices (all pairs: cells have few).
double diameter(const Mesh& cell) {
  const size_t n = cell.num_vertices();
  const double* p = cell.positions.data();
  double best = 0;
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j) {
      const double dx = p[3 * i] - p[3 * j], dy = p[3 * i + 1] - p[3 * j + 1], dz = p[3 * i + 2] - p[3 * j + 2];
      best = std::max(best, dx * dx + dy * dy + dz * dz);
    }
  return std::sqrt(best);
}

// The range's entries of cell_offsets (each cell's own faces and face offsets are checked by
// cell_surface): a caller running many small ranges pays for its own cells only.
bool range_offsets_ok(const VolumeMesh& mesh, size_t first, size_t count, std::string& why) {
  if (!mesh.face_offsets.empty() && mesh.face_offsets[0] != 0) return why = "face_offsets[0] is not 0", false;
  if (mesh.cell_offsets.empty()) return true;
  if (mesh.cell_offsets[0] != 0) return why = "cell_offsets[0] is not 0", false;
  for (size_t i = first + 1; i <= first + count; ++i)
    if (mesh.cell_offsets[i] < mesh.cell_offsets[i - 1] || mesh.cell_offsets[i] > mesh.cell_faces.size())
      return why = "cell_offsets decrease or run past cell_faces at " + std::to_string(i), false;
  return true;
}

// compute_kernel's message without its closing advice about Options fields (weld, repair,
// allow_open, ...), which compute_cell_kernels does not take.
std::string without_option_advice(const std::string& message) {
  const size_t at = message.find("Options::");
  if (at == std::string::npos) return message;
  const size_t paren = message.rfind(" (", at), semicolon = message.rfind("; ", at);
  size_t cut = std::string::npos;
  if (paren != std::string::npos) cut = paren;
  if (semicolon != std::string::npos && (cut == std::string::npos || semicolon > cut)) cut = semicolon;
  return cut == std::string::npos ? message : message.substr(0, cut);
}

// `k` is the batch's reused result (its arrays keep their capacity from cell to cell).
CellKernel one_cell(const VolumeMesh& mesh, size_t cell, const Options& kernel_options, KernelBatch& batch, Kernel& k) {
  CellKernel out;
  CellSurface surface = cell_surface(mesh, cell);
  if (!surface.ok()) {
    out.error = surface.error;
    out.message = surface.message;
    return out;
  }
  out.diameter = diameter(surface.mesh);
  batch.compute(surface.mesh.view(), kernel_options, k);
  out.reoriented = surface.reoriented;
  for (Warning& w : k.warnings) {
    if (w.kind == Warning::Kind::OrientationFlipped)
      out.reoriented = true;
    else
      out.warnings.push_back(std::move(w));
  }
  if (!k.ok()) {
    out.error = k.error;
    out.message = "cell " + std::to_string(cell) + ": " + without_option_advice(k.message);
    return out;
  }
  out.type = k.type;
  out.kernel_volume = k.volume;
  out.cell_volume = k.shape_volume;
  out.kernel_ratio = k.volume_ratio;
  out.has_deepest_point = k.has_deepest_point;
  if (k.has_deepest_point) {
    out.deepest_point = k.deepest_point;
    out.inscribed_radius = k.inscribed_radius;
    out.rho_over_h = out.diameter > 0 ? k.inscribed_radius / out.diameter : 0;
  }
  if (!k.witness_faces.empty()) {
    out.witness_faces = k.witness_faces;
    const uint32_t base = mesh.cell_offsets[cell];
    for (uint32_t local : k.witness_faces) out.witness_global_faces.push_back(mesh.cell_faces[base + local]);
  }
  return out;
}

}  // namespace

int32_t cell_status_code(const CellKernel& cell) {
  return cell.ok() ? static_cast<int32_t>(cell.type) : -static_cast<int32_t>(cell.error);
}

CellKernels compute_cell_kernels(const VolumeMesh& mesh, const CellOptions& options, size_t first_cell, size_t count) {
  CellKernels out;
  const size_t cells = mesh.num_cells();
  if (first_cell > cells) {
    out.error = Error::InvalidArgument;
    out.message =
        "first cell " + std::to_string(first_cell) + " is past the mesh's " + std::to_string(cells) + " cells";
    return out;
  }
  count = std::min(count, cells - first_cell);
  std::string why;
  if (!range_offsets_ok(mesh, first_cell, count, why)) {
    out.error = Error::InvalidArgument;
    out.message = "malformed volume mesh: " + why;
    return out;
  }
  Options kernel_options;
  kernel_options.deepest_point = options.deepest_point;
  out.cells.reserve(count);
  KernelBatch batch;
  Kernel kernel;
  size_t reoriented = 0;
  const size_t every = std::max<size_t>(options.progress_every, 1);
  for (size_t i = 0; i < count; ++i) {
    out.cells.push_back(one_cell(mesh, first_cell + i, kernel_options, batch, kernel));
    reoriented += out.cells.back().reoriented;
    if (options.on_progress && ((i + 1) % every == 0 || i + 1 == count)) options.on_progress(i + 1, count);
  }
  if (reoriented > 0)
    out.warnings.push_back({Warning::Kind::OrientationFlipped, reoriented,
                            std::to_string(reoriented) + " cells had faces turned to face outward"});
  return out;
}

}  // namespace kergen
