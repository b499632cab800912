// vtu.cpp — the VTK XML UnstructuredGrid reader (read_vtu): "VTK File Formats", section "XML File
// Formats" (docs.vtk.org/en/latest/design_documents/VTKFileFormats.html), and for polyhedra the
// `faces` / `faceoffsets` arrays of the "Polyhedron Support" design (vtk.org/Wiki/VTK/Polyhedron_Support,
// the layout VTK 9.1 to 9.3 and meshio write: per polyhedron [nfaces, (npts, ids...)...], and
// faceoffsets the end of each polyhedron's part, -1 for other cells).
//
// The XML is scanned, not parsed by a general XML library: only tags and attributes are read
// (comments, <?...?> and <!...> skipped); DataArray contents are the text up to the next '<'
// (VTK puts InformationKey children after the data). Appended data starts after the '_' that
// follows <AppendedData>; its raw bytes are never scanned as XML.
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "io/numbers.h"
#include "io/reader.h"
#include "io/text_scan.h"
#include "io/volume_reader.h"
#include "io/vtu_arrays.h"
#include "kergen/volume.h"

namespace kergen {

using namespace io;
using namespace io::vtu;

namespace {

struct Tag {
  std::string_view name;
  std::string_view attrs;  // the text between the name and '>' (or "/>")
  bool closing = false, self_closing = false;
  size_t begin = 0, end = 0;  // byte offsets of '<' and one past '>'

  // The value of attribute `key` (quotes removed), or empty with `found` false.
  std::string_view attr(std::string_view key, bool* found = nullptr) const {
    size_t i = 0;
    while (i < attrs.size()) {
      while (i < attrs.size() && is_blank_xml(attrs[i])) ++i;
      const size_t name_begin = i;
      while (i < attrs.size() && attrs[i] != '=' && !is_blank_xml(attrs[i])) ++i;
      const std::string_view attr_name = attrs.substr(name_begin, i - name_begin);
      while (i < attrs.size() && is_blank_xml(attrs[i])) ++i;
      if (i >= attrs.size() || attrs[i] != '=') break;
      ++i;
      while (i < attrs.size() && is_blank_xml(attrs[i])) ++i;
      if (i >= attrs.size() || (attrs[i] != '"' && attrs[i] != '\'')) break;
      const char quote = attrs[i++];
      const size_t value_begin = i;
      while (i < attrs.size() && attrs[i] != quote) ++i;
      const std::string_view value = attrs.substr(value_begin, i - value_begin);
      ++i;
      if (attr_name == key) {
        if (found) *found = true;
        return value;
      }
    }
    if (found) *found = false;
    return {};
  }
  static bool is_blank_xml(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
};

class XmlScanner {
 public:
  XmlScanner(std::string_view text, const std::string& name) : text_(text), name_(name) {}
  // The next element tag; false at the end of the text.
  bool next(Tag& tag) {
    for (;;) {
      const size_t lt = text_.find('<', pos_);
      if (lt == std::string_view::npos) return false;
      if (text_.compare(lt, 4, "<!--") == 0) {
        pos_ = skip_past(lt, "-->");
        continue;
      }
      if (text_.compare(lt, 2, "<?") == 0) {
        pos_ = skip_past(lt, "?>");
        continue;
      }
      if (text_.compare(lt, 2, "<!") == 0) {
        pos_ = skip_past(lt, ">");
        continue;
      }
      const size_t gt = text_.find('>', lt);
      if (gt == std::string_view::npos) fail_at_byte(name_, lt, "unterminated tag");
      tag = Tag{};
      tag.begin = lt;
      tag.end = gt + 1;
      std::string_view body = text_.substr(lt + 1, gt - lt - 1);
      if (!body.empty() && body[0] == '/') tag.closing = true, body.remove_prefix(1);
      if (!body.empty() && body.back() == '/') tag.self_closing = true, body.remove_suffix(1);
      size_t n = 0;
      while (n < body.size() && !Tag::is_blank_xml(body[n])) ++n;
      tag.name = body.substr(0, n);
      tag.attrs = body.substr(n);
      pos_ = gt + 1;
      return true;
    }
  }
  size_t pos() const { return pos_; }

