// Embind bindings for the npm package `kergen-wasm`.
//
// This file only registers functions and converts values between JS and the C++ API in
// core/include/kergen/kergen.h; all geometry lives in the core. Every embind value (`val`) that
// crosses the boundary costs a JS<->wasm round trip (an object or a property set is several), which
// on small meshes cost as much as the computation, so data crosses as flat heap blocks instead:
//   - In: index.js mallocs one request block, copies the typed arrays into it (one memcpy-like
//     `set` each) and passes its address; the MeshView points into it (no copy here). Layout:
//     f64[kOptionSlots] options (NaN = not given), f64 positions, u32 indices, u32 face sizes.
//     readMesh's request is the file's bytes followed by the name's UTF-8 bytes.
//   - Out: one malloc'd result block (pack() below) that index.js copies into fresh JS typed
//     arrays and objects and frees, so JS never holds C++ objects and never calls delete().
//   - User errors cross as an error flag plus the core's error_name and message; no C++ exception
//     is thrown for bad input. An unexpected C++ exception is caught here and reported the same way
//     (OUT_OF_MEMORY for std::bad_alloc, otherwise INTERNAL_ERROR). A null result address means
//     the result block itself could not be allocated (out of memory).
//   - The step callback is a JS function called once per kergen::StepEvent with the address of a
//     StepOut on the stack (valid during the call); if it returns `false`, tracing stops (the
//     wrapper guarantees it never throws into C++). The progress callback gets the address of the
//     core's phase name (a static NUL-terminated string, so the names exist once, in the core)
//     and the count, as two numbers.
// index.js (writeRequest, readStep, readResult) reads and writes these layouts through wireFormat().
#include <emscripten/bind.h>
#include <emscripten/heap.h>
#include <emscripten/val.h>
#include <malloc.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <new>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "blocks.h"
#include "kergen/io.h"
#include "kergen/kergen.h"

using emscripten::val;

