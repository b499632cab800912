// off.cpp — the OFF reader (read_off): the ASCII Object File Format of Geomview (Geomview manual,
// "OFF Files", geomview.org/docs/html/OFF.html) with its [ST][C][N]OFF variants, whose texture
// coordinates, colours and normals are read past; 4D, n-dimensional and binary OFF are refused.
#include <cstdint>
#include <string>
#include <string_view>

#include "io/numbers.h"
#include "io/reader.h"
#include "io/text_scan.h"
#include "kergen/io.h"
#include "util/plural.h"

namespace kergen {

using namespace io;  // the readers' shared parts: reader.h, text_scan.h, numbers.h

namespace io {

// [ST][C][N][4][n]OFF: texture coordinates, colours and normals trail the xyz (ignored by the
// reader); 4 and n mark the higher-dimensional variants.
bool is_off_keyword(std::string_view kind, bool& higher_dimension) {
  if (kind.substr(0, 2) == "ST") kind.remove_prefix(2);
  if (kind.substr(0, 1) == "C") kind.remove_prefix(1);
  if (kind.substr(0, 1) == "N") kind.remove_prefix(1);
  higher_dimension = false;
  if (kind.substr(0, 1) == "4") kind.remove_prefix(1), higher_dimension = true;
  if (kind.substr(0, 1) == "n") kind.remove_prefix(1), higher_dimension = true;
  return kind == "OFF";
}

}  // namespace io

namespace {

// Next line with content (comments and blank lines skipped); false at the end of the text.
bool next_content_line(LineReader& lines, Tokens& tokens) {
  std::string_view line;
  while (lines.next(line)) {
    tokens = Tokens(strip_comment(line));
    if (!tokens.at_end()) return true;
  }
  return false;
}

long long read_count(Tokens& tokens, const std::string& name, size_t line, const char* what) {
  std::string_view token;
  long long value = 0;
  if (!tokens.next(token)) fail_at_line(name, line, std::string("missing ") + what + " count");
  if (!parse_integer(token, value) || value < 0)
    fail_at_line(name, line, std::string("invalid ") + what + " count " + quoted(token));
  return value;
}

void parse_off(std::string_view text, const std::string& name, Mesh& mesh) {
  text = prepare_text(text, name);
  LineReader lines(text);
  Tokens tokens{std::string_view{}};
  next_content_line(lines, tokens);  // not empty: prepare_text refused blank files
  std::string_view keyword;
  tokens.next(keyword);
  bool higher_dimension = false;
  if (!is_off_keyword(keyword, higher_dimension))
    fail_at_line(name, lines.line_number(), "expected an OFF header, found " + quoted(keyword));
  if (higher_dimension) fail_at_line(name, lines.line_number(), "4D / n-dimensional OFF is not supported");
  if (tokens.at_end()) {
    if (!next_content_line(lines, tokens)) fail_at_line(name, lines.line_number(), "missing vertex/face counts");
  } else {
    // "OFF BINARY" or "OFF nv nf ne" on the header line.
    Tokens peek = tokens;
    std::string_view next;
    peek.next(next);
    if (equals_ignore_case(next, "BINARY")) fail_at_line(name, lines.line_number(), "binary OFF is not supported");
  }
  const size_t counts_line = lines.line_number();
  const long long vertex_count = read_count(tokens, name, counts_line, "vertex");
  const long long face_count = read_count(tokens, name, counts_line, "face");
  // The edge count is optional in practice and unused.

  // Every vertex and face needs a line of its own, at least one character and a newline (the last
  // one possibly without): a header asking for more lines than the file can hold is a lie, caught
  // here before anything is reserved. Finer problems are reported by the line that shows them.
  const uint64_t available = lines.remaining_bytes();
  const uint64_t huge = uint64_t(1) << 40;
  if (static_cast<uint64_t>(vertex_count) > huge || static_cast<uint64_t>(face_count) > huge ||
      2 * (static_cast<uint64_t>(vertex_count) + static_cast<uint64_t>(face_count)) > available + 1)
    fail_at_line(name, counts_line,
                 "header declares " + count_of(vertex_count, "vertex", "vertices") + " and " +
                     count_of(face_count, "face", "faces") + " but only " + count_of(available, "byte", "bytes") +
                     verb_for(available, " follows", " follow"));
  check_vertex_count(static_cast<size_t>(vertex_count), name, counts_line);
  mesh.positions.reserve(3 * static_cast<size_t>(vertex_count));
  mesh.face_sizes.reserve(static_cast<size_t>(face_count));
  mesh.indices.reserve(3 * static_cast<size_t>(face_count));

  for (long long v = 0; v < vertex_count; ++v) {
    if (!next_content_line(lines, tokens))
      fail_at_line(name, lines.line_number(),
                   "unexpected end of file: " + std::to_string(v) + " of " +
                       count_of(vertex_count, "vertex", "vertices") + " read");
    double xyz[3];
    read_coordinates(tokens, xyz, name, lines.line_number(), "vertex");
    for (double x : xyz) mesh.positions.push_back(x);
  }
  for (long long f = 0; f < face_count; ++f) {
    if (!next_content_line(lines, tokens))
      fail_at_line(
          name, lines.line_number(),
          "unexpected end of file: " + std::to_string(f) + " of " + count_of(face_count, "face", "faces") + " read");
    const size_t line = lines.line_number();
    std::string_view token;
    tokens.next(token);
    long long size = 0;
    if (!parse_integer(token, size) || size < 0) fail_at_line(name, line, "invalid face size " + quoted(token));
    if (size < 3) fail_at_line(name, line, "face has " + count_of(size, "vertex", "vertices") + " (at least 3 needed)");
    for (long long k = 0; k < size; ++k) {
      if (!tokens.next(token))
        fail_at_line(
            name, line,
            "face declares " + count_of(size, "vertex", "vertices") + " but the line has only " + std::to_string(k));
      long long index = 0;
      if (!parse_integer(token, index)) fail_at_line(name, line, "invalid vertex index " + quoted(token));
      if (index < 0 || index >= vertex_count)
        fail_at_line(name, line,
                     "vertex index " + std::to_string(index) + " out of range (the file has " +
                         count_of(vertex_count, "vertex", "vertices") + ")");
      mesh.indices.push_back(static_cast<uint32_t>(index));
    }
    // A colour may follow the indices; it is ignored.
    mesh.face_sizes.push_back(static_cast<uint32_t>(size));
  }
  if (vertex_count == 0 && face_count == 0) fail(Error::EmptyInput, name + ": no vertices and no faces");
  if (face_count == 0) fail(Error::EmptyInput, name + ": no faces");
  drop_face_sizes_if_all_triangles(mesh);
}

}  // namespace

ReadResult read_off(std::string_view text, const std::string& name) {
  return run_reader([&](ReadResult& r) { parse_off(text, name, r.mesh); });
}

}  // namespace kergen
