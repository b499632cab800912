// Seed corpus writer for the fuzz targets (run by scripts/fuzz.sh; the corpus is not committed).
//   make_seeds OUT_DIR MESH...
// Writes every readable MESH (up to 64 KB) as OFF, OBJ, ascii STL, binary STL and PLY (ascii,
// binary little- and big-endian) into OUT_DIR/{fuzz_off,fuzz_obj,fuzz_stl_ascii,fuzz_stl_binary,
// fuzz_ply}/, copies the original file into
// the directory of its own format as it is (so format quirks are kept), and writes one seed per
// generated base mesh for fuzz_kernel (and fuzz_small_path), and volume seeds (each small mesh as one cell) for
// fuzz_vtu, fuzz_vtk_legacy and fuzz_node_ele.
#include <sys/stat.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>

#include "kergen/io.h"
#include "kergen/volume.h"

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

// PLY seeds (the project has no PLY writer): double coordinates, uchar counts and int indices,
// plus an ignored vertex property and an ignored element so the fuzzer starts from files that
// exercise the skipping paths. `order`: 0 ascii, 1 little-endian, 2 big-endian.
std::string ply_seed(const kergen::Mesh& m, int order) {
  const char* format[] = {"ascii", "binary_little_endian", "binary_big_endian"};
  std::string s = std::string("ply\nformat ") + format[order] + " 1.0\ncomment seed\nelement vertex " +
                  std::to_string(m.num_vertices()) +
                  "\nproperty double x\nproperty double y\nproperty double z\nproperty uchar red\nelement edge 1\n"
                  "property list uchar int vertex_index\nelement face " +
                  std::to_string(m.num_faces()) + "\nproperty list uchar int vertex_indices\nend_header\n";
  auto put_bytes = [&](const void* p, size_t n) {
    char b[8];
    std::memcpy(b, p, n);
    if (order == 2) std::reverse(b, b + n);  // the seed writer runs on little-endian hosts
    s.append(b, n);
  };
  auto number = [&](double v, const char* type, char after) {
    if (order == 0) {
      char buf[40];
      std::snprintf(buf, sizeof buf, "%.17g%c", v, after);
      s += buf;
    } else if (type[0] == 'd') {
      put_bytes(&v, 8);
    } else if (type[0] == 'i') {
      const int32_t i = static_cast<int32_t>(v);
      put_bytes(&i, 4);
    } else {
      const uint8_t u = static_cast<uint8_t>(v);
      put_bytes(&u, 1);
    }
  };
  for (size_t v = 0; v < m.num_vertices(); ++v) {
    for (int k = 0; k < 3; ++k) number(m.positions[3 * v + k], "double", ' ');
    number(7, "uchar", '\n');
  }
  number(2, "uchar", ' '), number(0, "int", ' '), number(1, "int", '\n');
  size_t off = 0;
  for (size_t f = 0; f < m.num_faces(); ++f) {
    const size_t n = m.face_sizes.empty() ? 3 : m.face_sizes[f];
    number(double(n), "uchar", ' ');
    for (size_t i = 0; i < n; ++i) number(m.indices[off + i], "int", i + 1 < n ? ' ' : '\n');
    off += n;
  }
  return s;
}

