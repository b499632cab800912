// reader.cpp — the readers' shared failure (ReadFailure, the messages naming line or byte, the
// quoting of a token), run_reader, prepare_text and the final face-size step (reader.h).
#include "io/reader.h"

#include <algorithm>
#include <cstdio>
#include <new>
#include <stdexcept>

#include "io/text_scan.h"

namespace kergen::io {

[[noreturn]] void fail(Error error, std::string message) { throw ReadFailure{error, std::move(message)}; }

[[noreturn]] void fail_at_line(const std::string& name, size_t line, const std::string& reason) {
  fail(Error::ParseError, name + ":" + std::to_string(line) + ": " + reason);
}

[[noreturn]] void fail_at_byte(const std::string& name, uint64_t offset, const std::string& reason) {
  fail(Error::ParseError, name + ": byte " + std::to_string(offset) + ": " + reason);
}

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

void drop_face_sizes_if_all_triangles(Mesh& mesh) {
  if (std::all_of(mesh.face_sizes.begin(), mesh.face_sizes.end(), [](uint32_t k) { return k == 3; }))
    mesh.face_sizes.clear();
}

}  // namespace kergen::io
