// kernel_dump: every result field of the four entry points, printed exactly (%a), for mesh files
// or folders (recursive). Two builds' dumps are compared with `cmp` to show that a refactor or a
// speed-up left the results byte-identical; timings are left out.
//
//   kernel_dump [--from-first] [--results] [--out FILE] PATH...
//
// --results prints the results only, each kernel put in canonical order by this tool itself (not
// by the library, so that two builds whose output orders differ still compare): vertices sorted
// by coordinates (ties keep the library's order), edges as sorted (low, high) pairs, faces as
// loops started at their lowest vertex, sorted by loop, each with its face source. Left out: the
// statistics, the LP's kernel point (compute_kernel's kernel_point, find_kernel_point's point:
// any kernel vertex), and the triangles, replaced by whether they are each face's fan from its
// first corner. An algorithm change must leave this output identical.
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

// The kernel in canonical order (see --results above), printed.
void dump_kernel_canonical(FILE* out, const char* label, const kergen::Kernel& k) {
  std::fprintf(out, "%s %s type=%s complete=%d msg=%s\n", label, kergen::error_name(k.error),
               kergen::kernel_type_name(k.type), int(k.complete), k.message.c_str());
  const size_t V = k.num_vertices();
  std::vector<uint32_t> order(V), rank(V);
  for (uint32_t i = 0; i < V; ++i) order[i] = i;
  const double* p = k.vertices.data();
  std::stable_sort(order.begin(), order.end(), [p](uint32_t a, uint32_t b) {
    return std::lexicographical_compare(p + 3 * a, p + 3 * a + 3, p + 3 * b, p + 3 * b + 3);
  });
  std::vector<double> vertices;
  for (uint32_t i = 0; i < V; ++i) {
    rank[order[i]] = i;
    vertices.insert(vertices.end(), p + 3 * order[i], p + 3 * order[i] + 3);
  }
  print_doubles(out, "vertices", vertices.data(), vertices.size());
  std::vector<std::pair<uint32_t, uint32_t>> edges;
  for (size_t e = 0; e < k.num_edges(); ++e) {
    const uint32_t a = rank[k.edges[2 * e]], b = rank[k.edges[2 * e + 1]];
    edges.push_back({std::min(a, b), std::max(a, b)});
  }
  std::sort(edges.begin(), edges.end());
  std::vector<uint32_t> flat_edges;
  for (const auto& [a, b] : edges) flat_edges.insert(flat_edges.end(), {a, b});
  print_ids(out, "edges", flat_edges);
  // Faces: (loop from its lowest vertex, source), sorted; the triangles checked against the fans.
  std::vector<std::pair<std::vector<uint32_t>, int32_t>> faces;
  bool fans = k.triangles.size() == 3 * [&] {
    size_t t = 0;
    for (uint32_t n : k.face_sizes) t += n >= 2 ? n - 2 : 0;
    return t;
  }();
  for (size_t f = 0, at = 0, tri = 0; f < k.num_faces(); at += k.face_sizes[f], ++f) {
    const uint32_t* loop = k.face_indices.data() + at;
    const uint32_t n = k.face_sizes[f];
    for (uint32_t i = 1; fans && i + 1 < n; ++i, tri += 3)
      fans = k.triangles[tri] == loop[0] && k.triangles[tri + 1] == loop[i] && k.triangles[tri + 2] == loop[i + 1];
    std::vector<uint32_t> ranked(n);
    for (uint32_t i = 0; i < n; ++i) ranked[i] = rank[loop[i]];
    std::rotate(ranked.begin(), std::min_element(ranked.begin(), ranked.end()), ranked.end());
    faces.push_back({ranked, f < k.face_sources.size() ? k.face_sources[f] : INT32_MIN});
  }
  std::sort(faces.begin(), faces.end());
  std::vector<uint32_t> face_indices, face_sizes;
  std::vector<int32_t> face_sources;
  for (const auto& [loop, source] : faces) {
    face_indices.insert(face_indices.end(), loop.begin(), loop.end());
    face_sizes.push_back(uint32_t(loop.size()));
    face_sources.push_back(source);
  }
  print_ids(out, "face_indices", face_indices);
  print_ids(out, "face_sizes", face_sizes);
  print_ints(out, "face_sources", face_sources);
  std::fprintf(out, "triangles %zu fans=%d\n", k.triangles.size() / 3, int(fans));
  std::fprintf(out, "volume %a area %a shape_volume %a ratio %a\n", k.volume, k.area, k.shape_volume, k.volume_ratio);
  print_ids(out, "witness", k.witness_faces);
  print_ids(out, "witness_boundary_edges", k.witness_boundary_edges);
  std::fprintf(out, "kernel_point %d deepest %d %a %a %a r %a\n", int(k.has_kernel_point), int(k.has_deepest_point),
               k.deepest_point[0], k.deepest_point[1], k.deepest_point[2], k.inscribed_radius);
  print_warnings(out, k.warnings);
}

void dump_file(FILE* out, const std::string& path, bool from_first, bool results) {
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
  auto dump = results ? dump_kernel_canonical : dump_kernel;
  dump(out, "compute", kergen::compute_kernel(view, options));
  if (from_first && r.mesh.num_vertices() > 0) {
    kergen::Options from = options;
    from.has_from = true;
    from.from = {r.mesh.positions[0], r.mesh.positions[1], r.mesh.positions[2]};
    dump(out, "compute_from", kergen::compute_kernel(view, from));
  }
  kergen::KernelPoint p = kergen::find_kernel_point(view, options);
  if (results)
    std::fprintf(out, "point %s star=%d msg=%s\n", kergen::error_name(p.error), int(p.star_shaped), p.message.c_str());
  else
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
  bool from_first = false, results = false;
  FILE* out = stdout;
  std::vector<std::string> files;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--from-first") {
      from_first = true;
    } else if (a == "--results") {
      results = true;
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
    std::fprintf(stderr, "usage: kernel_dump [--from-first] [--results] [--out FILE] PATH...\n");
    return 2;
  }
  std::sort(files.begin(), files.end());
  for (const auto& f : files) dump_file(out, f, from_first, results);
  std::fprintf(stderr, "kernel_dump: %zu files\n", files.size());
  return 0;
}
