// vtk_legacy.cpp — the legacy VTK reader (read_vtk_legacy): "VTK File Formats", section "Simple
// Legacy Formats" (docs.vtk.org/en/latest/design_documents/VTKFileFormats.html), ASCII
// DATASET UNSTRUCTURED_GRID only. CELLS in both layouts: version 4 and earlier
// (`CELLS n size`, then per cell `count values...`) and version 5 (`CELLS noffsets nconn`, then
// OFFSETS and CONNECTIVITY arrays); a polyhedron's values are its face stream
// [nfaces, (npts, ids...)...]. Sections other than POINTS, CELLS, CELL_TYPES and METADATA end
// the read (POINT_DATA, CELL_DATA: attributes are not needed).
#include <string>
#include <string_view>
#include <vector>

#include "io/numbers.h"
#include "io/reader.h"
#include "io/text_scan.h"
#include "io/volume_reader.h"
#include "kergen/volume.h"

namespace kergen {

using namespace io;

namespace {

class Words {
 public:
  Words(std::string_view text, const std::string& name) : lines_(text), tokens_(std::string_view{}), name_(name) {}
  bool next(std::string_view& token) {
    while (!tokens_.next(token)) {
      std::string_view line;
      if (!lines_.next(line)) return false;
      tokens_ = Tokens(line);
    }
    return true;
  }
  std::string_view word(const char* what) {
    std::string_view token;
    if (!next(token)) fail_at_line(name_, line(), std::string("file ends where ") + what + " was expected");
    return token;
  }
  long long integer(const char* what) {
    const std::string_view token = word(what);
    long long v = 0;
    if (!parse_integer(token, v)) fail_at_line(name_, line(), std::string("invalid ") + what + " " + quoted(token));
    return v;
  }
  long long count(const char* what) {
    const long long v = integer(what);
    if (v < 0) fail_at_line(name_, line(), std::string("negative ") + what);
    return v;
  }
  double number() {
    const std::string_view token = word("a coordinate");
    double v = 0;
    if (parse_double(token, v) != NumberStatus::Ok)
      fail_at_line(name_, line(), "invalid or non-finite number " + quoted(token));
    return v;
  }
  // Next raw line (the header's title and format lines).
  bool raw_line(std::string_view& line) {
    tokens_ = Tokens(std::string_view{});
    return lines_.next(line);
  }
  void skip_line() { tokens_ = Tokens(std::string_view{}); }
  size_t line() const { return lines_.line_number(); }

