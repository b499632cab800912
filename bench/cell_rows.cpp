// kergen_bench --cells (cell_rows.h): whole folders of small meshes in one warm process, the way
// a volume mesh's cells are computed, through compute_kernel and through a KernelBatch.
#include "cell_rows.h"

#include <time.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "bench_util.h"
#include "kergen/batch.h"
#include "kergen/io.h"
#include "kergen/kergen.h"

namespace kergen_bench {

namespace {

namespace fs = std::filesystem;

struct Folder {
  std::string label;
  std::vector<kergen::Mesh> meshes;
  size_t faces = 0, errors = 0;
};

bool read_folder(const std::string& dir, const std::string& label, Folder& out) {
  std::vector<std::string> files;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string ext = entry.path().extension().string();
    if (entry.is_regular_file() && (ext == ".off" || ext == ".obj" || ext == ".stl" || ext == ".ply"))
      files.push_back(entry.path().string());
  }
  if (ec || files.empty()) return false;
  std::sort(files.begin(), files.end());
  out.label = label;
  for (const std::string& f : files) {
    kergen::ReadResult r = kergen::read_mesh_file(f);
    if (!r.ok()) continue;
    out.faces += r.mesh.num_faces();
    out.meshes.push_back(std::move(r.mesh));
  }
  return !out.meshes.empty();
}

// The thread's CPU time (as input_bench's): on a machine shared with builds, wall time loses whole
// time slices to other processes, which no median of a few rounds removes.
double cpu_ms() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

// One round over every mesh: total CPU ms. `sink` keeps the results observable.
double single_round(const Folder& f, double& sink) {
  const double t = cpu_ms();
  for (const kergen::Mesh& m : f.meshes) {
    const kergen::Kernel k = kergen::compute_kernel(m.view());
    sink += k.volume + double(k.num_vertices());
  }
  return cpu_ms() - t;
}
double batch_round(const Folder& f, kergen::KernelBatch& batch, kergen::Kernel& k, double& sink) {
  const double t = cpu_ms();
  for (const kergen::Mesh& m : f.meshes) {
    batch.compute(m.view(), kergen::Options{}, k);
    sink += k.volume + double(k.num_vertices());
  }
  return cpu_ms() - t;
}

}  // namespace

int run_cell_rows(const std::string& meshes, const std::vector<std::string>& folders, int runs, bool json,
                  const std::string& json_context) {
  std::vector<std::pair<std::string, std::string>> dirs;  // path, label
  if (folders.empty()) {
    for (const char* d : {"tet10", "tet20", "tet30", "voro"})
      dirs.emplace_back((fs::path(meshes) / "polyhedra" / d).string(), std::string("polyhedra/") + d);
  } else {
    for (const std::string& d : folders) dirs.emplace_back(d, d);
  }
  if (!json)
    std::printf(
        "| cells | meshes | mean faces | single: CPU µs/cell | single: cells/s | batch: CPU µs/cell | batch: cells/s | "
        "single/batch |\n|---|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const auto& [dir, label] : dirs) {
    Folder f;
    if (!read_folder(dir, label, f)) {
      std::fprintf(stderr, "cells: no readable mesh file in %s\n", dir.c_str());
      return 1;
    }
    kergen::KernelBatch batch;
    kergen::Kernel reused;
    double sink = 0;
    for (const kergen::Mesh& m : f.meshes) f.errors += !kergen::compute_kernel(m.view()).ok();  // warm-up
    batch_round(f, batch, reused, sink);
    std::vector<double> single, batched;
    for (int r = 0; r < std::max(1, runs); ++r) {
      single.push_back(single_round(f, sink));
      batched.push_back(batch_round(f, batch, reused, sink));
    }
    const double n = double(f.meshes.size());
    const double us_single = 1000 * median(single) / n, us_batch = 1000 * median(batched) / n;
    if (json) {
      std::printf(
          "{\"cells\":\"%s\",%s,\"runs\":%d,\"meshes\":%zu,\"errors\":%zu,\"mean_faces\":%.2f,\"single_us_per_cell\":%."
          "3f,\"batch_us_per_cell\":%.3f,\"sink\":%g}\n",
          label.c_str(), json_context.c_str(), runs, f.meshes.size(), f.errors, double(f.faces) / n, us_single,
          us_batch, sink);
    } else {
      std::printf("| %s | %zu | %s | %s | %s | %s | %s | %s |\n", label.c_str(), f.meshes.size(),
                  fmt(double(f.faces) / n, 1).c_str(), fmt(us_single, 1).c_str(), fmt(1e6 / us_single, 0).c_str(),
                  fmt(us_batch, 1).c_str(), fmt(1e6 / us_batch, 0).c_str(), fmt(us_single / us_batch).c_str());
    }
    std::fflush(stdout);
  }
  return 0;
}

}  // namespace kergen_bench
