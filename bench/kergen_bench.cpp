// kergen_bench: end-to-end kernel timings of kergen::compute_kernel against CGAL's
// halfspace_intersection_3 (Epick and Epeck) and Qhull's halfspace intersection, one table row
// (or JSON object) per mesh; with --streaming, the cost of an on_step callback instead.
// See bench/README.md for the columns.
//
//   kergen_bench [options] [mesh files...]
//     --runs N                timed runs per measurement, the median is reported (default 5)
//     --json                  one JSON object per row instead of the table
//     --cpu-time              time with the thread's CPU clock instead of the wall clock (a busy
//                             machine); CGAL 6.2's column stays wall clock
//     --quick                 small default list, 1 run (smoke test)
//     --no-epeck / --no-epick / --no-qhull   skip a baseline
//     --epeck-max-faces N     skip the Epeck baseline above N input faces (default: no limit)
//     --epick-max-faces N     skip the Epick baseline above N input faces (default: no limit)
//     --qhull-max-faces N     skip the Qhull baseline above N input faces (default: no limit)
//     --baseline-budget-ms T  stop repeating a baseline once one run took longer than T (default 2000)
//     --no-cgal62             skip CGAL 6.2's PMP::kernel (built only with -DKERGEN_CGAL62_DIR, see README)
//     --cgal62-timeout-s T    stop a CGAL 6.2 measurement after T seconds (default 60)
//     --meshes DIR            shared mesh folder for the default list (default: the build's KERGEN_SHARED_MESHES)
//     --family DIR            also run every mesh file of DIR and print one summary row for them
//                             (ratio geomean, minimum, how many are slower than each baseline)
//     --families              --family for each polyhedra set of the mesh folder (tet10, tet20,
//                             tet30, voro: 1000 small meshes each)
//     --streaming             only the streaming rows: compute_kernel without and with an on_step
//                             callback (two generated spheres, vase6, spiral6, princeton/325)
//     --streaming-budget-ms T stop repeating a streaming measurement once one run took longer than T
//                             (default 20000)
//     --streaming-cap-ms T    the callback stops a run with on_step after T (default 120000): the
//                             row then gives a lower bound
//     --cells [DIR...]        only the cell rows: cells per second of whole folders of small meshes
//                             (default: the four polyhedra sets), single calls and a KernelBatch
#include <CGAL/Convex_hull_3/dual/halfspace_intersection_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>
#include <CGAL/version.h>
#include <benchmark/benchmark.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "bench_util.h"
#include "cell_rows.h"
#include "fixtures.h"  // tests/core: the sphere generators of the dense rows
#include "kergen/io.h"
#include "kergen/kergen.h"
#include "streaming_rows.h"

namespace fs = std::filesystem;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;

#ifndef KERGEN_SHARED_MESHES
#define KERGEN_SHARED_MESHES "../shared/meshes"
#endif

namespace {

using kergen_bench::Baseline;
using kergen_bench::fmt;
using kergen_bench::median;
using kergen_bench::now_ms;

struct Args {
  int runs = 5;
  bool json = false, quick = false, epeck = true, epick = true, qhull = true, cgal62 = true, streaming = false,
       cells = false;
  int cgal62_timeout_s = 60;
  size_t epeck_max_faces = std::numeric_limits<size_t>::max();
  size_t epick_max_faces = std::numeric_limits<size_t>::max();
  size_t qhull_max_faces = std::numeric_limits<size_t>::max();
  double baseline_budget_ms = 2000;
  double streaming_budget_ms = 20000, streaming_cap_ms = 120000;
  std::string meshes = KERGEN_SHARED_MESHES;
  std::vector<std::string> files;
  std::vector<std::string> families;  // folders summarized, not listed row by row
};

std::string compiler_string() {
#if defined(__clang__)
  std::string v = __clang_version__;
  while (!v.empty() && v.back() == ' ') v.pop_back();
  return "clang++ " + v;
#elif defined(__GNUC__)
  return std::string("g++ ") + __VERSION__;
#else
  return "unknown compiler";
#endif
}

std::string cpu_string() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) {
      auto p = line.find(':');
      if (p != std::string::npos) return line.substr(p + 2);
    }
  return "unknown CPU";
}

// 1-minute load average: timings on a busy machine are not comparable with a quiet one.
std::string loadavg_string() {
  std::ifstream in("/proc/loadavg");
  std::string a;
  return (in >> a) ? a : std::string("?");
}

struct Row {
  std::string mesh;
  size_t faces = 0, planes = 0, culled = 0;
  std::string type;
  std::string error;
  size_t V = 0, E = 0, F = 0;
  double volume = 0;
  double ours_ms = 0;
  kergen::Stats stats;
  Baseline epick, epeck, qhull, cgal62;
  bool star = false;
  std::string reference;  // non-star: the star mesh our time is compared with
  double reference_ms = 0;
};

