// kergen_bench --streaming: compute_kernel without and with an on_step callback, same run.
#include "streaming_rows.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "bench_util.h"
#include "fixtures.h"  // tests/core: the sphere generators the core tests use
#include "kergen/io.h"
#include "kergen/kergen.h"

namespace kergen_bench {
namespace {

namespace fs = std::filesystem;

struct Side {
  double ms = 0;  // median
  int runs = 0;
  bool stopped = false;  // the budget cut the repetitions short
};

struct StreamRow {
  std::string mesh, error, note;
  size_t faces = 0, V = 0, E = 0, F = 0;
  std::string type;
  uint64_t events = 0;
  Side plain, streamed;
};

// A near-convex sphere: the core tests' bumpy UV sphere with a small amplitude, so the kernel is
// most of the shape and most faces are kernel faces (the most events per input face). 2 nu (nv-1)
// triangles.
constexpr double kNearConvexAmplitude = 0.01;

// Runs compute_kernel up to `runs` times (fewer once one run exceeds budget_ms); returns the
// median and keeps the last result.
Side measure(const kergen::MeshView& view, const kergen::Options& options, int runs, double budget_ms,
             kergen::Kernel& result) {
  std::vector<double> times;
  Side side;
  for (int r = 0; r < runs; ++r) {
    const double t0 = now_ms();
    result = kergen::compute_kernel(view, options);
    benchmark::DoNotOptimize(result);
    times.push_back(now_ms() - t0);
    if (times.back() > budget_ms) {
      side.stopped = r + 1 < runs;
      break;
    }
  }
  side.ms = median(times);
  side.runs = int(times.size());
  return side;
}

StreamRow stream_row(const std::string& label, const kergen::Mesh& mesh, int runs, double budget_ms) {
  StreamRow row;
  row.mesh = label;
  row.faces = mesh.num_faces();
  const kergen::MeshView view = mesh.view();
  kergen::Kernel plain, streamed;
  row.plain = measure(view, kergen::Options(), runs, budget_ms, plain);
  if (!plain.ok()) {
    row.error = std::string(kergen::error_name(plain.error)) + ": " + plain.message;
    return row;
  }
  uint64_t events = 0;  // over all runs: every run reports the same events
  kergen::Options counting;
  counting.on_step = [&events](const kergen::StepEvent&) {
    ++events;
    return true;
  };
  row.streamed = measure(view, counting, runs, budget_ms, streamed);
  row.events = events / uint64_t(row.streamed.runs);
  row.type = kergen::kernel_type_name(plain.type);
  row.V = plain.num_vertices();
  row.E = plain.num_edges();
  row.F = plain.num_faces();
  // Streaming must not change the result: say how it differs if it does. The volume is compared
  // relatively: a different order of the kernel's vertices sums it in a different order.
  const double volume_diff = std::fabs(streamed.volume - plain.volume) / std::fabs(plain.volume);
  char buf[256];
  if (streamed.type != plain.type || streamed.num_vertices() != row.V || streamed.num_edges() != row.E ||
      streamed.num_faces() != row.F || !streamed.complete || events % uint64_t(row.streamed.runs) != 0 ||
      !(volume_diff <= 1e-12)) {
    std::snprintf(buf, sizeof buf,
                  "**with on_step: %s V %zu E %zu F %zu, volume %.17g (without: %.17g), complete %d, events %llu over %d runs**",
                  kergen::kernel_type_name(streamed.type), streamed.num_vertices(), streamed.num_edges(),
                  streamed.num_faces(), streamed.volume, plain.volume, int(streamed.complete),
                  (unsigned long long)events, row.streamed.runs);
    row.note = buf;
  } else if (volume_diff > 0) {
    std::snprintf(buf, sizeof buf, "same V E F; volume differs by %.1e relative", volume_diff);
    row.note = buf;
  }
  return row;
}

std::string fmt(double v, int prec = 2) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", prec, v);
  return buf;
}

std::string side_cell(const Side& s) {
  return fmt(s.ms) + " (" + std::to_string(s.runs) + (s.stopped ? " run, budget" : s.runs == 1 ? " run" : " runs") + ")";
}

void print_row(const StreamRow& r, bool json, const std::string& json_context, double budget_ms) {
  const double ratio = r.plain.ms > 0 ? r.streamed.ms / r.plain.ms : 0;
  std::string note = r.note;
  if (r.plain.stopped || r.streamed.stopped)
    note += std::string(note.empty() ? "" : "; ") + "stopped repeating after a run over " + fmt(budget_ms / 1000, 0) + " s";
  if (json) {
    std::ostringstream os;
    os << "{\"streaming_mesh\":\"" << r.mesh << "\"," << json_context << ",\"faces\":" << r.faces;
    if (!r.error.empty()) os << ",\"error\":\"" << r.error << "\"}";
    else
      os << ",\"type\":\"" << r.type << "\",\"V\":" << r.V << ",\"E\":" << r.E << ",\"F\":" << r.F
         << ",\"events\":" << r.events << ",\"plain_ms\":" << r.plain.ms << ",\"plain_runs\":" << r.plain.runs
         << ",\"on_step_ms\":" << r.streamed.ms << ",\"on_step_runs\":" << r.streamed.runs << ",\"ratio\":" << ratio
         << ",\"budget_stopped\":" << (r.plain.stopped || r.streamed.stopped ? "true" : "false") << ",\"note\":\""
         << note << "\"}";
    std::printf("%s\n", os.str().c_str());
  } else if (!r.error.empty()) {
    std::printf("| %s | %zu | ERROR | | | | | | | | %s |\n", r.mesh.c_str(), r.faces, r.error.c_str());
  } else {
    std::printf("| %s | %zu | %s | %zu | %zu | %zu | %llu | %s | %s | %sx | %s |\n", r.mesh.c_str(), r.faces,
                r.type.c_str(), r.V, r.E, r.F, (unsigned long long)r.events, side_cell(r.plain).c_str(),
                side_cell(r.streamed).c_str(), fmt(ratio, ratio < 10 ? 2 : 1).c_str(), note.c_str());
  }
  std::fflush(stdout);
}

}  // namespace