namespace {

// The wire format is declared once, here: each list below gives the enum used in this file and
// the layout object wireFormat() returns, which index.js reads at init() (it names fields, never
// offsets, and refuses a module whose layout lacks a field it uses).

// Request block options, f64 slots (NaN = not given: the core's default applies).
// clang-format off
#define KERGEN_OPTION_SLOTS(X) \
  X(fromX) X(fromY) X(fromZ) X(maxSteps) X(allowOpen) X(deepestPoint) X(maxFaces) X(maxVertices) \
  X(cullFaces) X(seed) X(weld) X(weldRelative) X(repair) X(openBoundary) X(flipFaces)
// clang-format on
enum Option : uint32_t {
#define KERGEN_ENUM(name) kOpt_##name,
  KERGEN_OPTION_SLOTS(KERGEN_ENUM)
#undef KERGEN_ENUM
      kOptionSlots
};

// Result block: u32 head[kHeadWords], f64 scalars[kScalars], f64 warning counts[head[numWarnings]],
// f64 vertices, u32 edges, face indices, face sizes, triangles, witness faces, i32 face sources,
// u32 witness boundary edges, u8 bytes (writeMesh's file), then
// the text: NUL-terminated UTF-8 strings: name (kernel status, "" for findPoint, or the error
// code), message ("" unless error), then kind and message of each warning.
// clang-format off
#define KERGEN_HEAD_WORDS(X) \
  X(ok) X(complete) X(hasKernelPoint) X(hasDeepestPoint) X(starShaped) X(numWarnings) X(textBytes) \
  X(numVertexValues) X(numEdgeValues) X(numFaceIndices) X(numFaces) X(numTriangleValues) \
  X(numWitnessFaces) X(numFaceSources) X(numWitnessBoundaryEdgeValues) X(numBytes)
// clang-format on
enum Head : uint32_t {
#define KERGEN_ENUM(name) kHead_##name,
  KERGEN_HEAD_WORDS(KERGEN_ENUM)
#undef KERGEN_ENUM
      kHeadWords
};
static_assert(kHeadWords % 2 == 0, "the f64 section after the head must stay 8-byte aligned");

// f64 scalars after the head: (name, number of values); stats holds kergen::stats_fields in order.
constexpr uint32_t kNumStats = std::tuple_size<decltype(kergen::stats_fields(kergen::Stats{}))>::value;
// clang-format off
#define KERGEN_SCALARS(X) \
  X(volume, 1) X(area, 1) X(shapeVolume, 1) X(volumeRatio, 1) X(kernelPoint, 3) X(deepestPoint, 3) \
  X(inscribedRadius, 1) X(stats, kNumStats)
// clang-format on
enum Scalar : uint32_t {
#define KERGEN_ENUM(name, width) kScalar_##name, kScalarLast_##name = kScalar_##name + (width)-1,
  KERGEN_SCALARS(KERGEN_ENUM)
#undef KERGEN_ENUM
      kScalars
};

// One step event as index.js reads it; kind 0 vertex, 1 edge, 2 face.
struct StepOut {
  uint32_t kind, id, a, b, loop, loop_size;
  double position[3];
};
static_assert(offsetof(StepOut, loop_size) == 20 && offsetof(StepOut, position) == 24, "layout read by index.js");
static_assert(static_cast<int>(kergen::StepEvent::Kind::Vertex) == 0 &&
                  static_cast<int>(kergen::StepEvent::Kind::Edge) == 1 &&
                  static_cast<int>(kergen::StepEvent::Kind::Face) == 2,
              "StepOut kinds");

// Codes index.js sends: readMesh/writeMesh formats (its FORMATS list) and kernel types (STATUSES).
static_assert(static_cast<int>(kergen::MeshFormat::Unknown) == 0 && static_cast<int>(kergen::MeshFormat::Off) == 1 &&
                  static_cast<int>(kergen::MeshFormat::Obj) == 2 && static_cast<int>(kergen::MeshFormat::Stl) == 3 &&
                  static_cast<int>(kergen::MeshFormat::Ply) == 4,
              "format codes of index.js");
static_assert(static_cast<int>(kergen::KernelType::Empty) == 0 && static_cast<int>(kergen::KernelType::Point) == 1 &&
                  static_cast<int>(kergen::KernelType::Segment) == 2 &&
                  static_cast<int>(kergen::KernelType::Polygon) == 3 &&
                  static_cast<int>(kergen::KernelType::Polyhedron) == 4 &&
                  static_cast<int>(kergen::KernelType::Unbounded) == 5,
              "kernel type codes of index.js (its STATUSES)");

// What goes into a result block; arrays stay owned by the caller until pack() has copied them
// (null = none). readMesh sends a mesh as vertices (positions), face indices and face sizes.
struct Out {
  uint32_t head[kHeadWords] = {};
  double scalars[kScalars] = {};
  const char* name = "";
  std::string message;
  const std::vector<kergen::Warning>* warnings = nullptr;
  const std::vector<double>* vertices = nullptr;
  const std::vector<uint32_t>* edges = nullptr;
  const std::vector<uint32_t>* face_indices = nullptr;
  const std::vector<uint32_t>* face_sizes = nullptr;
  const std::vector<uint32_t>* triangles = nullptr;
  const std::vector<uint32_t>* witness_faces = nullptr;
  const std::vector<int32_t>* face_sources = nullptr;
  const std::vector<uint32_t>* witness_boundary_edges = nullptr;
  const std::string* bytes = nullptr;

