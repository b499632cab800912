// kergen/io.h — mesh files in and out (native side; the browser demo has JavaScript readers that
// follow these, web/loaders.js).
//
// Readers: OFF, OBJ (polygons, negative/relative indices, `v/vt/vn` forms, comments, groups,
// materials and other records ignored), STL ascii and binary (told apart by content, not by the
// word "solid"). STL vertices are welded by exact coordinate equality. Every error names the file,
// the line (text formats) or byte offset (binary STL) and the reason.
// Writers: OBJ, OFF, STL (binary) of a polygon mesh (STL fan-triangulates).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "kergen/kergen.h"

namespace kergen {

struct ReadResult {
  Error error = Error::Ok;         // Ok, IoError, ParseError, EmptyInput, TooLarge
  std::string message;             // "<file>:<line>: <reason>"
  Mesh mesh;
  bool ok() const { return error == Error::Ok; }
};

enum class MeshFormat { Unknown, Off, Obj, Stl };
MeshFormat format_from_path(const std::string& path);  // by extension, case-insensitive

// Reads a file; the format comes from the extension.
ReadResult read_mesh_file(const std::string& path, size_t max_bytes = SIZE_MAX);  // 0 = no limit
// Parses bytes already in memory; `name` is used in messages.
ReadResult read_mesh(std::string_view bytes, MeshFormat format, const std::string& name = "<memory>");
ReadResult read_off(std::string_view text, const std::string& name = "<memory>");
ReadResult read_obj(std::string_view text, const std::string& name = "<memory>");
ReadResult read_stl(std::string_view bytes, const std::string& name = "<memory>");

// Writes positions + polygon faces (face_sizes empty = triangles). Returns Ok or IoError with
// `message` set.
Error write_mesh_file(const std::string& path, const Mesh& mesh, std::string* message = nullptr);
std::string write_obj(const Mesh& mesh);
std::string write_off(const Mesh& mesh);
std::string write_stl_binary(const Mesh& mesh);

// The kernel as a mesh (vertices + polygon faces), ready for the writers.
Mesh kernel_mesh(const Kernel& kernel);

}  // namespace kergen
