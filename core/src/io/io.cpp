// io.cpp — mesh files in and out: OFF, OBJ and STL readers, OBJ/OFF/STL writers, Mesh::view and
// kernel_mesh.
//
// The readers are strict: a malformed number, an index out of range or a truncated file is a
// ParseError naming the file and the line (text) or byte offset (binary STL), never a silently
// repaired mesh. Geometric problems of a well-formed file (holes, degenerate faces, ...) are left to
// the core's validation. No reader trusts a count from a header before checking it against the
// bytes that follow, so a lying header cannot trigger a huge allocation.
#include "kergen/io.h"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <new>
#include <stdexcept>
#if defined(__has_include)
#if __has_include(<version>)
#include <version>
#endif
#endif

#include "util/point_table.h"

// libstdc++ (g++ >= 11) has a correctly rounded, locale-independent std::from_chars for double.
// Emscripten's libc++ deletes that overload; there we use strtod, which in its musl-based libc
// ignores the locale (the decimal point is always '.').
#if defined(__cpp_lib_to_chars) && defined(__GLIBCXX__)
#define KERGEN_FROM_CHARS_DOUBLE 1
#else
#define KERGEN_FROM_CHARS_DOUBLE 0
#endif

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

// Internal control flow only: every public entry point catches it and turns it into a ReadResult.
struct ReadFailure {
  Error error;
  std::string message;
};

[[noreturn]] void fail(Error error, std::string message) { throw ReadFailure{error, std::move(message)}; }

[[noreturn]] void fail_at_line(const std::string& name, size_t line, const std::string& reason) {
  fail(Error::ParseError, name + ":" + std::to_string(line) + ": " + reason);
}

[[noreturn]] void fail_at_byte(const std::string& name, uint64_t offset, const std::string& reason) {
  fail(Error::ParseError, name + ": byte " + std::to_string(offset) + ": " + reason);
}

// A token quoted for an error message: control and non-ASCII bytes escaped, long tokens shortened,
// so a binary file fed to a text reader still gives a readable one-line message.
std::string quoted(std::string_view token) {
  constexpr size_t kMaxShown = 40;
  std::string out = "'";
  for (size_t i = 0; i < token.size() && i < kMaxShown; ++i) {
    unsigned char c = static_cast<unsigned char>(token[i]);
    if (c >= 0x20 && c < 0x7f && c != '\'' && c != '\\') {
      out += static_cast<char>(c);
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    }
  }
  if (token.size() > kMaxShown) out += "...";
  out += "'";
  return out;
}

ReadResult run_reader(const std::function<void(ReadResult&)>& body) {
  ReadResult result;
  try {
    body(result);
  } catch (const ReadFailure& failure) {
    result = ReadResult{};
    result.error = failure.error;
    result.message = failure.message;
  } catch (const std::bad_alloc&) {
    result = ReadResult{};
    result.error = Error::TooLarge;
    result.message = "out of memory while reading the mesh";
  } catch (const std::length_error&) {
    result = ReadResult{};
    result.error = Error::TooLarge;
    result.message = "mesh too large to hold in memory";
  }
  return result;
}

// ---------------------------------------------------------------------------------------------
// Lines and tokens.

// ' ', '\t', '\r', '\v' or '\f' (not '\n'). Every byte above ' ' (most of a token's) is answered by
// the first comparison.
inline bool is_blank(char c) {
  const unsigned char u = static_cast<unsigned char>(c);
  return u <= ' ' && (u == ' ' || (u >= '\t' && u <= '\r' && u != '\n'));
}

class LineReader {
 public:
  explicit LineReader(std::string_view text) : text_(text) {}
  bool next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    const char* begin = text_.data() + pos_;
    const void* newline = std::memchr(begin, '\n', text_.size() - pos_);
    size_t end = newline ? static_cast<size_t>(static_cast<const char*>(newline) - text_.data()) : text_.size();
    line = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    ++line_number_;
    return true;
  }
  size_t line_number() const { return line_number_; }
  size_t remaining_bytes() const { return pos_ >= text_.size() ? 0 : text_.size() - pos_; }

 private:
  std::string_view text_;
  size_t pos_ = 0;
  size_t line_number_ = 0;
};

class Tokens {
 public:
  explicit Tokens(std::string_view line) : line_(line) {}
  bool next(std::string_view& token) {
    while (pos_ < line_.size() && is_blank(line_[pos_])) ++pos_;
    if (pos_ >= line_.size()) return false;
    size_t start = pos_;
    while (pos_ < line_.size() && !is_blank(line_[pos_])) ++pos_;
    token = line_.substr(start, pos_ - start);
    return true;
  }
  bool at_end() {
    while (pos_ < line_.size() && is_blank(line_[pos_])) ++pos_;
    return pos_ >= line_.size();
  }

 private:
  std::string_view line_;
  size_t pos_ = 0;
};

std::string_view strip_comment(std::string_view line) {
  size_t hash = line.find('#');
  return hash == std::string_view::npos ? line : line.substr(0, hash);
}

bool equals_ignore_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    char x = a[i], y = b[i];
    if (x >= 'A' && x <= 'Z') x = static_cast<char>(x - 'A' + 'a');
    if (y >= 'A' && y <= 'Z') y = static_cast<char>(y - 'A' + 'a');
    if (x != y) return false;
  }
  return true;
}

bool only_blank(std::string_view text) {
  for (char c : text)
    if (!is_blank(c) && c != '\n') return false;
  return true;
}