  void set_mesh(const kergen::Mesh& m) {
    vertices = &m.positions;
    face_indices = &m.indices;
    face_sizes = &m.face_sizes;
  }
  void set_kernel(const kergen::Kernel& k) {
    vertices = &k.vertices;
    edges = &k.edges;
    face_indices = &k.face_indices;
    face_sizes = &k.face_sizes;
    triangles = &k.triangles;
    witness_faces = &k.witness_faces;
    face_sources = &k.face_sources;
    witness_boundary_edges = &k.witness_boundary_edges;
  }
};

template <typename T>
char* put(char* at, const T* p, size_t n) {
  if (n) std::memcpy(at, p, n * sizeof(T));
  return at + n * sizeof(T);
}

// The result block (see Head); 0 when it cannot be allocated.
uintptr_t pack(Out& o) {
  static const std::vector<kergen::Warning> kNone;
  static const std::vector<double> kNoValues;
  static const std::vector<uint32_t> kNoIndices;
  static const std::vector<int32_t> kNoSources;
  static const std::string kNoBytes;
  const std::vector<kergen::Warning>& ws = o.warnings ? *o.warnings : kNone;
  const std::vector<double>& vertices = o.vertices ? *o.vertices : kNoValues;
  const std::vector<uint32_t>& edges = o.edges ? *o.edges : kNoIndices;
  const std::vector<uint32_t>& face_indices = o.face_indices ? *o.face_indices : kNoIndices;
  const std::vector<uint32_t>& face_sizes = o.face_sizes ? *o.face_sizes : kNoIndices;
  const std::vector<uint32_t>& triangles = o.triangles ? *o.triangles : kNoIndices;
  const std::vector<uint32_t>& witness_faces = o.witness_faces ? *o.witness_faces : kNoIndices;
  const std::vector<int32_t>& face_sources = o.face_sources ? *o.face_sources : kNoSources;
  const std::vector<uint32_t>& wall_edges = o.witness_boundary_edges ? *o.witness_boundary_edges : kNoIndices;
  const std::string& bytes_out = o.bytes ? *o.bytes : kNoBytes;

  std::string text = o.name;
  text += '\0';
  text += o.message;
  text += '\0';
  std::vector<double> counts(ws.size());
  for (size_t i = 0; i < ws.size(); ++i) {
    text += kergen::warning_kind_name(ws[i].kind);
    text += '\0';
    text += ws[i].message;
    text += '\0';
    counts[i] = static_cast<double>(ws[i].count);
  }
  o.head[kHead_numWarnings] = static_cast<uint32_t>(ws.size());
  o.head[kHead_textBytes] = static_cast<uint32_t>(text.size());
  o.head[kHead_numVertexValues] = static_cast<uint32_t>(vertices.size());
  o.head[kHead_numEdgeValues] = static_cast<uint32_t>(edges.size());
  o.head[kHead_numFaceIndices] = static_cast<uint32_t>(face_indices.size());
  o.head[kHead_numFaces] = static_cast<uint32_t>(face_sizes.size());
  o.head[kHead_numTriangleValues] = static_cast<uint32_t>(triangles.size());
  o.head[kHead_numWitnessFaces] = static_cast<uint32_t>(witness_faces.size());
  o.head[kHead_numFaceSources] = static_cast<uint32_t>(face_sources.size());
  o.head[kHead_numWitnessBoundaryEdgeValues] = static_cast<uint32_t>(wall_edges.size());
  o.head[kHead_numBytes] = static_cast<uint32_t>(bytes_out.size());

  const size_t bytes = sizeof o.head + sizeof o.scalars + 8 * (counts.size() + vertices.size()) +
                       4 * (edges.size() + face_indices.size() + face_sizes.size() + triangles.size() +
                            witness_faces.size() + face_sources.size() + wall_edges.size()) +
                       bytes_out.size() + text.size();
  char* block = static_cast<char*>(std::malloc(bytes));
  if (!block) return 0;
  char* at = put(block, o.head, kHeadWords);
  at = put(at, o.scalars, kScalars);
  at = put(at, counts.data(), counts.size());
  at = put(at, vertices.data(), vertices.size());
  at = put(at, edges.data(), edges.size());
  at = put(at, face_indices.data(), face_indices.size());
  at = put(at, face_sizes.data(), face_sizes.size());
  at = put(at, triangles.data(), triangles.size());
  at = put(at, witness_faces.data(), witness_faces.size());
  at = put(at, face_sources.data(), face_sources.size());
  at = put(at, wall_edges.data(), wall_edges.size());
  at = put(at, bytes_out.data(), bytes_out.size());
  put(at, text.data(), text.size());
  return reinterpret_cast<uintptr_t>(block);
}

// The request block as a MeshView (it points into the block, which index.js frees after the call).
kergen::MeshView mesh_view(uintptr_t request, uint32_t num_values, uint32_t num_indices, uint32_t num_face_sizes) {
  const double* positions = reinterpret_cast<const double*>(request) + kOptionSlots;
  const uint32_t* indices = reinterpret_cast<const uint32_t*>(positions + num_values);
  kergen::MeshView m;
  m.positions = positions;
  m.num_vertices = num_values / 3;
  m.indices = indices;
  m.num_indices = num_indices;
  if (num_face_sizes) {
    m.face_sizes = indices + num_indices;
    m.num_faces = num_face_sizes;
  }
  return m;
}

void put_stats(const kergen::Stats& s, double* out) {
  for (const kergen::StatsField& f : kergen::stats_fields(s)) *out++ = f.value;
}

void put_xyz(const std::array<double, 3>& p, double* out) {
  out[0] = p[0];
  out[1] = p[1];
  out[2] = p[2];
}

}  // namespace

