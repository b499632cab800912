// kergen — command-line front end: computes the kernel of one or many mesh files.
//
//   kergen MESH... [-o OUT.{obj,off,stl}] [--json] [--from x,y,z] [--allow-open] [--deepest]
//                  [--open clip|perpendicular] [--flip-faces] [--write-repaired FILE] [--max-steps N]
//                  [--jobs N]
//   kergen --cells VOLUME_MESH [--json] [--deepest] [--jobs N] [-o OUT.vtu]   (cells.cpp)
//
// Exit code: 0 when every mesh was processed (an empty kernel is a result, not an error), 1 when
// some mesh could not be read or was rejected by validation, 2 for a usage error.
#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <map>
#include <mutex>
#include <string>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

#include "cells.h"
#include "json_out.h"
#include "kergen/batch.h"
#include "kergen/io.h"
#include "kergen/kergen.h"

namespace {

namespace fs = std::filesystem;

const char* const kUsage =
    "usage: kergen MESH... [-o OUT.{obj,off,stl}] [--json] [--from x,y,z] [--allow-open]\n"
    "                      [--deepest] [--max-steps N] [--jobs N] [--no-cull-faces] [--seed N]\n"
    "                      [--weld [EPS]] [--weld-relative R] [--no-weld] [--repair]\n"
    "                      [--open clip|perpendicular] [--flip-faces] [--write-repaired FILE]\n"
    "       kergen --cells VOLUME_MESH [--json] [--deepest] [--jobs N] [-o OUT.vtu]\n"
    "\n"
    "Computes the kernel (the region that sees the whole shape) of closed polygon meshes.\n"
    "  MESH            a .off, .obj, .stl or .ply file (any other name: the format is told by\n"
    "                  the content), or a folder (its .off, .obj, .stl and .ply files, sorted)\n"
    "  -o OUT          write the kernel as OBJ, OFF or binary STL (one mesh only)\n"
    "  --json          one JSON object per mesh on stdout\n"
    "  --from x,y,z    grow the kernel from the vertex nearest to this direction\n"
    "  --allow-open    accept meshes with holes (the kernel may be unbounded, then clipped)\n"
    "  --open MODE     accept meshes with holes and bound their kernel: clip (as --allow-open)\n"
    "                  or perpendicular (also a wall through each boundary edge, perpendicular\n"
    "                  to its face; the kernel may still be unbounded, then clipped)\n"
    "  --flip-faces    turn every face over first (an open surface given inside out; an open\n"
    "                  surface is never turned over by itself)\n"
    "  --deepest       also compute the centre and radius of the largest inscribed ball\n"
    "  --max-steps N   stop after N trace events (the result is then partial)\n"
    "  --jobs N        compute N meshes at a time (default: the machine's threads); the\n"
    "                  output is the same as with --jobs 1, in input order\n"
    "  --no-cull-faces keep every face's plane (the same kernel; distinct_planes then counts all)\n"
    "  --seed N        order of the LP's constraints (the results do not depend on it)\n"
    "  --weld [EPS]    merge vertices closer than EPS (default: 1e-9 of the bounding box\n"
    "                  diagonal) before validation: closes triangle soups and seams\n"
    "  --weld-relative R  merge vertices closer than R times the bounding box diagonal\n"
    "  --no-weld       do not weld .stl files (welded by default, as with --weld)\n"
    "  --repair        weld, remove repeated and cancelling faces, split T-junctions (exactly)\n"
    "  --write-repaired FILE  write the mesh the kernel is computed on (after --weld and\n"
    "                  --repair) as OBJ, OFF or binary STL (one mesh only)\n"
    "Exit code: 0 all meshes processed, 1 some mesh had an input error, 2 usage error.\n";

struct Arguments {
  std::vector<std::string> inputs;
  std::string output;
  std::string repaired_output;  // --write-repaired
  bool json = false;
  unsigned jobs = 0;  // 0: std::thread::hardware_concurrency()
  kergen::Options options;
  bool weld_given = false;  // --weld, --weld-relative or --no-weld: else STL files are welded
};

[[noreturn]] void usage_error(const std::string& reason) {
  std::fprintf(stderr, "kergen: %s\n\n%s", reason.c_str(), kUsage);
  std::exit(2);
}

// --weld without a distance: vertices within this fraction of the bounding box diagonal merge.
constexpr double kDefaultRelativeWeld = 1e-9;

// The core's messages name options as the C++ API does (Options::field); the CLI names its flags
// (kergen::option_names; an option without a flag keeps the library's name).
std::string in_cli_words(std::string text) {
  for (const kergen::OptionName& o : kergen::option_names()) {
    if (!o.cli) continue;
    const std::string api = std::string("Options::") + o.field;
    for (size_t at = text.find(api); at != std::string::npos; at = text.find(api, at + std::strlen(o.cli)))
      text.replace(at, api.size(), o.cli);
  }
  return text;
}

// A whole number from 0 to `max` given to `flag`, else a usage error.
uint64_t parse_count(const std::string& flag, const std::string& text, uint64_t max) {
  char* end = nullptr;
  errno = 0;
  const unsigned long long n = std::strtoull(text.c_str(), &end, 10);
  if (text.empty() || text[0] == '-' || end != text.c_str() + text.size() || errno == ERANGE || n > max)
    usage_error(flag + " needs a non-negative integer" + (max < UINT64_MAX ? " up to " + std::to_string(max) : "") +
                ", got '" + text + "'");
  return n;
}

bool parse_number(const std::string& text, double& out) {
  if (text.empty()) return false;
  char* end = nullptr;
  out = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && std::isfinite(out);
}

Arguments parse_arguments(int argc, char** argv) {
  Arguments args;
  bool only_paths = false;  // after "--"
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) usage_error(arg + " needs a value");
      return argv[++i];
    };
    if (only_paths || arg.empty() || arg[0] != '-' || arg == "-") {
      args.inputs.push_back(arg);
    } else if (arg == "--") {
      only_paths = true;
    } else if (arg == "-h" || arg == "--help") {
      std::fputs(kUsage, stdout);
      std::exit(0);
    } else if (arg == "-o" || arg == "--output") {
      args.output = value();
      const kergen::MeshFormat format = kergen::format_from_path(args.output);
      if (format != kergen::MeshFormat::Obj && format != kergen::MeshFormat::Off && format != kergen::MeshFormat::Stl)
        usage_error("output '" + args.output + "' must end in .obj, .off or .stl");
    } else if (arg == "--write-repaired") {
      args.repaired_output = value();
      const kergen::MeshFormat format = kergen::format_from_path(args.repaired_output);
      if (format != kergen::MeshFormat::Obj && format != kergen::MeshFormat::Off && format != kergen::MeshFormat::Stl)
        usage_error("--write-repaired '" + args.repaired_output + "' must end in .obj, .off or .stl");
    } else if (arg == "--json") {
      args.json = true;
    } else if (arg == "--no-weld") {
      args.options.weld = -1;
      args.weld_given = true;
    } else if (arg == "--weld") {
      args.weld_given = true;
      // An optional distance: the next argument when it is a number (else the default, relative).
      double eps = 0;
      if (i + 1 < argc && parse_number(argv[i + 1], eps)) {
        if (eps < 0) usage_error("--weld needs a non-negative distance, got '" + std::string(argv[i + 1]) + "'");
        ++i;
        args.options.weld = eps;
        args.options.weld_relative = false;
      } else {
        args.options.weld = kDefaultRelativeWeld;
        args.options.weld_relative = true;
      }
    } else if (arg == "--repair") {
      args.options.repair = true;
    } else if (arg == "--flip-faces") {
      args.options.flip_faces = true;
    } else if (arg == "--weld-relative") {
      args.weld_given = true;
      const std::string text = value();
      double r = 0;
      if (!parse_number(text, r) || r < 0)
        usage_error("--weld-relative needs a non-negative number, got '" + text + "'");
      args.options.weld = r;
      args.options.weld_relative = true;
    } else if (arg == "--allow-open") {
      args.options.allow_open = true;
    } else if (arg == "--open") {
      const std::string mode = value();
      if (mode == kergen::open_boundary_name(kergen::OpenBoundary::Clip)) {
        args.options.allow_open = true;
        args.options.open_boundary = kergen::OpenBoundary::Clip;
      } else if (mode == kergen::open_boundary_name(kergen::OpenBoundary::Perpendicular)) {
        args.options.open_boundary = kergen::OpenBoundary::Perpendicular;
      } else {
        usage_error("--open needs clip or perpendicular, got '" + mode + "'");
      }
    } else if (arg == "--deepest") {
      args.options.deepest_point = true;
    } else if (arg == "--from") {
      const std::string text = value();
      std::vector<std::string> parts(1);
      for (char c : text) {
        if (c == ',')
          parts.emplace_back();
        else
          parts.back() += c;
      }
      if (parts.size() != 3) usage_error("--from needs x,y,z, got '" + text + "'");
      for (int k = 0; k < 3; ++k)
        if (!parse_number(parts[k], args.options.from[k])) usage_error("--from needs x,y,z, got '" + text + "'");
      args.options.has_from = true;
    } else if (arg == "--max-steps") {
      args.options.max_steps = parse_count(arg, value(), UINT64_MAX);
    } else if (arg == "--no-cull-faces") {
      args.options.cull_faces = false;
    } else if (arg == "--seed") {
      args.options.seed = parse_count(arg, value(), UINT64_MAX);
    } else if (arg == "--jobs") {
      const std::string text = value();
      char* end = nullptr;
      errno = 0;
      const unsigned long n = std::strtoul(text.c_str(), &end, 10);
      if (text.empty() || text[0] == '-' || end != text.c_str() + text.size() || errno == ERANGE || n == 0 || n > 1024)
        usage_error("--jobs needs a whole number from 1 to 1024, got '" + text + "'");
      args.jobs = unsigned(n);
    } else {
      usage_error("unknown option '" + arg + "'");
    }
  }
  if (args.inputs.empty()) usage_error("no mesh given");
  return args;
}

