// The README's C++ example: the kernel of an L-shaped prism, streamed step by step.
// Built and run by ctest (test name: api_example).
#include <cstdio>
#include <vector>

#include "kergen/io.h"
#include "kergen/kergen.h"

int main() {
  // An L-shaped prism: the L (0,0)-(2,0)-(2,1)-(1,1)-(1,2)-(0,2) extruded over z in [0, 1].
  // Polygon faces, counter-clockwise seen from outside.
  const double L[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  kergen::Mesh mesh;
  for (int z = 0; z <= 1; ++z)
    for (const auto& p : L) mesh.positions.insert(mesh.positions.end(), {p[0], p[1], double(z)});
  mesh.indices = {5, 4, 3, 2, 1, 0, 6, 7, 8, 9, 10, 11};  // bottom (seen from below), top
  mesh.face_sizes = {6, 6};
  for (uint32_t i = 0; i < 6; ++i) {  // side quads
    uint32_t j = (i + 1) % 6;
    mesh.indices.insert(mesh.indices.end(), {i, j, 6 + j, 6 + i});
    mesh.face_sizes.push_back(4);
  }

  kergen::Options options;
  int edges_seen = 0;
  options.on_step = [&](const kergen::StepEvent& e) {
    if (e.kind == kergen::StepEvent::Kind::Edge) ++edges_seen;
    return true;  // false would stop here with a valid partial kernel
  };
  kergen::Kernel k = kergen::compute_kernel(mesh.view(), options);
  if (!k.ok()) {
    std::fprintf(stderr, "error %s: %s\n", kergen::error_name(k.error), k.message.c_str());
    return 1;
  }
  std::printf("%s: %zu vertices, %zu edges (%d streamed), %zu faces, volume %g of %g\n",
              kergen::kernel_type_name(k.type), k.num_vertices(), k.num_edges(), edges_seen, k.num_faces(), k.volume,
              k.shape_volume);
  // What bounds it: the input face each kernel face lies on (the bottom 0, the top 1, the sides
  // y = 0 and x = 0, faces 2 and 7, and the L's inner sides y = 1 and x = 1, faces 4 and 5).
  std::printf("on input faces");
  for (int32_t source : k.face_sources) std::printf(" %d", source);
  std::printf("\n");

  // Emptiness test only (one LP), and the kernel written as a mesh file.
  kergen::KernelPoint p = kergen::find_kernel_point(mesh.view());
  std::printf("star-shaped: %s, kernel point (%g, %g, %g)\n", p.star_shaped ? "yes" : "no", p.point[0], p.point[1],
              p.point[2]);
  std::string obj = kergen::write_obj(kergen::kernel_mesh(k));
  return (k.type == kergen::KernelType::Polyhedron && k.volume == 1 && !obj.empty()) ? 0 : 1;
}
