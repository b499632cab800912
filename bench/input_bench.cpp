// input_bench: the input pass, in memory — reader throughput (MB/s, ns per face) and the
// validation and plane phases (ns per face), median of --runs runs. Files are read from disk once
// and parsed from memory, so the disk is not timed. With --formats every mesh is also written in
// memory as OFF, OBJ, ASCII STL and binary STL and each of those is parsed, so one generated
// sphere gives every reader's row.
//
// The STL path (--stl): each mesh written as binary STL in memory, then per phase what a user of
// `kergen file.stl` meets with the default weld (1e-9 of the bounding box diagonal): the reader
// (which merges equal positions), validate_mesh without weld, with weld 0 and with the default
// weld (their difference is the weld), compute_kernel with the default weld, and bytes to kernel
// (reader + compute_kernel). A checksum of repair_mesh's welded mesh (FNV-1a over its positions,
// indices and warning counts) compares builds.
//
// Times are the thread's CPU time (CLOCK_THREAD_CPUTIME_ID), not wall time: on a machine shared
// with builds, a wall-clock run is preempted for whole time slices (milliseconds), which no median
// of a few runs removes; CPU time counts only the work done (cache misses included).
//
//   input_bench [--runs N] [--formats] [--stl] FILE...
#include <time.h>

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "bench_util.h"
#include "kergen/io.h"
#include "kergen/kergen.h"

namespace {

using kergen_bench::fmt;
using kergen_bench::median;

double cpu_ms() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

// ASCII STL as exporters write it (write_mesh's STL is binary): polygons fanned, normals zero.
std::string ascii_stl(const kergen::Mesh& mesh) {
  std::string out = "solid bench\n";
  char buf[32];
  auto put = [&](double x) {
    out += ' ';
    out.append(buf, std::to_chars(buf, buf + sizeof buf, x).ptr);
  };
  auto facet = [&](uint32_t a, uint32_t b, uint32_t c) {
    out += "  facet normal 0 0 0\n    outer loop\n";
    for (uint32_t v : {a, b, c}) {
      out += "      vertex";
      for (int k = 0; k < 3; ++k) put(mesh.positions[3 * size_t(v) + k]);
      out += '\n';
    }
    out += "    endloop\n  endfacet\n";
  };
  size_t at = 0;
  for (size_t f = 0; f < mesh.num_faces(); ++f) {
    const size_t k = mesh.face_sizes.empty() ? 3 : mesh.face_sizes[f];
    for (size_t i = 1; i + 1 < k; ++i) facet(mesh.indices[at], mesh.indices[at + i], mesh.indices[at + i + 1]);
    at += k;
  }
  return out + "endsolid bench\n";
}

struct Input {
  std::string label;  // file name and, with --formats, the format it was written in
  std::string bytes;
  kergen::MeshFormat format;
};

// The file's bytes; a file that cannot be opened ends the run with the system's reason (not an
// "empty file" row, which is what reading nothing would give).
std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "input_bench: %s: %s\n", path.c_str(), std::strerror(errno));
    std::exit(1);
  }
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Median ms of `runs` calls of f.
template <class F>
double time_median(int runs, F f) {
  std::vector<double> ms;
  for (int r = 0; r < runs; ++r) {
    const double t = cpu_ms();
    f();
    ms.push_back(cpu_ms() - t);
  }
  return median(ms);
}

void reader_row(const Input& in, int runs) {
  kergen::ReadResult result;
  const double ms = time_median(runs, [&] { result = kergen::read_mesh(in.bytes, in.format, in.label); });
  if (!result.ok()) {
    std::printf("| %s | %s | error: %s |\n", in.label.c_str(), fmt(in.bytes.size() / 1e6).c_str(),
                result.message.c_str());
    return;
  }
  const double faces = double(result.mesh.num_faces());
  std::printf("| %s | %s | %.0f | %s | %s | %s |\n", in.label.c_str(), fmt(in.bytes.size() / 1e6).c_str(), faces,
              fmt(ms).c_str(), fmt(in.bytes.size() / 1e3 / ms, 0).c_str(), fmt(ms * 1e6 / faces, 1).c_str());
}

// validate_mesh; find_kernel_point, which is validation, planes and one LP (so planes + LP is
// the difference); compute_kernel.
void core_row(const std::string& label, const kergen::Mesh& mesh, int runs) {
  const double validate = time_median(runs, [&] { (void)kergen::validate_mesh(mesh.view()); });
  const double point = time_median(runs, [&] { (void)kergen::find_kernel_point(mesh.view()); });
  const double total = time_median(runs, [&] { (void)kergen::compute_kernel(mesh.view()); });
  const double per_face = 1e6 / double(mesh.num_faces());
  std::printf("| %s | %zu | %s | %s | %s | %s |\n", label.c_str(), mesh.num_faces(),
              fmt(validate * per_face, 1).c_str(), fmt((point - validate) * per_face, 1).c_str(),
              fmt(point * per_face, 1).c_str(), fmt(total * per_face, 1).c_str());
}

uint64_t fnv1a(uint64_t h, const void* data, size_t bytes) {
  const auto* b = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < bytes; ++i) h = (h ^ b[i]) * 0x100000001b3ull;
  return h;
}