bool is_mesh_file_name(const fs::path& path) {
  return kergen::format_from_path(path.string()) != kergen::MeshFormat::Unknown;
}

// A folder contributes its mesh files (not recursively), sorted by name; anything else is taken as
// a file path, so a missing file is reported by the reader like any other unreadable input.
std::vector<std::string> expand_inputs(const std::vector<std::string>& inputs, std::vector<std::string>& problems) {
  std::vector<std::string> files;
  for (const std::string& input : inputs) {
    std::error_code ec;
    if (!fs::is_directory(input, ec)) {
      files.push_back(input);
      continue;
    }
    std::vector<std::string> found;
    for (fs::directory_iterator it(input, ec), end; !ec && it != end; it.increment(ec)) {
      std::error_code type_ec;
      if (it->is_regular_file(type_ec) && is_mesh_file_name(it->path())) found.push_back(it->path().string());
    }
    if (ec)
      problems.push_back(input + ": cannot list folder: " + ec.message());
    else if (found.empty())
      problems.push_back(input + ": folder has no .off, .obj, .stl or .ply file");
    std::sort(found.begin(), found.end());
    files.insert(files.end(), found.begin(), found.end());
  }
  return files;
}

// ---------------------------------------------------------------------------------------------
// Output.

std::string json_point(bool present, const std::array<double, 3>& p) {
  if (!present) return "null";
  return "[" + json_number(p[0]) + "," + json_number(p[1]) + "," + json_number(p[2]) + "]";
}