// One plane per face from its first non-collinear vertex triple (what a CGAL user would build);
// the planes are part of the timed baseline.
template <class K>
std::vector<typename K::Plane_3> face_planes(const kergen::Mesh& m, bool flip) {
  std::vector<typename K::Point_3> pts;
  pts.reserve(m.num_vertices());
  for (size_t v = 0; v < m.num_vertices(); ++v)
    pts.emplace_back(m.positions[3 * v], m.positions[3 * v + 1], m.positions[3 * v + 2]);
  std::vector<typename K::Plane_3> planes;
  planes.reserve(m.num_faces());
  size_t off = 0;
  for (size_t f = 0; f < m.num_faces(); ++f) {
    const size_t k = m.face_sizes.empty() ? 3 : m.face_sizes[f];
    const uint32_t* loop = m.indices.data() + off;
    off += k;
    for (size_t j = 1; j + 1 < k; ++j) {
      const auto &a = pts[loop[0]], &b = pts[loop[j]], &c = pts[loop[j + 1]];
      if (CGAL::collinear(a, b, c)) continue;
      planes.push_back(flip ? typename K::Plane_3(a, c, b) : typename K::Plane_3(a, b, c));
      break;
    }
  }
  return planes;
}

template <class K>
Baseline run_baseline(const kergen::Mesh& m, bool flip, const std::array<double, 3>& o, const Args& args) {
  Baseline b;
  std::vector<double> times;
  const typename K::Point_3 origin(o[0], o[1], o[2]);
  {
    // Not timed: CGAL requires the origin strictly inside every plane (exact predicate), and
    // crashes otherwise, so this is checked before the first call. (One plane per face from its
    // first corners can face inward on a non-planar, non-convex polygon.)
    for (const auto& p : face_planes<K>(m, flip))
      if (!p.has_on_negative_side(origin)) {
        b.skipped =
            "origin not strictly inside every face plane (kernel too thin for a double centroid, or a face's first "
            "corners turn inward)";
        return b;
      }
  }
  for (int r = 0; r < args.runs; ++r) {
    const double t0 = now_ms();
    const auto planes = face_planes<K>(m, flip);
    CGAL::Surface_mesh<typename K::Point_3> out;
    try {
      CGAL::halfspace_intersection_3(planes.begin(), planes.end(), out, boost::optional<typename K::Point_3>(origin));
    } catch (const std::exception& e) {
      b.skipped = std::string("failed: ") + e.what();
      return b;
    }
    benchmark::DoNotOptimize(out);
    const double ms = now_ms() - t0;
    times.push_back(ms);
    b.raw_vertices = out.number_of_vertices();
    if (ms > args.baseline_budget_ms) break;
  }
  b.ran = true;
  b.ms = median(times);
  b.runs = int(times.size());
  return b;
}

// The dense rows of the default list: generated spheres whose kernel is (nearly) the whole shape,
// so the kernel has about as many vertices as the input has faces (or more: the two float
// triangles of a UV quad are not exactly coplanar, and the kernel keeps both). A path of this
// form names one (see generated_mesh).
constexpr const char* kGeneratedPrefix = "generated:";
const char* const kDenseRows[] = {"generated:uv sphere 40k",       "generated:uv sphere 200k",
                                  "generated:dimpled sphere 40k",  "generated:wavy sphere 40k",
                                  "generated:geodesic sphere 40k", "generated:near-convex bumpy sphere 40k"};
// UV spheres 200 x 100 (39,600 triangles) and 400 x 250 (199,200); the 40k one with a dimple at
// its top pole, and with waves r = 1 + 0.05 sin 5t cos 7ph (fixtures.h); the geodesic sphere of
// 40,500 triangles (convex: its own kernel); the bumpy sphere of the streaming rows (amplitude
// 0.01, 200 x 101: 40,000 triangles).
bool generated_mesh(const std::string& path, kergen::Mesh& mesh) {
  if (path == kDenseRows[0])
    mesh = kergen_test::uv_sphere(200, 100, 0);
  else if (path == kDenseRows[1])
    mesh = kergen_test::uv_sphere(400, 250, 0);
  else if (path == kDenseRows[2])
    mesh = kergen_test::dimpled_sphere(200, 100);
  else if (path == kDenseRows[3])
    mesh = kergen_test::wavy_sphere(200, 100);
  else if (path == kDenseRows[4])
    mesh = kergen_test::geodesic_sphere(45).mesh;
  else if (path == kDenseRows[5])
    mesh = kergen_test::bumpy_sphere(200, 101, 0.01);
  else
    return false;
  return true;
}

