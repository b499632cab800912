// kergen/io.h — mesh files in and out. The one file grammar of the project: the CLI reads files
// with these readers and the npm package's readMesh runs the same code compiled to WebAssembly,
// so a file means the same mesh (or the same error) everywhere.
//
// Readers: OFF, OBJ (polygons, negative/relative indices, `v/vt/vn` forms, comments, groups,
// materials and other records ignored), STL ascii and binary (told apart by content, not by the
// word "solid"), PLY 1.0 (below). STL vertices are welded by exact coordinate equality. Every
// error names the file, the line (text formats, PLY headers) or byte offset (binary STL and PLY
// data) and the reason. No reader trusts a count before checking it against the bytes that follow.
//
// PLY: ascii, binary_little_endian and binary_big_endian 1.0. Element `vertex` needs scalar
// properties x, y, z (any PLY scalar type: char/int8 ... double/float64; binary values convert
// exactly, ascii values are read as written, in double, like OFF and OBJ); element `face` needs a
// list `vertex_indices` (or `vertex_index`) of integers, 0-based. Other properties (lists too)
// and other elements (edge, material, ...) are read past; their ascii values are only counted.
// `comment` and `obj_info` lines are ignored. Ascii data has one element per line.
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

enum class MeshFormat { Unknown, Off, Obj, Stl, Ply };
MeshFormat format_from_path(const std::string& path);  // by extension, case-insensitive

// The format a file's content shows, Unknown when none: PLY by "ply" alone on the first line,
// binary STL by its size (84 + 50 × the header's triangle count), ascii STL by a first word
// "solid", OFF by its header keyword, OBJ by a first record that is an OBJ keyword (v, f, vn, g,
// o, mtllib, ...); blank lines and '#' comments before the last two are skipped.
MeshFormat detect_format(std::string_view bytes);

// Reads a file, as read_mesh(bytes, MeshFormat::Unknown, path) (extension first, then content).
ReadResult read_mesh_file(const std::string& path, size_t max_bytes = SIZE_MAX);  // 0 = no limit
// Parses bytes already in memory; `name` is used in messages. With MeshFormat::Unknown the format
// comes from `name`'s extension, else from the content (detect_format); content that is none of
// the formats is a ParseError ("unknown mesh format"), blank content EmptyInput.
ReadResult read_mesh(std::string_view bytes, MeshFormat format, const std::string& name = "<memory>");
ReadResult read_off(std::string_view text, const std::string& name = "<memory>");
ReadResult read_obj(std::string_view text, const std::string& name = "<memory>");
ReadResult read_stl(std::string_view bytes, const std::string& name = "<memory>");
ReadResult read_ply(std::string_view bytes, const std::string& name = "<memory>");

// Writes positions + polygon faces (face_sizes empty = triangles) as OFF, OBJ or STL (there is
// no PLY writer). Returns Ok or IoError with `message` set.
Error write_mesh_file(const std::string& path, const Mesh& mesh, std::string* message = nullptr);
// The file as bytes; `format` is Off, Obj or Stl (anything else throws std::invalid_argument).
std::string write_mesh(const Mesh& mesh, MeshFormat format);
std::string write_obj(const Mesh& mesh);
std::string write_off(const Mesh& mesh);
std::string write_stl_binary(const Mesh& mesh);

// The kernel as a mesh (vertices + polygon faces), ready for the writers.
Mesh kernel_mesh(const Kernel& kernel);

}  // namespace kergen
