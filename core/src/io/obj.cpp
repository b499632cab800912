// obj.cpp — the OBJ reader (read_obj): vertex positions and faces of a Wavefront OBJ file
// (Wavefront Technologies, "Object Files (.obj)", Appendix B1 of The Advanced Visualizer manual).
// Faces may use relative (negative) indices and may refer to vertices defined further down;
// texture coordinates, normals, groups, materials and curves do not affect the shape and are skipped.
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "io/numbers.h"
#include "io/reader.h"
#include "io/text_scan.h"
#include "kergen/io.h"
#include "util/plural.h"

namespace kergen {

using namespace io;  // the readers' shared parts: reader.h, text_scan.h, numbers.h

namespace {

void parse_obj(std::string_view text, const std::string& name, Mesh& mesh) {
  text = prepare_text(text, name);
  LineReader lines(text);
  std::string_view line;
  size_t point_and_line_records = 0;
  // Positive indices may refer to vertices defined further down; they are checked at the end.
  uint64_t largest_positive_index = 0;
  size_t largest_positive_index_line = 0;
  std::vector<uint32_t> face;
  while (lines.next(line)) {
    Tokens tokens(strip_comment(line));
    std::string_view keyword;
    if (!tokens.next(keyword)) continue;
    size_t line_number = lines.line_number();
    if (keyword == "v") {
      double xyz[3];
      read_coordinates(tokens, xyz, name, line_number, "vertex");
      for (double x : xyz) mesh.positions.push_back(x);
      check_vertex_count(mesh.positions.size() / 3, name, line_number);
      // Anything after x y z (a w component or vertex colours) is ignored.
    } else if (keyword == "f" || keyword == "fo") {
      face.clear();
      const long long vertices_so_far = static_cast<long long>(mesh.positions.size() / 3);
      std::string_view token;
      while (tokens.next(token)) {
        // v, v/vt, v//vn or v/vt/vn: only the position index matters, the others must be integers.
        // (A byte loop: the tokens are short, a memchr call per part cost more than the scan.)
        std::string_view parts[3];
        size_t part_count = 0, start = 0;
        for (size_t i = 0;; ++i) {
          if (i < token.size() && token[i] != '/') continue;
          if (part_count == 3) fail_at_line(name, line_number, "invalid face vertex " + quoted(token));
          parts[part_count++] = token.substr(start, i - start);
          if (i == token.size()) break;
          start = i + 1;
        }
        long long index = 0, unused = 0;
        if (!parse_integer(parts[0], index)) fail_at_line(name, line_number, "invalid face vertex " + quoted(token));
        for (size_t p = 1; p < part_count; ++p)
          if (!parts[p].empty() && !parse_integer(parts[p], unused))
            fail_at_line(name, line_number, "invalid face vertex " + quoted(token));
        if (index == 0) fail_at_line(name, line_number, "vertex index 0 (OBJ indices start at 1)");
        uint32_t resolved;
        if (index < 0) {
          if (-index > vertices_so_far)
            fail_at_line(name, line_number,
                         "relative vertex index " + std::to_string(index) + " points before the first vertex (" +
                             count_of(vertices_so_far, "vertex", "vertices") + " so far)");
          resolved = static_cast<uint32_t>(vertices_so_far + index);
        } else {
          if (index > static_cast<long long>(std::numeric_limits<uint32_t>::max()))
            fail_at_line(name, line_number, "vertex index " + std::to_string(index) + " out of range");
          if (static_cast<uint64_t>(index) > largest_positive_index) {
            largest_positive_index = static_cast<uint64_t>(index);
            largest_positive_index_line = line_number;
          }
          resolved = static_cast<uint32_t>(index - 1);
        }
        face.push_back(resolved);
      }
      if (face.size() < 3)
        fail_at_line(name, line_number,
                     "face has " + count_of(face.size(), "vertex", "vertices") + " (at least 3 needed)");
      for (uint32_t v : face) mesh.indices.push_back(v);
      mesh.face_sizes.push_back(static_cast<uint32_t>(face.size()));
    } else if (keyword == "l" || keyword == "p") {
      ++point_and_line_records;
    }
    // Everything else (vt, vn, vp, g, o, s, usemtl, mtllib, curves, ...) does not affect the shape.
  }
  const size_t vertex_count = mesh.positions.size() / 3;
  if (largest_positive_index > vertex_count)
    fail_at_line(name, largest_positive_index_line,
                 "vertex index " + std::to_string(largest_positive_index) + " out of range (the file has " +
                     count_of(vertex_count, "vertex", "vertices") + ")");
  if (mesh.face_sizes.empty()) {
    if (point_and_line_records > 0) fail(Error::EmptyInput, name + ": no faces (only points/lines)");
    fail(Error::EmptyInput, name + (vertex_count == 0 ? ": no vertices and no faces" : ": no faces"));
  }
  drop_face_sizes_if_all_triangles(mesh);
}

}  // namespace

ReadResult read_obj(std::string_view text, const std::string& name) {
  return run_reader([&](ReadResult& r) { parse_obj(text, name, r.mesh); });
}

}  // namespace kergen