// CGAL 6.2's Polygon_mesh_processing::kernel, run by the cgal62_kernel program (compiled against
// CGAL 6.2's headers, which must not meet the system CGAL's in this program) on the mesh file, or
// on a temporary OFF copy of a generated mesh; stopped after --cgal62-timeout-s.
Baseline run_cgal62(const std::string& path, const kergen::Mesh& mesh, bool flip, const Args& args) {
  Baseline b;
#ifndef KERGEN_CGAL62_BIN
  (void)path, (void)mesh, (void)flip, (void)args;
  b.skipped = "not built (bench/get-cgal62.sh, then cmake -DKERGEN_CGAL62_DIR=...)";
  return b;
#else
  std::string file = path, temp;
  if (path.rfind(kGeneratedPrefix, 0) == 0) {
    temp = (fs::temp_directory_path() / ("kergen_bench_" + std::to_string(::getpid()) + ".off")).string();
    std::ofstream(temp) << kergen::write_off(mesh);  // (shortest round-trip digits: the same doubles)
    file = temp;
  }
  const std::string cmd = "timeout " + std::to_string(args.cgal62_timeout_s) + " '" KERGEN_CGAL62_BIN "' '" + file +
                          "' " + std::to_string(args.runs) + " " + std::to_string(args.baseline_budget_ms) + " " +
                          (flip ? "1" : "0") + " 2>/dev/null";
  FILE* pipe = popen(cmd.c_str(), "r");
  char line[256] = {0};
  const bool got = pipe && std::fgets(line, sizeof line, pipe);
  const int status = pipe ? pclose(pipe) : -1;
  if (!temp.empty()) fs::remove(temp);
  double ms = 0;
  int runs = 0;
  size_t vertices = 0, faces = 0;
  if (got && std::sscanf(line, "ms %lf runs %d vertices %zu faces %zu", &ms, &runs, &vertices, &faces) == 4) {
    b.ran = true;
    b.ms = ms;
    b.runs = runs;
    b.raw_vertices = vertices;
  } else if (status != -1 && WIFEXITED(status) && WEXITSTATUS(status) == 124) {
    b.skipped = "> " + std::to_string(args.cgal62_timeout_s) + " s (stopped)";
  } else {
    b.skipped = "failed";
  }
  return b;
#endif
}

// "CGAL 6.2.1 PMP::kernel" from the helper, or a note that it was not built.
std::string cgal62_version() {
#ifdef KERGEN_CGAL62_BIN
  FILE* pipe = popen("'" KERGEN_CGAL62_BIN "' --version", "r");
  char line[64] = {0};
  const bool got = pipe && std::fgets(line, sizeof line, pipe);
  if (pipe) pclose(pipe);
  std::string v = got ? line : "?";
  while (!v.empty() && (v.back() == '\n' || v.back() == ' ')) v.pop_back();
  return "CGAL " + v + " PMP::kernel";
#else
  return "CGAL 6.2 column not built";
#endif
}

Row bench_mesh(const std::string& path, const std::string& label, const Args& args) {
  Row row;
  row.mesh = label;
  kergen::ReadResult rr;
  if (path.rfind(kGeneratedPrefix, 0) == 0) {
    if (!generated_mesh(path, rr.mesh)) {
      row.error = "unknown generated mesh " + path;
      return row;
    }
  } else {
    rr = kergen::read_mesh_file(path);
    if (!rr.ok()) {
      row.error = rr.message;
      return row;
    }
  }
  row.faces = rr.mesh.num_faces();
  const kergen::MeshView view = rr.mesh.view();
  std::vector<double> times;
  std::vector<kergen::Kernel> results;
  for (int r = 0; r < args.runs; ++r) {
    const double t0 = now_ms();
    kergen::Kernel k = kergen::compute_kernel(view);
    benchmark::DoNotOptimize(k);
    times.push_back(now_ms() - t0);
    results.push_back(std::move(k));
  }
  // The run whose time is the median supplies the phase split.
  std::vector<size_t> order(times.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return times[a] < times[b]; });
  const kergen::Kernel& k = results[order[order.size() / 2]];
  row.ours_ms = median(times);
  row.stats = k.stats;
  row.planes = k.stats.distinct_planes;
  row.culled = k.stats.culled_faces;
  if (row.culled > 0) {
    // The planes column counts the distinct planes of every face: one more run, not timed, with
    // face culling off (the timed runs merge only the faces that can touch the kernel).
    kergen::Options all_faces;
    all_faces.cull_faces = false;
    row.planes = kergen::compute_kernel(view, all_faces).stats.distinct_planes;
  }
  if (!k.ok()) {
    row.error = std::string(kergen::error_name(k.error)) + ": " + k.message;
    return row;
  }
  row.type = kergen::kernel_type_name(k.type);
  row.V = k.num_vertices();
  row.E = k.num_edges();
  row.F = k.num_faces();
  row.volume = k.volume;
  row.star = k.type != kergen::KernelType::Empty;
  if (k.type != kergen::KernelType::Polyhedron) {
    const char* why = k.type == kergen::KernelType::Empty ? "n/a (empty kernel)" : "n/a (not full-dimensional)";
    row.epick.skipped = row.epeck.skipped = row.qhull.skipped = why;
    return row;
  }
  // Interior point for CGAL and Qhull: centroid of our kernel's vertices (not timed).
  std::array<double, 3> c{0, 0, 0};
  for (size_t v = 0; v < k.num_vertices(); ++v)
    for (int a = 0; a < 3; ++a) c[a] += k.vertices[3 * v + a];
  for (int a = 0; a < 3; ++a) c[a] /= double(k.num_vertices());
  bool flip = false;
  for (const auto& w : k.warnings) flip |= w.kind == kergen::Warning::Kind::OrientationFlipped;

  // Each baseline runs unless switched off or over its face limit (the cell then says which).
  auto baseline = [&](Baseline& out, bool on, size_t max_faces, const char* name, auto&& run) {
    if (!on)
      out.skipped = std::string("skipped (--no-") + name + ")";
    else if (row.faces > max_faces)
      out.skipped = std::string("skipped (> --") + name + "-max-faces)";
    else
      out = run();
  };
  baseline(row.epick, args.epick, args.epick_max_faces, "epick",
           [&] { return run_baseline<Epick>(rr.mesh, flip, c, args); });
  baseline(row.epeck, args.epeck, args.epeck_max_faces, "epeck",
           [&] { return run_baseline<Epeck>(rr.mesh, flip, c, args); });
  baseline(row.qhull, args.qhull, args.qhull_max_faces, "qhull",
           [&] { return kergen_bench::run_qhull(rr.mesh, flip, c, k.volume, args.runs, args.baseline_budget_ms); });
  baseline(row.cgal62, args.cgal62, std::numeric_limits<size_t>::max(), "cgal62",
           [&] { return run_cgal62(path, rr.mesh, flip, args); });
  return row;
}