// Text formats: refuses UTF-16 (a common export option of Windows tools) with a clear reason instead
// of a confusing "invalid number" on line 1, and drops a UTF-8 byte order mark.
std::string_view prepare_text(std::string_view text, const std::string& name) {
  if (text.size() >= 2) {
    unsigned char b0 = static_cast<unsigned char>(text[0]), b1 = static_cast<unsigned char>(text[1]);
    bool bom16 = (b0 == 0xFF && b1 == 0xFE) || (b0 == 0xFE && b1 == 0xFF);
    bool ascii_as_utf16 = (b0 == 0 && b1 != 0) || (b0 != 0 && b1 == 0);
    if (bom16 || ascii_as_utf16) fail_at_line(name, 1, "UTF-16 is not supported (save the file as UTF-8 or ASCII)");
  }
  if (text.size() >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  if (only_blank(text)) fail(Error::EmptyInput, name + ": empty file");
  return text;
}

// ---------------------------------------------------------------------------------------------
// Numbers.

enum class NumberStatus { Ok, Invalid, NonFinite };

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// Decimal exponent of the leading significant digit of a syntactically valid decimal number with
// at least one non-zero digit; used only to tell overflow from underflow.
long long leading_decimal_exponent(std::string_view mantissa, long long exponent) {
  long long position = -1;  // exponent of the next digit relative to the decimal point
  size_t point = mantissa.find('.');
  size_t integer_digits = point == std::string_view::npos ? mantissa.size() : point;
  position = static_cast<long long>(integer_digits) - 1;
  for (char c : mantissa) {
    if (c == '.') continue;
    if (c != '0') return position + exponent;
    --position;
  }
  return std::numeric_limits<long long>::min();
}

// Strict decimal syntax: [+-] (digits [. digits] | . digits) [(e|E) [+-] digits]. "inf" and "nan"
// spellings are recognised so they can be reported as non-finite rather than as garbage.
NumberStatus parse_double_checked(std::string_view token, double& out) {
  size_t i = 0, n = token.size();
  bool negative = false;
  if (i < n && (token[i] == '+' || token[i] == '-')) negative = token[i++] == '-';
  std::string_view unsigned_part = token.substr(i);
  if (!unsigned_part.empty() && !is_digit(unsigned_part[0]) && unsigned_part[0] != '.') {
    const bool nan_with_payload = unsigned_part.size() > 4 && equals_ignore_case(unsigned_part.substr(0, 4), "nan(") &&
                                  unsigned_part.back() == ')';
    if (equals_ignore_case(unsigned_part, "inf") || equals_ignore_case(unsigned_part, "infinity") ||
        equals_ignore_case(unsigned_part, "nan") || nan_with_payload)
      return NumberStatus::NonFinite;
    return NumberStatus::Invalid;
  }
  size_t mantissa_begin = i, digits = 0;
  while (i < n && is_digit(token[i])) ++i, ++digits;
  if (i < n && token[i] == '.') {
    ++i;
    while (i < n && is_digit(token[i])) ++i, ++digits;
  }
  if (digits == 0) return NumberStatus::Invalid;
  std::string_view mantissa = token.substr(mantissa_begin, i - mantissa_begin);
  long long exponent = 0;
  if (i < n && (token[i] == 'e' || token[i] == 'E')) {
    ++i;
    bool exponent_negative = false;
    if (i < n && (token[i] == '+' || token[i] == '-')) exponent_negative = token[i++] == '-';
    size_t exponent_digits = 0;
    while (i < n && is_digit(token[i])) {
      if (exponent < 1'000'000'000) exponent = exponent * 10 + (token[i] - '0');
      ++i, ++exponent_digits;
    }
    if (exponent_digits == 0) return NumberStatus::Invalid;
    if (exponent_negative) exponent = -exponent;
  }
  if (i != n) return NumberStatus::Invalid;

  // Hand the validated text (without a leading '+', which from_chars refuses) to the converter.
  std::string_view number = token.substr(token[0] == '+' ? 1 : 0);
  double value = 0;
  bool out_of_range = false;
#if KERGEN_FROM_CHARS_DOUBLE
  auto converted = std::from_chars(number.data(), number.data() + number.size(), value);
  if (converted.ec == std::errc::result_out_of_range)
    out_of_range = true;
  else if (converted.ec != std::errc() || converted.ptr != number.data() + number.size())
    return NumberStatus::Invalid;
#else
  char small[64];
  std::string large;
  const char* text;
  if (number.size() < sizeof small) {
    std::memcpy(small, number.data(), number.size());
    small[number.size()] = '\0';
    text = small;
  } else {
    large.assign(number);
    text = large.c_str();
  }
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text, &end);
  if (end != text + number.size()) return NumberStatus::Invalid;
  if (errno == ERANGE || std::isinf(value)) out_of_range = true;
#endif
  if (out_of_range) {
    // Too large for a double is a non-finite coordinate; too small rounds to a signed zero.
    if (leading_decimal_exponent(mantissa, exponent) > 0) return NumberStatus::NonFinite;
    if (value == 0 || std::isinf(value)) value = negative ? -0.0 : 0.0;
  }
  if (!std::isfinite(value)) return NumberStatus::NonFinite;
  out = value;
  return NumberStatus::Ok;
}

// parse_double_checked, with a fast path for the usual token: without a leading '+', the strings
// std::from_chars reads in full as a finite number are exactly those of the strict syntax above
// (its general format is [-] (digits [. digits] | . digits) [(e|E) [+-] digits], or inf / nan
// spellings, which are not finite), and parse_double_checked converts them with the same call.
// Anything else (a '+', a partial read, out of range, non-finite) goes the checked way.
inline NumberStatus parse_double(std::string_view token, double& out) {
#if KERGEN_FROM_CHARS_DOUBLE
  if (!token.empty() && token[0] != '+') {
    double value;
    const auto converted = std::from_chars(token.data(), token.data() + token.size(), value);
    if (converted.ec == std::errc() && converted.ptr == token.data() + token.size() && std::isfinite(value)) {
      out = value;
      return NumberStatus::Ok;
    }
  }
#endif
  return parse_double_checked(token, out);
}

// [+-]digits, no overflow.
bool parse_integer(std::string_view token, long long& out) {
  // The usual token, 1 to 9 digits, cannot overflow: read directly.
  if (!token.empty() && token.size() <= 9) {
    long long value = 0;
    size_t i = 0;
    for (; i < token.size() && token[i] >= '0' && token[i] <= '9'; ++i) value = value * 10 + (token[i] - '0');
    if (i == token.size()) {
      out = value;
      return true;
    }
  }
  if (!token.empty() && token[0] == '+') {
    token.remove_prefix(1);
    if (!token.empty() && token[0] == '-') return false;
  }
  if (token.empty()) return false;
  auto converted = std::from_chars(token.data(), token.data() + token.size(), out);
  return converted.ec == std::errc() && converted.ptr == token.data() + token.size();
}

// Reads three coordinates; reports a bad or non-finite one with the line number.
void read_coordinates(Tokens& tokens, double xyz[3], const std::string& name, size_t line, const char* what) {
  for (int k = 0; k < 3; ++k) {
    std::string_view token;
    if (!tokens.next(token))
      fail_at_line(name, line, std::string(what) + " needs 3 coordinates, found " + std::to_string(k));
    switch (parse_double(token, xyz[k])) {
      case NumberStatus::Ok: break;
      case NumberStatus::Invalid: fail_at_line(name, line, "invalid number " + quoted(token));
      case NumberStatus::NonFinite: fail_at_line(name, line, "non-finite coordinate " + quoted(token));
    }
  }
}

void check_vertex_count(size_t count, const std::string& name, size_t line) {
  if (count > std::numeric_limits<uint32_t>::max())
    fail_at_line(name, line, "more than 4294967295 vertices (indices are 32-bit)");
}

// Faces are stored with explicit sizes while reading; an all-triangle mesh drops them, which is
// what "face_sizes empty = triangles" means in the public API.
void drop_face_sizes_if_all_triangles(Mesh& mesh) {
  if (std::all_of(mesh.face_sizes.begin(), mesh.face_sizes.end(), [](uint32_t k) { return k == 3; }))
    mesh.face_sizes.clear();
}

// ---------------------------------------------------------------------------------------------
// OBJ.

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
                             std::to_string(vertices_so_far) + " vertices so far)");
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
        fail_at_line(name, line_number, "face has " + std::to_string(face.size()) + " vertices (at least 3 needed)");
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
                     std::to_string(vertex_count) + " vertices)");
  if (mesh.face_sizes.empty()) {
    if (point_and_line_records > 0) fail(Error::EmptyInput, name + ": no faces (only points/lines)");
    fail(Error::EmptyInput, name + (vertex_count == 0 ? ": no vertices and no faces" : ": no faces"));
  }
  drop_face_sizes_if_all_triangles(mesh);
}

