// kernel_info [mesh file]: the kernel of a mesh file (OFF, OBJ, STL, PLY), or of the cube
// [-1, 1]^3 when no file is given, as three lines: type, vertices, volume.
#include <cstdio>
#include <utility>

#include "kergen/io.h"
#include "kergen/kergen.h"

static kergen::Mesh cube() {
  kergen::Mesh mesh;
  for (int i = 0; i < 8; ++i)  // vertex i has x, y, z = bits 0, 1, 2 of i
    mesh.positions.insert(mesh.positions.end(), {i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0});
  // Quads counter-clockwise seen from outside: -z, +z, -y, +y, -x, +x.
  mesh.indices = {0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4, 2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5};
  mesh.face_sizes = {4, 4, 4, 4, 4, 4};
  return mesh;
}

int main(int argc, char** argv) {
  kergen::Mesh mesh = cube();
  if (argc > 1) {
    kergen::ReadResult file = kergen::read_mesh_file(argv[1]);
    if (!file.ok()) {
      std::fprintf(stderr, "error %s: %s\n", kergen::error_name(file.error), file.message.c_str());
      return 1;
    }
    mesh = std::move(file.mesh);
  }
  kergen::Kernel kernel = kergen::compute_kernel(mesh.view());
  if (!kernel.ok()) {
    std::fprintf(stderr, "error %s: %s\n", kergen::error_name(kernel.error), kernel.message.c_str());
    return 1;
  }
  std::printf("type: %s\nvertices: %zu\nvolume: %.17g\n", kergen::kernel_type_name(kernel.type), kernel.num_vertices(),
              kernel.volume);
  return 0;
}
