// The input as the kernel sees it (prepare_input.h): Options::flip_faces, Options::weld and
// Options::repair run first when the input allows them, then validation (mesh_prep.h), whose
// verdict is completed here: the pieces of a mesh of several shells judged, and an open mesh's
// refusal naming open_boundary; an open mesh's volume is that of the surface closed over its
// holes, and one whose faces point inward is said to (open_orientation.h).
#include "input/prepare_input.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numeric>
#include <string>
#include <utility>

#include "input/open_orientation.h"
#include "input/repair.h"
#include "input/shells.h"
#include "input/weld.h"
#include "util/compiler_hints.h"
#include "util/plural.h"

namespace kergen {

namespace {

// Whether the n coordinates x are finite and the k indices below nv, as two reductions with no
// early exit, so that they vectorize: the coordinates' largest magnitude as bits (without the sign
// bit, doubles order like their bit patterns, and every NaN or infinity lies at or above
// infinity's; below 2^63, so signed 64-bit maxima, which SIMD units have, order them) and the
// largest index. (Multiversioned: the AVX2 clone takes four coordinates and eight indices a step.)
KERGEN_MULTIVERSION
bool finite_and_below(const double* x, size_t n, const uint32_t* index, size_t k, size_t nv) {
  constexpr uint64_t kAbs = ~(uint64_t(1) << 63);
  int64_t top = 0;
  for (size_t i = 0; i < n; ++i) {
    uint64_t b;
    std::memcpy(&b, x + i, sizeof b);
    top = std::max(top, int64_t(b & kAbs));
  }
  uint32_t largest = 0;
  for (size_t i = 0; i < k; ++i) largest = std::max(largest, index[i]);
  return top < int64_t(0x7ff0000000000000ll) && (k == 0 || largest < nv);
}

// Whether Options::weld can run on the input as given: finite coordinates, indices in range,
// face sizes that add up, no face of fewer than three corners. Otherwise validation reports the
// input's defect as given (welding would hide or change it).
bool weldable(const MeshView& m) {
  if (m.num_vertices == 0 || (m.face_sizes == nullptr && m.num_indices % 3 != 0)) return false;
  if (!finite_and_below(m.positions, 3 * m.num_vertices, m.indices, m.num_indices, m.num_vertices)) return false;
  if (m.face_sizes) {
    size_t sum = 0;
    for (size_t f = 0; f < m.num_faces; ++f) {
      if (m.face_sizes[f] < 3) return false;
      sum += m.face_sizes[f];
    }
    if (sum != m.num_indices) return false;
  }
  return true;
}

// A copy of the arrays `m` views (what Mesh::view would give back).
Mesh copy_of(const MeshView& m) {
  Mesh out;
  out.positions.assign(m.positions, m.positions + 3 * m.num_vertices);
  out.indices.assign(m.indices, m.indices + m.num_indices);
  if (m.face_sizes) out.face_sizes.assign(m.face_sizes, m.face_sizes + m.num_faces);
  return out;
}

// A closed mesh of several pieces (shells.h): refused when two pieces cross or touch, else
// prepared with a warning (the kernel is then empty, or the pieces are nested alike: the entry
// points refuse that once the LP has found a point).
PreparedMesh judge_shells(PreparedMesh m) {
  if (m.error != Error::Ok || m.shells < 2) return m;
  const std::string pieces = std::to_string(m.shells) + " separate pieces";
  if (find_shell_contact(m).found) {
    m.error = Error::SelfIntersection;
    m.message = "the mesh has " + pieces + " and two of them cross or touch each other: no solid has that surface";
    return m;
  }
  m.warnings.push_back({Warning::Kind::SeparateShells, m.shells,
                        "the mesh has " + pieces +
                            " that neither cross nor touch (disjoint solids, or a solid and a void inside it): no "
                            "point sees all of them from inside"});
  return m;
}

// An open mesh (`judged`: the mesh validation judged). Refused: the message also names the other
// way of accepting it, and says when its faces point inward. Accepted: its volume is that of the
// surface closed over its holes, and faces pointing inward are a warning.
PreparedMesh judge_open(PreparedMesh m, const MeshView& judged) {
  const bool refused = m.error == Error::OpenMesh;
  if (!refused && (m.error != Error::Ok || m.boundary_edges == 0)) return m;
  const CappedVolume capped = capped_volume(judged);
  if (refused) {
    if (capped.inward) m.message += "; " + faces_point_inward_message(capped);
    m.message += "; Options::open_boundary bounds such a surface's kernel by walls at its boundary edges";
    return m;
  }
  m.volume = std::ldexp(capped.volume, 3 * m.scale_exp);
  if (capped.inward)
    m.warnings.push_back({Warning::Kind::FacesPointInward, m.input_faces,
                          "the surface is open and " + faces_point_inward_message(capped)});
  return m;
}

// `m` with every face's loop reversed (Options::flip_faces); `m` as given when its arrays do not
// describe faces (validation refuses that as given).
Mesh flipped(const MeshView& m) {
  Mesh out = copy_of(m);
  const size_t nf = m.face_sizes ? m.num_faces : m.num_indices / 3;
  size_t begin = 0;
  for (size_t f = 0; f < nf; ++f) {
    const size_t size = m.face_sizes ? m.face_sizes[f] : 3;
    std::reverse(out.indices.begin() + long(begin), out.indices.begin() + long(begin + size));
    begin += size;
  }
  return out;
}

// What Options::weld and Options::repair did, one warning per kind of change, in the order they
// were made (reported before validation's own warnings).
std::vector<Warning> weld_and_repair_warnings(const WeldResult& w, const RepairCounts& repaired) {
  std::vector<Warning> done;
  if (w.merged_vertices || w.dropped_faces) {
    char tolerance[32];
    std::snprintf(tolerance, sizeof tolerance, "%.3g", w.tolerance);
    std::string message = count_of(w.merged_vertices, "vertex", "vertices") +
                          verb_for(w.merged_vertices, " was merged into another", " were merged into others") +
                          " within " + tolerance;
    if (w.dropped_faces)
      message += ", and " + count_of(w.dropped_faces, "face", "faces") + " that collapsed " +
                 verb_for(w.dropped_faces, "was", "were") + " dropped";
    done.push_back({Warning::Kind::VerticesWelded, w.merged_vertices, message});
  }
  if (repaired.duplicate_faces)
    done.push_back({Warning::Kind::DuplicateFacesRemoved, repaired.duplicate_faces,
                    count_of(repaired.duplicate_faces, "face", "faces") + " repeating another face " +
                        verb_for(repaired.duplicate_faces, "was", "were") + " removed"});
  if (repaired.cancelling_faces)
    done.push_back({Warning::Kind::CancellingFacesRemoved, repaired.cancelling_faces,
                    count_of(repaired.cancelling_faces, "face", "faces") + " " +
                        verb_for(repaired.cancelling_faces, "was", "were") +
                        " removed in pairs of opposite orientation on the same corners"});
  if (repaired.t_junctions)
    done.push_back({Warning::Kind::TJunctionsSplit, repaired.t_junctions,
                    count_of(repaired.t_junctions, "vertex", "vertices") + " lying on the edge of another face " +
                        verb_for(repaired.t_junctions, "was", "were") + " inserted into it (" +
                        verb_for(repaired.t_junctions, "a T-junction", "T-junctions") + " split)"});
  return done;
}

}  // namespace

PreparedMesh prepare_input(const MeshView& mesh, const Options& options, Mesh* validated, PrepareFor purpose) {
  if (options.flip_faces) {
    Options as_given = options;
    as_given.flip_faces = false;
    if (!weldable(mesh)) return prepare_input(mesh, as_given, validated, purpose);
    const Mesh turned = flipped(mesh);
    return prepare_input(turned.view(), as_given, validated, purpose);
  }
  if (options.open_boundary == OpenBoundary::Perpendicular && !options.allow_open) {
    Options accepting = options;
    accepting.allow_open = true;
    return prepare_input(mesh, accepting, validated, purpose);
  }
  const bool weld = options.weld >= 0;
  if (!weld && !options.repair) {  // (no pass over the input to check what no one asked for)
    if (validated && weldable(mesh)) *validated = copy_of(mesh);
    return judge_open(judge_shells(prepare_mesh(mesh, options, true, purpose)), mesh);
  }
  const bool can_weld = weldable(mesh);
  if (!can_weld) return judge_open(judge_shells(prepare_mesh(mesh, options, true, purpose)), mesh);
  WeldResult w = weld_vertices(mesh, weld ? options.weld : 0, weld && options.weld_relative);
  if (w.unchanged && options.repair) {  // (repair changes its own copy)
    w.mesh = copy_of(mesh);
    w.source_face.resize(mesh.face_sizes ? mesh.num_faces : mesh.num_indices / 3);
    std::iota(w.source_face.begin(), w.source_face.end(), 0u);
    w.unchanged = false;
  }
  RepairCounts repaired;
  std::vector<uint32_t> repair_kept;
  if (options.repair) repaired = repair_mesh(w.mesh, &repair_kept);
  // (A weld that changed nothing leaves the input as it is: it is validated in place.)
  const MeshView welded = w.unchanged ? mesh : w.mesh.view();
  // (After a weld no two vertices share a position: equal positions are within any tolerance. A
  // repair changes the faces after the weld, so its mesh is searched as any other.)
  PreparedMesh m = judge_open(judge_shells(prepare_mesh(welded, options, true, purpose, !options.repair)), welded);
  // Faces are named by their index in the input (the witness): through the repair, then the weld.
  m.welded_source = std::move(w.source_face);
  if (options.repair) {
    for (uint32_t& f : repair_kept) f = m.welded_source[f];
    m.welded_source = std::move(repair_kept);
  }
  m.input_faces += w.dropped_faces + repaired.duplicate_faces + repaired.cancelling_faces;
  m.dropped_faces += w.dropped_faces + repaired.duplicate_faces + repaired.cancelling_faces;
  // The merged vertices are no face's any more: only the input's own unused ones are reported.
  for (size_t i = 0; i < m.warnings.size(); ++i)
    if (m.warnings[i].kind == Warning::Kind::UnusedVertices) {
      const size_t unused = m.warnings[i].count - std::min(m.warnings[i].count, w.merged_vertices);
      if (unused == 0)
        m.warnings.erase(m.warnings.begin() + long(i));
      else
        m.warnings[i] = unused_vertices_warning(unused);
      break;
    }
  const std::vector<Warning> done = weld_and_repair_warnings(w, repaired);
  m.warnings.insert(m.warnings.begin(), done.begin(), done.end());
  if (validated) *validated = w.unchanged ? copy_of(mesh) : std::move(w.mesh);
  return m;
}

Mesh without_unused_vertices(Mesh mesh) {
  const size_t nv = mesh.num_vertices();
  std::vector<uint32_t> new_id(nv, 0);
  for (uint32_t v : mesh.indices) new_id[v] = 1;
  uint32_t kept = 0;
  for (size_t v = 0; v < nv; ++v) {
    if (!new_id[v]) continue;
    for (int k = 0; k < 3; ++k) mesh.positions[3 * size_t(kept) + k] = mesh.positions[3 * v + k];
    new_id[v] = kept++;
  }
  mesh.positions.resize(3 * size_t(kept));
  for (uint32_t& v : mesh.indices) v = new_id[v];
  return mesh;
}

}  // namespace kergen