std::vector<std::pair<std::string, std::string>> default_list(const Args& args) {
  std::vector<std::pair<std::string, std::string>> list;  // (path, label)
  const fs::path root = args.meshes;
  auto add = [&](const std::string& rel) { list.emplace_back((root / rel).string(), rel); };
  if (args.quick) {
    for (const char* f : {"princeton/350.off", "princeton/200.off", "refinements/spiral1.off", "refinements/vase1.off",
                          "polyhedra/tet10/0.off", "polyhedra/voro/0.off"})
      add(f);
    return list;
  }
  for (const char* p : {"325", "326", "337", "350", "1", "10", "100", "200", "300"})
    add(std::string("princeton/") + p + ".off");
  for (const char* s : {"spiral", "vase"})
    for (int i = 1; i <= 6; ++i) add(std::string("refinements/") + s + std::to_string(i) + ".off");
  for (const char* d : {"tet10", "tet20", "tet30", "voro"})
    for (const char* i : {"0", "500"}) add(std::string("polyhedra/") + d + "/" + i + ".off");
  for (const char* name : {"bot_eye", "plus", "button", "rt4_arm"}) add(std::string("thingi/") + name + ".off");
  for (const char* g : kDenseRows) list.emplace_back(g, std::string(g).substr(std::strlen(kGeneratedPrefix)));
  return list;
}

// Our time per kernel vertex in microseconds (the cost the dense rows are about).
std::string per_vertex_cell(const Row& r) { return r.V ? fmt(1000 * r.ours_ms / double(r.V), 2) : "-"; }

std::string baseline_cell(const Baseline& b) {
  if (b.ran) return fmt(b.ms);
  if (b.skipped.rfind("n/a", 0) == 0) return "n/a";
  if (b.skipped.rfind("> ", 0) == 0) return b.skipped.substr(0, b.skipped.find(" s") + 2);  // "> 60 s"
  return "skip";
}
std::string ratio_cell(const Baseline& b, double ours) {
  if (!b.ran || ours <= 0) return "-";
  const double r = b.ms / ours;
  // Rows where a baseline is faster than us are bold, to be seen at a glance.
  return r < 1 ? "**" + fmt(r, 2) + "x**" : fmt(r, 1) + "x";
}

std::string json_escape(const std::string& s) {
  std::string o;
  for (char ch : s) {
    if (ch == '"' || ch == '\\') o += '\\';
    if (static_cast<unsigned char>(ch) < 0x20) {
      o += ' ';
      continue;
    }
    o += ch;
  }
  return o;
}

std::string json_baseline(const Baseline& b, double ours) {
  std::ostringstream os;
  os << "{\"ran\":" << (b.ran ? "true" : "false");
  if (b.ran)
    os << ",\"ms\":" << b.ms << ",\"runs\":" << b.runs << ",\"ratio\":" << (ours > 0 ? b.ms / ours : 0)
       << ",\"raw_vertices\":" << b.raw_vertices;
  if (b.ran && b.has_volume)
    os << ",\"volume\":" << b.volume << ",\"volume_rel_diff\":" << b.volume_rel_diff
       << ",\"volume_ok\":" << (b.volume_ok() ? "true" : "false");
  if (!b.ran) os << ",\"skipped\":\"" << json_escape(b.skipped) << "\"";
  os << "}";
  return os.str();
}

// One summary per folder of meshes: each baseline's ratio (baseline / ours) as a geometric mean,
// its minimum and the number of meshes where we are slower (ratio < 1). A median of a few runs of
// a 0.1 ms computation is at the mercy of this VM's hiccups, so every mesh found slower is measured
// again (both sides, kRecheckRuns runs each): `confirmed` counts those still slower then. The
// geometric mean and the minimum stay those of the first measurement.
constexpr int kRecheckRuns = 21;
struct RatioStats {
  size_t count = 0, slower = 0, confirmed = 0;
  std::vector<std::string> rechecks;  // "mesh: first ratio -> ratio measured again"
  double log_sum = 0, min = std::numeric_limits<double>::infinity();
  std::string min_mesh;
  // Counts the ratio; returns whether we are slower.
  bool add(const Baseline& b, double ours, const std::string& mesh) {
    if (!b.ran || ours <= 0) return false;
    const double r = b.ms / ours;
    ++count;
    log_sum += std::log(r);
    slower += r < 1;
    if (r < min) {
      min = r;
      min_mesh = mesh;
    }
    return r < 1;
  }
  double geomean() const { return count ? std::exp(log_sum / double(count)) : 0; }
};
// The baselines, in column order.
struct BaselineInfo {
  const char* name;      // table header
  const char* json_key;  // JSON field
  Baseline Row::*member;
};
const std::array<BaselineInfo, 4> kBaselines{{{"Epick", "cgal_epick", &Row::epick},
                                              {"Epeck", "cgal_epeck", &Row::epeck},
                                              {"Qhull", "qhull", &Row::qhull},
                                              {"CGAL 6.2", "cgal62_pmp_kernel", &Row::cgal62}}};
