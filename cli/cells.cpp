// cells.cpp — `kergen --cells MESH [--json] [--deepest] [--jobs N] [-o OUT.vtu]`: the kernel of every
// cell of a volume mesh (kergen/volume.h). Threads take chunks of cells in turn (cells differ in
// cost) and call compute_cell_kernels on each chunk; the output is in cell order, the same with
// any --jobs.
#include "cells.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

#include "json_out.h"
#include "kergen/volume.h"

namespace {

constexpr const char* kUsage =
    "usage: kergen --cells MESH [--json] [--deepest] [--jobs N] [-o OUT.vtu]\n"
    "  MESH        a volume mesh: .vtu, .vtk (legacy ASCII), or a .node/.ele pair (either name)\n"
    "  --json      one JSON object per cell in cell order, then {\"summary\": {...}}\n"
    "  --deepest   also the inscribed ball of each kernel: inscribed_radius, rho_over_h\n"
    "  --jobs N    threads (default: the machine's); the output does not depend on it\n"
    "  -o OUT.vtu  write the mesh with the results as CellData arrays (for ParaView)\n";

[[noreturn]] void usage_error(const std::string& message) {
  std::fprintf(stderr, "kergen: %s\n%s", message.c_str(), kUsage);
  std::exit(2);
}

struct CellArgs {
  std::string mesh, output;
  bool json = false, deepest = false;
  unsigned jobs = 0;
};

CellArgs parse(int argc, char** argv) {
  CellArgs args;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) usage_error(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "--cells") {
      if (!args.mesh.empty()) usage_error("--cells takes one mesh");
      args.mesh = value();
    } else if (arg == "--json") {
      args.json = true;
    } else if (arg == "--deepest") {
      args.deepest = true;
    } else if (arg == "-o" || arg == "--output") {
      args.output = value();
      const size_t dot = args.output.find_last_of('.');
      if (dot == std::string::npos || args.output.substr(dot) != ".vtu")
        usage_error("-o '" + args.output + "' must end in .vtu with --cells");
    } else if (arg == "--jobs") {
      const std::string text = value();
      char* end = nullptr;
      const unsigned long n = std::strtoul(text.c_str(), &end, 10);
      if (text.empty() || text[0] == '-' || *end != '\0' || n == 0 || n > 1024)
        usage_error("--jobs needs a whole number from 1 to 1024, got '" + text + "'");
      args.jobs = unsigned(n);
    } else if (arg == "-h" || arg == "--help") {
      std::fputs(kUsage, stdout);
      std::exit(0);
    } else {
      usage_error("option '" + arg + "' is not available with --cells");
    }
  }
  if (args.mesh.empty()) usage_error("--cells needs a mesh");
  return args;
}