// What batch_bindings.cpp shares (blocks.h).
namespace kergen_wasm {

uintptr_t error_block(const char* code, const std::string& message) {
  Out o;
  o.name = code;
  o.message = message;
  return pack(o);
}

kergen::Options read_options(uintptr_t request) {
  const double* slot = reinterpret_cast<const double*>(request);
  kergen::Options o;
  if (!std::isnan(slot[kOpt_fromX])) {
    o.has_from = true;
    o.from = {slot[kOpt_fromX], slot[kOpt_fromY], slot[kOpt_fromZ]};
  }
  if (!std::isnan(slot[kOpt_maxSteps])) o.max_steps = static_cast<uint64_t>(slot[kOpt_maxSteps]);
  if (!std::isnan(slot[kOpt_allowOpen])) o.allow_open = slot[kOpt_allowOpen] != 0;
  if (!std::isnan(slot[kOpt_deepestPoint])) o.deepest_point = slot[kOpt_deepestPoint] != 0;
  if (!std::isnan(slot[kOpt_maxFaces])) o.max_faces = static_cast<size_t>(slot[kOpt_maxFaces]);
  if (!std::isnan(slot[kOpt_maxVertices])) o.max_vertices = static_cast<size_t>(slot[kOpt_maxVertices]);
  if (!std::isnan(slot[kOpt_cullFaces])) o.cull_faces = slot[kOpt_cullFaces] != 0;
  if (!std::isnan(slot[kOpt_seed])) o.seed = static_cast<uint64_t>(slot[kOpt_seed]);
  if (!std::isnan(slot[kOpt_weld])) o.weld = slot[kOpt_weld];
  if (!std::isnan(slot[kOpt_weldRelative])) o.weld_relative = slot[kOpt_weldRelative] != 0;
  if (!std::isnan(slot[kOpt_repair])) o.repair = slot[kOpt_repair] != 0;
  if (!std::isnan(slot[kOpt_flipFaces])) o.flip_faces = slot[kOpt_flipFaces] != 0;
  // (index.js sends a code of wireFormat().openBoundaries, the enum's values in order)
  if (!std::isnan(slot[kOpt_openBoundary]))
    o.open_boundary = static_cast<kergen::OpenBoundary>(static_cast<int>(slot[kOpt_openBoundary]));
  return o;
}

uintptr_t kernel_block(const kergen::Kernel& k) {
  if (k.error != kergen::Error::Ok) return error_block(kergen::error_name(k.error), k.message);
  Out o;
  o.head[kHead_ok] = 1;
  o.head[kHead_complete] = k.complete;
  o.head[kHead_hasKernelPoint] = k.has_kernel_point;
  o.head[kHead_hasDeepestPoint] = k.has_deepest_point;
  o.scalars[kScalar_volume] = k.volume;
  o.scalars[kScalar_area] = k.area;
  o.scalars[kScalar_shapeVolume] = k.shape_volume;
  o.scalars[kScalar_volumeRatio] = k.volume_ratio;
  put_xyz(k.kernel_point, o.scalars + kScalar_kernelPoint);
  put_xyz(k.deepest_point, o.scalars + kScalar_deepestPoint);
  o.scalars[kScalar_inscribedRadius] = k.inscribed_radius;
  put_stats(k.stats, o.scalars + kScalar_stats);
  o.name = kergen::kernel_type_name(k.type);
  o.warnings = &k.warnings;
  o.set_kernel(k);
  return pack(o);
}

}  // namespace kergen_wasm

