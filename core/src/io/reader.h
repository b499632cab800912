// reader.h — what the four readers (off.cpp, obj.cpp, stl.cpp, ply.cpp) share, private to io/:
// the failure each public reader turns into a ReadResult, its messages naming the file and the
// line (text) or byte offset (binary STL, PLY); the checks on the mesh being built; and the two
// format facts that detection (detect.cpp) asks of the OFF and STL readers.
//
// The readers are strict: a malformed number, an index out of range or a truncated file is a
// ParseError naming the file and the line (text) or byte offset (binary STL), never a silently
// repaired mesh. Geometric problems of a well-formed file (holes, degenerate faces, ...) are left to
// the core's validation. No reader trusts a count from a header before checking it against the
// bytes that follow, so a lying header cannot trigger a huge allocation.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <string_view>

#include "kergen/io.h"

namespace kergen::io {

// Internal control flow only: every public entry point catches it and turns it into a ReadResult.
struct ReadFailure {
  Error error;
  std::string message;
};

[[noreturn]] void fail(Error error, std::string message);
[[noreturn]] void fail_at_line(const std::string& name, size_t line, const std::string& reason);
[[noreturn]] void fail_at_byte(const std::string& name, uint64_t offset, const std::string& reason);

// A token quoted for an error message: control and non-ASCII bytes escaped, long tokens shortened,
// so a binary file fed to a text reader still gives a readable one-line message.
std::string quoted(std::string_view token);

// Runs one reader's body: a ReadFailure, or running out of memory, becomes the result's error.
ReadResult run_reader(const std::function<void(ReadResult&)>& body);

// A whole file's bytes (detect.cpp; the volume readers use it too): false with `error` (IoError,
// TooLarge) and `message` naming the path. max_bytes 0 or SIZE_MAX: no limit.
bool read_file_bytes(const std::string& path, size_t max_bytes, std::string& bytes, Error& error, std::string& message);

// Writes bytes to a file (writers.cpp; the VTU writer uses it too): Ok, or IoError with `message`.
Error write_file_bytes(const std::string& path, const std::string& bytes, std::string* message);

// Text formats: refuses UTF-16 (a common export option of Windows tools) with a clear reason instead
// of a confusing "invalid number" on line 1, and drops a UTF-8 byte order mark.
std::string_view prepare_text(std::string_view text, const std::string& name);

// Called for every vertex an OBJ file adds, hence inline.
inline void check_vertex_count(size_t count, const std::string& name, size_t line) {
  if (count > std::numeric_limits<uint32_t>::max())
    fail_at_line(name, line, "more than 4294967295 vertices (indices are 32-bit)");
}

// Faces are stored with explicit sizes while reading; an all-triangle mesh drops them, which is
// what "face_sizes empty = triangles" means in the public API.
void drop_face_sizes_if_all_triangles(Mesh& mesh);

// Little-endian 32-bit word (binary STL's triangle count and coordinates; detection reads the count).
inline uint32_t read_le32(const unsigned char* p) {
  return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

// Asked by detection (detect.cpp). off.cpp: [ST][C][N][4][n]OFF, `higher_dimension` set for 4/n.
bool is_off_keyword(std::string_view kind, bool& higher_dimension);
// stl.cpp: the text starts with the word "solid" (after a UTF-8 byte order mark and blanks).
bool starts_with_solid(std::string_view bytes);

}  // namespace kergen::io
