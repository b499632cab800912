// Seed corpus writer for the fuzz targets (run by scripts/fuzz.sh; the corpus is not committed).
//   make_seeds OUT_DIR MESH...
// Writes every readable MESH (up to 64 KB) as OFF, OBJ, ascii STL and binary STL into
// OUT_DIR/{fuzz_off,fuzz_obj,fuzz_stl_ascii,fuzz_stl_binary}/, copies the original file into
// the directory of its own format as it is (so format quirks are kept), and writes one seed per
// generated base mesh for fuzz_kernel.
#include <sys/stat.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "kergen/io.h"

namespace {

void put(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
}

std::string ascii_stl(const kergen::Mesh& m) {
  std::string s = "solid seed\n";
  char buf[256];
  size_t off = 0;
  for (size_t f = 0; f < m.num_faces(); ++f) {
    size_t n = m.face_sizes.empty() ? 3 : m.face_sizes[f];
    for (size_t i = 1; i + 1 < n; ++i) {
      s += " facet normal 0 0 0\n  outer loop\n";
      for (size_t c : {size_t(0), i, i + 1}) {
        const double* p = &m.positions[3 * size_t(m.indices[off + c])];
        std::snprintf(buf, sizeof buf, "   vertex %.9g %.9g %.9g\n", p[0], p[1], p[2]);
        s += buf;
      }
      s += "  endloop\n endfacet\n";
    }
    off += n;
  }
  return s + "endsolid seed\n";
}

std::string base(const std::string& path) {
  size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: make_seeds OUT_DIR MESH...\n");
    return 2;
  }
  const std::string out = argv[1];
  const char* dirs[] = {"fuzz_off", "fuzz_obj", "fuzz_stl_ascii", "fuzz_stl_binary", "fuzz_kernel"};
  mkdir(out.c_str(), 0755);
  for (const char* d : dirs) mkdir((out + "/" + d).c_str(), 0755);
  int written = 0;
  for (int i = 2; i < argc; ++i) {
    const std::string path = argv[i];
    struct stat st;
    if (stat(path.c_str(), &st) != 0 || st.st_size > 65536) continue;
    std::ifstream f(path, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    const std::string name = base(path);
    const kergen::MeshFormat fmt = kergen::format_from_path(path);
    if (fmt == kergen::MeshFormat::Off) put(out + "/fuzz_off/orig-" + name, bytes);
    if (fmt == kergen::MeshFormat::Obj) put(out + "/fuzz_obj/orig-" + name, bytes);
    if (fmt == kergen::MeshFormat::Stl) {
      put(out + "/fuzz_stl_ascii/orig-" + name, bytes);
      put(out + "/fuzz_stl_binary/orig-" + name, std::string(1, '\0') + bytes);
    }
    const kergen::ReadResult r = kergen::read_mesh(bytes, fmt, name);
    if (!r.ok()) continue;
    put(out + "/fuzz_off/" + name + ".off", kergen::write_off(r.mesh));
    put(out + "/fuzz_obj/" + name + ".obj", kergen::write_obj(r.mesh));
    if (r.mesh.num_faces() <= 400) {
      put(out + "/fuzz_stl_ascii/" + name + ".stl", ascii_stl(r.mesh));
      put(out + "/fuzz_stl_binary/" + name + ".stl", std::string(1, '\1') + kergen::write_stl_binary(r.mesh));
    }
    ++written;
  }
  // fuzz_kernel: one seed per base mesh, plain and at the extreme scales.
  for (int which = 0; which < 24; ++which)
    for (int sb : {0, 1, 2}) {
      std::string s;
      s += char(which);
      s += char(0);
      s += char(sb);
      s += char(0);
      put(out + "/fuzz_kernel/base-" + std::to_string(which) + "-" + std::to_string(sb), s);
    }
  std::printf("make_seeds: %d meshes converted into %s\n", written, out.c_str());
  return 0;
}
