// The `kergen` command: exit codes, JSON lines, folders, -o. Runs the built binary via popen.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "fixtures.h"
#include "kergen/io.h"
#include "open_surfaces.h"

namespace {

namespace fs = std::filesystem;

struct CliRun {
  int exit_code = -1;
  std::string out;  // stdout
  std::string err;  // stderr
};

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

class CliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("kergen_cli_test_" + std::to_string(::getpid()) + "_" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
    if (!fs::exists(KERGEN_CLI_PATH)) GTEST_SKIP() << "CLI not built at " << KERGEN_CLI_PATH;
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  CliRun run(const std::string& arguments) {
    const std::string err_file = (dir_ / "stderr.txt").string();
    const std::string command = shell_quote(KERGEN_CLI_PATH) + " " + arguments + " 2>" + shell_quote(err_file);
    CliRun r;
    FILE* pipe = ::popen(command.c_str(), "r");
    if (!pipe) return r;
    char buffer[4096];
    size_t got;
    while ((got = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) r.out.append(buffer, got);
    const int status = ::pclose(pipe);
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    std::ifstream err(err_file, std::ios::binary);
    r.err.assign(std::istreambuf_iterator<char>(err), std::istreambuf_iterator<char>());
    return r;
  }

  // An axis-aligned box with quad faces, outward, written with the project's own writer.
  std::string write_box(const std::string& name, double sx, double sy, double sz) {
    kergen::Mesh m;
    for (int i = 0; i < 8; ++i) {
      m.positions.push_back((i & 1) ? sx : 0.0);
      m.positions.push_back((i & 2) ? sy : 0.0);
      m.positions.push_back((i & 4) ? sz : 0.0);
    }
    m.indices = {0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4, 2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5};
    m.face_sizes = {4, 4, 4, 4, 4, 4};
    const std::string path = (dir_ / name).string();
    std::string message;
    EXPECT_EQ(kergen::write_mesh_file(path, m, &message), kergen::Error::Ok) << message;
    return path;
  }

  fs::path dir_;
};

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    lines.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return lines;
}

// Minimal field extraction from one JSON line written by the CLI (flat keys are unique enough).
std::string json_raw(const std::string& line, const std::string& key) {
  const std::string needle = "\"" + key + "\":";
  size_t at = line.find(needle);
  if (at == std::string::npos) return "<missing>";
  at += needle.size();
  size_t end = at;
  if (line[at] == '"') {
    end = at + 1;
    while (end < line.size() && line[end] != '"') end += line[end] == '\\' ? 2 : 1;
    return line.substr(at + 1, end - at - 1);
  }
  int depth = 0;
  while (end < line.size()) {
    const char c = line[end];
    if (c == '[' || c == '{') ++depth;
    if ((c == ']' || c == '}') && depth-- == 0) break;
    if (c == ',' && depth == 0) break;
    ++end;
  }
  return line.substr(at, end - at);
}

double json_number(const std::string& line, const std::string& key) {
  return std::strtod(json_raw(line, key).c_str(), nullptr);
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST_F(CliTest, BoxJsonIsPolyhedronWithItsVolume) {
  const std::string box = write_box("box.off", 2.0, 3.0, 0.5);
  CliRun r = run("--json " + shell_quote(box));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::vector<std::string> lines = lines_of(r.out);
  ASSERT_EQ(lines.size(), 1u) << r.out;
  const std::string& line = lines[0];
  EXPECT_EQ(line.front(), '{');
  EXPECT_EQ(line.back(), '}');
  EXPECT_EQ(json_raw(line, "file"), box);
  EXPECT_EQ(json_raw(line, "ok"), "true");
  EXPECT_EQ(json_raw(line, "error"), "null");
  EXPECT_EQ(json_raw(line, "status"), "POLYHEDRON");
  EXPECT_EQ(json_raw(line, "complete"), "true");
  EXPECT_EQ(json_raw(line, "vertices"), "8");
  EXPECT_EQ(json_raw(line, "edges"), "12");
  EXPECT_EQ(json_raw(line, "faces"), "6");
  const double volume = json_number(line, "volume");
  EXPECT_NEAR(volume, 3.0, 3.0 * 1e-12);
  EXPECT_NEAR(json_number(line, "shape_volume"), 3.0, 3.0 * 1e-12);
  EXPECT_NEAR(json_number(line, "volume_ratio"), 1.0, 1e-12);
  EXPECT_NEAR(json_number(line, "area"), 2 * (6.0 + 1.0 + 1.5), 1e-12);
  EXPECT_NE(json_raw(line, "kernel_point"), "null");
  for (const char* key : {"warnings", "stats", "input_faces", "distinct_planes", "active_planes", "traced_lines",
                          "exact_fallbacks", "ms_parse", "ms_validate", "ms_planes", "ms_lp", "ms_trace", "ms_assemble",
                          "ms_total", "deepest_point", "inscribed_radius", "message"})
    EXPECT_NE(json_raw(line, key), "<missing>") << key;
  EXPECT_EQ(json_raw(line, "input_faces"), "6");
  EXPECT_TRUE(r.err.empty()) << "single mesh: no progress output: " << r.err;
}

TEST_F(CliTest, HumanOutputAndKernelFile) {
  const std::string box = write_box("box.obj", 1.0, 1.0, 1.0);
  const std::string out = (dir_ / "kernel.off").string();
  CliRun r = run(shell_quote(box) + " -o " + shell_quote(out));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(has(r.out, box)) << r.out;
  EXPECT_TRUE(has(r.out, "POLYHEDRON")) << r.out;
  kergen::ReadResult kernel = kergen::read_mesh_file(out);
  ASSERT_TRUE(kernel.ok()) << kernel.message;
  EXPECT_EQ(kernel.mesh.num_vertices(), 8u);
  EXPECT_EQ(kernel.mesh.num_faces(), 6u);
}

TEST_F(CliTest, MissingFileIsAnInputError) {
  const std::string missing = (dir_ / "missing.off").string();
  CliRun r = run(shell_quote(missing));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(has(r.err, "kergen: ")) << r.err;
  EXPECT_TRUE(has(r.err, "missing.off")) << r.err;

  r = run("--json " + shell_quote(missing));
  EXPECT_EQ(r.exit_code, 1);
  ASSERT_EQ(lines_of(r.out).size(), 1u) << r.out;
  EXPECT_EQ(json_raw(r.out, "ok"), "false");
  EXPECT_EQ(json_raw(r.out, "error"), "IO_ERROR");
  EXPECT_TRUE(has(json_raw(r.out, "message"), "missing.off"));
}

TEST_F(CliTest, ParseErrorIsReportedWithLine) {
  const std::string bad = (dir_ / "bad.obj").string();
  {
    std::ofstream out(bad);
    out << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n";
  }
  CliRun r = run(shell_quote(bad));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(has(r.err, "bad.obj:4: vertex index 7 out of range")) << r.err;
}

TEST_F(CliTest, UsageErrorsExitWithTwo) {
  for (const std::string& arguments :
       {std::string(""), std::string("--no-such-option x.off"), std::string("x.off --from 1,2"),
        std::string("x.off --max-steps minus"), std::string("x.off -o kernel.ply"), std::string("x.off -o"),
        std::string("a.off b.off -o k.obj"), std::string("x.off --seed -1"), std::string("x.off --seed one")}) {
    CliRun r = run(arguments);
    EXPECT_EQ(r.exit_code, 2) << "kergen " << arguments;
    EXPECT_TRUE(has(r.err, "usage: kergen")) << r.err;
  }
  CliRun help = run("--help");
  EXPECT_EQ(help.exit_code, 0);
  EXPECT_TRUE(has(help.out, "usage: kergen"));
}

TEST_F(CliTest, FolderGivesOneJsonLinePerMeshAndASummary) {
  write_box("b.off", 1, 1, 1);
  write_box("a.stl", 1, 2, 3);
  write_box("c.obj", 2, 2, 2);
  {
    std::ofstream notes(dir_ / "notes.txt");
    notes << "not a mesh\n";
  }
  CliRun r = run("--json " + shell_quote(dir_.string()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::vector<std::string> lines = lines_of(r.out);
  ASSERT_EQ(lines.size(), 3u) << r.out;
  // Sorted by name; every line is a complete object.
  EXPECT_TRUE(has(json_raw(lines[0], "file"), "a.stl"));
  EXPECT_TRUE(has(json_raw(lines[1], "file"), "b.off"));
  EXPECT_TRUE(has(json_raw(lines[2], "file"), "c.obj"));
  EXPECT_NEAR(json_number(lines[0], "volume"), 6.0, 6e-12);
  EXPECT_NEAR(json_number(lines[2], "volume"), 8.0, 8e-12);
  EXPECT_TRUE(has(r.err, "[1/3]")) << r.err;
  EXPECT_TRUE(has(r.err, "[3/3]")) << r.err;
  EXPECT_TRUE(has(r.err, "3 meshes")) << r.err;
}

TEST_F(CliTest, PlyFilesAndFilesOfOtherNames) {
  // A PLY box 1 x 2 x 4 (binary, little-endian) is read from a folder like the other formats.
  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 8\nproperty float x\nproperty float y\n"
      "property float z\nelement face 6\nproperty list uchar int vertex_indices\nend_header\n";
  for (int i = 0; i < 8; ++i)
    for (float v : {(i & 1) ? 1.0f : 0.0f, (i & 2) ? 2.0f : 0.0f, (i & 4) ? 4.0f : 0.0f})
      ply.append(reinterpret_cast<const char*>(&v), 4);  // the test host is little-endian
  const int32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& quad : quads) {
    ply += char(4);
    ply.append(reinterpret_cast<const char*>(quad), sizeof quad);
  }
  std::ofstream(dir_ / "p.ply", std::ios::binary) << ply;
  write_box("b.off", 1, 1, 1);
  std::ofstream(dir_ / "notes.txt") << "not a mesh\n";
  CliRun r = run("--json " + shell_quote(dir_.string()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::vector<std::string> lines = lines_of(r.out);
  ASSERT_EQ(lines.size(), 2u) << r.out;
  EXPECT_TRUE(has(json_raw(lines[1], "file"), "p.ply"));
  EXPECT_EQ(json_raw(lines[1], "status"), "POLYHEDRON") << lines[1];
  EXPECT_NEAR(json_number(lines[1], "volume"), 8.0, 8e-12);

  // Another name: the content says the format, or the file is refused as unknown.
  fs::rename(dir_ / "p.ply", dir_ / "box-without-extension");
  r = run("--json " + shell_quote((dir_ / "box-without-extension").string()));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NEAR(json_number(r.out, "volume"), 8.0, 8e-12) << r.out;
  r = run(shell_quote((dir_ / "notes.txt").string()));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(has(r.err, "notes.txt: unknown mesh format")) << r.err;
}

TEST_F(CliTest, BatchWithOneBadMeshExitsWithOne) {
  const std::string good = write_box("good.off", 1, 1, 1);
  const std::string empty = (dir_ / "empty.stl").string();
  { std::ofstream create(empty); }
  CliRun r = run("--json " + shell_quote(good) + " " + shell_quote(empty));
  EXPECT_EQ(r.exit_code, 1);
  std::vector<std::string> lines = lines_of(r.out);
  ASSERT_EQ(lines.size(), 2u) << r.out;
  EXPECT_EQ(json_raw(lines[0], "ok"), "true");
  EXPECT_EQ(json_raw(lines[1], "ok"), "false");
  EXPECT_EQ(json_raw(lines[1], "error"), "EMPTY_INPUT");
  EXPECT_TRUE(has(r.err, "EMPTY_INPUT 1")) << r.err;
}

// Timings differ from run to run: every "ms_...": number becomes "ms_...":T, the batch summary's
// seconds become S.
std::string without_timings(const std::string& text) {
  static const std::regex ms("(\"ms_[a-z]+\":)[-+0-9.eE]+"), seconds("meshes in [0-9.]+ s");
  return std::regex_replace(std::regex_replace(text, ms, "$1T"), seconds, "meshes in S s");
}

TEST_F(CliTest, JobsGiveTheSameOutputInInputOrder) {
  // Meshes of very different sizes (a large one first, so that the small ones after it finish
  // first on the other threads), an empty kernel and two input errors between them.
  for (int i = 0; i < 6; ++i) write_box("box" + std::to_string(i) + ".off", 1 + i, 2, 3);
  std::string message;
  ASSERT_EQ(kergen::write_mesh_file((dir_ / "a_sphere.off").string(), kergen_test::bumpy_sphere(120, 61), &message),
            kergen::Error::Ok)
      << message;
  ASSERT_EQ(kergen::write_mesh_file((dir_ / "box2_sphere.obj").string(), kergen_test::bumpy_sphere(40, 21), &message),
            kergen::Error::Ok)
      << message;
  { std::ofstream(dir_ / "box3_empty.stl"); }
  { std::ofstream(dir_ / "box4_bad.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n"; }
  const std::string folder = shell_quote(dir_.string());
  const CliRun one = run("--json --jobs 1 " + folder);
  ASSERT_EQ(one.exit_code, 1) << one.err;
  ASSERT_EQ(lines_of(one.out).size(), 10u) << one.out;
  EXPECT_TRUE(has(json_raw(lines_of(one.out)[0], "file"), "a_sphere.off"));
  for (const std::string& jobs : {"2", "3", "16"}) {
    const CliRun many = run("--json --jobs " + jobs + " " + folder);
    EXPECT_EQ(many.exit_code, one.exit_code) << "--jobs " << jobs;
    EXPECT_EQ(without_timings(many.out), without_timings(one.out)) << "--jobs " << jobs;
    EXPECT_EQ(without_timings(many.err), without_timings(one.err)) << "--jobs " << jobs;
  }
  // The readable output and the default (the machine's threads) too.
  const CliRun human_one = run("--jobs 1 " + folder), human_default = run(folder);
  static const std::regex time_line("  time  [^\n]*");
  EXPECT_EQ(std::regex_replace(without_timings(human_default.out), time_line, "T"),
            std::regex_replace(without_timings(human_one.out), time_line, "T"));
  EXPECT_EQ(without_timings(human_default.err), without_timings(human_one.err));
  EXPECT_TRUE(has(human_one.err, "box4_bad.obj:4: vertex index 7 out of range")) << human_one.err;
}

// Options::cull_faces and Options::seed reach the CLI: the same kernel either way.
TEST_F(CliTest, NoCullFacesAndSeedKeepTheKernel) {
  const std::string path = (dir_ / "sphere.off").string();
  std::string message;
  ASSERT_EQ(kergen::write_mesh_file(path, kergen_test::bumpy_sphere(60, 40), &message), kergen::Error::Ok) << message;
  const CliRun plain = run("--json " + shell_quote(path));
  const CliRun kept = run("--json --no-cull-faces " + shell_quote(path));
  const CliRun seeded = run("--json --seed 12345 " + shell_quote(path));
  for (const CliRun* r : {&plain, &kept, &seeded}) ASSERT_EQ(r->exit_code, 0) << r->err;
  EXPECT_NE(json_raw(plain.out, "culled_faces"), "0");
  EXPECT_EQ(json_raw(kept.out, "culled_faces"), "0");
  EXPECT_NEAR(std::stod(json_raw(kept.out, "volume")), std::stod(json_raw(plain.out, "volume")),
              1e-12 * std::stod(json_raw(plain.out, "volume")));
  EXPECT_EQ(json_raw(seeded.out, "volume"), json_raw(plain.out, "volume"));
  EXPECT_EQ(json_raw(seeded.out, "kernel_point"), json_raw(plain.out, "kernel_point"));
}

// --weld closes a triangle soup; without it the message names the CLI's flags, not the C++ API.
TEST_F(CliTest, WeldClosesASoupAndOpenMeshesNameTheFlags) {
  kergen::Mesh cube = kergen_test::unit_cube(), soup;
  for (uint32_t v : cube.indices) {
    for (int k = 0; k < 3; ++k)
      soup.positions.push_back(cube.positions[3 * v + k] + (soup.indices.size() % 2 ? 1e-12 : 0));
    soup.indices.push_back(uint32_t(soup.indices.size()));
  }
  const std::string path = (dir_ / "soup.off").string();
  std::string message;
  ASSERT_EQ(kergen::write_mesh_file(path, soup, &message), kergen::Error::Ok) << message;
  const CliRun open = run(shell_quote(path));
  EXPECT_EQ(open.exit_code, 1);
  EXPECT_TRUE(has(open.err, "--weld") && has(open.err, "--allow-open")) << open.err;
  EXPECT_FALSE(has(open.err, "Options::")) << open.err;
  for (const std::string& flags :
       {std::string("--weld"), std::string("--weld 1e-9"), std::string("--weld-relative 1e-6")}) {
    const CliRun r = run("--json " + flags + " " + shell_quote(path));
    ASSERT_EQ(r.exit_code, 0) << flags << ": " << r.err;
    EXPECT_EQ(json_raw(r.out, "status"), "POLYHEDRON") << flags;
    EXPECT_TRUE(has(r.out, "VERTICES_WELDED")) << flags;
  }
  EXPECT_EQ(run("--weld-relative -1 " + shell_quote(path)).exit_code, 2);
}

// STL files are welded by default (their triangles' corners are stored apart), other formats not.
TEST_F(CliTest, StlIsWeldedByDefault) {
  kergen::Mesh cube = kergen_test::unit_cube();
  cube.positions[3 * 6] += 1e-13;  // a corner's copies differ by rounding once written per triangle
  kergen::Mesh soup;
  for (size_t i = 0; i < cube.indices.size(); ++i) {
    const uint32_t v = cube.indices[i];
    for (int k = 0; k < 3; ++k)
      soup.positions.push_back(cube.positions[3 * v + k] - (v == 6 && i % 2 && k == 0 ? 1e-13 : 0));
    soup.indices.push_back(uint32_t(i));
  }
  const std::string stl = (dir_ / "seam.stl").string(), off = (dir_ / "seam.off").string();
  ASSERT_EQ(kergen::write_mesh_file(stl, soup), kergen::Error::Ok);
  ASSERT_EQ(kergen::write_mesh_file(off, soup), kergen::Error::Ok);
  const CliRun welded = run("--json " + shell_quote(stl));
  ASSERT_EQ(welded.exit_code, 0) << welded.err;
  EXPECT_TRUE(has(welded.out, "VERTICES_WELDED")) << welded.out;
  EXPECT_EQ(run("--json --no-weld " + shell_quote(stl)).exit_code, 1);
  EXPECT_EQ(run("--json " + shell_quote(off)).exit_code, 1);  // OFF: only with --weld
  EXPECT_EQ(run("--json --weld " + shell_quote(off)).exit_code, 0);
}

TEST_F(CliTest, JobsNeedsAPositiveCount) {
  for (const std::string& value : {"0", "-1", "two", "", "1025"}) {
    CliRun r = run("x.off --jobs " + shell_quote(value));
    EXPECT_EQ(r.exit_code, 2) << "--jobs " << value;
    EXPECT_TRUE(has(r.err, "--jobs needs")) << r.err;
  }
}

TEST_F(CliTest, EmptyKernelIsNotAnError) {
  // A U-shaped prism: the inner walls of its two arms face each other, so no point sees both.
  kergen::Mesh u;
  // Outline of the U in the xy-plane (counter-clockwise), extruded from z = 0 to z = 1.
  const double outline[][2] = {{0, 0}, {3, 0}, {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
  const uint32_t n = 8;
  for (int layer = 0; layer < 2; ++layer)
    for (const auto& p : outline) u.positions.insert(u.positions.end(), {p[0], p[1], double(layer)});
  // Bottom (seen from below: clockwise in xy) and top as single non-convex polygons.
  for (uint32_t i = 0; i < n; ++i) u.indices.push_back(n - 1 - i);
  u.face_sizes.push_back(n);
  for (uint32_t i = 0; i < n; ++i) u.indices.push_back(n + i);
  u.face_sizes.push_back(n);
  for (uint32_t i = 0; i < n; ++i) {
    const uint32_t j = (i + 1) % n;
    u.indices.insert(u.indices.end(), {i, j, n + j, n + i});
    u.face_sizes.push_back(4);
  }
  const std::string path = (dir_ / "u.obj").string();
  ASSERT_EQ(kergen::write_mesh_file(path, u), kergen::Error::Ok);
  CliRun r = run("--json " + shell_quote(path));
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_EQ(json_raw(r.out, "ok"), "true");
  EXPECT_EQ(json_raw(r.out, "status"), "EMPTY");
  EXPECT_EQ(json_raw(r.out, "kernel_point"), "null");
}

}  // namespace

TEST_F(CliTest, OpenPerpendicularWallsAnOpenCube) {
  const std::string path = (dir_ / "open_cube.off").string();
  std::string message;
  ASSERT_EQ(kergen::write_mesh_file(path, kergen_test::open_cube(), &message), kergen::Error::Ok) << message;
  const CliRun refused = run(shell_quote(path));
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_TRUE(has(refused.err, "--open perpendicular")) << refused.err;
  const CliRun clip = run("--json --open clip " + shell_quote(path));
  ASSERT_EQ(clip.exit_code, 0) << clip.err;
  EXPECT_EQ(json_raw(clip.out, "status"), "UNBOUNDED");
  const CliRun walls = run("--json --open perpendicular " + shell_quote(path));
  ASSERT_EQ(walls.exit_code, 0) << walls.err;
  EXPECT_EQ(json_raw(walls.out, "status"), "POLYHEDRON");
  EXPECT_DOUBLE_EQ(json_number(walls.out, "volume"), 1.0);
  EXPECT_EQ(run("--open sideways " + shell_quote(path)).exit_code, 2);
}

// face_sources and witness_boundary_edges are the library's, as flat JSON arrays; the readable
// summary names the witness's walls on a line of their own.
TEST_F(CliTest, FaceSourcesAndWallsOfTheWitness) {
  auto json_ints = [](const auto& values) {
    std::string s = "[";
    for (size_t i = 0; i < values.size(); ++i) s += (i ? "," : "") + std::to_string(values[i]);
    return s + "]";
  };
  kergen::Options walled;
  walled.open_boundary = kergen::OpenBoundary::Perpendicular;
  kergen::Options clipped;
  clipped.allow_open = true;
  const kergen::Mesh cube = kergen_test::open_cube();
  const std::string cube_path = (dir_ / "open_cube.off").string();
  ASSERT_EQ(kergen::write_mesh_file(cube_path, cube), kergen::Error::Ok);
  for (const auto& [flag, options] : {std::pair{"clip", clipped}, {"perpendicular", walled}}) {
    const CliRun r = run("--json --open " + std::string(flag) + " " + shell_quote(cube_path));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const kergen::Kernel k = kergen::compute_kernel(cube.view(), options);
    EXPECT_EQ(json_raw(r.out, "face_sources"), json_ints(k.face_sources)) << flag;
    EXPECT_EQ(json_raw(r.out, "witness_boundary_edges"), "[]") << flag;
  }
  const kergen::Mesh frustum = kergen_test::open_frustum();
  const std::string path = (dir_ / "frustum.off").string();
  ASSERT_EQ(kergen::write_mesh_file(path, frustum), kergen::Error::Ok);
  const kergen::Kernel k = kergen::compute_kernel(frustum.view(), walled);
  ASSERT_EQ(k.type, kergen::KernelType::Empty);
  ASSERT_FALSE(k.witness_boundary_edges.empty());
  const CliRun r = run("--json --open perpendicular " + shell_quote(path));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(json_raw(r.out, "status"), "EMPTY");
  EXPECT_EQ(json_raw(r.out, "face_sources"), "[]");
  EXPECT_EQ(json_raw(r.out, "witness_faces"), json_ints(k.witness_faces));
  EXPECT_EQ(json_raw(r.out, "witness_boundary_edges"), json_ints(k.witness_boundary_edges));
  const CliRun text = run("--open perpendicular " + shell_quote(path));
  ASSERT_EQ(text.exit_code, 0) << text.err;
  std::string walls = "  witness     walls at boundary edges";
  for (size_t i = 0; i < k.witness_boundary_edges.size(); i += 2)
    walls += " " + std::to_string(k.witness_boundary_edges[i]) + "->" + std::to_string(k.witness_boundary_edges[i + 1]);
  EXPECT_TRUE(has(text.out, walls + "\n")) << text.out;
  EXPECT_TRUE(has(text.out, "and lies inside the walls below")) << text.out;
}

TEST_F(CliTest, WriteRepairedSavesWhatTheKernelIsComputedOn) {
  const std::string path = (dir_ / "t_junction.off").string(), out = (dir_ / "repaired.obj").string();
  std::string message;
  ASSERT_EQ(kergen::write_mesh_file(path, kergen_test::t_junction_box(), &message), kergen::Error::Ok) << message;
  const CliRun r = run("--json --repair --write-repaired " + shell_quote(out) + " " + shell_quote(path));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_DOUBLE_EQ(json_number(r.out, "volume"), 2.0);
  const kergen::ReadResult back = kergen::read_mesh_file(out);
  ASSERT_TRUE(back.ok()) << back.message;
  const kergen::Kernel k = kergen::compute_kernel(back.mesh.view());
  ASSERT_TRUE(k.ok()) << k.message;
  EXPECT_EQ(k.volume, 2.0);
  // Written also when the kernel is refused (still open without --repair), to be looked at.
  const std::string open_out = (dir_ / "as_given.off").string();
  EXPECT_EQ(run("--write-repaired " + shell_quote(open_out) + " " + shell_quote(path)).exit_code, 1);
  EXPECT_TRUE(fs::exists(open_out));
  EXPECT_EQ(run("--write-repaired out.ply " + shell_quote(path)).exit_code, 2);
}

namespace {

// An open surface given inside out: the CLI says so (refused, and accepted with walls, in its own
// flag names), and --flip-faces computes the kernel of the surface turned over: the unit cube
// that the five faces and the walls at the open top's edges enclose, with no ratio printed.
TEST_F(CliTest, InsideOutOpenSurfaceIsSaidAndFlippedOnRequest) {
  kergen::Mesh m = kergen_test::open_cube();
  for (size_t t = 0; t < m.indices.size(); t += 3) std::swap(m.indices[t], m.indices[t + 2]);
  const std::string path = (dir_ / "inside-out.off").string();
  std::string message;
  ASSERT_EQ(kergen::write_mesh_file(path, m, &message), kergen::Error::Ok) << message;

  const CliRun refused = run(shell_quote(path));
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_NE(refused.err.find("its faces point inward"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("--flip-faces turns every face over"), std::string::npos) << refused.err;
  EXPECT_EQ(refused.err.find("Options::"), std::string::npos) << refused.err;

  const CliRun walled = run("--open perpendicular " + shell_quote(path));
  EXPECT_EQ(walled.exit_code, 0) << walled.err;
  EXPECT_NE(walled.out.find("status      EMPTY"), std::string::npos) << walled.out;
  EXPECT_NE(walled.out.find("FACES_POINT_INWARD (10)"), std::string::npos) << walled.out;
  EXPECT_NE(walled.out.find("--flip-faces turns every face over; turned over, its kernel is not empty"),
            std::string::npos)
      << walled.out;

  const CliRun flipped = run("--open perpendicular --flip-faces " + shell_quote(path));
  EXPECT_EQ(flipped.exit_code, 0) << flipped.err;
  EXPECT_NE(flipped.out.find("status      POLYHEDRON"), std::string::npos) << flipped.out;
  EXPECT_NE(flipped.out.find("volume      1  (shape 1)\n"), std::string::npos) << flipped.out;
  EXPECT_EQ(flipped.out.find("FACES_POINT_INWARD"), std::string::npos) << flipped.out;
}

}  // namespace

namespace {

// Two boxes as VTK hexahedra (an ascii .vtu written here), the second with a point named twice
// so that it is not closed.
std::string two_hexahedra_vtu(bool second_broken) {
  std::string points;
  for (int c = 0; c < 2; ++c)
    for (int i = 0; i < 8; ++i) {
      const int x = (i == 1 || i == 2 || i == 5 || i == 6), y = (i == 2 || i == 3 || i == 6 || i == 7), z = i >= 4;
      points += std::to_string(x + 2 * c) + " " + std::to_string(2 * y) + " " + std::to_string(3 * z) + " ";
    }
  const std::string second = second_broken ? "8 9 10 11 12 13 14 8" : "8 9 10 11 12 13 14 15";
  return "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\">\n<UnstructuredGrid><Piece NumberOfPoints=\"16\" "
         "NumberOfCells=\"2\">\n<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">" +
         points +
         "</DataArray></Points>\n<Cells><DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 1 2 3 4 5 6 "
         "7 " +
         second +
         "</DataArray>\n<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">8 16</DataArray>\n"
         "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">12 12</DataArray></Cells></Piece>"
         "</UnstructuredGrid></VTKFile>\n";
}

}  // namespace

TEST_F(CliTest, CellsJsonSummaryJobsAndOutput) {
  const std::string path = (dir_ / "boxes.vtu").string();
  std::ofstream(path) << two_hexahedra_vtu(false);
  CliRun r = run("--cells " + shell_quote(path) + " --json --deepest --jobs 1");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::vector<std::string> lines = lines_of(r.out);
  ASSERT_EQ(lines.size(), 3u) << r.out;
  EXPECT_EQ(json_raw(lines[1], "cell"), "1");
  EXPECT_EQ(json_raw(lines[1], "status"), "POLYHEDRON");
  EXPECT_EQ(json_number(lines[1], "kernel_volume"), 6);
  EXPECT_EQ(json_number(lines[1], "diameter"), std::sqrt(1 + 4 + 9.0));
  EXPECT_NEAR(json_number(lines[1], "inscribed_radius"), 0.5, 1e-9);
  EXPECT_TRUE(has(lines[2], "{\"summary\":{\"cells\":2,\"ok\":2,\"by_status\":{\"POLYHEDRON\":2}")) << lines[2];
  EXPECT_EQ(run("--cells " + shell_quote(path) + " --json --deepest --jobs 2").out, r.out);

  const std::string out = (dir_ / "out.vtu").string();
  r = run("--cells " + shell_quote(path) + " -o " + shell_quote(out));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(has(r.out, "2 cells, 2 ok, POLYHEDRON 2")) << r.out;
  EXPECT_EQ(run("--cells " + shell_quote(out) + " --json").out, run("--cells " + shell_quote(path) + " --json").out);
}

TEST_F(CliTest, CellsOneBadCellAndUsage) {
  const std::string path = (dir_ / "broken.vtu").string();
  std::ofstream(path) << two_hexahedra_vtu(true);
  CliRun r = run("--cells " + shell_quote(path) + " --json");
  EXPECT_EQ(r.exit_code, 1);
  std::vector<std::string> lines = lines_of(r.out);
  ASSERT_EQ(lines.size(), 3u) << r.out;
  EXPECT_EQ(json_raw(lines[0], "status"), "POLYHEDRON");
  EXPECT_EQ(json_raw(lines[1], "status"), "null");
  EXPECT_TRUE(has(json_raw(lines[1], "message"), "cell 1: ")) << lines[1];
  EXPECT_EQ(run("--cells " + shell_quote((dir_ / "none.vtu").string())).exit_code, 1);
  for (const std::string& arguments :
       {std::string("--cells"), std::string("--cells a.vtu --from 1,2,3"), std::string("--cells a.vtu -o out.obj"),
        std::string("--cells a.vtu --jobs 0")}) {
    r = run(arguments);
    EXPECT_EQ(r.exit_code, 2) << "kergen " << arguments;
    EXPECT_TRUE(has(r.err, "usage: kergen --cells")) << r.err;
  }
}