// ---------------------------------------------------------------------------------------------
// OFF.

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
                 "header declares " + std::to_string(vertex_count) + " vertices and " + std::to_string(face_count) +
                     " faces but only " + std::to_string(available) + " bytes follow");
  check_vertex_count(static_cast<size_t>(vertex_count), name, counts_line);
  mesh.positions.reserve(3 * static_cast<size_t>(vertex_count));
  mesh.face_sizes.reserve(static_cast<size_t>(face_count));
  mesh.indices.reserve(3 * static_cast<size_t>(face_count));

  for (long long v = 0; v < vertex_count; ++v) {
    if (!next_content_line(lines, tokens))
      fail_at_line(
          name, lines.line_number(),
          "unexpected end of file: " + std::to_string(v) + " of " + std::to_string(vertex_count) + " vertices read");
    double xyz[3];
    read_coordinates(tokens, xyz, name, lines.line_number(), "vertex");
    for (double x : xyz) mesh.positions.push_back(x);
  }
  for (long long f = 0; f < face_count; ++f) {
    if (!next_content_line(lines, tokens))
      fail_at_line(
          name, lines.line_number(),
          "unexpected end of file: " + std::to_string(f) + " of " + std::to_string(face_count) + " faces read");
    const size_t line = lines.line_number();
    std::string_view token;
    tokens.next(token);
    long long size = 0;
    if (!parse_integer(token, size) || size < 0) fail_at_line(name, line, "invalid face size " + quoted(token));
    if (size < 3) fail_at_line(name, line, "face has " + std::to_string(size) + " vertices (at least 3 needed)");
    for (long long k = 0; k < size; ++k) {
      if (!tokens.next(token))
        fail_at_line(name, line,
                     "face declares " + std::to_string(size) + " vertices but the line has only " + std::to_string(k));
      long long index = 0;
      if (!parse_integer(token, index)) fail_at_line(name, line, "invalid vertex index " + quoted(token));
      if (index < 0 || index >= vertex_count)
        fail_at_line(name, line,
                     "vertex index " + std::to_string(index) + " out of range (the file has " +
                         std::to_string(vertex_count) + " vertices)");
      mesh.indices.push_back(static_cast<uint32_t>(index));
    }
    // A colour may follow the indices; it is ignored.
    mesh.face_sizes.push_back(static_cast<uint32_t>(size));
  }
  if (vertex_count == 0 && face_count == 0) fail(Error::EmptyInput, name + ": no vertices and no faces");
  if (face_count == 0) fail(Error::EmptyInput, name + ": no faces");
  drop_face_sizes_if_all_triangles(mesh);
}

// ---------------------------------------------------------------------------------------------
// STL.

// Welds vertices that have exactly the same coordinates (an STL stores every triangle's corners
// separately), numbered in the order they are first met. -0.0 and 0.0 are the same point.
class VertexWelder {
 public:
  explicit VertexWelder(std::vector<double>& positions, size_t expected_vertices)
      : positions_(positions), table_(expected_vertices) {}
  // A corner, its coordinates with -0.0 turned into +0.0 (adding +0.0 does it, round-to-nearest),
  // and its hash: what add() needs, computed ahead of it by binary STL's blocks.
  struct Corner {
    double xyz[3];
    uint64_t hash;
  };
  static Corner corner(double x, double y, double z) {
    Corner c{{x + 0.0, y + 0.0, z + 0.0}, 0};
    c.hash = PointTable::hash(c.xyz);
    return c;
  }
  void prefetch(const Corner& c) const { table_.prefetch_slot(c.hash); }
  void prefetch_held(const Corner& c) const { table_.prefetch_held(positions_.data(), c.hash); }
  uint32_t add(double x, double y, double z) { return add(corner(x, y, z)); }
  uint32_t add(const Corner& c) {
    const size_t count = positions_.size() / 3;
    if (count >= std::numeric_limits<uint32_t>::max()) {
      const uint32_t found = table_.find(positions_.data(), c.xyz, c.hash);
      if (found != PointTable::kEmpty) return found;
      fail(Error::TooLarge, "more than 4294967295 distinct vertices");
    }
    const uint32_t id = table_.find_or_insert(positions_.data(), c.xyz, c.hash, uint32_t(count));
    if (id == count) positions_.insert(positions_.end(), c.xyz, c.xyz + 3);
    return id;
  }

 private:
  std::vector<double>& positions_;
  PointTable table_;
};