constexpr size_t kQhullIndex = 2;  // kBaselines[kQhullIndex] is Qhull
using PerBaseline = std::array<bool, kBaselines.size()>;

struct FamilySummary {
  std::string dir;
  size_t meshes = 0, errors = 0;
  std::vector<std::pair<std::string, size_t>> types;
  std::vector<double> ours;
  std::array<RatioStats, kBaselines.size()> ratios;  // in kBaselines' order
  // Qhull's inexact kernels whose volume is off ours by more than the tolerance (mesh: difference).
  std::vector<std::string> qhull_volume_off;
  // Counts the row; returns which baselines it was slower than.
  PerBaseline add(const Row& r) {
    PerBaseline slower{};
    ++meshes;
    if (!r.error.empty()) {
      ++errors;
      return slower;
    }
    auto it = std::find_if(types.begin(), types.end(), [&](const auto& t) { return t.first == r.type; });
    if (it == types.end())
      types.emplace_back(r.type, 1);
    else
      ++it->second;
    ours.push_back(r.ours_ms);
    for (size_t b = 0; b < kBaselines.size(); ++b)
      slower[b] = ratios[b].add(r.*kBaselines[b].member, r.ours_ms, r.mesh);
    if (r.qhull.ran && !r.qhull.volume_ok())
      qhull_volume_off.push_back(fs::path(r.mesh).filename().string() + ": " + fmt(r.qhull.volume_rel_diff, 9));
    return slower;
  }
  std::string types_cell() const {
    std::string s;
    for (const auto& [t, n] : types) s += (s.empty() ? "" : ", ") + t + " " + std::to_string(n);
    return s;
  }
  static std::string ratio_cells(const RatioStats& r) {
    if (!r.count) return "- | - | -";
    std::string slower = std::to_string(r.slower) + " of " + std::to_string(r.count);
    if (r.slower) slower = "**" + slower + "** (" + std::to_string(r.confirmed) + " when measured again)";
    return fmt(r.geomean()) + "x | " + fmt(r.min) + "x (" + fs::path(r.min_mesh).filename().string() + ") | " + slower;
  }
  std::string table_row() const {
    std::string s = "| " + dir + " | " + std::to_string(meshes) + " | " + std::to_string(errors) + " | " +
                    types_cell() + " | " + fmt(median(ours), 3) + " |";
    for (const RatioStats& r : ratios) s += " " + ratio_cells(r) + " |";
    return s;
  }
  static std::string ratio_json(const RatioStats& r) {
    std::ostringstream os;
    os << "{\"meshes\":" << r.count << ",\"geomean\":" << r.geomean() << ",\"min\":" << (r.count ? r.min : 0)
       << ",\"min_mesh\":\"" << json_escape(r.min_mesh) << "\",\"slower\":" << r.slower
       << ",\"slower_when_measured_again\":" << r.confirmed << ",\"rechecks\":[";
    for (size_t i = 0; i < r.rechecks.size(); ++i) os << (i ? "," : "") << "\"" << json_escape(r.rechecks[i]) << "\"";
    os << "]}";
    return os.str();
  }
  std::string json(const std::string& compiler, const std::string& load, int runs) const {
    std::ostringstream os;
    os << "{\"family\":\"" << json_escape(dir) << "\",\"compiler\":\"" << json_escape(compiler)
       << "\",\"loadavg_at_start\":\"" << load << "\",\"runs\":" << runs << ",\"meshes\":" << meshes
       << ",\"errors\":" << errors << ",\"ours_median_ms\":" << median(ours);
    for (size_t b = 0; b < kBaselines.size(); ++b)
      os << ",\"" << kBaselines[b].json_key << "\":" << ratio_json(ratios[b]);
    os << ",\"qhull_volume_off\":[";
    for (size_t i = 0; i < qhull_volume_off.size(); ++i)
      os << (i ? "," : "") << "\"" << json_escape(qhull_volume_off[i]) << "\"";
    os << "]}";
    return os.str();
  }
};

const char* const kUsage =
    "usage: kergen_bench [--runs N] [--json] [--cpu-time] [--quick] [--no-epeck] [--no-epick] [--no-qhull]\n"
    "                    [--epeck-max-faces N] [--epick-max-faces N] [--qhull-max-faces N]\n"
    "                    [--baseline-budget-ms T] [--no-cgal62] [--cgal62-timeout-s T]\n"
    "                    [--meshes DIR] [--family DIR]... [--families]\n"
    "                    [--streaming [--streaming-budget-ms T] [--streaming-cap-ms T]] [--cells [DIR...]]\n"
    "                    [mesh files...]\n";

