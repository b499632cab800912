// Embind bindings of polyhedral volume meshes (core/include/kergen/volume.h) for wasm/cells.js.
//
// As in bindings.cpp, data crosses as flat heap blocks, never as embind objects:
//   - A *volume*: a kergen::VolumeMesh kept in the heap between calls (read from a file's bytes or
//     built from JS arrays), so that JS can compute the cells' kernels range by range (reporting
//     progress between ranges) without copying the mesh again. cells.js opens one per call and
//     closes it in a `finally`: JS never keeps a C++ object beyond the call that made it.
//   - Every entry returns one malloc'd result block (cells.js copies it out and frees it):
//     u32 head[kCellHeadWords] (ok, volume address, text bytes, then the length of each array),
//     the f64 arrays in the order of KERGEN_CELL_F64, the u32 arrays in the order of
//     KERGEN_CELL_U32 (`status` holds int32 values), then NUL-terminated strings: the error code
//     and message ("" when ok), the message of each cell in `errorCells`, then kind and message of
//     each warning (their counts are the f64 array `warningCounts`).
//   - User errors cross as ok = 0 with the core's error_name and message; an unexpected C++
//     exception is caught and reported the same way (OUT_OF_MEMORY, INTERNAL_ERROR). A null block
//     means the block itself could not be allocated.
// cellWireFormat() names every list below; cells.js reads the layout by those names.
#include <emscripten/bind.h>
#include <emscripten/val.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <limits>
#include <new>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "blocks.h"
#include "kergen/kergen.h"
#include "kergen/volume.h"

using emscripten::val;