uint32_t read_le32(const unsigned char* p) {
  return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

float read_le_float(const unsigned char* p) {
  uint32_t bits = read_le32(p);
  float f;
  std::memcpy(&f, &bits, sizeof f);
  return f;
}

// Triangles are read in blocks: their corners hashed and their table slots prefetched first,
// then welded in order (the table is larger than the caches on big files).
void parse_binary_stl(std::string_view bytes, uint32_t triangle_count, const std::string& name, Mesh& mesh) {
  if (triangle_count == 0) fail(Error::EmptyInput, name + ": no triangles");
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  // A closed mesh has about half as many vertices as triangles.
  const size_t expected_vertices = std::min<size_t>(triangle_count / 2 + 16, size_t(1) << 24);
  VertexWelder welder(mesh.positions, expected_vertices);
  mesh.positions.reserve(3 * expected_vertices);
  mesh.indices.resize(3 * size_t(triangle_count));
  uint32_t* index_out = mesh.indices.data();
  constexpr uint32_t kBlock = 32;
  VertexWelder::Corner corners[3 * kBlock];
  for (uint32_t first = 0; first < triangle_count; first += kBlock) {
    const uint32_t n = std::min(kBlock, triangle_count - first);
    for (uint32_t i = 0; i < n; ++i) {
      const uint32_t t = first + i;
      const size_t record = 84 + 50 * size_t(t);
      for (int corner = 0; corner < 3; ++corner) {
        const size_t offset = record + 12 + 12 * size_t(corner);  // after the 12-byte normal
        double xyz[3];
        for (int k = 0; k < 3; ++k) {
          float value = read_le_float(data + offset + 4 * k);
          if (!std::isfinite(value))
            fail_at_byte(
                name, offset + 4 * k,
                "non-finite coordinate in triangle " + std::to_string(t) + " (vertex " + std::to_string(corner) + ")");
          xyz[k] = static_cast<double>(value);  // exact: every float is a double
        }
        corners[3 * i + corner] = VertexWelder::corner(xyz[0], xyz[1], xyz[2]);
        welder.prefetch(corners[3 * i + corner]);
      }
    }
    for (uint32_t c = 0; c < 3 * n; ++c) welder.prefetch_held(corners[c]);
    for (uint32_t c = 0; c < 3 * n; ++c) *index_out++ = welder.add(corners[c]);
  }
}

// "normal nx ny nz" after "facet". The normal is recomputed by everyone; it only has to be three
// numbers (some exporters write nan for degenerate facets, which is harmless here).
void read_facet_normal(Tokens& tokens, const std::string& name, size_t line_number) {
  std::string_view word;
  if (!tokens.next(word) || !equals_ignore_case(word, "normal"))
    fail_at_line(name, line_number, "expected 'facet normal nx ny nz'");
  for (int k = 0; k < 3; ++k) {
    std::string_view token;
    double ignored;
    if (!tokens.next(token)) fail_at_line(name, line_number, "facet normal needs 3 components");
    if (parse_double(token, ignored) == NumberStatus::Invalid)
      fail_at_line(name, line_number, "invalid number " + quoted(token));
  }
}

void parse_ascii_stl(std::string_view text, const std::string& name, Mesh& mesh) {
  if (text.size() >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  enum class State { OutsideSolid, InSolid, InFacet, InLoop, AfterLoop };
  State state = State::OutsideSolid;
  LineReader lines(text);
  std::string_view line;
  // A facet line is about 200 bytes of text; a generous guess keeps rehashing rare.
  VertexWelder welder(mesh.positions, text.size() / 200 + 16);
  VertexWelder::Corner corners[3];
  // Finished facets' corners are welded a block at a time, their table slots prefetched when the
  // facet ends (binary STL's scheme). The weld's only failure, more than 2^32 - 1 distinct
  // vertices, then shows up to kBlock facets later, which no file under ~400 GB can reach.
  constexpr size_t kBlock = 32;
  std::vector<VertexWelder::Corner> pending;
  pending.reserve(3 * kBlock);
  auto weld_pending = [&] {
    for (const auto& c : pending) mesh.indices.push_back(welder.add(c));
    pending.clear();
  };
  int corner_count = 0;
  auto expect_end = [&](Tokens& tokens, std::string_view keyword) {
    std::string_view extra;
    if (tokens.next(extra))
      fail_at_line(name, lines.line_number(), "unexpected " + quoted(extra) + " after '" + std::string(keyword) + "'");
  };
  while (lines.next(line)) {
    Tokens tokens(line);
    std::string_view keyword;
    if (!tokens.next(keyword)) continue;
    const size_t line_number = lines.line_number();
    auto unexpected = [&](const char* expected) {
      fail_at_line(name, line_number, "expected " + std::string(expected) + ", found " + quoted(keyword));
    };
    switch (state) {
      case State::OutsideSolid:
        if (!equals_ignore_case(keyword, "solid")) unexpected("'solid'");
        state = State::InSolid;  // the rest of the line is the solid's name
        break;
      case State::InSolid:
        if (equals_ignore_case(keyword, "endsolid")) {
          state = State::OutsideSolid;
        } else if (equals_ignore_case(keyword, "facet")) {
          read_facet_normal(tokens, name, line_number);
          expect_end(tokens, "facet normal");
          state = State::InFacet;
        } else {
          unexpected("'facet' or 'endsolid'");
        }
        break;
      case State::InFacet: {
        std::string_view word;
        if (!equals_ignore_case(keyword, "outer") || !tokens.next(word) || !equals_ignore_case(word, "loop"))
          fail_at_line(name, line_number, "expected 'outer loop', found " + quoted(keyword));
        expect_end(tokens, "outer loop");
        state = State::InLoop;
        corner_count = 0;
        break;
      }
      case State::InLoop:
        if (equals_ignore_case(keyword, "vertex")) {
          if (corner_count == 3) fail_at_line(name, line_number, "facet has more than 3 vertices");
          double xyz[3];
          read_coordinates(tokens, xyz, name, line_number, "vertex");
          expect_end(tokens, "vertex x y z");
          corners[corner_count++] = VertexWelder::corner(xyz[0], xyz[1], xyz[2]);
        } else if (equals_ignore_case(keyword, "endloop")) {
          if (corner_count != 3)
            fail_at_line(name, line_number, "facet has " + std::to_string(corner_count) + " vertices (3 needed)");
          expect_end(tokens, "endloop");
          state = State::AfterLoop;
        } else {
          unexpected("'vertex' or 'endloop'");
        }
        break;
      case State::AfterLoop:
        if (!equals_ignore_case(keyword, "endfacet")) unexpected("'endfacet'");
        expect_end(tokens, "endfacet");
        for (const auto& c : corners) {
          welder.prefetch(c);
          pending.push_back(c);
        }
        if (pending.size() == 3 * kBlock) weld_pending();
        state = State::InSolid;
        break;
    }
  }
  weld_pending();
  // A missing final "endsolid" is tolerated (common in hand-written files); a cut facet is not.
  if (state != State::OutsideSolid && state != State::InSolid)
    fail_at_line(name, lines.line_number(), "unexpected end of file inside a facet");
  if (mesh.indices.empty()) fail(Error::EmptyInput, name + ": no facets");
}

bool starts_with_solid(std::string_view bytes) {
  if (bytes.size() >= 3 && bytes.substr(0, 3) == "\xEF\xBB\xBF") bytes.remove_prefix(3);
  size_t i = 0;
  while (i < bytes.size() && (is_blank(bytes[i]) || bytes[i] == '\n')) ++i;
  return bytes.size() - i >= 5 && equals_ignore_case(bytes.substr(i, 5), "solid") &&
         (bytes.size() - i == 5 || is_blank(bytes[i + 5]) || bytes[i + 5] == '\n');
}

[[noreturn]] void fail_binary_size(std::string_view bytes, const std::string& name) {
  const uint64_t declared = read_le32(reinterpret_cast<const unsigned char*>(bytes.data()) + 80);
  const uint64_t room = (bytes.size() - 84) / 50;
  fail_at_byte(name, 80,
               "binary STL header declares " + std::to_string(declared) + " triangles (" +
                   std::to_string(84 + 50 * declared) + " bytes) but the file has " + std::to_string(bytes.size()) +
                   " bytes (room for " + std::to_string(room) + " triangles)");
}

void parse_stl(std::string_view bytes, const std::string& name, Mesh& mesh) {
  if (bytes.empty()) fail(Error::EmptyInput, name + ": empty file");
  // Binary vs ascii is decided by content: many binary files start their header with "solid" too.
  if (bytes.size() >= 84) {
    const uint32_t declared = read_le32(reinterpret_cast<const unsigned char*>(bytes.data()) + 80);
    if (84 + 50 * uint64_t(declared) == bytes.size()) return parse_binary_stl(bytes, declared, name, mesh);
  }
  if (starts_with_solid(bytes)) {
    try {
      parse_ascii_stl(bytes, name, mesh);
      return;
    } catch (const ReadFailure& failure) {
      // A NUL byte means binary data whose header happens to start with "solid": the real problem
      // is then its triangle count, not its "text".
      if (failure.error == Error::ParseError && bytes.size() >= 84 &&
          std::memchr(bytes.data(), '\0', bytes.size()) != nullptr)
        fail_binary_size(bytes, name);
      throw;
    }
  }
  if (bytes.size() < 84)
    fail_at_byte(name, 0,
                 "not an STL file: " + std::to_string(bytes.size()) +
                     " bytes is shorter than a binary STL header (84 bytes) and the text does not start with 'solid'");
  fail_binary_size(bytes, name);
}

// ---------------------------------------------------------------------------------------------
// PLY.

enum class PlyType : uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

bool ply_type_from_name(std::string_view name, PlyType& type) {
  static const struct {
    const char* name;
    PlyType type;
  } kNames[] = {{"char", PlyType::Int8},      {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
                {"uint8", PlyType::UInt8},    {"short", PlyType::Int16},     {"int16", PlyType::Int16},
                {"ushort", PlyType::UInt16},  {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
                {"int32", PlyType::Int32},    {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
                {"float", PlyType::Float32},  {"float32", PlyType::Float32}, {"double", PlyType::Float64},
                {"float64", PlyType::Float64}};
  for (const auto& entry : kNames)
    if (name == entry.name) return type = entry.type, true;
  return false;
}

size_t ply_size(PlyType t) {
  switch (t) {
    case PlyType::Int8:
    case PlyType::UInt8: return 1;
    case PlyType::Int16:
    case PlyType::UInt16: return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32: return 4;
    case PlyType::Float64: return 8;
  }
  return 8;
}

bool ply_is_integer(PlyType t) { return t != PlyType::Float32 && t != PlyType::Float64; }

struct PlyProperty {
  bool is_list = false;
  PlyType count_type = PlyType::UInt8;  // lists only
  PlyType type = PlyType::Float32;      // the value's, or a list item's
};

struct PlyElement {
  std::string name;
  uint64_t count = 0;
  size_t line = 0;  // the header line declaring it
  std::vector<PlyProperty> properties;
  // vertex: the properties x, y, z; face: [0] the vertex index list. -1 = not declared.
  int role[3] = {-1, -1, -1};
};

enum class PlyEncoding { Ascii, LittleEndian, BigEndian };

struct PlyHeader {
  PlyEncoding encoding = PlyEncoding::Ascii;
  std::vector<PlyElement> elements;
  int vertex = -1, face = -1;  // which elements
  size_t data_offset = 0;      // first byte after the end_header line
  size_t end_line = 0;         // the end_header line
};

// "vertices", "faces", or "'edge' elements", for messages.
std::string ply_plural(const PlyElement& e) {
  if (e.name == "vertex") return "vertices";
  if (e.name == "face") return "faces";
  return "'" + e.name + "' elements";
}

// One "property ..." header line, added to the last element; x/y/z of `vertex` and the index list
// of `face` get their roles here, so a misdeclared one is reported at its line.
void parse_ply_property(Tokens& tokens, PlyElement& e, const std::string& name, size_t line) {
  std::string_view word, property_name;
  PlyProperty p;
  auto type_of = [&](std::string_view type_name) {
    PlyType t;
    if (!ply_type_from_name(type_name, t)) fail_at_line(name, line, "unknown property type " + quoted(type_name));
    return t;
  };
  if (!tokens.next(word)) fail_at_line(name, line, "property needs a type and a name");
  if (word == "list") {
    std::string_view count_type, item_type;
    if (!tokens.next(count_type) || !tokens.next(item_type))
      fail_at_line(name, line, "list property needs a count type, an item type and a name");
    p.is_list = true;
    p.count_type = type_of(count_type);
    p.type = type_of(item_type);
    if (!ply_is_integer(p.count_type))
      fail_at_line(name, line, "list count type " + quoted(count_type) + " is not an integer type");
  } else {
    p.type = type_of(word);
  }
  if (!tokens.next(property_name)) fail_at_line(name, line, "property needs a name");
  std::string_view extra;
  if (tokens.next(extra)) fail_at_line(name, line, "unexpected " + quoted(extra) + " after the property name");
  const int index = static_cast<int>(e.properties.size());
  if (e.name == "vertex" && property_name.size() == 1 && property_name[0] >= 'x' && property_name[0] <= 'z') {
    int& role = e.role[property_name[0] - 'x'];
    if (role >= 0) fail_at_line(name, line, "second vertex property " + quoted(property_name));
    if (p.is_list) fail_at_line(name, line, "vertex property " + quoted(property_name) + " is a list, not a number");
    role = index;
  } else if (e.name == "face" && (property_name == "vertex_indices" || property_name == "vertex_index")) {
    if (e.role[0] >= 0) fail_at_line(name, line, "second vertex index list " + quoted(property_name));
    if (!p.is_list || !ply_is_integer(p.type))
      fail_at_line(name, line, "face property " + quoted(property_name) + " must be a list of integers");
    e.role[0] = index;
  }
  e.properties.push_back(p);
}

// The "format" and "element" header lines.
void parse_ply_format(Tokens& tokens, PlyHeader& h, const std::string& name, size_t line) {
  std::string_view encoding, version, extra;
  if (!tokens.next(encoding) || !tokens.next(version) || tokens.next(extra))
    fail_at_line(name, line, "expected 'format <encoding> 1.0'");
  if (encoding == "ascii")
    h.encoding = PlyEncoding::Ascii;
  else if (encoding == "binary_little_endian")
    h.encoding = PlyEncoding::LittleEndian;
  else if (encoding == "binary_big_endian")
    h.encoding = PlyEncoding::BigEndian;
  else
    fail_at_line(name, line, "unknown PLY format " + quoted(encoding));
  if (version != "1.0") fail_at_line(name, line, "unsupported PLY version " + quoted(version) + " (1.0 expected)");
}

void parse_ply_element(Tokens& tokens, PlyHeader& h, const std::string& name, size_t line) {
  std::string_view element_name, count, extra;
  if (!tokens.next(element_name) || !tokens.next(count) || tokens.next(extra))
    fail_at_line(name, line, "expected 'element <name> <count>'");
  long long value = 0;
  if (!parse_integer(count, value) || value < 0) fail_at_line(name, line, "invalid element count " + quoted(count));
  PlyElement e;
  e.name = std::string(element_name);
  e.count = static_cast<uint64_t>(value);
  e.line = line;
  if (e.name == "vertex" || e.name == "face") {
    int& which = e.name == "vertex" ? h.vertex : h.face;
    if (which >= 0) fail_at_line(name, line, "second '" + e.name + "' element");
    which = static_cast<int>(h.elements.size());
  }
  h.elements.push_back(std::move(e));
}

PlyHeader parse_ply_header(std::string_view bytes, const std::string& name) {
  LineReader lines(bytes);
  std::string_view line, keyword, extra;
  PlyHeader h;
  Tokens first{std::string_view{}};
  if (lines.next(line)) first = Tokens(line);
  if (!first.next(keyword) || keyword != "ply" || first.next(extra))
    fail_at_line(name, 1, "expected 'ply' on the first line, found " + quoted(line));
  bool has_format = false;
  while (true) {
    if (!lines.next(line)) fail_at_line(name, lines.line_number(), "the header has no 'end_header' line");
    const size_t n = lines.line_number();
    Tokens tokens(line);
    if (!tokens.next(keyword) || keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "end_header") {
      if (tokens.next(extra)) fail_at_line(name, n, "unexpected " + quoted(extra) + " after 'end_header'");
      break;
    }
    if (keyword == "format") {
      if (has_format) fail_at_line(name, n, "second 'format' line");
      parse_ply_format(tokens, h, name, n);
      has_format = true;
    } else if (keyword == "element") {
      parse_ply_element(tokens, h, name, n);
    } else if (keyword == "property") {
      if (h.elements.empty()) fail_at_line(name, n, "property before any element");
      parse_ply_property(tokens, h.elements.back(), name, n);
    } else {
      fail_at_line(name, n, "unknown header keyword " + quoted(keyword));
    }
  }
  h.end_line = lines.line_number();
  h.data_offset = bytes.size() - lines.remaining_bytes();
  if (!has_format) fail_at_line(name, h.end_line, "the header has no 'format' line");
  if (h.vertex >= 0) {
    const PlyElement& v = h.elements[h.vertex];
    for (int k = 0; k < 3; ++k)
      if (v.role[k] < 0)
        fail_at_line(name, v.line, std::string("vertex element has no '") + char('x' + k) + "' property");
  }
  if (h.face >= 0 && h.elements[h.face].role[0] < 0)
    fail_at_line(name, h.elements[h.face].line, "face element has no 'vertex_indices' list");
  return h;
}

// Every element instance takes at least a few bytes (binary: its scalars and list counts; ascii:
// a value and a separator), so a header asking for more instances than the data can hold is a lie,
// caught here before anything is reserved. Finer problems are reported where the data shows them.
void check_ply_counts(const PlyHeader& h, uint64_t available, const std::string& name) {
  const bool binary = h.encoding != PlyEncoding::Ascii;
  uint64_t needed = 0;
  for (const PlyElement& e : h.elements) {
    uint64_t per_instance = 0;
    for (const PlyProperty& p : e.properties) per_instance += ply_size(p.is_list ? p.count_type : p.type);
    if (!binary) per_instance = e.properties.empty() ? 0 : 2;
    const uint64_t room = available + (binary ? 0 : 1) - std::min(needed, available);
    if (e.count > (uint64_t(1) << 40) || (per_instance > 0 && e.count > room / per_instance))
      fail_at_line(name, e.line,
                   "header declares " + std::to_string(e.count) + " " + ply_plural(e) + " but only " +
                       std::to_string(available) + " bytes of data follow");
    needed += e.count * per_instance;
  }
  if (h.vertex >= 0)
    check_vertex_count(static_cast<size_t>(h.elements[h.vertex].count), name, h.elements[h.vertex].line);
}

// The values of an ascii PLY body: one element instance per line (blank lines skipped).
class PlyAsciiValues {
 public:
  PlyAsciiValues(std::string_view data, size_t lines_before, const std::string& name)
      : lines_(data), lines_before_(lines_before), name_(name) {}
  void begin(const PlyElement& e, uint64_t index) {
    std::string_view line;
    do {
      if (!lines_.next(line))
        fail("unexpected end of file: " + std::to_string(index) + " of " + std::to_string(e.count) + " " +
             ply_plural(e) + " read");
      tokens_ = Tokens(line);
    } while (tokens_.at_end());
    element_ = &e;
    values_ = 0;
  }
  double coordinate(PlyType) {
    const std::string_view token = next();
    double value = 0;
    switch (parse_double(token, value)) {
      case NumberStatus::Ok: break;
      case NumberStatus::Invalid: fail("invalid number " + quoted(token));
      case NumberStatus::NonFinite: fail("non-finite coordinate " + quoted(token));
    }
    return value;
  }
  long long integer(PlyType, const char* what) {
    const std::string_view token = next();
    long long value = 0;
    if (!parse_integer(token, value)) fail(std::string("invalid ") + what + " " + quoted(token));
    return value;
  }
  // Values of properties the mesh does not use: present, not checked.
  void skip(PlyType, uint64_t n) {
    for (uint64_t i = 0; i < n; ++i) next();
  }
  void end() {
    if (!tokens_.at_end())
      fail("the line has more than the " + std::to_string(values_) + " values element '" + element_->name +
           "' declares");
  }
  [[noreturn]] void fail(const std::string& reason) const {
    fail_at_line(name_, lines_before_ + lines_.line_number(), reason);
  }

 private:
  std::string_view next() {
    std::string_view token;
    if (!tokens_.next(token))
      fail("too few values for element '" + element_->name + "' (the line has " + std::to_string(values_) + ")");
    ++values_;
    return token;
  }
  LineReader lines_;
  size_t lines_before_;
  const std::string& name_;
  Tokens tokens_{std::string_view{}};
  const PlyElement* element_ = nullptr;
  size_t values_ = 0;
};

// The values of a binary PLY body, in either byte order; errors name the byte offset in the file.
class PlyBinaryValues {
 public:
  PlyBinaryValues(std::string_view bytes, size_t offset, bool big_endian, const std::string& name)
      : data_(reinterpret_cast<const unsigned char*>(bytes.data())),
        size_(bytes.size()),
        pos_(offset),
        big_endian_(big_endian),
        name_(name) {}
  void begin(const PlyElement& e, uint64_t index) {
    element_ = &e;
    index_ = index;
  }
  double coordinate(PlyType t) {
    const double value = read(t);
    if (!std::isfinite(value)) fail("non-finite coordinate in vertex " + std::to_string(index_));
    return value;
  }
  long long integer(PlyType t, const char*) { return static_cast<long long>(read(t)); }
  void skip(PlyType t, uint64_t n) {
    last_ = pos_;
    if (n > (size_ - pos_) / ply_size(t)) truncated();
    pos_ += static_cast<size_t>(n) * ply_size(t);
  }
  void end() {}
  [[noreturn]] void fail(const std::string& reason) const { fail_at_byte(name_, last_, reason); }

 private:
  // One value, converted exactly to double (every PLY scalar type fits).
  double read(PlyType t) {
    const size_t n = ply_size(t);
    last_ = pos_;
    if (n > size_ - pos_) truncated();
    unsigned char b[8];
    for (size_t i = 0; i < n; ++i) b[i] = data_[pos_ + (big_endian_ ? n - 1 - i : i)];  // to little-endian
    pos_ += n;
    uint64_t bits = 0;
    for (size_t i = n; i-- > 0;) bits = bits << 8 | b[i];
    switch (t) {
      case PlyType::Int8: return static_cast<int8_t>(bits);
      case PlyType::UInt8: return static_cast<uint8_t>(bits);
      case PlyType::Int16: return static_cast<int16_t>(bits);
      case PlyType::UInt16: return static_cast<uint16_t>(bits);
      case PlyType::Int32: return static_cast<int32_t>(bits);
      case PlyType::UInt32: return static_cast<uint32_t>(bits);
      case PlyType::Float32: {
        const uint32_t bits32 = static_cast<uint32_t>(bits);
        float f;
        std::memcpy(&f, &bits32, sizeof f);
        return f;
      }
      case PlyType::Float64: {
        double d;
        std::memcpy(&d, &bits, sizeof d);
        return d;
      }
    }
    return 0;
  }
  [[noreturn]] void truncated() const {
    fail("unexpected end of file: " + std::to_string(index_) + " of " + std::to_string(element_->count) + " " +
         ply_plural(*element_) + " read");
  }
  const unsigned char* data_;
  size_t size_, pos_, last_ = 0;
  bool big_endian_;
  const std::string& name_;
  const PlyElement* element_ = nullptr;
  uint64_t index_ = 0;
};

template <class Values>
void read_ply_face(Values& values, PlyType index_type, long long size, uint64_t vertex_count, Mesh& mesh) {
  if (size < 3) values.fail("face has " + std::to_string(size) + " vertices (at least 3 needed)");
  for (long long k = 0; k < size; ++k) {
    const long long index = values.integer(index_type, "vertex index");
    if (index < 0 || static_cast<uint64_t>(index) >= vertex_count)
      values.fail("vertex index " + std::to_string(index) + " out of range (the file has " +
                  std::to_string(vertex_count) + " vertices)");
    mesh.indices.push_back(static_cast<uint32_t>(index));
  }
  mesh.face_sizes.push_back(static_cast<uint32_t>(size));
}

// Reads every element in header order: vertex positions and face index lists into the mesh, the
// rest (other properties and elements) read past.
template <class Values>
void read_ply_body(Values& values, const PlyHeader& h, Mesh& mesh) {
  const uint64_t vertex_count = h.vertex >= 0 ? h.elements[h.vertex].count : 0;
  for (size_t which = 0; which < h.elements.size(); ++which) {
    const PlyElement& e = h.elements[which];
    if (e.properties.empty()) continue;  // its instances hold no values
    const bool is_vertex = static_cast<int>(which) == h.vertex, is_face = static_cast<int>(which) == h.face;
    for (uint64_t i = 0; i < e.count; ++i) {
      values.begin(e, i);
      double xyz[3] = {0, 0, 0};
      for (size_t k = 0; k < e.properties.size(); ++k) {
        const PlyProperty& p = e.properties[k];
        const int property = static_cast<int>(k);
        if (p.is_list) {
          const long long n = values.integer(p.count_type, "list count");
          if (n < 0) values.fail("negative list count " + std::to_string(n));
          if (is_face && property == e.role[0])
            read_ply_face(values, p.type, n, vertex_count, mesh);
          else
            values.skip(p.type, static_cast<uint64_t>(n));
        } else if (is_vertex && (property == e.role[0] || property == e.role[1] || property == e.role[2])) {
          xyz[property == e.role[0] ? 0 : property == e.role[1] ? 1 : 2] = values.coordinate(p.type);
        } else {
          values.skip(p.type, 1);
        }
      }
      values.end();
      if (is_vertex) mesh.positions.insert(mesh.positions.end(), xyz, xyz + 3);
    }
  }
}

void parse_ply(std::string_view bytes, const std::string& name, Mesh& mesh) {
  if (bytes.empty()) fail(Error::EmptyInput, name + ": empty file");
  const PlyHeader h = parse_ply_header(bytes, name);
  const uint64_t available = bytes.size() - h.data_offset;
  check_ply_counts(h, available, name);
  const uint64_t vertex_count = h.vertex >= 0 ? h.elements[h.vertex].count : 0;
  const uint64_t face_count = h.face >= 0 ? h.elements[h.face].count : 0;
  mesh.positions.reserve(3 * static_cast<size_t>(vertex_count));
  mesh.face_sizes.reserve(static_cast<size_t>(face_count));
  mesh.indices.reserve(static_cast<size_t>(std::min<uint64_t>(3 * face_count, available)));
  if (h.encoding == PlyEncoding::Ascii) {
    PlyAsciiValues values(bytes.substr(h.data_offset), h.end_line, name);
    read_ply_body(values, h, mesh);
  } else {
    PlyBinaryValues values(bytes, h.data_offset, h.encoding == PlyEncoding::BigEndian, name);
    read_ply_body(values, h, mesh);
  }
  if (vertex_count == 0 && face_count == 0) fail(Error::EmptyInput, name + ": no vertices and no faces");
  if (face_count == 0) fail(Error::EmptyInput, name + ": no faces");
  drop_face_sizes_if_all_triangles(mesh);
}

// ---------------------------------------------------------------------------------------------
// Format detection by content.

// The first keyword of a text, skipping blank lines and '#' comments (OFF and OBJ allow them
// before their first record).
std::string_view first_keyword(std::string_view text) {
  LineReader lines(text);
  std::string_view line, keyword;
  while (lines.next(line)) {
    Tokens tokens(strip_comment(line));
    if (tokens.next(keyword)) return keyword;
  }
  return {};
}

bool is_obj_keyword(std::string_view keyword) {
  static const char* const kKeywords[] = {"v", "vt", "vn", "vp", "f",      "fo",    "l",
                                          "p", "o",  "g",  "s",  "mtllib", "usemtl"};
  return std::any_of(std::begin(kKeywords), std::end(kKeywords), [&](const char* k) { return keyword == k; });
}

MeshFormat detect_content_format(std::string_view bytes) {
  // Binary STL first, by its size: its 80-byte header is free text and may say anything.
  if (bytes.size() >= 84 &&
      84 + 50 * uint64_t(read_le32(reinterpret_cast<const unsigned char*>(bytes.data()) + 80)) == bytes.size())
    return MeshFormat::Stl;
  // "ply" alone on the first line is the PLY magic.
  if (bytes.substr(0, 4) == "ply\n" || bytes.substr(0, 5) == "ply\r\n") return MeshFormat::Ply;
  if (starts_with_solid(bytes)) return MeshFormat::Stl;
  std::string_view text = bytes;
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  const std::string_view keyword = first_keyword(text);
  bool higher_dimension;
  if (is_off_keyword(keyword, higher_dimension)) return MeshFormat::Off;
  if (is_obj_keyword(keyword)) return MeshFormat::Obj;
  return MeshFormat::Unknown;
}

// ---------------------------------------------------------------------------------------------
// Writers.

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

}  // namespace

// ---------------------------------------------------------------------------------------------
// Public readers.

MeshFormat format_from_path(const std::string& path) {
  size_t slash = path.find_last_of("/\\");
  size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return MeshFormat::Unknown;
  std::string_view extension = std::string_view(path).substr(dot + 1);
  if (equals_ignore_case(extension, "off")) return MeshFormat::Off;
  if (equals_ignore_case(extension, "obj")) return MeshFormat::Obj;
  if (equals_ignore_case(extension, "stl")) return MeshFormat::Stl;
  if (equals_ignore_case(extension, "ply")) return MeshFormat::Ply;
  return MeshFormat::Unknown;
}

ReadResult read_off(std::string_view text, const std::string& name) {
  return run_reader([&](ReadResult& r) { parse_off(text, name, r.mesh); });
}

ReadResult read_obj(std::string_view text, const std::string& name) {
  return run_reader([&](ReadResult& r) { parse_obj(text, name, r.mesh); });
}

ReadResult read_stl(std::string_view bytes, const std::string& name) {
  return run_reader([&](ReadResult& r) { parse_stl(bytes, name, r.mesh); });
}

ReadResult read_ply(std::string_view bytes, const std::string& name) {
  return run_reader([&](ReadResult& r) { parse_ply(bytes, name, r.mesh); });
}

MeshFormat detect_format(std::string_view bytes) { return detect_content_format(bytes); }

ReadResult read_mesh(std::string_view bytes, MeshFormat format, const std::string& name) {
  if (format == MeshFormat::Unknown) format = format_from_path(name);
  if (format == MeshFormat::Unknown) format = detect_format(bytes);
  switch (format) {
    case MeshFormat::Off: return read_off(bytes, name);
    case MeshFormat::Obj: return read_obj(bytes, name);
    case MeshFormat::Stl: return read_stl(bytes, name);
    case MeshFormat::Ply: return read_ply(bytes, name);
    case MeshFormat::Unknown: break;
  }
  ReadResult result;
  if (only_blank(bytes)) {
    result.error = Error::EmptyInput;
    result.message = name + ": empty file";
  } else {
    result.error = Error::ParseError;
    result.message = name +
                     ": unknown mesh format: the name does not end in .off, .obj, .stl or .ply and the content is "
                     "none of them";
  }
  return result;
}

ReadResult read_mesh_file(const std::string& path, size_t max_bytes) {
  // 0, like the default SIZE_MAX, means no limit beyond what the address space allows.
  if (max_bytes == 0) max_bytes = std::numeric_limits<size_t>::max();
  ReadResult result;
  auto io_error = [&](const std::string& reason) {
    result.error = Error::IoError;
    result.message = path + ": " + reason;
    return result;
  };
  struct stat info;
  if (::stat(path.c_str(), &info) != 0) return io_error(std::strerror(errno));
  if (S_ISDIR(info.st_mode)) return io_error("is a directory");
  auto too_large = [&](uint64_t size) {
    result.error = Error::TooLarge;
    result.message = path + ": file is " + std::to_string(size) + " bytes, more than the limit of " +
                     std::to_string(max_bytes) + " bytes";
    return result;
  };
  if (S_ISREG(info.st_mode) && static_cast<uint64_t>(info.st_size) > max_bytes) return too_large(info.st_size);

  FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return io_error(std::strerror(errno));
  std::string bytes;
  try {
    if (S_ISREG(info.st_mode)) bytes.reserve(static_cast<size_t>(info.st_size));
    char buffer[1 << 16];
    size_t got;
    while ((got = std::fread(buffer, 1, sizeof buffer, file)) > 0) {
      if (bytes.size() + got > max_bytes) {
        std::fclose(file);
        return too_large(bytes.size() + got);
      }
      bytes.append(buffer, got);
    }
  } catch (const std::bad_alloc&) {
    std::fclose(file);
    result.error = Error::TooLarge;
    result.message = path + ": out of memory while reading the file";
    return result;
  }
  const bool read_failed = std::ferror(file) != 0;
  std::fclose(file);
  if (read_failed) return io_error("read error");
  return read_mesh(bytes, MeshFormat::Unknown, path);
}

// ---------------------------------------------------------------------------------------------
// One "<prefix>x y z" line per vertex, every coordinate bit kept.
static void append_vertex_lines(std::string& out, const Mesh& mesh, const char* prefix) {
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
