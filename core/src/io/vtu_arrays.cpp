// vtu_arrays.cpp — decoding of a VTK XML file's DataArrays (vtu_arrays.h).
#include "io/vtu_arrays.h"

#include <cmath>
#include <cstring>
#include <limits>

#include "io/numbers.h"
#include "io/reader.h"
#include "io/text_scan.h"
#include "io/volume_reader.h"

namespace kergen::io::vtu {

namespace {

enum class Kind { Signed, Unsigned, Float };
struct ElementType {
  const char* name;
  size_t size;
  Kind kind;
};
constexpr ElementType kTypes[] = {
    {"Int8", 1, Kind::Signed},     {"UInt8", 1, Kind::Unsigned},  {"Int16", 2, Kind::Signed},
    {"UInt16", 2, Kind::Unsigned}, {"Int32", 4, Kind::Signed},    {"UInt32", 4, Kind::Unsigned},
    {"Int64", 8, Kind::Signed},    {"UInt64", 8, Kind::Unsigned}, {"Float32", 4, Kind::Float},
    {"Float64", 8, Kind::Float},
};

const ElementType* element_type(std::string_view name) {
  for (const ElementType& t : kTypes)
    if (name == t.name) return &t;
  return nullptr;
}

// The `size` bytes at p as an unsigned integer, from the file's byte order.
uint64_t load(const unsigned char* p, size_t size, bool big_endian) {
  uint64_t v = 0;
  for (size_t i = 0; i < size; ++i) v |= uint64_t(p[big_endian ? size - 1 - i : i]) << (8 * i);
  return v;
}

double as_double(uint64_t bits, const ElementType& t) {
  switch (t.kind) {
    case Kind::Unsigned: return double(bits);
    case Kind::Signed: {
      const unsigned shift = unsigned(64 - 8 * t.size);
      return double(int64_t(bits << shift) >> shift);
    }
    case Kind::Float:
      if (t.size == 4) {
        float f;
        const uint32_t b = uint32_t(bits);
        std::memcpy(&f, &b, 4);
        return double(f);
      } else {
        double d;
        std::memcpy(&d, &bits, 8);
        return d;
      }
  }
  return 0;
}

size_t base64_chars(uint64_t bytes) { return size_t((bytes + 2) / 3 * 4); }

// Whitespace-separated values of an ascii DataArray (across lines, unlike text_scan's Tokens).
class AsciiValues {
 public:
  explicit AsciiValues(std::string_view text) : text_(text) {}
  bool next(std::string_view& token) {
    while (pos_ < text_.size() && (is_blank(text_[pos_]) || text_[pos_] == '\n')) ++pos_;
    if (pos_ >= text_.size()) return false;
    const size_t start = pos_;
    while (pos_ < text_.size() && !is_blank(text_[pos_]) && text_[pos_] != '\n') ++pos_;
    token = text_.substr(start, pos_ - start);
    return true;
  }

