// Embind bindings for the npm package `kergen-wasm`.
//
// This file only registers functions and converts values between JS and the C++ API in
// core/include/kergen/kergen.h; all geometry lives in the core. Conventions:
//   - Arrays in: JS typed arrays (or plain arrays) are copied into std::vectors
//     (convertJSArrayToNumberVector). The JS wrapper (index.js) checks shapes and types first.
//   - Arrays out: copied into fresh JS typed arrays (a bare typed_memory_view would alias the wasm
//     heap and die when it grows), so JS never holds C++ objects and never calls delete().
//   - User errors cross the boundary as a status string (`error`, the core's error_name) plus a
//     message; no C++ exception is thrown for bad input. An unexpected C++ exception (e.g.
//     std::bad_alloc) is caught here and reported the same way with code "INTERNAL_ERROR".
//   - The step callback is a JS function called once per kergen::StepEvent; if it returns the
//     value `false`, tracing stops (the wrapper guarantees it never throws into C++).
#include <emscripten/bind.h>
#include <emscripten/heap.h>
#include <emscripten/val.h>
#include <malloc.h>

#include <cstdint>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "kergen/kergen.h"

using emscripten::val;

namespace {

val to_f64(const std::vector<double>& v) {
  return val::global("Float64Array").new_(emscripten::typed_memory_view(v.size(), v.data()));
}

val to_u32(const std::vector<uint32_t>& v) {
  return val::global("Uint32Array").new_(emscripten::typed_memory_view(v.size(), v.data()));
}

val to_xyz(const std::array<double, 3>& p) {
  val a = val::array();
  a.set(0, p[0]);
  a.set(1, p[1]);
  a.set(2, p[2]);
  return a;
}

const char* warning_kind_name(kergen::Warning::Kind k) {
  switch (k) {
    case kergen::Warning::Kind::OrientationFlipped: return "ORIENTATION_FLIPPED";
    case kergen::Warning::Kind::DegenerateFacesDropped: return "DEGENERATE_FACES_DROPPED";
    case kergen::Warning::Kind::NonPlanarFacesSplit: return "NON_PLANAR_FACES_SPLIT";
    case kergen::Warning::Kind::UnusedVertices: return "UNUSED_VERTICES";
  }
  return "UNKNOWN";
}

val to_warnings(const std::vector<kergen::Warning>& ws) {
  val out = val::array();
  for (size_t i = 0; i < ws.size(); ++i) {
    val w = val::object();
    w.set("kind", std::string(warning_kind_name(ws[i].kind)));
    w.set("count", static_cast<double>(ws[i].count));
    w.set("message", ws[i].message);
    out.set(i, w);
  }
  return out;
}

val error_result(const char* code, const std::string& message) {
  val r = val::object();
  r.set("error", std::string(code));
  r.set("message", message);
  return r;
}

// Owns the converted input; view() points into it.
struct Input {
  std::vector<double> positions;
  std::vector<uint32_t> indices;
  std::vector<uint32_t> face_sizes;