// Exits with 2 on a usage error. `families_default`: --families was given.
Args parse_args(int argc, char** argv, bool& families_default) {
  Args args;
  bool runs_given = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "%s needs a value\n", a.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--runs")
      args.runs = std::max(1, std::atoi(next().c_str())), runs_given = true;
    else if (a == "--json")
      args.json = true;
    else if (a == "--cpu-time")
      kergen_bench::thread_cpu_clock() = true;
    else if (a == "--quick")
      args.quick = true;
    else if (a == "--no-epeck")
      args.epeck = false;
    else if (a == "--no-epick")
      args.epick = false;
    else if (a == "--no-qhull")
      args.qhull = false;
    else if (a == "--no-cgal62")
      args.cgal62 = false;
    else if (a == "--cgal62-timeout-s")
      args.cgal62_timeout_s = std::max(1, std::atoi(next().c_str()));
    else if (a == "--epeck-max-faces")
      args.epeck_max_faces = std::strtoull(next().c_str(), nullptr, 10);
    else if (a == "--epick-max-faces")
      args.epick_max_faces = std::strtoull(next().c_str(), nullptr, 10);
    else if (a == "--qhull-max-faces")
      args.qhull_max_faces = std::strtoull(next().c_str(), nullptr, 10);
    else if (a == "--baseline-budget-ms")
      args.baseline_budget_ms = std::atof(next().c_str());
    else if (a == "--streaming")
      args.streaming = true;
    else if (a == "--cells")
      args.cells = true;
    else if (a == "--streaming-budget-ms")
      args.streaming_budget_ms = std::atof(next().c_str());
    else if (a == "--streaming-cap-ms")
      args.streaming_cap_ms = std::atof(next().c_str());
    else if (a == "--meshes")
      args.meshes = next();
    else if (a == "--family")
      args.families.push_back(next());
    else if (a == "--families")
      families_default = true;
    else if (a == "-h" || a == "--help") {
      std::fputs(kUsage, stdout);
      std::exit(0);
    } else if (!a.empty() && a[0] == '-') {
      std::fprintf(stderr, "unknown option %s (try --help)\n", a.c_str());
      std::exit(2);
    } else
      args.files.push_back(a);
  }
  if (args.quick && !runs_given) args.runs = 1;
  // A run cut off at the cap is then always the last one of its measurement.
  args.streaming_cap_ms = std::max(args.streaming_cap_ms, args.streaming_budget_ms);
  return args;
}

// One summary row for every mesh file of `dir`; meshes found slower than a baseline are measured
// again (see RatioStats). Returns false when the folder has no mesh file.
bool run_family(const std::string& dir, const Args& args, FamilySummary& fam) {
  std::vector<std::string> files;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string ext = entry.path().extension().string();
    if (entry.is_regular_file() && (ext == ".off" || ext == ".obj" || ext == ".stl"))
      files.push_back(entry.path().string());
  }
  if (ec || files.empty()) return false;
  std::sort(files.begin(), files.end());
  const fs::path rel = fs::path(dir).lexically_relative(args.meshes);
  fam.dir = !rel.empty() && *rel.begin() != ".." ? rel.string() : dir;  // polyhedra/voro, not /abs/../polyhedra/voro
  Args again = args;
  again.runs = std::max(args.runs, kRecheckRuns);
  for (const std::string& f : files) {
    const Row r = bench_mesh(f, f, args);
    const PerBaseline slower = fam.add(r);
    if (std::none_of(slower.begin(), slower.end(), [](bool s) { return s; })) continue;
    const Row r2 = bench_mesh(f, f, again);
    for (size_t b = 0; b < kBaselines.size(); ++b) {
      if (!slower[b]) continue;
      const Baseline &first = r.*kBaselines[b].member, &second = r2.*kBaselines[b].member;
      const double ratio = second.ran && r2.ours_ms > 0 ? second.ms / r2.ours_ms : 0;
      fam.ratios[b].confirmed += second.ran && ratio < 1;
      fam.ratios[b].rechecks.push_back(fs::path(f).filename().string() + ": " + fmt(first.ms / r.ours_ms) + "x -> " +
                                       fmt(ratio) + "x");
    }
  }
  return true;
}

// Non-star meshes: compare with our full run on the star mesh of closest size.
void set_star_references(std::vector<Row>& rows) {
  for (Row& r : rows) {
    if (!r.error.empty() || r.star) continue;
    const Row* best = nullptr;
    for (const Row& s : rows)
      if (s.error.empty() && s.type == "POLYHEDRON" &&
          (!best || std::llabs((long long)s.faces - (long long)r.faces) <
                        std::llabs((long long)best->faces - (long long)r.faces)))
        best = &s;
    if (best) {
      r.reference = best->mesh;
      r.reference_ms = best->ours_ms;
    }
  }
}