struct MeshOutcome {
  std::string file;
  bool read_ok = false;
  kergen::Error error = kergen::Error::Ok;
  std::string message;
  kergen::Kernel kernel;  // meaningful when read_ok
  double ms_parse = 0;
  double ms_total = 0;  // parse + kernel
  bool ok() const { return error == kergen::Error::Ok; }
};

std::string json_line(const MeshOutcome& m) {
  const kergen::Kernel& k = m.kernel;
  const bool computed = m.ok();
  std::string s = "{";
  s += "\"file\":" + json_string(m.file);
  s += ",\"ok\":" + std::string(computed ? "true" : "false");
  s += ",\"error\":" + (computed ? std::string("null") : json_string(kergen::error_name(m.error)));
  s += ",\"message\":" + json_string(m.message);
  s += ",\"status\":" + (computed ? json_string(kergen::kernel_type_name(k.type)) : std::string("null"));
  s += ",\"complete\":" + (computed ? std::string(k.complete ? "true" : "false") : std::string("null"));
  auto count = [&](size_t n) { return computed ? std::to_string(n) : std::string("null"); };
  auto number = [&](double x) { return computed ? json_number(x) : std::string("null"); };
  s += ",\"vertices\":" + count(k.num_vertices());
  s += ",\"edges\":" + count(k.num_edges());
  s += ",\"faces\":" + count(k.num_faces());
  s += ",\"volume\":" + number(k.volume);
  s += ",\"area\":" + number(k.area);
  s += ",\"shape_volume\":" + number(k.shape_volume);
  s += ",\"volume_ratio\":" + number(k.volume_ratio);
  s += ",\"kernel_point\":" + json_point(computed && k.has_kernel_point, k.kernel_point);
  s += ",\"deepest_point\":" + json_point(computed && k.has_deepest_point, k.deepest_point);
  s += ",\"inscribed_radius\":" + (computed && k.has_deepest_point ? json_number(k.inscribed_radius) : "null");
  auto json_array = [&](const char* name, const auto& values) {
    s += ",\"" + std::string(name) + "\":[";
    for (size_t i = 0; i < values.size(); ++i) s += (i ? "," : "") + std::to_string(values[i]);
    s += "]";
  };
  json_array("face_sources", k.face_sources);
  json_array("witness_faces", k.witness_faces);
  json_array("witness_boundary_edges", k.witness_boundary_edges);
  s += ",\"warnings\":[";
  for (size_t i = 0; i < k.warnings.size(); ++i) {
    const kergen::Warning& w = k.warnings[i];
    if (i) s += ",";
    s += "{\"kind\":" + json_string(kergen::warning_kind_name(w.kind)) + ",\"count\":" + std::to_string(w.count) +
         ",\"message\":" + json_string(in_cli_words(w.message)) + "}";
  }
  s += "]";
  const kergen::Stats& st = k.stats;
  s += ",\"stats\":{";
  s += "\"input_faces\":" + std::to_string(st.input_faces);
  s += ",\"culled_faces\":" + std::to_string(st.culled_faces);
  s += ",\"distinct_planes\":" + std::to_string(st.distinct_planes);
  s += ",\"active_planes\":" + std::to_string(st.active_planes);
  s += ",\"traced_lines\":" + std::to_string(st.traced_lines);
  s += ",\"exact_fallbacks\":" + std::to_string(st.exact_fallbacks);
  s += ",\"ms_parse\":" + json_number(m.ms_parse);
  s += ",\"ms_validate\":" + json_number(st.ms_validate);
  s += ",\"ms_planes\":" + json_number(st.ms_planes);
  s += ",\"ms_lp\":" + json_number(st.ms_lp);
  s += ",\"ms_trace\":" + json_number(st.ms_trace);
  s += ",\"ms_assemble\":" + json_number(st.ms_assemble);
  s += ",\"ms_total\":" + json_number(m.ms_total);
  s += "}}";
  return s;
}