 private:
  std::string_view text_;
  size_t pos_ = 0;
};

}  // namespace

size_t line_at(std::string_view text, size_t offset) {
  size_t line = 1;
  for (size_t i = 0; i < offset && i < text.size(); ++i) line += text[i] == '\n';
  return line;
}

Decoder::Decoder(std::string_view text, const std::string& name, bool big_endian, bool header64,
                 std::string_view compressor, bool appended, bool appended_raw, size_t appended_begin)
    : text_(text),
      name_(name),
      big_endian_(big_endian),
      header64_(header64),
      compressor_(compressor),
      appended_(appended),
      appended_raw_(appended_raw),
      appended_begin_(appended_begin) {}

void Decoder::fail_array(const ArraySpec& array, const std::string& reason) const {
  fail_at_line(name_, line_at(text_, array.tag_at), "DataArray: " + reason);
}

uint64_t Decoder::header_value(const std::string& bytes) const {
  return load(reinterpret_cast<const unsigned char*>(bytes.data()), header64_ ? 8 : 4, big_endian_);
}

std::string Decoder::base64_payload(const ArraySpec& array, std::string_view encoded, size_t where) const {
  const size_t header = header64_ ? 8 : 4, header_chars = base64_chars(header);
  std::string decoded;
  size_t bad_at = 0;
  if (encoded.size() < header_chars || !base64_decode(encoded.substr(0, header_chars), decoded, bad_at, true))
    fail_at_byte(name_, where, "invalid or truncated base64 data header");
  const uint64_t count = header_value(decoded);
  if (count > encoded.size())
    fail_at_byte(name_, where,
                 "base64 data header claims " + std::to_string(count) + " bytes, more than the file holds");
  // Separately encoded header: its last quantum is padded. Else one stream.
  const bool separate = encoded[header_chars - 1] == '=';
  const size_t total = separate ? header_chars + base64_chars(count) : base64_chars(header + count);
  if (total > encoded.size())
    fail_at_byte(name_, where, "base64 data ends before its " + std::to_string(count) + " bytes");
  decoded.clear();
  if (!base64_decode(encoded.substr(0, total), decoded, bad_at))
    fail_at_byte(name_, where + bad_at, "invalid base64 character");
  (void)array;
  if (decoded.size() < header + count) fail_at_byte(name_, where, "base64 data shorter than its header says");
  return decoded.substr(header, size_t(count));
}

std::string Decoder::payload(const ArraySpec& array) const {
  if (!compressor_.empty())
    fail_array(array, "compressed data (compressor \"" + std::string(compressor_) +
                          "\") is not supported: save the file uncompressed (ParaView: Compressor None; "
                          "VTK: SetCompressorTypeToNone; meshio: compression=None)");
  const size_t header = header64_ ? 8 : 4;
  if (array.format == "binary") {
    std::string decoded;
    size_t bad_at = 0;
    const std::string_view encoded = text_.substr(array.text_begin, array.text_end - array.text_begin);
    if (!base64_decode(encoded, decoded, bad_at)) fail_at_byte(name_, array.text_begin + bad_at, "invalid base64 data");
    if (decoded.size() < header) fail_array(array, "binary data shorter than its header");
    const uint64_t count = header_value(decoded);
    if (count > decoded.size() - header)
      fail_array(array, "binary data header claims " + std::to_string(count) + " bytes, the data holds " +
                            std::to_string(decoded.size() - header));
    return decoded.substr(header, size_t(count));
  }
  if (!appended_) fail_array(array, "format=\"appended\" without <AppendedData>");
  if (!array.has_offset) fail_array(array, "appended DataArray without an offset");
  if (array.offset > text_.size() - appended_begin_) fail_array(array, "offset past the end of the file");
  const size_t at = appended_begin_ + size_t(array.offset);
  if (!appended_raw_) return base64_payload(array, text_.substr(at), at);
  if (text_.size() - at < header) fail_at_byte(name_, at, "appended data truncated in its header");
  const uint64_t count = load(reinterpret_cast<const unsigned char*>(text_.data() + at), header, big_endian_);
  if (count > text_.size() - at - header)
    fail_at_byte(name_, at,
                 "appended data header claims " + std::to_string(count) + " bytes, the file holds " +
                     std::to_string(text_.size() - at - header));
  return std::string(text_.substr(at + header, size_t(count)));
}

void Decoder::doubles(const ArraySpec& array, uint64_t expected, std::vector<double>& out) {
  const ElementType* type = element_type(array.type);
  if (!type) fail_array(array, "unsupported type " + quoted(array.type));
  if (array.format == "ascii") {
    AsciiValues tokens(text_.substr(array.text_begin, array.text_end - array.text_begin));
    std::string_view token;
    uint64_t n = 0;
    while (tokens.next(token)) {
      double v = 0;
      const size_t offset = size_t(token.data() - text_.data());
      if (parse_double(token, v) != NumberStatus::Ok)
        fail_at_line(name_, line_at(text_, offset), "invalid or non-finite number " + quoted(token));
      if (expected != SIZE_MAX && n >= expected) fail_array(array, "more than " + std::to_string(expected) + " values");
      out.push_back(v);
      ++n;
    }
    if (expected != SIZE_MAX && n != expected)
      fail_array(array, std::to_string(n) + " values, expected " + std::to_string(expected));
    return;
  }
  if (array.format != "binary" && array.format != "appended")
    fail_array(array, "unsupported format " + quoted(array.format));
  const std::string bytes = payload(array);
  if (bytes.size() % type->size != 0) fail_array(array, "byte count not a multiple of the value size");
  const uint64_t n = bytes.size() / type->size;
  if (expected != SIZE_MAX && n != expected)
    fail_array(array, std::to_string(n) + " values, expected " + std::to_string(expected));
  const unsigned char* p = reinterpret_cast<const unsigned char*>(bytes.data());
  for (uint64_t i = 0; i < n; ++i) {
    const double v = as_double(load(p + i * type->size, type->size, big_endian_), *type);
    if (!std::isfinite(v)) fail_array(array, "non-finite value at index " + std::to_string(i));
    out.push_back(v);
  }
}

void Decoder::integers(const ArraySpec& array, uint64_t expected, std::vector<int64_t>& out) {
  const ElementType* type = element_type(array.type);
  if (!type || type->kind == Kind::Float) fail_array(array, "needs an integer type, not " + quoted(array.type));
  out.clear();
  if (array.format == "ascii") {
    AsciiValues tokens(text_.substr(array.text_begin, array.text_end - array.text_begin));
    std::string_view token;
    while (tokens.next(token)) {
      long long v = 0;
      if (!parse_integer(token, v))
        fail_at_line(name_, line_at(text_, size_t(token.data() - text_.data())), "invalid integer " + quoted(token));
      if (expected != SIZE_MAX && out.size() >= expected)
        fail_array(array, "more than " + std::to_string(expected) + " values");
      out.push_back(v);
    }
  } else {
    if (array.format != "binary" && array.format != "appended")
      fail_array(array, "unsupported format " + quoted(array.format));
    const std::string bytes = payload(array);
    if (bytes.size() % type->size != 0) fail_array(array, "byte count not a multiple of the value size");
    const size_t n = bytes.size() / type->size;
    if (expected != SIZE_MAX && n != expected)
      fail_array(array, std::to_string(n) + " values, expected " + std::to_string(expected));
    out.resize(n);
    const unsigned char* p = reinterpret_cast<const unsigned char*>(bytes.data());
    const unsigned shift = unsigned(64 - 8 * type->size);
    for (size_t i = 0; i < n; ++i) {
      const uint64_t bits = load(p + i * type->size, type->size, big_endian_);
      if (type->kind == Kind::Signed) {
        out[i] = int64_t(bits << shift) >> shift;
      } else {
        if (bits > uint64_t(std::numeric_limits<int64_t>::max()))
          fail_array(array, "value too large at index " + std::to_string(i));
        out[i] = int64_t(bits);
      }
    }
  }
  if (expected != SIZE_MAX && out.size() != expected)
    fail_array(array, std::to_string(out.size()) + " values, expected " + std::to_string(expected));
}

}  // namespace kergen::io::vtu