void print_json(const std::vector<Row>& rows, const std::vector<FamilySummary>& families, const std::string& compiler,
                const std::string& load_at_start, int runs) {
  for (const Row& r : rows) {
    std::ostringstream os;
    os << "{\"mesh\":\"" << json_escape(r.mesh) << "\",\"compiler\":\"" << json_escape(compiler)
       << "\",\"loadavg_at_start\":\"" << load_at_start << "\",\"runs\":" << runs;
    if (!r.error.empty()) {
      os << ",\"error\":\"" << json_escape(r.error) << "\"}";
      std::printf("%s\n", os.str().c_str());
      continue;
    }
    const auto& s = r.stats;
    os << ",\"faces\":" << r.faces << ",\"distinct_planes\":" << r.planes << ",\"culled_faces\":" << r.culled
       << ",\"merged_planes\":" << s.distinct_planes << ",\"active_planes\":" << s.active_planes << ",\"type\":\""
       << r.type << "\",\"V\":" << r.V << ",\"E\":" << r.E << ",\"F\":" << r.F << ",\"volume\":" << r.volume
       << ",\"ours_ms\":" << r.ours_ms << ",\"us_per_kernel_vertex\":" << (r.V ? 1000 * r.ours_ms / double(r.V) : 0)
       << ",\"phases_ms\":{\"validate\":" << s.ms_validate << ",\"planes\":" << s.ms_planes << ",\"lp\":" << s.ms_lp
       << ",\"trace\":" << s.ms_trace << ",\"assemble\":" << s.ms_assemble << ",\"total\":" << s.ms_total << "}"
       << ",\"traced_lines\":" << s.traced_lines << ",\"exact_fallbacks\":" << s.exact_fallbacks;
    for (const BaselineInfo& b : kBaselines)
      os << ",\"" << b.json_key << "\":" << json_baseline(r.*b.member, r.ours_ms);
    if (!r.reference.empty())
      os << ",\"star_reference\":\"" << json_escape(r.reference) << "\",\"star_reference_ms\":" << r.reference_ms
         << ",\"ratio_to_star_reference\":" << (r.reference_ms > 0 ? r.ours_ms / r.reference_ms : 0);
    os << "}";
    std::printf("%s\n", os.str().c_str());
  }
  for (const FamilySummary& f : families) std::printf("%s\n", f.json(compiler, load_at_start, runs).c_str());
}

std::string row_note(const Row& r) {
  std::string note;
  if (!r.reference.empty())
    note = "non-star: " + fmt(100.0 * r.ours_ms / std::max(1e-9, r.reference_ms), 1) + "% of " + r.reference + " (" +
           fmt(r.reference_ms) + " ms)";
  auto add = [&](const std::string& text) { note += (note.empty() ? "" : "; ") + text; };
  for (const BaselineInfo& info : kBaselines) {
    const Baseline& b = r.*info.member;
    if (b.ran && b.ms < r.ours_ms) add(std::string("**slower than ") + info.name + "**");
    if (!b.ran && b.skipped.rfind("n/a", 0) != 0 && !b.skipped.empty()) add(std::string(info.name) + " " + b.skipped);
  }
  if (r.qhull.ran && !r.qhull.volume_ok())
    add("**Qhull volume differs from ours by " + fmt(100 * r.qhull.volume_rel_diff, 6) + "%**");
  return note;
}

// The mesh table, then the geometric mean of each ratio over the rows that have it.
void print_row_table(const std::vector<Row>& rows) {
  std::printf(
      "| mesh | faces | planes | culled | kernel | V | E | F | ours | µs/V | Epick | Epeck | Qhull | CGAL 6.2 | "
      "Epick/ours | Epeck/ours | Qhull/ours | CGAL 6.2/ours | validate | planes | lp | trace | assemble | note |\n");
  std::printf(
      "|---|---:|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
      "---:|---|\n");
  std::array<RatioStats, kBaselines.size()> ratios;
  for (const Row& r : rows) {
    if (!r.error.empty()) {
      std::printf("| %s | %zu | | | ERROR | | | | %s | | | | | | | | | | | | | | | %s |\n", r.mesh.c_str(), r.faces,
                  r.ours_ms > 0 ? fmt(r.ours_ms).c_str() : "", r.error.c_str());
      continue;
    }
    const auto& s = r.stats;
    std::string times, ratio_cells;
    for (size_t b = 0; b < kBaselines.size(); ++b) {
      const Baseline& base = r.*kBaselines[b].member;
      times += baseline_cell(base) + " | ";
      ratio_cells += ratio_cell(base, r.ours_ms) + " | ";
      ratios[b].add(base, r.ours_ms, r.mesh);
    }
    std::printf("| %s | %zu | %zu | %zu | %s | %zu | %zu | %zu | %s | %s | %s%s%s | %s | %s | %s | %s | %s |\n",
                r.mesh.c_str(), r.faces, r.planes, r.culled, r.type.c_str(), r.V, r.E, r.F, fmt(r.ours_ms).c_str(),
                per_vertex_cell(r).c_str(), times.c_str(), ratio_cells.c_str(), fmt(s.ms_validate).c_str(),
                fmt(s.ms_planes).c_str(), fmt(s.ms_lp).c_str(), fmt(s.ms_trace).c_str(), fmt(s.ms_assemble).c_str(),
                row_note(r).c_str());
  }
  std::string summary;
  for (size_t b = 0; b < kBaselines.size(); ++b) {
    const RatioStats& st = ratios[b];
    if (!st.count) continue;
    summary += std::string(summary.empty() ? " " : "; ") + kBaselines[b].name + " geometric mean " + fmt(st.geomean()) +
               "x, minimum " + fmt(st.min) + "x (" + st.min_mesh + "), " + std::to_string(st.slower) + " of " +
               std::to_string(st.count) + " rows slower";
  }
  if (!summary.empty()) std::printf("\nbaseline/ours over the rows with both times:%s\n", summary.c_str());
}

