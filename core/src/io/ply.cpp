// ply.cpp — the PLY reader (read_ply): ASCII and binary (either byte order) PLY 1.0 (Greg Turk,
// "The PLY Polygon File Format", 1994). The vertex element's x, y, z and the face element's
// vertex_indices list make the mesh; every other property and element is read past, and the
// header's counts are checked against the bytes that follow before anything is reserved.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
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
                       count_of(available, "byte", "bytes") + " of data" + verb_for(available, " follows", " follow"));
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
  if (size < 3) values.fail("face has " + count_of(size, "vertex", "vertices") + " (at least 3 needed)");
  for (long long k = 0; k < size; ++k) {
    const long long index = values.integer(index_type, "vertex index");
    if (index < 0 || static_cast<uint64_t>(index) >= vertex_count)
      values.fail("vertex index " + std::to_string(index) + " out of range (the file has " +
                  count_of(vertex_count, "vertex", "vertices") + ")");
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

}  // namespace

ReadResult read_ply(std::string_view bytes, const std::string& name) {
  return run_reader([&](ReadResult& r) { parse_ply(bytes, name, r.mesh); });
}

}  // namespace kergen
