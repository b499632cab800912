// Table-driven bad-input test: every row of tests/bad_inputs.json (shared with the npm package's
// tests/node/bad-input.test.mjs) must give its expected kergen::Error code and a message that
// contains the row's fragment — through the native reader of its format and compute_kernel
// ('file' rows), or through compute_kernel directly ('mesh' rows). Rows using ../shared/meshes
// are skipped with a message when that folder is absent.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "kergen/io.h"
#include "kergen/kergen.h"
#include "kergen/volume.h"

#ifndef KERGEN_SHARED_MESHES
#define KERGEN_SHARED_MESHES "../shared/meshes"
#endif

namespace {

// ---- a minimal JSON reader (objects, arrays, strings with the usual escapes, numbers, literals) --
struct Json {
  enum Kind { Null, Bool, Number, String, Array, Object } kind = Null;
  bool b = false;
  double num = 0;
  std::string str;
  std::vector<Json> arr;
  std::map<std::string, Json> obj;

  bool has(const std::string& k) const { return kind == Object && obj.count(k) > 0; }
  const Json& operator[](const std::string& k) const {
    static const Json null;
    auto it = obj.find(k);
    return it == obj.end() ? null : it->second;
  }
};

class JsonParser {
 public:
  explicit JsonParser(const std::string& s) : s_(s) {}
  Json parse() {
    Json v = value();
    ws();
    if (p_ != s_.size()) throw std::runtime_error("trailing characters in JSON");
    return v;
  }