  kergen::MeshView view() const {
    kergen::MeshView m;
    m.positions = positions.data();
    m.num_vertices = positions.size() / 3;
    m.indices = indices.data();
    m.num_indices = indices.size();
    if (!face_sizes.empty()) {
      m.face_sizes = face_sizes.data();
      m.num_faces = face_sizes.size();
    }
    return m;
  }
};

Input read_input(const val& positions, const val& indices, const val& face_sizes) {
  Input in;
  in.positions = emscripten::convertJSArrayToNumberVector<double>(positions);
  in.indices = emscripten::convertJSArrayToNumberVector<uint32_t>(indices);
  if (!face_sizes.isUndefined() && !face_sizes.isNull()) {
    in.face_sizes = emscripten::convertJSArrayToNumberVector<uint32_t>(face_sizes);
  }
  return in;
}

bool has(const val& obj, const char* key) {
  val v = obj[key];
  return !v.isUndefined() && !v.isNull();
}

// Options object from JS: { from?: [x,y,z], onStep?: function, maxSteps?: number,
// allowOpen?: boolean, deepestPoint?: boolean, maxFaces?: number, maxVertices?: number }.
kergen::Options read_options(const val& opts) {
  kergen::Options o;
  if (opts.isUndefined() || opts.isNull()) return o;
  if (has(opts, "from")) {
    val f = opts["from"];
    o.has_from = true;
    o.from = {f[0].as<double>(), f[1].as<double>(), f[2].as<double>()};
  }
  if (has(opts, "maxSteps")) o.max_steps = static_cast<uint64_t>(opts["maxSteps"].as<double>());
  if (has(opts, "allowOpen")) o.allow_open = opts["allowOpen"].as<bool>();
  if (has(opts, "deepestPoint")) o.deepest_point = opts["deepestPoint"].as<bool>();
  if (has(opts, "maxFaces")) o.max_faces = static_cast<size_t>(opts["maxFaces"].as<double>());
  if (has(opts, "maxVertices")) o.max_vertices = static_cast<size_t>(opts["maxVertices"].as<double>());
  if (has(opts, "onStep")) {
    val cb = opts["onStep"];
    o.on_step = [cb](const kergen::StepEvent& e) -> bool {
      val ev = val::object();
      switch (e.kind) {
        case kergen::StepEvent::Kind::Vertex:
          ev.set("type", std::string("vertex"));
          ev.set("id", e.id);
          ev.set("position", to_xyz(e.position));
          break;
        case kergen::StepEvent::Kind::Edge:
          ev.set("type", std::string("edge"));
          ev.set("id", e.id);
          ev.set("a", e.a);
          ev.set("b", e.b);
          break;
        case kergen::StepEvent::Kind::Face: {
          ev.set("type", std::string("face"));
          ev.set("id", e.id);
          val loop = val::array();
          for (uint32_t i = 0; i < e.loop_size; ++i) loop.set(i, e.loop[i]);
          ev.set("loop", loop);
          break;
        }
      }
      return !cb(ev).isFalse();
    };
  }
  return o;
}

val to_stats(const kergen::Stats& s) {
  val o = val::object();
  o.set("inputVertices", static_cast<double>(s.input_vertices));
  o.set("inputFaces", static_cast<double>(s.input_faces));
  o.set("droppedFaces", static_cast<double>(s.dropped_faces));
  o.set("distinctPlanes", static_cast<double>(s.distinct_planes));
  o.set("activePlanes", static_cast<double>(s.active_planes));
  o.set("tracedLines", static_cast<double>(s.traced_lines));
  o.set("exactFallbacks", static_cast<double>(s.exact_fallbacks));
  o.set("msValidate", s.ms_validate);
  o.set("msPlanes", s.ms_planes);
  o.set("msLp", s.ms_lp);
  o.set("msTrace", s.ms_trace);
  o.set("msAssemble", s.ms_assemble);
  o.set("msTotal", s.ms_total);
  return o;
}

// compute(positions, indices, faceSizes|null, options|undefined) → plain object.
// On error: { error: "OPEN_MESH", message }. On success: { status, complete, vertices, edges,
// faceIndices, faceSizes, triangles, volume, ..., warnings, stats } (the wrapper splits faces).
val compute(val positions, val indices, val face_sizes, val opts) {
  try {
    const Input in = read_input(positions, indices, face_sizes);
    const kergen::Options options = read_options(opts);
    const kergen::Kernel k = kergen::compute_kernel(in.view(), options);
    if (k.error != kergen::Error::Ok) return error_result(kergen::error_name(k.error), k.message);

    val r = val::object();
    r.set("status", std::string(kergen::kernel_type_name(k.type)));
    r.set("complete", k.complete);
    r.set("vertices", to_f64(k.vertices));
    r.set("edges", to_u32(k.edges));
    r.set("faceIndices", to_u32(k.face_indices));
    r.set("faceSizes", to_u32(k.face_sizes));
    r.set("triangles", to_u32(k.triangles));
    r.set("volume", k.volume);
    r.set("area", k.area);
    r.set("shapeVolume", k.shape_volume);
    r.set("volumeRatio", k.volume_ratio);
    r.set("kernelPoint", k.has_kernel_point ? to_xyz(k.kernel_point) : val::null());
    r.set("deepestPoint", k.has_deepest_point ? to_xyz(k.deepest_point) : val::null());
    r.set("inscribedRadius", k.inscribed_radius);
    r.set("warnings", to_warnings(k.warnings));
    r.set("stats", to_stats(k.stats));
    return r;
  } catch (const std::bad_alloc&) {
    return error_result("OUT_OF_MEMORY", "out of memory (the wasm heap is limited to 4 GB)");
  } catch (const std::exception& e) {
    return error_result("INTERNAL_ERROR", std::string("internal error: ") + e.what());
  }
}

// findPoint(positions, indices, faceSizes|null, options|undefined) → { starShaped, point, warnings }
// or { error, message }.
val find_point(val positions, val indices, val face_sizes, val opts) {
  try {
    const Input in = read_input(positions, indices, face_sizes);
    kergen::Options options = read_options(opts);
    options.on_step = nullptr;
    const kergen::KernelPoint p = kergen::find_kernel_point(in.view(), options);
    if (p.error != kergen::Error::Ok) return error_result(kergen::error_name(p.error), p.message);
    val r = val::object();
    r.set("starShaped", p.star_shaped);
    r.set("point", p.star_shaped ? to_xyz(p.point) : val::null());
    r.set("warnings", to_warnings(p.warnings));
    return r;
  } catch (const std::bad_alloc&) {
    return error_result("OUT_OF_MEMORY", "out of memory (the wasm heap is limited to 4 GB)");
  } catch (const std::exception& e) {
    return error_result("INTERNAL_ERROR", std::string("internal error: ") + e.what());
  }
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

}  // namespace

EMSCRIPTEN_BINDINGS(kergen) {
  emscripten::function("compute", &compute);
  emscripten::function("findPoint", &find_point);
  emscripten::function("memoryStats", &memory_stats);
}
