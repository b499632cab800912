// kergen_bench --streaming: compute_kernel without and with an on_step callback, same run.
#include "streaming_rows.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "bench_util.h"
#include "fixtures.h"  // tests/core: the sphere generators the core tests use
#include "kergen/io.h"
#include "kergen/kergen.h"

namespace kergen_bench {
namespace {

namespace fs = std::filesystem;

struct Side {
  std::vector<double> times;
  bool done = false;     // no more runs: all done, or one took longer than the budget
  bool stopped = false;  // the budget cut the repetitions short
  bool cut = false;      // the on_step callback stopped the run at the cap: ms is a lower bound
  double ms() const { return median(times); }
  int runs() const { return int(times.size()); }
};

struct StreamRow {
  std::string mesh, error, note;
  size_t faces = 0, V = 0, E = 0, F = 0;
  std::string type;
  uint64_t events = 0;  // per run (when cut: the events before the cut)
  Side plain, streamed;
};

// A near-convex sphere: the core tests' bumpy UV sphere with a small amplitude, so the kernel is
// most of the shape and most faces are kernel faces (the most events per input face). 2 nu (nv-1)
// triangles.
constexpr double kNearConvexAmplitude = 0.01;

// One timed run of one side; keeps the result. `run_start` is set as the run starts.
void time_once(Side& side, const kergen::MeshView& view, const kergen::Options& options, int runs, double budget_ms,
               kergen::Kernel& result, double& run_start) {
  const double t0 = run_start = now_ms();
  result = kergen::compute_kernel(view, options);
  benchmark::DoNotOptimize(result);
  side.times.push_back(now_ms() - t0);
  if (side.runs() >= runs)
    side.done = true;
  else if (side.times.back() > budget_ms)
    side.done = side.stopped = true;
}

StreamRow stream_row(const std::string& label, const kergen::Mesh& mesh, int runs, double budget_ms, double cap_ms) {
  StreamRow row;
  row.mesh = label;
  row.faces = mesh.num_faces();
  const kergen::MeshView view = mesh.view();
  // The callback counts, and stops a run that has taken longer than cap_ms (looking at the clock
  // every 1024 events): a slow streaming path then costs the cap, and the row gives a lower bound.
  double run_start = 0;
  uint64_t events = 0;  // over all runs: every complete run reports the same events
  bool cut = false;
  kergen::Options counting;
  counting.on_step = [&](const kergen::StepEvent&) {
    if ((++events & 1023) == 0 && now_ms() - run_start > cap_ms) cut = true;
    return !cut;
  };
  // The two sides alternate run by run, so that a drift of the machine's speed and the first
  // run's page faults weigh on both alike.
  kergen::Kernel plain, streamed;
  uint64_t events_before_last = 0;
  while (!row.plain.done || !row.streamed.done) {
    if (!row.plain.done) time_once(row.plain, view, kergen::Options(), runs, budget_ms, plain, run_start);
    if (!plain.ok()) {
      row.error = std::string(kergen::error_name(plain.error)) + ": " + plain.message;
      return row;
    }
    if (row.streamed.done) continue;
    events_before_last = events;
    time_once(row.streamed, view, counting, runs, budget_ms, streamed, run_start);
    if (cut) row.streamed.done = true;
  }
  row.type = kergen::kernel_type_name(plain.type);
  row.V = plain.num_vertices();
  row.E = plain.num_edges();
  row.F = plain.num_faces();
  if (cut) {
    row.streamed.cut = true;
    row.events = events - events_before_last;
    return row;
  }
  row.events = events / uint64_t(row.streamed.runs());
  // Streaming must not change the result: say how it differs if it does. The volume is compared
  // relatively: a different order of the kernel's vertices sums it in a different order.
  const double volume_diff = std::fabs(streamed.volume - plain.volume) / std::fabs(plain.volume);
  char buf[256];
  if (streamed.type != plain.type || streamed.num_vertices() != row.V || streamed.num_edges() != row.E ||
      streamed.num_faces() != row.F || !streamed.complete || events % uint64_t(row.streamed.runs()) != 0 ||
      !(volume_diff <= 1e-12)) {
    std::snprintf(
        buf, sizeof buf,
        "**with on_step: %s V %zu E %zu F %zu, volume %.17g (without: %.17g), complete %d, events %llu over %d runs**",
        kergen::kernel_type_name(streamed.type), streamed.num_vertices(), streamed.num_edges(), streamed.num_faces(),
        streamed.volume, plain.volume, int(streamed.complete), (unsigned long long)events, row.streamed.runs());
    row.note = buf;
  } else if (volume_diff > 0) {
    std::snprintf(buf, sizeof buf, "same V E F; volume differs by %.1e relative", volume_diff);
    row.note = buf;
  }
  return row;
}

std::string side_cell(const Side& s) {
  if (s.cut) return "> " + fmt(s.ms()) + " (cut off)";
  return fmt(s.ms()) + " (" + std::to_string(s.runs()) + (s.runs() == 1 ? " run" : " runs") +
         (s.stopped ? ", budget" : "") + ")";
}

void print_row(const StreamRow& r, bool json, const std::string& json_context, double budget_ms, double cap_ms) {
  const double ratio = r.plain.ms() > 0 ? r.streamed.ms() / r.plain.ms() : 0;
  std::string note = r.note;
  auto add = [&](const std::string& text) { note += (note.empty() ? "" : "; ") + text; };
  if (r.plain.stopped || r.streamed.stopped)
    add("stopped repeating after a run over " + fmt(budget_ms / 1000, 0) + " s");
  if (r.streamed.cut)
    add("with on_step cut off at the " + fmt(cap_ms / 1000, 0) + " s cap after " + std::to_string(r.events) + " of " +
        std::to_string(r.V + r.E + r.F) + " events (V + E + F): time and ratio are lower bounds");
  if (json) {
    std::ostringstream os;
    os << "{\"streaming_mesh\":\"" << r.mesh << "\"," << json_context << ",\"faces\":" << r.faces;
    if (!r.error.empty())
      os << ",\"error\":\"" << r.error << "\"}";
    else
      os << ",\"type\":\"" << r.type << "\",\"V\":" << r.V << ",\"E\":" << r.E << ",\"F\":" << r.F
         << ",\"events\":" << r.events << ",\"plain_ms\":" << r.plain.ms() << ",\"plain_runs\":" << r.plain.runs()
         << ",\"on_step_ms\":" << r.streamed.ms() << ",\"on_step_runs\":" << r.streamed.runs() << ",\"ratio\":" << ratio
         << ",\"budget_stopped\":" << (r.plain.stopped || r.streamed.stopped ? "true" : "false")
         << ",\"cut_off\":" << (r.streamed.cut ? "true" : "false") << ",\"note\":\"" << note << "\"}";
    std::printf("%s\n", os.str().c_str());
  } else if (!r.error.empty()) {
    std::printf("| %s | %zu | ERROR | | | | | | | | %s |\n", r.mesh.c_str(), r.faces, r.error.c_str());
  } else {
    std::printf("| %s | %zu | %s | %zu | %zu | %zu | %llu | %s | %s | %sx | %s |\n", r.mesh.c_str(), r.faces,
                r.type.c_str(), r.V, r.E, r.F, (unsigned long long)r.events, side_cell(r.plain).c_str(),
                side_cell(r.streamed).c_str(), ((r.streamed.cut ? "> " : "") + fmt(ratio, ratio < 10 ? 2 : 1)).c_str(),
                note.c_str());
  }
  std::fflush(stdout);
}

}  // namespace

int run_streaming_rows(const std::string& meshes, const std::vector<std::string>& files, int runs, double budget_ms,
                       double cap_ms, bool json, const std::string& json_context) {
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
    std::printf(
        "| mesh | faces | kernel | V | E | F | events | default ms | with on_step ms | with/without | note |\n");
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
    print_row(stream_row(label, mesh, runs, budget_ms, cap_ms), json, json_context, budget_ms, cap_ms);
  }
  return exit_code;
}

}  // namespace kergen_bench