 private:
  void ws() {
    while (p_ < s_.size() && (s_[p_] == ' ' || s_[p_] == '\n' || s_[p_] == '\r' || s_[p_] == '\t')) ++p_;
  }
  char peek() {
    ws();
    if (p_ >= s_.size()) throw std::runtime_error("unexpected end of JSON");
    return s_[p_];
  }
  void expect(char c) {
    if (peek() != c) throw std::runtime_error(std::string("JSON: expected ") + c + " at " + std::to_string(p_));
    ++p_;
  }
  Json value() {
    Json v;
    char c = peek();
    if (c == '{') {
      v.kind = Json::Object;
      ++p_;
      if (peek() == '}') {
        ++p_;
        return v;
      }
      for (;;) {
        std::string k = string_lit();
        expect(':');
        v.obj[k] = value();
        if (peek() == ',') {
          ++p_;
          continue;
        }
        expect('}');
        return v;
      }
    }
    if (c == '[') {
      v.kind = Json::Array;
      ++p_;
      if (peek() == ']') {
        ++p_;
        return v;
      }
      for (;;) {
        v.arr.push_back(value());
        if (peek() == ',') {
          ++p_;
          continue;
        }
        expect(']');
        return v;
      }
    }
    if (c == '"') {
      v.kind = Json::String;
      v.str = string_lit();
      return v;
    }
    for (const char* lit : {"true", "false", "null"}) {
      if (s_.compare(p_, std::strlen(lit), lit) == 0) {
        p_ += std::strlen(lit);
        v.kind = lit[0] == 'n' ? Json::Null : Json::Bool;
        v.b = lit[0] == 't';
        return v;
      }
    }
    size_t end = p_;
    while (end < s_.size() && std::strchr("+-0123456789.eE", s_[end])) ++end;
    if (end == p_) throw std::runtime_error("JSON: unexpected character at " + std::to_string(p_));
    v.kind = Json::Number;
    v.num = std::strtod(s_.substr(p_, end - p_).c_str(), nullptr);
    p_ = end;
    return v;
  }
  std::string string_lit() {
    expect('"');
    std::string out;
    while (p_ < s_.size() && s_[p_] != '"') {
      char c = s_[p_++];
      if (c != '\\') {
        out += c;
        continue;
      }
      char e = s_[p_++];
      switch (e) {
        case 'n': out += '\n'; break;
        case 't': out += '\t'; break;
        case 'r': out += '\r'; break;
        case 'b': out += '\b'; break;
        case 'f': out += '\f'; break;
        case 'u': {
          unsigned cp = std::stoul(s_.substr(p_, 4), nullptr, 16);
          p_ += 4;
          if (cp < 0x80)
            out += char(cp);
          else if (cp < 0x800) {
            out += char(0xc0 | (cp >> 6));
            out += char(0x80 | (cp & 0x3f));
          } else {
            out += char(0xe0 | (cp >> 12));
            out += char(0x80 | ((cp >> 6) & 0x3f));
            out += char(0x80 | (cp & 0x3f));
          }
          break;
        }
        default: out += e;
      }
    }
    expect('"');
    return out;
  }
  const std::string& s_;
  size_t p_ = 0;
};

std::string read_file(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) return {};
  std::ostringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

const Json& table() {
  static const Json t = [] {
    // This file is tests/core/bad_input_test.cpp; the table is tests/bad_inputs.json.
    std::string here = __FILE__;
    const std::string path = here.substr(0, here.rfind("core/bad_input_test.cpp")) + "bad_inputs.json";
    const std::string text = read_file(path);
    if (text.empty()) throw std::runtime_error("cannot read " + path);
    return JsonParser(text).parse();
  }();
  return t;
}

std::string from_hex(const std::string& h) {
  std::string out;
  for (size_t i = 0; i + 1 < h.size(); i += 2) out += char(std::stoi(h.substr(i, 2), nullptr, 16));
  return out;
}

double number(const Json& v) {
  if (v.kind == Json::Number) return v.num;
  if (v.str == "NaN") return std::numeric_limits<double>::quiet_NaN();
  if (v.str == "Infinity") return std::numeric_limits<double>::infinity();
  if (v.str == "-Infinity") return -std::numeric_limits<double>::infinity();
  throw std::runtime_error("not a number: " + v.str);
}

// Checks an outcome (error code + message, or a kernel) against a row's expectation.
void expect_outcome(const Json& expect, kergen::Error error, const std::string& message, const kergen::Kernel* k) {
  const std::string code = expect["code"].str;
  const std::string got = error == kergen::Error::Ok ? "OK" : kergen::error_name(error);
  ASSERT_EQ(got, code) << "message: " << message;
  EXPECT_NE(error, kergen::Error::Internal) << message;
  if (error != kergen::Error::Ok) {
    EXPECT_FALSE(message.empty());
    EXPECT_NE(message.find(expect["message"].str), std::string::npos)
        << "message \"" << message << "\" lacks \"" << expect["message"].str << "\"";
    return;
  }
  ASSERT_NE(k, nullptr);
  if (expect.has("status")) EXPECT_STREQ(kergen::kernel_type_name(k->type), expect["status"].str.c_str());
  if (expect.has("volume")) EXPECT_NEAR(k->volume, expect["volume"].num, 1e-12 * expect["volume"].num);
  if (expect.has("warning")) {
    bool found = false;
    for (const auto& w : k->warnings) found |= expect["warning"].str == kergen::warning_kind_name(w.kind);
    EXPECT_TRUE(found) << "warning " << expect["warning"].str << " missing";
  }
}

kergen::MeshFormat format_of(const std::string& f) {
  if (f == "off") return kergen::MeshFormat::Off;
  if (f == "obj") return kergen::MeshFormat::Obj;
  if (f == "stl") return kergen::MeshFormat::Stl;
  return kergen::MeshFormat::Unknown;
}

// Volume rows: the reader's error ('native'), or each listed cell's outcome ('cells').
void expect_cells(const Json& row, const kergen::VolumeMesh& mesh) {
  const kergen::CellKernels run = kergen::compute_cell_kernels(mesh);
  ASSERT_TRUE(run.ok()) << run.message;
  for (const Json& c : row["cells"].arr) {
    const size_t index = size_t(c["cell"].num);
    ASSERT_LT(index, run.cells.size());
    const kergen::CellKernel& cell = run.cells[index];
    SCOPED_TRACE("cell " + std::to_string(index));
    const std::string got = cell.ok() ? "OK" : kergen::error_name(cell.error);
    ASSERT_EQ(got, c["code"].str) << cell.message;
    EXPECT_NE(cell.error, kergen::Error::Internal);
    if (!cell.ok()) {
      EXPECT_NE(cell.message.find(c["message"].str), std::string::npos) << cell.message;
      continue;
    }
    if (c.has("status")) EXPECT_STREQ(kergen::kernel_type_name(cell.type), c["status"].str.c_str());
    if (c.has("volume")) EXPECT_NEAR(cell.kernel_volume, c["volume"].num, 1e-12 * c["volume"].num);
    EXPECT_EQ(cell.reoriented, c.has("reoriented") && c["reoriented"].b);
  }
}

void volume_row(const Json& row) {
  if (row.has("volume_mesh")) {
    const Json& m = row["volume_mesh"];
    kergen::VolumeMesh mesh;
    for (const Json& v : m["positions"].arr) mesh.positions.push_back(number(v));
    mesh.face_offsets.push_back(0);
    for (const Json& f : m["faces"].arr) {
      for (const Json& v : f.arr) mesh.face_indices.push_back(uint32_t(v.num));
      mesh.face_offsets.push_back(uint32_t(mesh.face_indices.size()));
    }
    mesh.cell_offsets.push_back(0);
    for (const Json& c : m["cells"].arr) {
      for (const Json& f : c.arr) mesh.cell_faces.push_back(uint32_t(f.num));
      mesh.cell_offsets.push_back(uint32_t(mesh.cell_faces.size()));
    }
    expect_cells(row, mesh);
    return;
  }
  const Json& file = row["volume_file"];
  const std::string format = file["format"].str, name = row["name"].str;
  const kergen::VolumeReadResult r =
      format == "node_ele"
          ? kergen::read_node_ele(file["node"].str, file["ele"].str, name + ".node", name + ".ele")
          : kergen::read_volume_mesh(file["text"].str,
                                     format == "vtu" ? kergen::VolumeFormat::Vtu : kergen::VolumeFormat::VtkLegacy,
                                     name + "." + format);
  if (std::getenv("KERGEN_PRINT_MESSAGES")) std::printf("ROW %s: %s\n", name.c_str(), r.message.c_str());
  if (row.has("native")) {
    EXPECT_NE(r.message.find(name), std::string::npos) << r.message;  // names the file
    expect_outcome(row["native"], r.error, r.message, nullptr);
    return;
  }
  ASSERT_TRUE(r.ok()) << r.message;
  expect_cells(row, r.mesh);
}

class BadInput : public ::testing::TestWithParam<size_t> {};

TEST_P(BadInput, Row) {
  const Json& row = table()["rows"].arr.at(GetParam());
  SCOPED_TRACE(row["name"].str + ": " + row["what"].str);
  if (row.has("volume_file") || row.has("volume_mesh")) {
    volume_row(row);
    return;
  }
  if (row.has("file")) {
    const Json& file = row["file"];
    std::string bytes, name = row["name"].str + "." + file["format"].str;
    if (file.has("shared")) {
      const std::string path = std::string(KERGEN_SHARED_MESHES) + "/" + file["shared"].str;
      std::ifstream probe(path);
      if (!probe) GTEST_SKIP() << "shared meshes not found (" << path << "): skipping this row";
      bytes = read_file(path);
      name = file["shared"].str;
    } else if (file.has("hex")) {
      bytes = from_hex(file["hex"].str);
    } else {
      bytes = file["text"].str;
    }
    const kergen::ReadResult r = kergen::read_mesh(bytes, format_of(file["format"].str), name);
    if (!r.ok()) {
      // A reader error names the file.
      EXPECT_NE(r.message.find(name), std::string::npos) << r.message;
      if (std::getenv("KERGEN_PRINT_MESSAGES")) std::printf("ROW %s: %s\n", row["name"].str.c_str(), r.message.c_str());
      expect_outcome(row["native"], r.error, r.message, nullptr);
      return;
    }
    const kergen::Kernel k = kergen::compute_kernel(r.mesh.view());
    if (std::getenv("KERGEN_PRINT_MESSAGES")) std::printf("ROW %s: %s\n", row["name"].str.c_str(), k.message.c_str());
    expect_outcome(row["native"], k.error, k.message, &k);
    return;
  }
  const Json& m = row["mesh"];
  std::vector<double> positions;
  std::vector<uint32_t> indices, sizes;
  for (const Json& v : m["positions"].arr) positions.push_back(number(v));
  for (const Json& v : m["indices"].arr) indices.push_back(uint32_t(v.num));
  for (const Json& v : m["faceSizes"].arr) sizes.push_back(uint32_t(v.num));
  kergen::MeshView view;
  view.positions = positions.data();
  view.num_vertices = positions.size() / 3;
  view.indices = indices.data();
  view.num_indices = indices.size();
  if (m.has("faceSizes")) {
    view.face_sizes = sizes.data();
    view.num_faces = sizes.size();
  }
  kergen::Options o;
  if (row["options"].has("maxFaces")) o.max_faces = size_t(row["options"]["maxFaces"].num);
  if (row["options"].has("repair")) o.repair = row["options"]["repair"].b;
  if (row["options"].has("allowOpen")) o.allow_open = row["options"]["allowOpen"].b;
  if (row["options"].has("open")) {
    // The package's `open`: 'clip' is allowOpen; 'perpendicular' is OpenBoundary::Perpendicular.
    const std::string open = row["options"]["open"].str;
    bool known = false;
    for (kergen::OpenBoundary b : {kergen::OpenBoundary::Clip, kergen::OpenBoundary::Perpendicular})
      if (open == kergen::open_boundary_name(b)) {
        o.open_boundary = b;
        o.allow_open |= b == kergen::OpenBoundary::Clip;
        known = true;
      }
    ASSERT_TRUE(known) << "unknown open option " << open;
  }
  const kergen::Kernel k = kergen::compute_kernel(view, o);
  if (std::getenv("KERGEN_PRINT_MESSAGES")) std::printf("ROW %s: %s\n", row["name"].str.c_str(), k.message.c_str());
  expect_outcome(row["expect"], k.error, k.message, &k);
  // The cheaper entry points agree on the verdict (except on what only compute_kernel certifies).
  if (row.has("compute_kernel_only")) return;
  const kergen::KernelPoint p = kergen::find_kernel_point(view, o);
  EXPECT_EQ(p.error, k.error) << p.message;
  const kergen::Validation val = kergen::validate_mesh(view, o);
  if (k.error != kergen::Error::Ok)
    EXPECT_EQ(val.error, row.has("validation_passes") ? kergen::Error::Ok : k.error) << val.message;
}

std::vector<size_t> row_ids() {
  std::vector<size_t> ids;
  for (size_t i = 0; i < table()["rows"].arr.size(); ++i) ids.push_back(i);
  return ids;
}

INSTANTIATE_TEST_SUITE_P(Table, BadInput, ::testing::ValuesIn(row_ids()),
                         [](const ::testing::TestParamInfo<size_t>& info) {
                           return table()["rows"].arr[info.param]["name"].str;
                         });

TEST(BadInputTable, CoversTheRequiredCases) {
  // The rows the reliability promise names; the table may grow, not lose these.
  const char* required[] = {"off_empty",
                            "stl_empty",
                            "off_garbage",
                            "stl_garbage",
                            "stl_truncated",
                            "stl_count_one_more",
                            "obj_index_out_of_range",
                            "obj_index_zero",
                            "obj_negative_out_of_range",
                            "mesh_face_two_vertices",
                            "mesh_nan",
                            "mesh_inf",
                            "mesh_duplicate_face",
                            "mesh_back_to_back",
                            "mesh_open",
                            "mesh_non_manifold_edge",
                            "mesh_two_components",
                            "mesh_inverted",
                            "mesh_flat",
                            "mesh_wound_twice",
                            "mesh_open_wound_twice",
                            "mesh_crossing_cubes",
                            "mesh_nested_alike",
                            "mesh_cube_with_void",
                            "mesh_t_junction",
                            "mesh_t_junction_repaired",
                            "mesh_bowl",
                            "mesh_bowl_allow_open",
                            "mesh_bowl_perpendicular",
                            "bad_empty2",
                            "bad_invalidvertex",
                            "bad_back_to_back",
                            "bad_zero_area_triangle",
                            "bad_toomanyvertices",
                            "bad_unparseable",
                            "bad_tardis"};
  std::map<std::string, int> names;
  for (const Json& r : table()["rows"].arr) names[r["name"].str]++;
  for (const char* n : required) EXPECT_EQ(names[n], 1) << n;
  for (const auto& [n, c] : names) EXPECT_EQ(c, 1) << "duplicate row name " << n;
}

TEST(BadInputTable, EveryFileInTheSharedBadFolderHasARow) {
  const std::string dir = std::string(KERGEN_SHARED_MESHES) + "/fixtures/bad";
  std::ifstream probe(dir + "/empty2.stl");
  if (!probe) GTEST_SKIP() << "shared meshes not found (" << dir << "): skipping";
  std::map<std::string, bool> covered;
  for (const Json& r : table()["rows"].arr)
    if (r["file"].has("shared")) covered[r["file"]["shared"].str] = true;
  size_t files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    const std::string f = e.path().filename().string();
    if (kergen::format_from_path(f) == kergen::MeshFormat::Unknown) continue;  // licence texts
    ++files;
    EXPECT_TRUE(covered["fixtures/bad/" + f]) << f << " has no row in tests/bad_inputs.json";
  }
  EXPECT_GE(files, 7u);
}

}  // namespace