// Every cell, by `threads` threads taking chunks of cells in turn; results in cell order.
std::vector<kergen::CellKernel> compute_all(const kergen::VolumeMesh& mesh, bool deepest, unsigned threads) {
  const size_t cells = mesh.num_cells();
  std::vector<kergen::CellKernel> results(cells);
  constexpr size_t kChunk = 256;
  std::atomic<size_t> next{0};
  kergen::CellOptions options;
  options.deepest_point = deepest;
  auto work = [&] {
    for (size_t first; (first = next.fetch_add(kChunk)) < cells;) {
      kergen::CellKernels chunk = kergen::compute_cell_kernels(mesh, options, first, kChunk);
      for (size_t i = 0; i < chunk.cells.size(); ++i) results[first + i] = std::move(chunk.cells[i]);
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  return results;
}

std::string cell_json(size_t index, const kergen::CellKernel& c, bool deepest) {
  std::string s = "{\"cell\":" + std::to_string(index);
  if (!c.ok()) {
    s += ",\"status\":null,\"error\":" + json_string(kergen::error_name(c.error));
    s += ",\"message\":" + json_string(c.message);
    s += ",\"diameter\":" + json_number(c.diameter) + "}";
    return s;
  }
  s += ",\"status\":" + json_string(kergen::kernel_type_name(c.type));
  s += ",\"kernel_volume\":" + json_number(c.kernel_volume);
  s += ",\"cell_volume\":" + json_number(c.cell_volume);
  s += ",\"kernel_ratio\":" + json_number(c.kernel_ratio);
  s += ",\"diameter\":" + json_number(c.diameter);
  if (deepest) {
    s += ",\"inscribed_radius\":" + json_number(c.inscribed_radius);
    s += ",\"rho_over_h\":" + json_number(c.rho_over_h);
  }
  if (c.type == kergen::KernelType::Empty) {
    s += ",\"witness_faces\":[";
    for (size_t i = 0; i < c.witness_faces.size(); ++i) s += (i ? "," : "") + std::to_string(c.witness_faces[i]);
    s += "]";
  }
  if (c.reoriented) s += ",\"reoriented\":true";
  return s + "}";
}

std::string spread_json(double lo, double mid, double hi) {
  return "{\"min\":" + json_number(lo) + ",\"median\":" + json_number(mid) + ",\"max\":" + json_number(hi) + "}";
}

std::string summary_json(const kergen::CellSummary& s, bool deepest) {
  std::string out = "{\"summary\":{\"cells\":" + std::to_string(s.cells) + ",\"ok\":" + std::to_string(s.ok_cells);
  out += ",\"by_status\":{";
  bool first = true;
  for (size_t t = 0; t < s.by_type.size(); ++t) {
    if (!s.by_type[t]) continue;
    out += (first ? "" : ",") + json_string(kergen::kernel_type_name(kergen::KernelType(t))) + ":" +
           std::to_string(s.by_type[t]);
    first = false;
  }
  out += "},\"by_error\":{";
  first = true;
  for (const auto& [error, n] : s.by_error) {
    out += (first ? "" : ",") + json_string(kergen::error_name(error)) + ":" + std::to_string(n);
    first = false;
  }
  out += "},\"reoriented_cells\":" + std::to_string(s.reoriented_cells);
  out += ",\"kernel_ratio\":" + spread_json(s.min_ratio, s.median_ratio, s.max_ratio);
  if (deepest) out += ",\"rho_over_h\":" + spread_json(s.min_rho_over_h, s.median_rho_over_h, s.max_rho_over_h);
  out += ",\"worst_cells\":[";
  for (size_t i = 0; i < s.worst_cells.size(); ++i) out += (i ? "," : "") + std::to_string(s.worst_cells[i]);
  return out + "]}}";
}

void print_readable(const CellArgs& args, const kergen::CellSummary& s, const std::vector<kergen::CellKernel>& cells,
                    double seconds) {
  std::printf("%s: %zu cells, %zu ok", args.mesh.c_str(), s.cells, s.ok_cells);
  for (size_t t = 0; t < s.by_type.size(); ++t)
    if (s.by_type[t]) std::printf(", %s %zu", kergen::kernel_type_name(kergen::KernelType(t)), s.by_type[t]);
  for (const auto& [error, n] : s.by_error) std::printf(", %s %zu", kergen::error_name(error), n);
  std::printf("\n");
  if (s.reoriented_cells) std::printf("reoriented cells: %zu (faces turned to face outward)\n", s.reoriented_cells);
  std::printf("kernel ratio: min %.6g, median %.6g, max %.6g\n", s.min_ratio, s.median_ratio, s.max_ratio);
  if (args.deepest)
    std::printf("rho/h: min %.6g, median %.6g, max %.6g\n", s.min_rho_over_h, s.median_rho_over_h, s.max_rho_over_h);
  if (!s.worst_cells.empty()) {
    std::printf("worst cells (%s):", args.deepest ? "rho/h" : "kernel ratio");
    for (size_t c : s.worst_cells)
      std::printf(" %zu (%.4g)", c, args.deepest ? cells[c].rho_over_h : cells[c].kernel_ratio);
    std::printf("\n");
  }
  size_t shown = 0;
  for (const kergen::CellKernel& c : cells)
    if (!c.ok() && shown++ < 10) std::printf("  %s: %s\n", kergen::error_name(c.error), c.message.c_str());
  if (shown > 10) std::printf("  ... %zu more cells with errors\n", shown - 10);
  std::printf("time: %.3f s (%.0f cells/s)\n", seconds, seconds > 0 ? double(s.cells) / seconds : 0.0);
}

}  // namespace

int run_cells(int argc, char** argv) {
  const CellArgs args = parse(argc, argv);
  const auto start = std::chrono::steady_clock::now();
  const kergen::VolumeReadResult read = kergen::read_volume_mesh_file(args.mesh);
  if (!read.ok()) {
    std::fprintf(stderr, "kergen: %s\n", read.message.c_str());
    return 1;
  }
  const unsigned jobs = args.jobs ? args.jobs : std::max(1u, std::thread::hardware_concurrency());
  const std::vector<kergen::CellKernel> cells = compute_all(read.mesh, args.deepest, jobs);
  const kergen::CellSummary summary = kergen::summarize_cells(cells);
  if (!args.output.empty()) {
    std::string message;
    if (kergen::write_vtu_with_cell_data_file(args.output, read.mesh, cells, &message) != kergen::Error::Ok) {
      std::fprintf(stderr, "kergen: %s\n", message.c_str());
      return 1;
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (args.json) {
    std::string out;
    for (size_t i = 0; i < cells.size(); ++i) out += cell_json(i, cells[i], args.deepest) + "\n";
    out += summary_json(summary, args.deepest) + "\n";
    std::fwrite(out.data(), 1, out.size(), stdout);
  } else {
    print_readable(args, summary, cells, seconds);
  }
  return summary.ok_cells == summary.cells ? 0 : 1;
}
