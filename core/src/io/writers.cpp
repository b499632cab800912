// writers.cpp — mesh files out: the OBJ, OFF and binary STL writers (every coordinate bit kept in
// the text formats), write_mesh and write_mesh_file (and write_file_bytes, which the VTU writer shares); and the two
// conversions between Mesh and the core's types, Mesh::view and kernel_mesh.
#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <new>
#include <stdexcept>
#include <string>

#include "io/numbers.h"  // KERGEN_FROM_CHARS_DOUBLE
#include "io/reader.h"   // write_file_bytes
#include "kergen/io.h"

namespace kergen {

MeshView Mesh::view() const {
  MeshView v;
  v.positions = positions.empty() ? nullptr : positions.data();
  v.num_vertices = positions.size() / 3;
  v.indices = indices.empty() ? nullptr : indices.data();
  v.num_indices = indices.size();
  if (!face_sizes.empty()) {
    v.face_sizes = face_sizes.data();
    v.num_faces = face_sizes.size();
  }
  return v;
}

namespace {

// %.17g round-trips every double. std::to_chars gives the same text without the locale (and
// faster); where it is missing, snprintf's decimal comma, if the host program set such a locale,
// is turned back into a point.
void append_double(std::string& out, double value) {
  char buf[40];
#if KERGEN_FROM_CHARS_DOUBLE
  auto converted = std::to_chars(buf, buf + sizeof buf, value, std::chars_format::general, 17);
  out.append(buf, converted.ptr);
#else
  int n = std::snprintf(buf, sizeof buf, "%.17g", value);
  for (int i = 0; i < n; ++i)
    if (buf[i] == ',') buf[i] = '.';
  out.append(buf, static_cast<size_t>(n));
#endif
}

void append_uint(std::string& out, uint64_t value) {
  char buf[24];
  auto converted = std::to_chars(buf, buf + sizeof buf, value);
  out.append(buf, converted.ptr);
}

// Calls visit(first_index_pointer, size) for each face; a face running past the index array (a
// malformed Mesh) ends the walk instead of reading out of bounds.
template <class Visit>
void for_each_face(const Mesh& mesh, Visit visit) {
  if (mesh.face_sizes.empty()) {
    for (size_t i = 0; i + 3 <= mesh.indices.size(); i += 3) visit(&mesh.indices[i], size_t(3));
    return;
  }
  size_t offset = 0;
  for (uint32_t size : mesh.face_sizes) {
    if (offset + size > mesh.indices.size()) break;
    visit(mesh.indices.data() + offset, size_t(size));
    offset += size;
  }
}

size_t count_faces(const Mesh& mesh) {
  size_t faces = 0;
  for_each_face(mesh, [&](const uint32_t*, size_t) { ++faces; });
  return faces;
}

void append_le32(std::string& out, uint32_t value) {
  char b[4] = {char(value & 0xFF), char((value >> 8) & 0xFF), char((value >> 16) & 0xFF), char((value >> 24) & 0xFF)};
  out.append(b, 4);
}

void append_le_float(std::string& out, float value) {
  uint32_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  append_le32(out, bits);
}

// One "<prefix>x y z" line per vertex, every coordinate bit kept.
void append_vertex_lines(std::string& out, const Mesh& mesh, const char* prefix) {
  for (size_t v = 0; v + 3 <= mesh.positions.size(); v += 3) {
    out += prefix;
    append_double(out, mesh.positions[v]);
    out += ' ';
    append_double(out, mesh.positions[v + 1]);
    out += ' ';
    append_double(out, mesh.positions[v + 2]);
    out += '\n';
  }
}

}  // namespace

// Public writers.

std::string write_obj(const Mesh& mesh) {
  std::string out = "# written by kergen\n";
  out.reserve(out.size() + mesh.positions.size() * 24 + mesh.indices.size() * 8);
  append_vertex_lines(out, mesh, "v ");
  for_each_face(mesh, [&](const uint32_t* loop, size_t size) {
    out += 'f';
    for (size_t k = 0; k < size; ++k) {
      out += ' ';
      append_uint(out, uint64_t(loop[k]) + 1);
    }
    out += '\n';
  });
  return out;
}

std::string write_off(const Mesh& mesh) {
  std::string out = "OFF\n";
  out.reserve(mesh.positions.size() * 24 + mesh.indices.size() * 8 + 32);
  append_uint(out, mesh.positions.size() / 3);
  out += ' ';
  append_uint(out, count_faces(mesh));
  out += " 0\n";
  append_vertex_lines(out, mesh, "");
  for_each_face(mesh, [&](const uint32_t* loop, size_t size) {
    append_uint(out, size);
    for (size_t k = 0; k < size; ++k) {
      out += ' ';
      append_uint(out, loop[k]);
    }
    out += '\n';
  });
  return out;
}

std::string write_stl_binary(const Mesh& mesh) {
  const size_t vertex_count = mesh.positions.size() / 3;
  std::string triangles;
  uint64_t triangle_count = 0;
  auto corner = [&](uint32_t index, int k) { return mesh.positions[3 * size_t(index) + k]; };
  for_each_face(mesh, [&](const uint32_t* loop, size_t size) {
    for (size_t k = 1; k + 1 < size; ++k) {
      const uint32_t a = loop[0], b = loop[k], c = loop[k + 1];
      if (a >= vertex_count || b >= vertex_count || c >= vertex_count) continue;  // malformed mesh
      double u[3], w[3], n[3];
      for (int d = 0; d < 3; ++d) u[d] = corner(b, d) - corner(a, d), w[d] = corner(c, d) - corner(a, d);
      n[0] = u[1] * w[2] - u[2] * w[1];
      n[1] = u[2] * w[0] - u[0] * w[2];
      n[2] = u[0] * w[1] - u[1] * w[0];
      const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      for (double& x : n) x = length > 0 && std::isfinite(length) ? x / length : 0.0;
      for (double x : n) append_le_float(triangles, static_cast<float>(x));
      for (uint32_t v : {a, b, c})
        for (int d = 0; d < 3; ++d) append_le_float(triangles, static_cast<float>(corner(v, d)));
      triangles.append(2, '\0');  // attribute byte count
      ++triangle_count;
    }
  });
  std::string out = "binary STL written by kergen";
  out.resize(80, ' ');
  append_le32(out, static_cast<uint32_t>(std::min<uint64_t>(triangle_count, 0xFFFFFFFFu)));
  out += triangles;
  return out;
}

std::string write_mesh(const Mesh& mesh, MeshFormat format) {
  switch (format) {
    case MeshFormat::Off: return write_off(mesh);
    case MeshFormat::Obj: return write_obj(mesh);
    case MeshFormat::Stl: return write_stl_binary(mesh);
    default: break;
  }
  throw std::invalid_argument("write_mesh: no writer for this format (Off, Obj or Stl)");
}

Error write_mesh_file(const std::string& path, const Mesh& mesh, std::string* message) {
  auto failed = [&](const std::string& reason) {
    if (message) *message = path + ": " + reason;
    return Error::IoError;
  };
  std::string bytes;
  const MeshFormat format = format_from_path(path);
  if (format != MeshFormat::Off && format != MeshFormat::Obj && format != MeshFormat::Stl)
    return failed("unsupported file type (expected .off, .obj or .stl)");
  try {
    bytes = write_mesh(mesh, format);
  } catch (const std::bad_alloc&) { return failed("out of memory while formatting the mesh"); }
  return io::write_file_bytes(path, bytes, message);
}

namespace io {

Error write_file_bytes(const std::string& path, const std::string& bytes, std::string* message) {
  auto failed = [&](const std::string& reason) {
    if (message) *message = path + ": " + reason;
    return Error::IoError;
  };
  FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) return failed(std::string("cannot open for writing: ") + std::strerror(errno));
  const bool written = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
  const int write_errno = errno;
  const bool closed = std::fclose(file) == 0;
  if (!written) return failed(std::string("write failed: ") + std::strerror(write_errno));
  if (!closed) return failed(std::string("write failed: ") + std::strerror(errno));
  if (message) message->clear();
  return Error::Ok;
}

}  // namespace io

Mesh kernel_mesh(const Kernel& kernel) {
  Mesh mesh;
  mesh.positions = kernel.vertices;
  // Point and segment kernels have vertices but no face; an empty kernel has neither.
  if (kernel.type == KernelType::Polygon || kernel.type == KernelType::Polyhedron ||
      kernel.type == KernelType::Unbounded) {
    mesh.indices = kernel.face_indices;
    mesh.face_sizes = kernel.face_sizes;
  }
  if (kernel.type == KernelType::Empty) mesh.positions.clear();
  return mesh;
}

}  // namespace kergen