void print_family_table(const std::vector<FamilySummary>& families, bool after_rows) {
  std::printf(
      "%s| family | meshes | errors | kernel types | ours: median ms | Epick/ours: geomean | min | slower | "
      "Epeck/ours: geomean | min | slower | Qhull/ours: geomean | min | slower | CGAL 6.2/ours: geomean | min | "
      "slower |\n",
      after_rows ? "\n" : "");
  std::printf("|---|---:|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const FamilySummary& f : families) std::printf("%s\n", f.table_row().c_str());
  bool any = false;
  for (const FamilySummary& f : families)
    for (size_t b = 0; b < kBaselines.size(); ++b)
      for (const std::string& r : f.ratios[b].rechecks) {
        std::printf("\nMeasured again (%d runs), %s vs %s: %s", kRecheckRuns, f.dir.c_str(), kBaselines[b].name,
                    r.c_str());
        any = true;
      }
  for (const FamilySummary& f : families) {
    std::printf("\nQhull volume check, %s: %zu of %zu kernels off ours by more than %g relative", f.dir.c_str(),
                f.qhull_volume_off.size(), f.ratios[kQhullIndex].count, Baseline::kVolumeTolerance);
    for (size_t i = 0; i < f.qhull_volume_off.size() && i < 10; ++i)
      std::printf("%s%s", i ? ", " : " (", f.qhull_volume_off[i].c_str());
    std::printf("%s", f.qhull_volume_off.empty() ? "" : f.qhull_volume_off.size() > 10 ? ", ...)" : ")");
    any = true;
  }
  if (any) std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  bool families_default = false;
  Args args = parse_args(argc, argv, families_default);
  if (families_default)
    for (const char* d : {"tet10", "tet20", "tet30", "voro"})
      args.families.push_back((fs::path(args.meshes) / "polyhedra" / d).string());
  std::vector<std::pair<std::string, std::string>> list;
  if (!args.files.empty())
    for (const auto& f : args.files) list.emplace_back(f, f);
  else if (!args.families.empty() && !families_default) {
    // only the families
  } else {
    if (!fs::is_directory(args.meshes)) {
      std::fprintf(stderr, "mesh folder %s not found: pass --meshes DIR or mesh files\n", args.meshes.c_str());
      return 1;
    }
    if (!args.streaming) list = default_list(args);
  }

  const std::string compiler = compiler_string();
  const std::string load_at_start = loadavg_string();
  if (!args.json) {
    std::printf(
        "# kergen_bench | %s | CGAL %s | %s | %s | %s, %u threads, load average %s at start | median of %d run(s) | "
        "times in ms%s, end to end (parse excluded)\n",
        compiler.c_str(), CGAL_VERSION_STR, kergen_bench::qhull_version().c_str(), cgal62_version().c_str(),
        cpu_string().c_str(), std::thread::hardware_concurrency(), load_at_start.c_str(), args.runs,
        kergen_bench::thread_cpu_clock() ? " of thread CPU time" : "");
    std::fflush(stdout);
  }
  if (args.cells) {
    const std::string context =
        "\"compiler\":\"" + json_escape(compiler) + "\",\"loadavg_at_start\":\"" + load_at_start + "\"";
    return kergen_bench::run_cell_rows(args.meshes, args.files, args.runs, args.json, context);
  }
  if (args.streaming) {
    const std::string context =
        "\"compiler\":\"" + json_escape(compiler) + "\",\"loadavg_at_start\":\"" + load_at_start + "\"";
    return kergen_bench::run_streaming_rows(args.meshes, args.files, args.runs, args.streaming_budget_ms,
                                            args.streaming_cap_ms, args.json, context);
  }

  std::vector<Row> rows;
  for (const auto& [path, label] : list) {
    rows.push_back(bench_mesh(path, label, args));
    if (!args.json) std::fprintf(stderr, "  done %s (%.1f ms)\n", label.c_str(), rows.back().ours_ms);
  }
  std::vector<FamilySummary> families;
  for (const std::string& dir : args.families) {
    FamilySummary fam;
    if (!run_family(dir, args, fam)) {
      std::fprintf(stderr, "family %s: no mesh files found\n", dir.c_str());
      return 1;
    }
    if (!args.json) std::fprintf(stderr, "  done family %s (%zu meshes)\n", dir.c_str(), fam.meshes);
    families.push_back(std::move(fam));
  }
  set_star_references(rows);
  if (args.json) {
    print_json(rows, families, compiler, load_at_start, args.runs);
    return 0;
  }
  if (!rows.empty()) print_row_table(rows);
  if (!families.empty()) print_family_table(families, !rows.empty());
  return 0;
}