namespace {

using kergen_wasm::error_block;
using kergen_wasm::guarded;
using kergen_wasm::kernel_block;
using kergen_wasm::read_options;

// compute(request, numPositionValues, numIndices, numFaceSizes, onStep|null, onProgress|null)
// → result block address.
uintptr_t compute(uintptr_t request, uint32_t num_values, uint32_t num_indices, uint32_t num_face_sizes, val on_step,
                  val on_progress) {
  return guarded([&]() -> uintptr_t {
    kergen::Options options = read_options(request);
    if (!on_progress.isNull() && !on_progress.isUndefined()) {
      options.on_progress = [&on_progress](const kergen::Progress& p) {
        on_progress(reinterpret_cast<uintptr_t>(kergen::progress_phase_name(p.phase)), static_cast<double>(p.count));
      };
    }
    if (!on_step.isNull() && !on_step.isUndefined()) {
      options.on_step = [&on_step](const kergen::StepEvent& e) -> bool {
        StepOut s{static_cast<uint32_t>(e.kind),
                  e.id,
                  e.a,
                  e.b,
                  static_cast<uint32_t>(reinterpret_cast<uintptr_t>(e.loop)),
                  e.loop_size,
                  {e.position[0], e.position[1], e.position[2]}};
        return !on_step(reinterpret_cast<uintptr_t>(&s)).isFalse();
      };
    }
    return kernel_block(kergen::compute_kernel(mesh_view(request, num_values, num_indices, num_face_sizes), options));
  });
}

// findPoint(request, numPositionValues, numIndices, numFaceSizes) → result block address
// (starShaped, the point in the kernel point slots, witness faces and boundary edges, warnings).
uintptr_t find_point(uintptr_t request, uint32_t num_values, uint32_t num_indices, uint32_t num_face_sizes) {
  return guarded([&]() -> uintptr_t {
    const kergen::KernelPoint p =
        kergen::find_kernel_point(mesh_view(request, num_values, num_indices, num_face_sizes), read_options(request));
    if (p.error != kergen::Error::Ok) return error_block(kergen::error_name(p.error), p.message);
    Out o;
    o.head[kHead_ok] = 1;
    o.head[kHead_starShaped] = p.star_shaped;
    o.head[kHead_hasKernelPoint] = p.star_shaped;
    put_xyz(p.point, o.scalars + kScalar_kernelPoint);
    o.witness_faces = &p.witness_faces;
    o.witness_boundary_edges = &p.witness_boundary_edges;
    o.warnings = &p.warnings;
    return pack(o);
  });
}

// readMesh(request, numBytes, numNameBytes, format) → result block address: the mesh as vertices
// (positions), face indices and face sizes (none = all triangles), or the reader's error.
uintptr_t read_mesh(uintptr_t request, uint32_t num_bytes, uint32_t num_name_bytes, uint32_t format) {
  return guarded([&]() -> uintptr_t {
    const char* bytes = reinterpret_cast<const char*>(request);
    const kergen::ReadResult r =
        kergen::read_mesh(std::string_view(bytes, num_bytes), static_cast<kergen::MeshFormat>(format),
                          std::string(bytes + num_bytes, num_name_bytes));
    if (!r.ok()) return error_block(kergen::error_name(r.error), r.message);
    Out o;
    o.head[kHead_ok] = 1;
    o.set_mesh(r.mesh);
    return pack(o);
  });
}

// writeMesh(request, numPositionValues, numIndices, numFaceSizes, format, kernelType) → result
// block address with the file's bytes. The request is compute's (options unused). kernelType -1:
// a plain mesh; otherwise the kergen::KernelType of a kernel result whose vertices and faces the
// request holds, written as kergen::kernel_mesh makes it.
uintptr_t write_mesh(uintptr_t request, uint32_t num_values, uint32_t num_indices, uint32_t num_face_sizes,
                     uint32_t format, int32_t kernel_type) {
  return guarded([&]() -> uintptr_t {
    const kergen::MeshView v = mesh_view(request, num_values, num_indices, num_face_sizes);
    kergen::Mesh mesh;
    std::vector<uint32_t> face_sizes(v.face_sizes, v.face_sizes + v.num_faces);
    if (kernel_type >= 0) {
      kergen::Kernel k;
      k.type = static_cast<kergen::KernelType>(kernel_type);
      k.vertices.assign(v.positions, v.positions + num_values);
      k.face_indices.assign(v.indices, v.indices + v.num_indices);
      k.face_sizes = std::move(face_sizes);
      mesh = kergen::kernel_mesh(k);
    } else {
      mesh.positions.assign(v.positions, v.positions + num_values);
      mesh.indices.assign(v.indices, v.indices + v.num_indices);
      mesh.face_sizes = std::move(face_sizes);
    }
    Out o;
    o.head[kHead_ok] = 1;
    const std::string file = kergen::write_mesh(mesh, static_cast<kergen::MeshFormat>(format));
    o.bytes = &file;
    return pack(o);
  });
}

// repair(request, numPositionValues, numIndices, numFaceSizes) → result block address: the mesh
// kergen::repair_mesh returns as vertices (positions), face indices and face sizes, with its
// warnings; the name slot holds validation's verdict on it (error_name: "OK", "OPEN_MESH", ...) and
// the message slot its message. An error block when the input is malformed (no mesh to return).
uintptr_t repair(uintptr_t request, uint32_t num_values, uint32_t num_indices, uint32_t num_face_sizes) {
  return guarded([&]() -> uintptr_t {
    const kergen::RepairedMesh r =
        kergen::repair_mesh(mesh_view(request, num_values, num_indices, num_face_sizes), read_options(request));
    if (r.mesh.num_faces() == 0) return error_block(kergen::error_name(r.error), r.message);
    Out o;
    o.head[kHead_ok] = 1;
    o.name = kergen::error_name(r.error);
    o.message = r.message;
    o.warnings = &r.warnings;
    o.set_mesh(r.mesh);
    return pack(o);
  });
}

// Heap figures for leak tests and diagnostics: { heapSize: bytes of wasm memory,
// heapUsed: bytes currently allocated by malloc }.
val memory_stats() {
  const struct mallinfo mi = mallinfo();
  val r = val::object();
  r.set("heapSize", static_cast<double>(emscripten_get_heap_size()));
  r.set("heapUsed", static_cast<double>(mi.uordblks));
  return r;
}

// The layout object index.js reads at init(): every list above by name, the step event's byte
// offsets, the names the codes in the blocks stand for, and the face source marks (kergen.h;
// scripts/build-wasm.sh writes them into dist/constants.js, which the package exports).
val wire_format() {
  auto fields = [](std::initializer_list<std::pair<const char*, uint32_t>> list, const char* count_name,
                   uint32_t count) {
    val o = val::object();
    for (const auto& [name, value] : list) o.set(name, value);
    o.set(count_name, count);
    return o;
  };
  val w = val::object();
#define KERGEN_PAIR(name) {#name, kOpt_##name},
  w.set("option", fields({KERGEN_OPTION_SLOTS(KERGEN_PAIR)}, "slots", kOptionSlots));
#undef KERGEN_PAIR
#define KERGEN_PAIR(name) {#name, kHead_##name},
  w.set("head", fields({KERGEN_HEAD_WORDS(KERGEN_PAIR)}, "words", kHeadWords));
#undef KERGEN_PAIR
#define KERGEN_PAIR(name, width) {#name, kScalar_##name},
  w.set("scalar", fields({KERGEN_SCALARS(KERGEN_PAIR)}, "count", kScalars));
#undef KERGEN_PAIR
  w.set("step", fields({{"kind", offsetof(StepOut, kind)},
                        {"id", offsetof(StepOut, id)},
                        {"a", offsetof(StepOut, a)},
                        {"b", offsetof(StepOut, b)},
                        {"loop", offsetof(StepOut, loop)},
                        {"loopSize", offsetof(StepOut, loop_size)},
                        {"position", offsetof(StepOut, position)}},
                       "bytes", sizeof(StepOut)));
  val stats = val::array();
  for (const kergen::StatsField& f : kergen::stats_fields(kergen::Stats{}))
    stats.call<void>("push", std::string(f.name));
  w.set("stats", stats);
  val kinds = val::array();  // StepOut.kind values 0, 1, 2 (static_assert above)
  for (const char* k : {"vertex", "edge", "face"}) kinds.call<void>("push", std::string(k));
  w.set("stepKinds", kinds);
  val words = val::array();  // [library name, JS name] of each option (kergen::option_names)
  for (const kergen::OptionName& o : kergen::option_names()) {
    val pair = val::array();
    pair.call<void>("push", std::string("Options::") + o.field);
    pair.call<void>("push", std::string(o.js));
    words.call<void>("push", pair);
  }
  w.set("optionWords", words);
  val statuses = val::array();
  for (int t = 0; t <= static_cast<int>(kergen::KernelType::Unbounded); ++t)
    statuses.call<void>("push", std::string(kergen::kernel_type_name(static_cast<kergen::KernelType>(t))));
  w.set("statuses", statuses);
  val open_boundaries = val::array();  // the codes of the openBoundary slot
  for (int o = 0; o <= static_cast<int>(kergen::OpenBoundary::Perpendicular); ++o)
    open_boundaries.call<void>("push", std::string(kergen::open_boundary_name(static_cast<kergen::OpenBoundary>(o))));
  w.set("openBoundaries", open_boundaries);
  val face_source = val::object();  // Kernel::face_sources values that name no input face
  face_source.set("box", kergen::kFaceSourceBox);
  face_source.set("wall", kergen::kFaceSourceWall);
  w.set("faceSource", face_source);
  return w;
}

}  // namespace

EMSCRIPTEN_BINDINGS(kergen) {
  emscripten::function("compute", &compute);
  emscripten::function("findPoint", &find_point);
  emscripten::function("readMesh", &read_mesh);
  emscripten::function("writeMesh", &write_mesh);
  emscripten::function("repair", &repair);
  emscripten::function("memoryStats", &memory_stats);
  emscripten::function("wireFormat", &wire_format);
}