 private:
  size_t skip_past(size_t from, const char* end) {
    const size_t at = text_.find(end, from);
    if (at == std::string_view::npos) fail_at_byte(name_, from, "unterminated comment or declaration");
    return at + std::strlen(end);
  }
  std::string_view text_;
  const std::string& name_;
  size_t pos_ = 0;
};

struct PieceSpec {
  uint64_t points = 0, cells = 0;
  size_t tag_at = 0;
  ArraySpec coordinates, connectivity, offsets, types, faces, faceoffsets;
};

struct FileSpec {
  bool big_endian = false, header64 = false;
  std::string_view compressor;
  std::vector<PieceSpec> pieces;
  bool appended = false, appended_raw = true;
  size_t appended_begin = 0;  // first byte after the '_'
};

uint64_t attr_count(const Tag& tag, std::string_view key, std::string_view text, const std::string& name) {
  bool found = false;
  const std::string_view value = tag.attr(key, &found);
  long long n = 0;
  if (!found)
    fail_at_line(name, line_at(text, tag.begin), "<" + std::string(tag.name) + "> without " + std::string(key));
  if (!parse_integer(value, n) || n < 0)
    fail_at_line(name, line_at(text, tag.begin), "invalid " + std::string(key) + " " + quoted(value));
  return uint64_t(n);
}

ArraySpec array_spec(const Tag& tag, std::string_view text, const std::string& name) {
  ArraySpec a;
  a.present = true;
  a.type = tag.attr("type");
  a.format = tag.attr("format");
  a.tag_at = tag.begin;
  bool found = false;
  const std::string_view components = tag.attr("NumberOfComponents", &found);
  if (found && (!parse_integer(components, a.components) || a.components < 1))
    fail_at_line(name, line_at(text, tag.begin), "invalid NumberOfComponents " + quoted(components));
  const std::string_view offset = tag.attr("offset", &a.has_offset);
  long long off = 0;
  if (a.has_offset && (!parse_integer(offset, off) || off < 0))
    fail_at_line(name, line_at(text, tag.begin), "invalid offset " + quoted(offset));
  a.offset = uint64_t(off);
  a.text_begin = a.text_end = tag.end;
  if (!tag.self_closing) {
    const size_t lt = text.find('<', tag.end);
    a.text_end = lt == std::string_view::npos ? text.size() : lt;
  }
  return a;
}

void record_cells_array(PieceSpec& piece, const Tag& tag, std::string_view text, const std::string& name) {
  const std::string_view array = tag.attr("Name");
  ArraySpec* slot = array == "connectivity"  ? &piece.connectivity
                    : array == "offsets"     ? &piece.offsets
                    : array == "types"       ? &piece.types
                    : array == "faces"       ? &piece.faces
                    : array == "faceoffsets" ? &piece.faceoffsets
                                             : nullptr;
  if (array == "face_connectivity" || array == "polyhedron_to_faces")
    fail_at_line(name, line_at(text, tag.begin),
                 "the polyhedron layout of VTK 9.4 (" + std::string(array) +
                     ") is not supported: write the file with `faces` and `faceoffsets` (VTK 9.1 to 9.3, meshio)");
  if (slot) *slot = array_spec(tag, text, name);
}

// Reads the tags up to <AppendedData> or the end: the file's settings and each piece's arrays.
FileSpec scan_structure(std::string_view text, const std::string& name) {
  FileSpec file;
  // A cut file would otherwise show as a missing or short array somewhere.
  size_t last = text.size();
  while (last > 0 && (Tag::is_blank_xml(text[last - 1]) || text[last - 1] == '\0')) --last;
  if (last < 10 || text.substr(last - 10, 10) != "</VTKFile>")
    fail_at_byte(name, text.size(), "the file does not end with </VTKFile> (truncated?)");
  XmlScanner xml(text, name);
  Tag tag;
  if (!xml.next(tag) || tag.name != "VTKFile" || tag.closing)
    fail_at_line(name, 1, "not a VTK XML file (no <VTKFile> element first)");
  const std::string_view type = tag.attr("type");
  if (type != "UnstructuredGrid")
    fail_at_line(name, line_at(text, tag.begin),
                 "VTKFile type " + quoted(type) + " is not a volume mesh (only UnstructuredGrid is read)");
  const std::string_view order = tag.attr("byte_order");
  file.big_endian = order == "BigEndian";
  const std::string_view header = tag.attr("header_type");
  if (!header.empty() && header != "UInt32" && header != "UInt64")
    fail_at_line(name, line_at(text, tag.begin), "unsupported header_type " + quoted(header));
  file.header64 = header == "UInt64";
  file.compressor = tag.attr("compressor");
  enum class Section { None, Points, Cells } section = Section::None;
  while (xml.next(tag)) {
    if (tag.name == "Piece" && !tag.closing) {
      PieceSpec piece;
      piece.points = attr_count(tag, "NumberOfPoints", text, name);
      piece.cells = attr_count(tag, "NumberOfCells", text, name);
      piece.tag_at = tag.begin;
      file.pieces.push_back(piece);
    } else if (tag.name == "Points" || tag.name == "Cells") {
      section = tag.closing || tag.self_closing ? Section::None
                : tag.name == "Points"          ? Section::Points
                                                : Section::Cells;
    } else if (tag.name == "DataArray" && !tag.closing && !file.pieces.empty()) {
      PieceSpec& piece = file.pieces.back();
      if (section == Section::Points && !piece.coordinates.present) piece.coordinates = array_spec(tag, text, name);
      if (section == Section::Cells) record_cells_array(piece, tag, text, name);
    } else if (tag.name == "AppendedData" && !tag.closing) {
      const std::string_view encoding = tag.attr("encoding");
      if (encoding != "raw" && encoding != "base64")
        fail_at_line(name, line_at(text, tag.begin), "unsupported AppendedData encoding " + quoted(encoding));
      file.appended = true;
      file.appended_raw = encoding == "raw";
      const size_t underscore = text.find('_', tag.end);
      if (underscore == std::string_view::npos) fail_at_byte(name, tag.end, "AppendedData without its '_' marker");
      file.appended_begin = underscore + 1;
      break;
    }
  }
  if (file.pieces.empty()) fail(Error::ParseError, name + ": no <Piece> in the UnstructuredGrid");
  return file;
}

void read_piece(const PieceSpec& piece, Decoder& decoder, VolumeBuilder& builder, const std::string& name,
                std::string_view text) {
  auto need = [&](const ArraySpec& a, const char* what) {
    if (!a.present)
      fail_at_line(name, line_at(text, piece.tag_at), std::string("piece without the ") + what + " DataArray");
  };
  need(piece.coordinates, "Points");
  if (piece.coordinates.components != 3)
    fail_at_line(name, line_at(text, piece.coordinates.tag_at), "Points need NumberOfComponents=\"3\"");
  VolumeMesh& mesh = builder.mesh();
  const uint64_t point_base = mesh.num_vertices();
  decoder.doubles(piece.coordinates, 3 * piece.points, mesh.positions);
  if (piece.cells == 0) return;
  need(piece.connectivity, "connectivity");
  need(piece.offsets, "offsets");
  need(piece.types, "types");
  std::vector<int64_t> connectivity, offsets, types, faces, faceoffsets;
  decoder.integers(piece.offsets, piece.cells, offsets);
  decoder.integers(piece.types, piece.cells, types);
  decoder.integers(piece.connectivity, SIZE_MAX, connectivity);
  bool any_polyhedron = false;
  for (int64_t t : types) any_polyhedron = any_polyhedron || t == kVtkPolyhedron;
  if (any_polyhedron) {
    need(piece.faces, "faces");
    need(piece.faceoffsets, "faceoffsets");
    decoder.integers(piece.faces, SIZE_MAX, faces);
    decoder.integers(piece.faceoffsets, piece.cells, faceoffsets);
  }
  int64_t begin = 0, face_cursor = 0;
  for (size_t c = 0; c < piece.cells; ++c) {
    const int64_t end = offsets[c];
    // Messages (and their line numbers, a scan of the text) are made only on failure.
    auto where = [c] { return "cell " + std::to_string(c) + ": "; };
    if (end < begin || uint64_t(end) > connectivity.size())
      fail_at_line(name, line_at(text, piece.offsets.tag_at),
                   where() + "offset " + std::to_string(end) + " outside the connectivity array");
    std::string why;
    if (types[c] == kVtkPolyhedron) {
      const int64_t face_end = faceoffsets[c];
      if (face_end < face_cursor || uint64_t(face_end) > faces.size())
        fail_at_line(name, line_at(text, piece.faceoffsets.tag_at),
                     where() + "faceoffset " + std::to_string(face_end) + " outside the faces array");
      why = append_vtk_cell(builder, kVtkPolyhedron, faces.data() + face_cursor, size_t(face_end - face_cursor),
                            point_base, piece.points);
      if (!why.empty()) fail_at_line(name, line_at(text, piece.faces.tag_at), where() + why);
      face_cursor = face_end;
    } else {
      why = append_vtk_cell(builder, types[c], connectivity.data() + begin, size_t(end - begin), point_base,
                            piece.points);
      if (!why.empty()) fail_at_line(name, line_at(text, piece.types.tag_at), where() + why);
    }
    begin = end;
  }
}

}  // namespace

VolumeReadResult read_vtu(std::string_view bytes, const std::string& name) {
  return run_volume_reader([&](VolumeMesh& mesh) {
    if (only_blank(bytes)) fail(Error::EmptyInput, name + ": empty file");
    const FileSpec file = scan_structure(bytes, name);
    Decoder decoder(bytes, name, file.big_endian, file.header64, file.compressor, file.appended, file.appended_raw,
                    file.appended_begin);
    VolumeBuilder builder(mesh);
    for (const PieceSpec& piece : file.pieces) read_piece(piece, decoder, builder, name, bytes);
  });
}

}  // namespace kergen