// printf into a string: each mesh's output is collected first, so that meshes computed in
// parallel are printed in input order.
void appendf(std::string& out, const char* format, ...) __attribute__((format(printf, 2, 3)));
void appendf(std::string& out, const char* format, ...) {
  va_list args, again;
  va_start(args, format);
  va_copy(again, args);
  const int n = std::vsnprintf(nullptr, 0, format, args);
  va_end(args);
  if (n > 0) {
    const size_t at = out.size();
    out.resize(at + size_t(n) + 1);
    std::vsnprintf(&out[at], size_t(n) + 1, format, again);
    out.resize(at + size_t(n));
  }
  va_end(again);
}

void append_human(std::string& out, const MeshOutcome& m) {
  const kergen::Kernel& k = m.kernel;
  appendf(out, "%s\n", m.file.c_str());
  appendf(out, "  status      %s%s\n", kergen::kernel_type_name(k.type), k.complete ? "" : " (partial: stopped early)");
  appendf(out, "  kernel      V %zu  E %zu  F %zu\n", k.num_vertices(), k.num_edges(), k.num_faces());
  // (An open surface's shape volume is that of the surface closed over its holes, which its
  // kernel may exceed: the core gives it no ratio.)
  if (!(k.volume > 0 && k.volume_ratio == 0))
    appendf(out, "  volume      %.10g  (shape %.10g, ratio %.6g)\n", k.volume, k.shape_volume, k.volume_ratio);
  else
    appendf(out, "  volume      %.10g  (shape %.10g)\n", k.volume, k.shape_volume);
  appendf(out, "  area        %.10g\n", k.area);
  if (k.has_kernel_point)
    appendf(out, "  point       %.10g %.10g %.10g\n", k.kernel_point[0], k.kernel_point[1], k.kernel_point[2]);
  const bool walls = !k.witness_boundary_edges.empty();
  if (!k.witness_faces.empty()) {
    appendf(out, "  witness     faces");
    for (uint32_t f : k.witness_faces) appendf(out, " %u", f);
    appendf(out, walls ? " (no point sees all of them from the inside and lies inside the walls below)\n"
                       : " (no point sees all of them from the inside)\n");
  }
  if (walls) {
    appendf(out, "  witness     walls at boundary edges");
    for (size_t i = 0; i + 1 < k.witness_boundary_edges.size(); i += 2)
      appendf(out, " %u->%u", k.witness_boundary_edges[i], k.witness_boundary_edges[i + 1]);
    appendf(out, k.witness_faces.empty() ? " (no point lies inside all of them)\n" : "\n");
  }
  if (k.has_deepest_point)
    appendf(out, "  deepest     %.10g %.10g %.10g  (radius %.10g)\n", k.deepest_point[0], k.deepest_point[1],
            k.deepest_point[2], k.inscribed_radius);
  for (const kergen::Warning& w : k.warnings)
    appendf(out, "  warning     %s (%zu): %s\n", kergen::warning_kind_name(w.kind), w.count,
            in_cli_words(w.message).c_str());
  const kergen::Stats& st = k.stats;
  appendf(
      out,
      "  planes      %zu faces (%zu culled), %zu distinct planes, %zu active, %zu traced lines, %zu exact fallbacks\n",
      st.input_faces, st.culled_faces, st.distinct_planes, st.active_planes, st.traced_lines, st.exact_fallbacks);
  appendf(out, "  time        %.3f ms (parse %.3f, validate %.3f, planes %.3f, lp %.3f, trace %.3f, assemble %.3f)\n",
          m.ms_total, m.ms_parse, st.ms_validate, st.ms_planes, st.ms_lp, st.ms_trace, st.ms_assemble);
}

double milliseconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

MeshOutcome process(const std::string& file, const Arguments& args, kergen::KernelBatch& batch) {
  MeshOutcome m;
  m.file = file;
  const auto start = std::chrono::steady_clock::now();
  kergen::ReadResult read = kergen::read_mesh_file(file);
  m.ms_parse = milliseconds_since(start);
  if (!read.ok()) {
    m.error = read.error;
    m.message = read.message;
    m.ms_total = m.ms_parse;
    return m;
  }
  m.read_ok = true;
  // An STL file stores every triangle's corners on their own: a seam whose copies differ by
  // rounding would leave it open, so STL is welded unless the command line says otherwise.
  kergen::Options options = args.options;
  if (!args.weld_given && kergen::format_from_path(file) == kergen::MeshFormat::Stl) {
    options.weld = kDefaultRelativeWeld;
    options.weld_relative = true;
  }
  batch.compute(read.mesh.view(), options, m.kernel);
  m.ms_total = milliseconds_since(start);
  m.error = m.kernel.error;
  m.message = in_cli_words(m.kernel.message);
  if (m.ok() && !args.output.empty()) {
    std::string write_message;
    if (kergen::write_mesh_file(args.output, kergen::kernel_mesh(m.kernel), &write_message) != kergen::Error::Ok) {
      m.error = kergen::Error::IoError;
      m.message = write_message;
    }
  }
  // Written whatever the kernel's verdict: a mesh repair leaves open is worth looking at too.
  if (!args.repaired_output.empty()) {
    const kergen::RepairedMesh repaired = kergen::repair_mesh(read.mesh.view(), options);
    std::string write_message;
    if (repaired.mesh.num_faces() == 0) {
      if (m.ok()) {
        m.error = repaired.error;
        m.message = in_cli_words(repaired.message);
      }
    } else if (kergen::write_mesh_file(args.repaired_output, repaired.mesh, &write_message) != kergen::Error::Ok) {
      m.error = kergen::Error::IoError;
      m.message = write_message;
    }
  }
  return m;
}