int run_streaming_rows(const std::string& meshes, const std::vector<std::string>& files, int runs, double budget_ms,
                       bool json, const std::string& json_context) {
  // (label, generated mesh or file to read)
  std::vector<std::pair<std::string, std::string>> list;
  if (files.empty()) {
    list = {{"near-convex sphere 40k (generated)", ""}, {"near-convex sphere 200k (generated)", ""}};
    for (const char* rel : {"refinements/vase6.off", "refinements/spiral6.off", "princeton/325.off"})
      list.emplace_back(rel, (fs::path(meshes) / rel).string());
  } else {
    for (const std::string& f : files) list.emplace_back(f, f);
  }
  if (!json) {
    std::printf("| mesh | faces | kernel | V | E | F | events | default ms | with on_step ms | with/without | note |\n");
    std::printf("|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---|\n");
  }
  int exit_code = 0;
  for (const auto& [label, path] : list) {
    kergen::Mesh mesh;
    if (path.empty()) {
      const bool big = label.find("200k") != std::string::npos;
      mesh = kergen_test::bumpy_sphere(big ? 500 : 200, big ? 201 : 101, kNearConvexAmplitude);
    } else {
      kergen::ReadResult rr = kergen::read_mesh_file(path);
      if (!rr.ok()) {
        std::fprintf(stderr, "%s\n", rr.message.c_str());
        exit_code = 1;
        continue;
      }
      mesh = std::move(rr.mesh);
    }
    print_row(stream_row(label, mesh, runs, budget_ms), json, json_context, budget_ms);
  }
  return exit_code;
}

}  // namespace kergen_bench