// The STL path of a mesh (see the header): ms per phase.
void stl_row(const std::string& label, const kergen::Mesh& mesh, int runs) {
  const std::string bytes = kergen::write_stl_binary(mesh);
  kergen::ReadResult read;
  const double parse = time_median(runs, [&] { read = kergen::read_mesh(bytes, kergen::MeshFormat::Stl, label); });
  if (!read.ok()) {
    std::printf("| %s | error: %s |\n", label.c_str(), read.message.c_str());
    return;
  }
  const kergen::MeshView view = read.mesh.view();
  kergen::Options exact, weld;
  exact.weld = 0;
  weld.weld = 1e-9;  // the CLI's default for STL files
  weld.weld_relative = true;
  const double none = time_median(runs, [&] { (void)kergen::validate_mesh(view); });
  const double equal = time_median(runs, [&] { (void)kergen::validate_mesh(view, exact); });
  const double welded = time_median(runs, [&] { (void)kergen::validate_mesh(view, weld); });
  const double kernel = time_median(runs, [&] { (void)kergen::compute_kernel(view, weld); });
  const kergen::RepairedMesh r = kergen::repair_mesh(view, weld);
  uint64_t h = 0xcbf29ce484222325ull;
  h = fnv1a(h, r.mesh.positions.data(), r.mesh.positions.size() * sizeof(double));
  h = fnv1a(h, r.mesh.indices.data(), r.mesh.indices.size() * sizeof(uint32_t));
  for (const auto& w : r.warnings) h = fnv1a(h, &w.count, sizeof w.count);
  std::printf("| %s | %zu | %zu | %s | %s | %s | %s | %s | %s | %016llx |\n", label.c_str(), read.mesh.num_faces(),
              read.mesh.num_vertices(), fmt(parse).c_str(), fmt(none).c_str(), fmt(equal).c_str(), fmt(welded).c_str(),
              fmt(kernel).c_str(), fmt(parse + kernel).c_str(), static_cast<unsigned long long>(h));
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 5;
  bool formats = false, stl = false;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--runs" && i + 1 < argc)
      runs = std::max(1, std::atoi(argv[++i]));
    else if (a == "--formats")
      formats = true;
    else if (a == "--stl")
      stl = true;
    else if (a == "-h" || a == "--help") {
      std::printf("usage: input_bench [--runs N] [--formats] [--stl] FILE...\n");
      return 0;
    } else
      files.push_back(a);
  }
  if (files.empty()) {
    std::fprintf(stderr, "input_bench: no files (try: node scripts/gen-big-mesh.mjs /tmp/sphere.off)\n");
    return 2;
  }
  double load[3] = {0, 0, 0};
  if (FILE* f = std::fopen("/proc/loadavg", "r")) {
    if (std::fscanf(f, "%lf %lf %lf", &load[0], &load[1], &load[2]) != 3) load[0] = -1;
    std::fclose(f);
  }
  std::printf("# input_bench | median of %d run(s), thread CPU time | load average %.2f at start\n\n", runs, load[0]);
  std::vector<Input> inputs;
  std::vector<std::pair<std::string, kergen::Mesh>> meshes;
  for (const auto& path : files) {
    std::string bytes = slurp(path);
    const std::string name = path.substr(path.find_last_of('/') + 1);
    kergen::ReadResult r = kergen::read_mesh(bytes, kergen::MeshFormat::Unknown, path);
    inputs.push_back({name, bytes, kergen::format_from_path(path)});
    if (!r.ok()) continue;
    if (formats) {
      inputs.push_back(
          {name + " as OFF", kergen::write_mesh(r.mesh, kergen::MeshFormat::Off), kergen::MeshFormat::Off});
      inputs.push_back(
          {name + " as OBJ", kergen::write_mesh(r.mesh, kergen::MeshFormat::Obj), kergen::MeshFormat::Obj});
      inputs.push_back({name + " as ASCII STL", ascii_stl(r.mesh), kergen::MeshFormat::Stl});
      inputs.push_back({name + " as binary STL", kergen::write_stl_binary(r.mesh), kergen::MeshFormat::Stl});
    }
    meshes.emplace_back(name, std::move(r.mesh));
  }
  std::printf("| input (parsed from memory) | MB | faces | ms | MB/s | ns/face |\n|---|---:|---:|---:|---:|---:|\n");
  for (const auto& in : inputs) reader_row(in, runs);
  std::printf(
      "\n| mesh | faces | validate ns/face | planes + LP ns/face | find_kernel_point ns/face | compute_kernel ns/face "
      "|\n|---|---:|---:|---:|---:|---:|\n");
  for (const auto& [name, mesh] : meshes) core_row(name, mesh, runs);
  if (stl) {
    std::printf(
        "\n| as binary STL | faces | vertices read | read ms | validate ms | weld 0 ms | weld 1e-9 ms | compute_kernel "
        "ms | bytes to kernel ms | welded mesh checksum |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---|\n");
    for (const auto& [name, mesh] : meshes) stl_row(name, mesh, runs);
  }
  return 0;
}