// What one mesh contributes to the output, computed by any thread and printed by the main one.
struct MeshReport {
  std::string out, err;  // its stdout and stderr text
  bool ok = false;
  std::string count_as;  // kernel type when ok, else error name (for the batch summary)
};

MeshReport report(const std::string& file, const Arguments& args, kergen::KernelBatch& batch) {
  const MeshOutcome m = process(file, args, batch);
  MeshReport r;
  r.ok = m.ok();
  r.count_as = r.ok ? kergen::kernel_type_name(m.kernel.type) : kergen::error_name(m.error);
  if (args.json) {
    r.out = json_line(m) + "\n";
  } else if (m.ok()) {
    append_human(r.out, m);
  } else {
    // Reader messages already start with the file name; kernel messages do not.
    const bool named = m.message.compare(0, m.file.size(), m.file) == 0;
    r.err = "kergen: " + (named ? "" : m.file + ": ") + m.message + "\n";
  }
  return r;
}

// Computes the reports of `files` on `threads` threads, each taking the next file not yet taken,
// and hands them to `emit` in input order as soon as each one and all before it are done;
// `wait(i)` is called before mesh i is awaited (one thread: before it is computed). An exception
// thrown for a mesh (out of memory) is rethrown in order, as one thread would throw it.
// Each thread computes with its own KernelBatch (batch.h), which keeps its working memory from one
// mesh to the next; the core has no mutable state outside a call and its batch.
template <class Wait, class Emit>
void run_in_order(const std::vector<std::string>& files, const Arguments& args, unsigned threads, Wait wait,
                  Emit emit) {
  if (threads <= 1) {
    kergen::KernelBatch batch;
    for (size_t i = 0; i < files.size(); ++i) {
      wait(i);
      emit(i, report(files[i], args, batch));
    }
    return;
  }
  std::vector<MeshReport> reports(files.size());
  std::vector<std::exception_ptr> failures(files.size());
  std::vector<char> done(files.size(), 0);
  std::atomic<size_t> next{0};
  std::mutex mutex;
  std::condition_variable finished;
  auto work = [&] {
    kergen::KernelBatch batch;
    for (size_t i; (i = next.fetch_add(1)) < files.size();) {
      MeshReport r;
      std::exception_ptr failure;
      try {
        r = report(files[i], args, batch);
      } catch (...) { failure = std::current_exception(); }
      std::lock_guard<std::mutex> lock(mutex);
      reports[i] = std::move(r);
      failures[i] = failure;
      done[i] = 1;
      finished.notify_all();
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < threads; ++t) pool.emplace_back(work);
  struct Join {  // the workers finish even when emit or a rethrow leaves this function
    std::vector<std::thread>& pool;
    std::atomic<size_t>& next;
    size_t n;
    ~Join() {
      next.store(n);
      for (std::thread& t : pool) t.join();
    }
  } join{pool, next, files.size()};
  for (size_t i = 0; i < files.size(); ++i) {
    wait(i);
    MeshReport r;
    {
      std::unique_lock<std::mutex> lock(mutex);
      finished.wait(lock, [&] { return done[i] != 0; });
      if (failures[i]) std::rethrow_exception(failures[i]);
      r = std::move(reports[i]);
    }
    emit(i, std::move(r));
  }
}

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--cells") == 0) return run_cells(argc, argv);
  const Arguments args = parse_arguments(argc, argv);
  std::vector<std::string> problems;
  const std::vector<std::string> files = expand_inputs(args.inputs, problems);
  if (!args.output.empty() && (files.size() != 1 || !problems.empty()))
    usage_error("-o needs exactly one mesh (got " + std::to_string(files.size()) + ")");
  if (!args.repaired_output.empty() && (files.size() != 1 || !problems.empty()))
    usage_error("--write-repaired needs exactly one mesh (got " + std::to_string(files.size()) + ")");
  for (const std::string& problem : problems) std::fprintf(stderr, "kergen: %s\n", problem.c_str());

  const bool batch = files.size() > 1;
  const auto start = std::chrono::steady_clock::now();
  std::map<std::string, size_t> statuses, errors;
  size_t failed = 0;
  const unsigned jobs = args.jobs ? args.jobs : std::max(1u, std::thread::hardware_concurrency());
  const unsigned threads = unsigned(std::min<size_t>(jobs, files.size()));
  // A mesh's progress line is printed when its turn comes in input order (with --jobs N it may be
  // done already), so that stderr reads the same with any --jobs.
  auto progress = [&](size_t i) {
    if (!batch) return;
    std::fprintf(stderr, "[%zu/%zu] %s ...\n", i + 1, files.size(), files[i].c_str());
    std::fflush(stderr);
  };
  run_in_order(files, args, threads, progress, [&](size_t, MeshReport r) {
    ++(r.ok ? statuses : errors)[r.count_as];
    failed += !r.ok;
    std::fputs(r.err.c_str(), stderr);
    std::fflush(stderr);
    std::fputs(r.out.c_str(), stdout);
    std::fflush(stdout);
  });

  if (batch) {
    std::string summary = "kergen: " + std::to_string(files.size()) + (files.size() == 1 ? " mesh in " : " meshes in ");
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.2f s", milliseconds_since(start) / 1000);
    summary += seconds;
    summary += ": " + std::to_string(files.size() - failed) + " ok";
    std::string detail;
    for (const auto& [name, n] : statuses) detail += (detail.empty() ? "" : ", ") + name + " " + std::to_string(n);
    if (!detail.empty()) summary += " (" + detail + ")";
    summary += ", " + std::to_string(failed) + " failed";
    detail.clear();
    for (const auto& [name, n] : errors) detail += (detail.empty() ? "" : ", ") + name + " " + std::to_string(n);
    if (!detail.empty()) summary += " (" + detail + ")";
    std::fprintf(stderr, "%s\n", summary.c_str());
  }
  return failed > 0 || !problems.empty() ? 1 : 0;
}