 private:
  LineReader lines_;
  Tokens tokens_;
  const std::string& name_;
};

struct Cells {
  std::vector<int64_t> offsets;  // num_cells + 1, into values
  std::vector<int64_t> values;
};

// A counted list of integers (values are never trusted for allocation beyond what is read).
void read_integers(Words& in, long long count, std::vector<int64_t>& out, const char* what) {
  for (long long i = 0; i < count; ++i) out.push_back(in.integer(what));
}

Cells read_cells(Words& in, const std::string& name, bool version5) {
  Cells cells;
  const long long first = in.count("CELLS count"), second = in.count("CELLS size");
  if (!version5) {
    cells.offsets.push_back(0);
    for (long long c = 0; c < first; ++c) {
      const long long n = in.count("cell value count");
      if (n > second) fail_at_line(name, in.line(), "cell " + std::to_string(c) + " longer than the CELLS size");
      read_integers(in, n, cells.values, "cell value");
      cells.offsets.push_back(int64_t(cells.values.size()));
    }
    if (int64_t(cells.values.size()) + first != second)
      fail_at_line(name, in.line(), "CELLS size " + std::to_string(second) + " does not match the cells read");
    return cells;
  }
  if (in.word("OFFSETS") != "OFFSETS") fail_at_line(name, in.line(), "expected OFFSETS after CELLS (version 5 layout)");
  in.word("the OFFSETS type");
  read_integers(in, first, cells.offsets, "offset");
  if (in.word("CONNECTIVITY") != "CONNECTIVITY")
    fail_at_line(name, in.line(), "expected CONNECTIVITY after the offsets");
  in.word("the CONNECTIVITY type");
  read_integers(in, second, cells.values, "connectivity value");
  if (cells.offsets.empty() || cells.offsets[0] != 0) fail_at_line(name, in.line(), "OFFSETS must start with 0");
  for (size_t i = 1; i < cells.offsets.size(); ++i)
    if (cells.offsets[i] < cells.offsets[i - 1] || cells.offsets[i] > int64_t(cells.values.size()))
      fail_at_line(name, in.line(), "OFFSETS not increasing within the connectivity at " + std::to_string(i));
  return cells;
}

void parse_vtk(std::string_view text, const std::string& name, VolumeMesh& mesh) {
  text = prepare_text(text, name);
  Words in(text, name);
  std::string_view line;
  in.raw_line(line);
  if (line.substr(0, 14) != "# vtk DataFile") fail_at_line(name, 1, "not a legacy VTK file (no '# vtk DataFile' line)");
  const bool version5 = line.find("Version 5") != std::string_view::npos;
  in.raw_line(line);  // title
  if (!in.raw_line(line)) fail_at_line(name, 3, "file ends before ASCII/BINARY");
  Tokens format_line(line);
  std::string_view format;
  if (!format_line.next(format) || !equals_ignore_case(format, "ASCII"))
    fail_at_line(name, 3, "only ASCII legacy VTK is read (found " + quoted(line) + ")");
  if (in.word("DATASET") != "DATASET") fail_at_line(name, in.line(), "expected DATASET");
  const std::string_view kind = in.word("the dataset type");
  if (kind != "UNSTRUCTURED_GRID")
    fail_at_line(name, in.line(), "DATASET " + quoted(kind) + " is not a volume mesh (only UNSTRUCTURED_GRID is read)");
  Cells cells;
  std::vector<int64_t> types;
  bool have_points = false, have_cells = false, have_types = false;
  std::string_view keyword;
  while (in.next(keyword)) {
    if (keyword == "POINTS") {
      const long long n = in.count("POINTS count");
      // Each coordinate takes at least two bytes: a larger count is a lie (and 3 * n could overflow).
      if (uint64_t(n) > text.size())
        fail_at_line(name, in.line(), "POINTS count " + std::to_string(n) + " exceeds the file");
      in.word("the POINTS type");
      for (long long i = 0; i < 3 * n; ++i) mesh.positions.push_back(in.number());
      have_points = true;
    } else if (keyword == "CELLS") {
      cells = read_cells(in, name, version5);
      have_cells = true;
    } else if (keyword == "CELL_TYPES") {
      read_integers(in, in.count("CELL_TYPES count"), types, "cell type");
      have_types = true;
    } else if (keyword == "METADATA") {
      // INFORMATION / NAME / DATA lines up to a blank line.
      std::string_view l;
      in.skip_line();
      while (in.raw_line(l) && !Tokens(l).at_end()) {}
    } else if (keyword == "POINT_DATA" || keyword == "CELL_DATA" || keyword == "FIELD") {
      break;
    } else {
      fail_at_line(name, in.line(), "unexpected " + quoted(keyword));
    }
  }
  if (!have_points) fail(Error::ParseError, name + ": no POINTS section");
  if (!have_cells || !have_types) fail(Error::ParseError, name + ": no CELLS and CELL_TYPES sections");
  if (types.size() + 1 != cells.offsets.size())
    fail(Error::ParseError, name + ": CELL_TYPES lists " + std::to_string(types.size()) + " cells, CELLS " +
                                std::to_string(cells.offsets.size() - 1));
  VolumeBuilder builder(mesh);
  const uint64_t points = mesh.num_vertices();
  for (size_t c = 0; c < types.size(); ++c) {
    const int64_t begin = cells.offsets[c], end = cells.offsets[c + 1];
    const std::string why =
        append_vtk_cell(builder, types[c], cells.values.data() + begin, size_t(end - begin), 0, points);
    if (!why.empty()) fail(Error::ParseError, name + ": cell " + std::to_string(c) + ": " + why);
  }
}

}  // namespace

VolumeReadResult read_vtk_legacy(std::string_view bytes, const std::string& name) {
  return run_volume_reader([&](VolumeMesh& mesh) { parse_vtk(bytes, name, mesh); });
}

}  // namespace kergen
