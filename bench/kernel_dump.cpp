// kernel_dump: every result field of the four entry points, printed exactly (%a), for mesh files
// or folders (recursive). Two builds' dumps are compared with `cmp` to show that a refactor or a
// speed-up left the results byte-identical; timings are left out.
//
//   kernel_dump [--from-first] [--out FILE] PATH...
//
// Per file: read_mesh_file, then compute_kernel (default options; STL welded by default as the
// CLI does), find_kernel_point, validate_mesh and repair_mesh (repair = true). --from-first also
// runs compute_kernel with Options::from at the first input vertex (the distance-ordered trace).
// (Fields added later print on lines of their own, face_sources and witness_boundary_edges*, so
// that a dump without them compares with an older build's.)
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "kergen/io.h"
#include "kergen/kergen.h"

namespace {

void print_doubles(FILE* out, const char* name, const double* v, size_t n) {
  std::fprintf(out, "%s %zu:", name, n);
  for (size_t i = 0; i < n; ++i) std::fprintf(out, " %a", v[i]);
  std::fputc('\n', out);
}

void print_ids(FILE* out, const char* name, const std::vector<uint32_t>& v) {
  std::fprintf(out, "%s %zu:", name, v.size());
  for (uint32_t x : v) std::fprintf(out, " %u", x);
  std::fputc('\n', out);
}

void print_ints(FILE* out, const char* name, const std::vector<int32_t>& v) {
  std::fprintf(out, "%s %zu:", name, v.size());
  for (int32_t x : v) std::fprintf(out, " %d", x);
  std::fputc('\n', out);
}

void print_warnings(FILE* out, const std::vector<kergen::Warning>& warnings) {
  for (const auto& w : warnings)
    std::fprintf(out, "warning %s %zu %s\n", kergen::warning_kind_name(w.kind), w.count, w.message.c_str());
}

void dump_kernel(FILE* out, const char* label, const kergen::Kernel& k) {
  std::fprintf(out, "%s %s type=%s complete=%d msg=%s\n", label, kergen::error_name(k.error),
               kergen::kernel_type_name(k.type), int(k.complete), k.message.c_str());
  print_doubles(out, "vertices", k.vertices.data(), k.vertices.size());
  print_ids(out, "edges", k.edges);
  print_ids(out, "face_indices", k.face_indices);
  print_ids(out, "face_sizes", k.face_sizes);
  print_ids(out, "triangles", k.triangles);
  print_ints(out, "face_sources", k.face_sources);
  std::fprintf(out, "volume %a area %a shape_volume %a ratio %a\n", k.volume, k.area, k.shape_volume, k.volume_ratio);
  print_ids(out, "witness", k.witness_faces);
  print_ids(out, "witness_boundary_edges", k.witness_boundary_edges);
  std::fprintf(out, "kernel_point %d %a %a %a deepest %d %a %a %a r %a\n", int(k.has_kernel_point), k.kernel_point[0],
               k.kernel_point[1], k.kernel_point[2], int(k.has_deepest_point), k.deepest_point[0], k.deepest_point[1],
               k.deepest_point[2], k.inscribed_radius);
  print_warnings(out, k.warnings);
  for (const auto& f : kergen::stats_fields(k.stats))
    if (std::strncmp(f.name, "ms_", 3) != 0) std::fprintf(out, "stat %s %a\n", f.name, f.value);
}

void dump_file(FILE* out, const std::string& path, bool from_first) {
  std::fprintf(out, "== %s\n", path.c_str());
  kergen::ReadResult r = kergen::read_mesh_file(path);
  std::fprintf(out, "read %s %s\n", kergen::error_name(r.error), r.message.c_str());
  if (!r.ok()) return;
  const kergen::MeshView view = r.mesh.view();
  kergen::Options options;
  if (kergen::format_from_path(path) == kergen::MeshFormat::Stl) {  // the CLI's default weld for STL
    options.weld = 1e-9;
    options.weld_relative = true;
  }
  dump_kernel(out, "compute", kergen::compute_kernel(view, options));
  if (from_first && r.mesh.num_vertices() > 0) {
    kergen::Options from = options;
    from.has_from = true;
    from.from = {r.mesh.positions[0], r.mesh.positions[1], r.mesh.positions[2]};
    dump_kernel(out, "compute_from", kergen::compute_kernel(view, from));
  }
  kergen::KernelPoint p = kergen::find_kernel_point(view, options);
  std::fprintf(out, "point %s star=%d %a %a %a msg=%s\n", kergen::error_name(p.error), int(p.star_shaped), p.point[0],
               p.point[1], p.point[2], p.message.c_str());
  print_ids(out, "point_witness", p.witness_faces);
  print_ids(out, "witness_boundary_edges_of_point", p.witness_boundary_edges);
  print_warnings(out, p.warnings);
  kergen::Validation v = kergen::validate_mesh(view, options);
  std::fprintf(out, "validate %s volume %a msg=%s\n", kergen::error_name(v.error), v.volume, v.message.c_str());
  print_warnings(out, v.warnings);
  kergen::Options repair = options;
  repair.repair = true;
  kergen::RepairedMesh m = kergen::repair_mesh(view, repair);
  std::fprintf(out, "repair %s msg=%s\n", kergen::error_name(m.error), m.message.c_str());
  print_doubles(out, "repaired_positions", m.mesh.positions.data(), m.mesh.positions.size());
  print_ids(out, "repaired_indices", m.mesh.indices);
  print_ids(out, "repaired_face_sizes", m.mesh.face_sizes);
  print_warnings(out, m.warnings);
}

bool is_mesh_file(const std::filesystem::path& p) {
  return kergen::format_from_path(p.string()) != kergen::MeshFormat::Unknown;
}

}  // namespace

int main(int argc, char** argv) {
  bool from_first = false;
  FILE* out = stdout;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--from-first") {
      from_first = true;
    } else if (a == "--out" && i + 1 < argc) {
      out = std::fopen(argv[++i], "w");
      if (!out) return std::perror(argv[i]), 2;
    } else if (std::filesystem::is_directory(a)) {
      for (const auto& e : std::filesystem::recursive_directory_iterator(a))
        if (e.is_regular_file() && is_mesh_file(e.path())) files.push_back(e.path().string());
    } else {
      files.push_back(a);
    }
  }
  if (files.empty()) {
    std::fprintf(stderr, "usage: kernel_dump [--from-first] [--out FILE] PATH...\n");
    return 2;
  }
  std::sort(files.begin(), files.end());
  for (const auto& f : files) dump_file(out, f, from_first);
  std::fprintf(stderr, "kernel_dump: %zu files\n", files.size());
  return 0;
}
