// detect.cpp — which reader a file goes to: the format from the name's extension (format_from_path)
// or from the content (detect_format), and the public entry points that dispatch on them,
// read_mesh (bytes in memory) and read_mesh_file (a file, with a size limit, read by read_file_bytes,
// which the volume readers share).
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <limits>
#include <new>
#include <string>
#include <string_view>

#include "io/reader.h"
#include "io/text_scan.h"
#include "kergen/io.h"
#include "util/plural.h"

namespace kergen {

using namespace io;  // the readers' shared parts: reader.h, text_scan.h

namespace {

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

}  // namespace

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
  std::string bytes;
  ReadResult result;
  if (!read_file_bytes(path, max_bytes, bytes, result.error, result.message)) return result;
  return read_mesh(bytes, MeshFormat::Unknown, path);
}

namespace io {

bool read_file_bytes(const std::string& path, size_t max_bytes, std::string& bytes, Error& error,
                     std::string& message) {
  // 0, like the default SIZE_MAX, means no limit beyond what the address space allows.
  if (max_bytes == 0) max_bytes = std::numeric_limits<size_t>::max();
  auto io_error = [&](const std::string& reason) {
    error = Error::IoError;
    message = path + ": " + reason;
    return false;
  };
  struct stat info;
  if (::stat(path.c_str(), &info) != 0) return io_error(std::strerror(errno));
  if (S_ISDIR(info.st_mode)) return io_error("is a directory");
  auto too_large = [&](uint64_t size) {
    error = Error::TooLarge;
    message = path + ": file is " + count_of(size, "byte", "bytes") + ", more than the limit of " +
              count_of(max_bytes, "byte", "bytes");
    return false;
  };
  if (S_ISREG(info.st_mode) && static_cast<uint64_t>(info.st_size) > max_bytes) return too_large(info.st_size);

  FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return io_error(std::strerror(errno));
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
    error = Error::TooLarge;
    message = path + ": out of memory while reading the file";
    return false;
  }
  const bool read_failed = std::ferror(file) != 0;
  std::fclose(file);
  if (read_failed) return io_error("read error");
  return true;
}

}  // namespace io

}  // namespace kergen