namespace {

// clang-format off
#define KERGEN_CELL_F64(X) \
  X(positions) X(kernelVolume) X(cellVolume) X(kernelRatio) X(diameter) X(inscribedRadius) X(rhoOverH) \
  X(deepestPoints) X(warningCounts) X(summary)
#define KERGEN_CELL_U32(X) \
  X(faceIndices) X(faceOffsets) X(cellFaces) X(cellOffsets) X(status) X(reoriented) X(witnessOffsets) \
  X(witnessFaces) X(witnessGlobalFaces) X(errorCells) X(faceSizes) X(globalVertices) X(summaryErrors) \
  X(worstCells)
#define KERGEN_CELL_HEAD(X) X(ok) X(volume) X(textBytes) X(numWarnings)
// The summary's f64 values (kergen::CellSummary), in order; byType is one value per KernelType.
#define KERGEN_CELL_SUMMARY(X) \
  X(cells, 1) X(okCells, 1) X(byType, 6) X(reorientedCells, 1) X(minRatio, 1) X(medianRatio, 1) X(maxRatio, 1) \
  X(hasRhoOverH, 1) X(minRhoOverH, 1) X(medianRhoOverH, 1) X(maxRhoOverH, 1)
// clang-format on

enum F64 : uint32_t {
#define KERGEN_ENUM(name) kF64_##name,
  KERGEN_CELL_F64(KERGEN_ENUM)
#undef KERGEN_ENUM
      kF64Arrays
};
enum U32 : uint32_t {
#define KERGEN_ENUM(name) kU32_##name,
  KERGEN_CELL_U32(KERGEN_ENUM)
#undef KERGEN_ENUM
      kU32Arrays
};
enum Head : uint32_t {
#define KERGEN_ENUM(name) kHead_##name,
  KERGEN_CELL_HEAD(KERGEN_ENUM)
#undef KERGEN_ENUM
      kFixedHeadWords
};
// The head: the fixed words, then the length of each f64 array, then of each u32 array (even, so
// the f64 arrays after it stay 8-byte aligned).
constexpr uint32_t kCellHeadWords = (kFixedHeadWords + kF64Arrays + kU32Arrays + 1) / 2 * 2;
enum Summary : uint32_t {
#define KERGEN_ENUM(name, width) kSum_##name, kSumLast_##name = kSum_##name + (width)-1,
  KERGEN_CELL_SUMMARY(KERGEN_ENUM)
#undef KERGEN_ENUM
      kSummaryValues
};
static_assert(kSumLast_byType - kSum_byType + 1 == static_cast<int>(kergen::KernelType::Unbounded) + 1,
              "one byType value per KernelType");
static_assert(static_cast<int>(kergen::VolumeFormat::Unknown) == 0 &&
                  static_cast<int>(kergen::VolumeFormat::Vtu) == 1 &&
                  static_cast<int>(kergen::VolumeFormat::VtkLegacy) == 2 &&
                  static_cast<int>(kergen::VolumeFormat::NodeEle) == 3,
              "the codes of cellWireFormat().formats");

// A volume mesh kept between calls, with the records of the cells computed on it so far (for the
// summary, which the core computes over them).
struct Volume {
  kergen::VolumeMesh mesh;
  std::vector<kergen::CellKernel> records;
  size_t first_cell = 0;  // the cell of records[0]
};

struct CellOut {
  uint32_t head[kCellHeadWords] = {};
  std::vector<double> f64[kF64Arrays];
  std::vector<uint32_t> u32[kU32Arrays];
  std::vector<std::string> strings{"", ""};  // error code, message, then the rest
};

uintptr_t pack(CellOut& o) {
  size_t bytes = sizeof o.head;
  for (uint32_t a = 0; a < kF64Arrays; ++a) {
    o.head[kFixedHeadWords + a] = static_cast<uint32_t>(o.f64[a].size());
    bytes += 8 * o.f64[a].size();
  }
  for (uint32_t a = 0; a < kU32Arrays; ++a) {
    o.head[kFixedHeadWords + kF64Arrays + a] = static_cast<uint32_t>(o.u32[a].size());
    bytes += 4 * o.u32[a].size();
  }
  std::string text;
  for (const std::string& s : o.strings) {
    text += s;
    text += '\0';
  }
  o.head[kHead_textBytes] = static_cast<uint32_t>(text.size());
  char* block = static_cast<char*>(std::malloc(bytes + text.size()));
  if (!block) return 0;
  char* at = block;
  std::memcpy(at, o.head, sizeof o.head);
  at += sizeof o.head;
  for (const auto& a : o.f64) {
    if (!a.empty()) std::memcpy(at, a.data(), 8 * a.size());
    at += 8 * a.size();
  }
  for (const auto& a : o.u32) {
    if (!a.empty()) std::memcpy(at, a.data(), 4 * a.size());
    at += 4 * a.size();
  }
  std::memcpy(at, text.data(), text.size());
  return reinterpret_cast<uintptr_t>(block);
}

uintptr_t error_block(const char* code, const std::string& message) {
  CellOut o;
  o.strings = {code, message};
  return pack(o);
}

// The blocks' guard (blocks.h) with this file's error_block().
template <class Body>
uintptr_t guarded(Body&& body) {
  return kergen_wasm::guarded_with(error_block, std::forward<Body>(body));
}

void put_mesh_arrays(const kergen::VolumeMesh& m, CellOut& o) {
  o.f64[kF64_positions] = m.positions;
  o.u32[kU32_faceIndices] = m.face_indices;
  o.u32[kU32_faceOffsets] = m.face_offsets;
  o.u32[kU32_cellFaces] = m.cell_faces;
  o.u32[kU32_cellOffsets] = m.cell_offsets;
}

// Hands the volume to JS (its address in the head) or, when JS did not ask to keep it, deletes it.
uintptr_t finish_volume(Volume* volume, bool keep, bool want_arrays) {
  CellOut o;
  o.head[kHead_ok] = 1;
  if (want_arrays) put_mesh_arrays(volume->mesh, o);
  if (keep) o.head[kHead_volume] = static_cast<uint32_t>(reinterpret_cast<uintptr_t>(volume));
  const uintptr_t block = pack(o);
  if (!keep || !block) delete volume;
  return block;
}

// volumeRead(request, numBytes, numNameBytes, format, numEleBytes, numEleNameBytes, keep, wantArrays)
// → block. The request holds the file's bytes, its name, then (format NodeEle) the .ele file's
// bytes and name. keep: the volume stays in the heap (its address in the head) for volumeCells.
uintptr_t volume_read(uintptr_t request, uint32_t num_bytes, uint32_t num_name, uint32_t format, uint32_t num_ele,
                      uint32_t num_ele_name, bool keep, bool want_arrays) {
  return guarded([&]() -> uintptr_t {
    const char* at = reinterpret_cast<const char*>(request);
    const std::string_view bytes(at, num_bytes);
    const std::string name(at + num_bytes, num_name);
    const char* ele = at + num_bytes + num_name;
    kergen::VolumeReadResult r = static_cast<kergen::VolumeFormat>(format) == kergen::VolumeFormat::NodeEle
                                     ? kergen::read_node_ele(bytes, std::string_view(ele, num_ele), name,
                                                             std::string(ele + num_ele, num_ele_name))
                                     : kergen::read_volume_mesh(bytes, static_cast<kergen::VolumeFormat>(format), name);
    if (!r.ok()) return error_block(kergen::error_name(r.error), r.message);
    Volume* volume = new Volume;
    volume->mesh = std::move(r.mesh);
    return finish_volume(volume, keep, want_arrays);
  });
}

// volumeFromArrays(request, numPositionValues, numFaceIndices, numFaceOffsets, numCellFaces,
// numCellOffsets) → block with the volume's address. The request: f64 positions, then the u32
// arrays in that order. The offsets are checked by the core (compute_cell_kernels, cell_surface).
uintptr_t volume_from_arrays(uintptr_t request, uint32_t num_values, uint32_t num_face_indices,
                             uint32_t num_face_offsets, uint32_t num_cell_faces, uint32_t num_cell_offsets) {
  return guarded([&]() -> uintptr_t {
    const double* positions = reinterpret_cast<const double*>(request);
    const uint32_t* at = reinterpret_cast<const uint32_t*>(positions + num_values);
    Volume* volume = new Volume;
    kergen::VolumeMesh& m = volume->mesh;
    auto take = [&at](std::vector<uint32_t>& out, uint32_t n) {
      out.assign(at, at + n);
      at += n;
    };
    m.positions.assign(positions, positions + num_values);
    take(m.face_indices, num_face_indices);
    take(m.face_offsets, num_face_offsets);
    take(m.cell_faces, num_cell_faces);
    take(m.cell_offsets, num_cell_offsets);
    return finish_volume(volume, true, false);
  });
}

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The records of one range as arrays (one value per cell; deepestPoints three, NaN without one).
void put_records(const std::vector<kergen::CellKernel>& cells, size_t first_cell, CellOut& o) {
  o.u32[kU32_witnessOffsets].push_back(0);
  for (size_t i = 0; i < cells.size(); ++i) {
    const kergen::CellKernel& c = cells[i];
    o.u32[kU32_status].push_back(static_cast<uint32_t>(kergen::cell_status_code(c)));
    o.u32[kU32_reoriented].push_back(c.reoriented ? 1 : 0);
    o.f64[kF64_kernelVolume].push_back(c.kernel_volume);
    o.f64[kF64_cellVolume].push_back(c.cell_volume);
    o.f64[kF64_kernelRatio].push_back(c.kernel_ratio);
    o.f64[kF64_diameter].push_back(c.diameter);
    o.f64[kF64_inscribedRadius].push_back(c.inscribed_radius);
    o.f64[kF64_rhoOverH].push_back(c.rho_over_h);
    for (int k = 0; k < 3; ++k) o.f64[kF64_deepestPoints].push_back(c.has_deepest_point ? c.deepest_point[k] : kNaN);
    auto& local = o.u32[kU32_witnessFaces];
    local.insert(local.end(), c.witness_faces.begin(), c.witness_faces.end());
    auto& global = o.u32[kU32_witnessGlobalFaces];
    global.insert(global.end(), c.witness_global_faces.begin(), c.witness_global_faces.end());
    o.u32[kU32_witnessOffsets].push_back(static_cast<uint32_t>(local.size()));
    if (!c.ok()) {
      o.u32[kU32_errorCells].push_back(static_cast<uint32_t>(first_cell + i));
      o.strings.push_back(c.message);
    }
  }
}

void put_warnings(const std::vector<kergen::Warning>& warnings, CellOut& o) {
  o.head[kHead_numWarnings] = static_cast<uint32_t>(warnings.size());
  for (const kergen::Warning& w : warnings) {
    o.f64[kF64_warningCounts].push_back(static_cast<double>(w.count));
    o.strings.push_back(kergen::warning_kind_name(w.kind));
    o.strings.push_back(w.message);
  }
}

// volumeCells(volume, firstCell, count, deepestPoint) → block with the records of cells firstCell ..
// firstCell + count - 1 (clipped to the mesh), kept in the volume for volumeSummary.
uintptr_t volume_cells(uintptr_t volume_address, double first_cell, double count, bool deepest_point) {
  return guarded([&]() -> uintptr_t {
    Volume* volume = reinterpret_cast<Volume*>(volume_address);
    kergen::CellOptions options;
    options.deepest_point = deepest_point;
    kergen::CellKernels r = kergen::compute_cell_kernels(volume->mesh, options, static_cast<size_t>(first_cell),
                                                         static_cast<size_t>(count));
    if (!r.ok()) return error_block(kergen::error_name(r.error), r.message);
    CellOut o;
    o.head[kHead_ok] = 1;
    put_records(r.cells, static_cast<size_t>(first_cell), o);
    put_warnings(r.warnings, o);
    if (volume->records.empty()) volume->first_cell = static_cast<size_t>(first_cell);
    for (kergen::CellKernel& c : r.cells) volume->records.push_back(std::move(c));
    return pack(o);
  });
}

// The summary's block (KERGEN_CELL_SUMMARY in f64 `summary`, `summaryErrors`, `worstCells`).
uintptr_t summary_block(const kergen::CellSummary& s) {
  CellOut o;
  o.head[kHead_ok] = 1;
  std::vector<double>& v = o.f64[kF64_summary];
  v.assign(kSummaryValues, 0);
  v[kSum_cells] = static_cast<double>(s.cells);
  v[kSum_okCells] = static_cast<double>(s.ok_cells);
  for (size_t t = 0; t < s.by_type.size(); ++t) v[kSum_byType + t] = static_cast<double>(s.by_type[t]);
  v[kSum_reorientedCells] = static_cast<double>(s.reoriented_cells);
  v[kSum_minRatio] = s.min_ratio;
  v[kSum_medianRatio] = s.median_ratio;
  v[kSum_maxRatio] = s.max_ratio;
  v[kSum_hasRhoOverH] = s.has_rho_over_h ? 1 : 0;
  v[kSum_minRhoOverH] = s.min_rho_over_h;
  v[kSum_medianRhoOverH] = s.median_rho_over_h;
  v[kSum_maxRhoOverH] = s.max_rho_over_h;
  for (const auto& [error, n] : s.by_error) {
    o.u32[kU32_summaryErrors].push_back(static_cast<uint32_t>(error));
    o.u32[kU32_summaryErrors].push_back(static_cast<uint32_t>(n));
  }
  for (size_t c : s.worst_cells) o.u32[kU32_worstCells].push_back(static_cast<uint32_t>(c));
  return pack(o);
}

// volumeSummary(volume, worst) → the summary block of every cell volumeCells computed on this
// volume (kergen::summarize_cells).
uintptr_t volume_summary(uintptr_t volume_address, uint32_t worst) {
  return guarded([&]() -> uintptr_t {
    const Volume* volume = reinterpret_cast<const Volume*>(volume_address);
    return summary_block(kergen::summarize_cells(volume->records, worst, volume->first_cell));
  });
}

// cellSummaryOf(request, numCells, firstCell, worst) → the summary block of records given as
// arrays (cells computed in parts, by several workers, joined): the request holds f64
// kernelRatio[n], rhoOverH[n], the deepest points' x[n] (NaN: none), then i32 status[n] and u32
// reoriented[n]: the fields kergen::summarize_cells reads, each record rebuilt from them.
uintptr_t cell_summary_of(uintptr_t request, uint32_t num_cells, double first_cell, uint32_t worst) {
  return guarded([&]() -> uintptr_t {
    const double* ratio = reinterpret_cast<const double*>(request);
    const double* rho_over_h = ratio + num_cells;
    const double* deepest_x = rho_over_h + num_cells;
    const int32_t* status = reinterpret_cast<const int32_t*>(deepest_x + num_cells);
    const uint32_t* reoriented = reinterpret_cast<const uint32_t*>(status + num_cells);
    std::vector<kergen::CellKernel> records(num_cells);
    for (uint32_t i = 0; i < num_cells; ++i) {
      kergen::CellKernel& c = records[i];
      // cell_status_code: the KernelType value, or minus the Error value.
      if (status[i] >= 0)
        c.type = static_cast<kergen::KernelType>(status[i]);
      else
        c.error = static_cast<kergen::Error>(-status[i]);
      c.kernel_ratio = ratio[i];
      c.rho_over_h = rho_over_h[i];
      c.has_deepest_point = !std::isnan(deepest_x[i]);
      c.reoriented = reoriented[i] != 0;
    }
    return summary_block(kergen::summarize_cells(records, worst, static_cast<size_t>(first_cell)));
  });
}

// volumeCellSurface(volume, cell) → block: the cell as a surface (kergen::cell_surface): positions,
// faceIndices, faceSizes, globalVertices, and reoriented (one value).
uintptr_t volume_cell_surface(uintptr_t volume_address, double cell) {
  return guarded([&]() -> uintptr_t {
    const Volume* volume = reinterpret_cast<const Volume*>(volume_address);
    const kergen::CellSurface s = kergen::cell_surface(volume->mesh, static_cast<size_t>(cell));
    if (!s.ok()) return error_block(kergen::error_name(s.error), s.message);
    CellOut o;
    o.head[kHead_ok] = 1;
    o.f64[kF64_positions] = s.mesh.positions;
    o.u32[kU32_faceIndices] = s.mesh.indices;
    o.u32[kU32_faceSizes] = s.mesh.face_sizes;
    o.u32[kU32_globalVertices] = s.global_vertices;
    o.u32[kU32_reoriented] = {s.reoriented ? 1u : 0u};
    return pack(o);
  });
}

void volume_close(uintptr_t volume_address) { delete reinterpret_cast<Volume*>(volume_address); }

// The layout cells.js reads: every list above by name, the format codes, and the names of the
// status codes (kernel types at their values, errors at minus their values).
val cell_wire_format() {
  val w = val::object();
  val head = val::object();
#define KERGEN_PAIR(name) head.set(#name, static_cast<uint32_t>(kHead_##name));
  KERGEN_CELL_HEAD(KERGEN_PAIR)
#undef KERGEN_PAIR
  head.set("words", kCellHeadWords);
  head.set("arrays", static_cast<uint32_t>(kFixedHeadWords));
  w.set("head", head);
  auto names = [](std::initializer_list<const char*> list) {
    val a = val::array();
    for (const char* n : list) a.call<void>("push", std::string(n));
    return a;
  };
#define KERGEN_NAME(name) #name,
  w.set("f64", names({KERGEN_CELL_F64(KERGEN_NAME)}));
  w.set("u32", names({KERGEN_CELL_U32(KERGEN_NAME)}));
#undef KERGEN_NAME
  val summary = val::object();
#define KERGEN_PAIR(name, width) summary.set(#name, static_cast<uint32_t>(kSum_##name));
  KERGEN_CELL_SUMMARY(KERGEN_PAIR)
#undef KERGEN_PAIR
  summary.set("count", static_cast<uint32_t>(kSummaryValues));
  w.set("summary", summary);
  w.set("formats", names({"", "vtu", "vtk", "node-ele"}));  // kergen::VolumeFormat codes
  val types = val::array();
  for (int t = 0; t <= static_cast<int>(kergen::KernelType::Unbounded); ++t)
    types.call<void>("push", std::string(kergen::kernel_type_name(static_cast<kergen::KernelType>(t))));
  w.set("kernelTypes", types);
  val errors = val::array();  // kergen::Error names at their values (the last one is SelfIntersection)
  for (int e = 0; e <= static_cast<int>(kergen::Error::SelfIntersection); ++e)
    errors.call<void>("push", std::string(kergen::error_name(static_cast<kergen::Error>(e))));
  w.set("errors", errors);
  return w;
}

}  // namespace

EMSCRIPTEN_BINDINGS(kergen_cells) {
  emscripten::function("volumeRead", &volume_read);
  emscripten::function("volumeFromArrays", &volume_from_arrays);
  emscripten::function("volumeCells", &volume_cells);
  emscripten::function("volumeSummary", &volume_summary);
  emscripten::function("cellSummaryOf", &cell_summary_of);
  emscripten::function("volumeCellSurface", &volume_cell_surface);
  emscripten::function("volumeClose", &volume_close);
  emscripten::function("cellWireFormat", &cell_wire_format);
}