std::string base(const std::string& path) {
  size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace

// Volume seeds from a surface mesh taken as one cell (fuzz_vtu: the VTU writer's file and an
// ascii one; fuzz_vtk_legacy: version 4 CELLS with a polyhedron; fuzz_node_ele: the pair).
void put_volume_seeds(const std::string& out, const std::string& name, const kergen::Mesh& m) {
  kergen::VolumeMesh v;
  v.positions = m.positions;
  v.face_indices = m.indices;
  v.face_offsets = {0};
  for (size_t f = 0, at = 0; f < m.num_faces(); ++f) {
    at += m.face_sizes.empty() ? 3 : m.face_sizes[f];
    v.face_offsets.push_back(uint32_t(at));
    v.cell_faces.push_back(uint32_t(f));
  }
  v.cell_offsets = {0, uint32_t(m.num_faces())};
  put(out + "/fuzz_vtu/" + name + ".vtu", kergen::write_vtu_with_cell_data(v, kergen::compute_cell_kernels(v).cells));
  std::string points, stream = std::to_string(m.num_faces()), conn, node,
                      ele = "1 0\n0 " + std::to_string(m.num_faces()) + "\n";
  char buf[100];
  for (size_t i = 0; i < m.num_vertices(); ++i) {
    std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g", m.positions[3 * i], m.positions[3 * i + 1],
                  m.positions[3 * i + 2]);
    points += std::string(buf) + "\n";
    node += std::to_string(i) + " " + buf + "\n";
    conn += (i ? " " : "") + std::to_string(i);
  }
  size_t values = 1;
  for (size_t f = 0; f < m.num_faces(); ++f) {
    const uint32_t b = v.face_offsets[f], e = v.face_offsets[f + 1];
    stream += " " + std::to_string(e - b);
    ele += std::to_string(f) + " " + std::to_string(e - b);
    for (uint32_t k = b; k < e; ++k)
      stream += " " + std::to_string(m.indices[k]), ele += " " + std::to_string(m.indices[k]);
    ele += "\n";
    values += 1 + e - b;
  }
  put(out + "/fuzz_vtk_legacy/" + name + ".vtk",
      "# vtk DataFile Version 4.2\nseed\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS " + std::to_string(m.num_vertices()) +
          " double\n" + points + "CELLS 1 " + std::to_string(values + 1) + "\n" + std::to_string(values) + " " +
          stream + "\nCELL_TYPES 1\n42\n");
  put(out + "/fuzz_vtu/" + name + ".ascii.vtu",
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\">\n<UnstructuredGrid><Piece "
      "NumberOfPoints=\"" +
          std::to_string(m.num_vertices()) +
          "\" NumberOfCells=\"1\">\n<Points><DataArray "
          "type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n" +
          points +
          "</DataArray></Points>\n<Cells>\n"
          "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">" +
          conn +
          "</DataArray>\n"
          "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">" +
          std::to_string(m.num_vertices()) +
          "</DataArray>\n"
          "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">42</DataArray>\n"
          "<DataArray type=\"Int64\" Name=\"faces\" format=\"ascii\">" +
          stream +
          "</DataArray>\n"
          "<DataArray type=\"Int64\" Name=\"faceoffsets\" format=\"ascii\">" +
          std::to_string(values) +
          "</DataArray>\n"
          "</Cells></Piece></UnstructuredGrid></VTKFile>\n");
  put(out + "/fuzz_node_ele/" + name + ".txt",
      "# seed\n" + std::to_string(m.num_vertices()) + " 3 0 0\n" + node + "\n=====\n" + ele);
}

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: make_seeds OUT_DIR MESH...\n");
    return 2;
  }
  const std::string out = argv[1];
  const char* dirs[] = {"fuzz_off",   "fuzz_obj", "fuzz_stl_ascii",  "fuzz_stl_binary", "fuzz_ply",       "fuzz_kernel",
                        "fuzz_batch", "fuzz_vtu", "fuzz_vtk_legacy", "fuzz_node_ele",   "fuzz_small_path"};
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
    if (fmt == kergen::MeshFormat::Ply) put(out + "/fuzz_ply/orig-" + name, bytes);
    if (fmt == kergen::MeshFormat::Stl) {
      put(out + "/fuzz_stl_ascii/orig-" + name, bytes);
      put(out + "/fuzz_stl_binary/orig-" + name, std::string(1, '\0') + bytes);
    }
    const kergen::ReadResult r = kergen::read_mesh(bytes, fmt, name);
    if (!r.ok()) continue;
    put(out + "/fuzz_off/" + name + ".off", kergen::write_off(r.mesh));
    put(out + "/fuzz_obj/" + name + ".obj", kergen::write_obj(r.mesh));
    for (int order = 0; order < 3; ++order)
      put(out + "/fuzz_ply/" + name + "." + std::to_string(order) + ".ply", ply_seed(r.mesh, order));
    if (r.mesh.num_faces() <= 400) {
      put(out + "/fuzz_stl_ascii/" + name + ".stl", ascii_stl(r.mesh));
      put(out + "/fuzz_stl_binary/" + name + ".stl", std::string(1, '\1') + kergen::write_stl_binary(r.mesh));
    }
    if (r.mesh.num_faces() <= 200) put_volume_seeds(out, name, r.mesh);
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
      // fuzz_small_path decodes its input as fuzz_kernel does: the same seeds.
      put(out + "/fuzz_small_path/base-" + std::to_string(which) + "-" + std::to_string(sb), s);
    }
  // fuzz_batch: pairs and quadruples of base meshes (a large one next to small ones, star and
  // not, open and closed), each part 8 bytes.
  for (int first = 0; first < 24; ++first)
    for (int count : {2, 4}) {
      std::string s(1, char(count - 1));
      for (int i = 0; i < count; ++i) {
        std::string part(8, '\0');
        part[0] = char((first + 7 * i) % 24);
        part[1] = char(i == 1 ? 8 : 0);  // allow_open for the second
        s += part;
      }
      put(out + "/fuzz_batch/seq-" + std::to_string(first) + "-" + std::to_string(count), s);
    }
  std::printf("make_seeds: %d meshes converted into %s\n", written, out.c_str());
  return 0;
}
