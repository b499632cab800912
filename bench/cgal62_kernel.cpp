// cgal62_kernel: CGAL 6.2's Polygon_mesh_processing::kernel on one mesh file, for kergen_bench's
// optional CGAL 6.2 column (see README.md). A program of its own because it is compiled against
// CGAL 6.2's headers (bench/get-cgal62.sh) while kergen_bench and the oracle use the system's CGAL:
// two CGAL versions must never meet in one link.
//   cgal62_kernel FILE RUNS BUDGET_MS FLIP
// reads FILE with kergen's reader (not timed), builds a Surface_mesh of Epeck points (timed, as
// a user starting from arrays would), computes the kernel RUNS times (stopping after a run longer
// than BUDGET_MS) and prints one line: "ms <median> runs <n> vertices <V> faces <F>".
// FLIP = 1 reverses every face (when kergen's validation found the mesh inward-facing).
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/version.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench_util.h"
#include "kergen/io.h"

using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Epeck::Point_3>;

namespace {

SurfaceMesh to_surface_mesh(const kergen::Mesh& m, bool flip) {
  SurfaceMesh sm;
  std::vector<SurfaceMesh::Vertex_index> v;
  v.reserve(m.num_vertices());
  for (size_t i = 0; i < m.num_vertices(); ++i)
    v.push_back(sm.add_vertex(Epeck::Point_3(m.positions[3 * i], m.positions[3 * i + 1], m.positions[3 * i + 2])));
  std::vector<SurfaceMesh::Vertex_index> loop;
  size_t off = 0;
  for (size_t f = 0; f < m.num_faces(); ++f) {
    const size_t k = m.face_sizes.empty() ? 3 : m.face_sizes[f];
    loop.clear();
    for (size_t j = 0; j < k; ++j) loop.push_back(v[m.indices[off + (flip ? k - 1 - j : j)]]);
    off += k;
    sm.add_face(loop);
  }
  return sm;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 2 && std::string(argv[1]) == "--version") {
    std::printf("%s\n", CGAL_VERSION_STR);
    return 0;
  }
  if (argc != 5) {
    std::fprintf(stderr, "usage: cgal62_kernel FILE RUNS BUDGET_MS FLIP\n");
    return 2;
  }
  const kergen::ReadResult rr = kergen::read_mesh_file(argv[1]);
  if (!rr.ok()) {
    std::fprintf(stderr, "%s\n", rr.message.c_str());
    return 1;
  }
  const int runs = std::max(1, std::atoi(argv[2]));
  const double budget_ms = std::atof(argv[3]);
  const bool flip = std::atoi(argv[4]) != 0;
  std::vector<double> times;
  size_t vertices = 0, faces = 0;
  for (int r = 0; r < runs; ++r) {
    const double t0 = kergen_bench::now_ms();
    const SurfaceMesh sm = to_surface_mesh(rr.mesh, flip);
    SurfaceMesh out;
    CGAL::Polygon_mesh_processing::kernel(sm, out);
    const double ms = kergen_bench::now_ms() - t0;
    times.push_back(ms);
    vertices = out.number_of_vertices();
    faces = out.number_of_faces();
    if (ms > budget_ms) break;
  }
  std::printf("ms %.6f runs %zu vertices %zu faces %zu\n", kergen_bench::median(times), times.size(), vertices, faces);
  return 0;
}
