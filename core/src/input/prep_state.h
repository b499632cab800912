// The state prepare_mesh's phases share (Prep) and the phases, declared for the files that
// define them and for mesh_prep.cpp, which runs them in order; private to input/. Each phase
// refuses the mesh (returns false after Prep::fail) or leaves its part of the state for the next.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "input/mesh_prep.h"
#include "kergen/kergen.h"
#include "util/compiler_hints.h"
#include "util/raw_vector.h"
#include "util/union_find.h"

namespace kergen::prep {

// The state prepare_mesh's phases share, filled in the order they run. Each phase returns false
// once it has refused the mesh (m.error and m.message set by fail()).
struct Prep {
  Prep(const MeshView& mesh_in, const Options& options_in, bool allow_shells_in, bool verdict_only_in)
      : mesh(mesh_in), options(options_in), allow_shells(allow_shells_in), verdict_only(verdict_only_in) {}
  const MeshView& mesh;
  const Options& options;
  const bool allow_shells;
  const bool verdict_only;  // PrepareFor::Verdict
  PreparedMesh m;           // the result
  size_t nv = 0, nf = 0;

  // check_coordinates: the largest magnitude (for the scale) and the smallest non-zero one (for
  // the exact shift); the scale's exponent.
  double maxabs = 0, min_nonzero_abs = INFINITY;
  int ex = 0;

  // clean_faces: the faces without repeated consecutive vertices (cf of them), the used
  // vertices, and the edge uses counted per bucket. Edge uses are bucketed by their lower vertex
  // id and direction: bucket 2 lo + 1 holds the uses running up from lo (lo -> hi, hi > lo),
  // bucket 2 lo those running down to lo. bucket[b + 1]: size of bucket b, then its start, then
  // (after pair_edges' fill) its end.
  // When every face is a triangle of three distinct vertices (the usual case) the clean faces are
  // the input's: `cl` then points at its indices (clean_viewed) and `clean` and `clean_offsets`
  // stay empty until a phase that changes or walks the loops in general asks for its own copy
  // (own_clean); the common phases read `cl`, whose loop f starts at 3 f when clean_size = 3 cf.
  RawVector<uint32_t> clean, clean_offsets;
  const uint32_t* cl = nullptr;  // the clean loops' entries (clean.data() once owned)
  size_t clean_size = 0;         // their number
  bool clean_viewed = false;
  size_t cf = 0;
  void own_clean() {
    if (!clean_viewed) return;
    clean.assign(cl, cl + clean_size);
    clean_offsets.resize(cf + 1);
    for (size_t f = 0; f <= cf; ++f) clean_offsets[f] = uint32_t(3 * f);
    cl = clean.data();
    clean_viewed = false;
  }
  // The input face of each clean face, from the first face dropped on (before it: the identity).
  std::vector<uint32_t> clean_source;
  bool clean_renumbered = false;
  uint32_t input_of_clean(size_t f) const { return clean_renumbered ? clean_source[f] : uint32_t(f); }
  std::vector<char> used;
  std::vector<uint32_t> bucket;
  uint32_t total_uses = 0;

  // pair_edges: faulty edges counted, the one named the smallest (lower id, upper id); pairs of
  // faces sharing an edge; connected pieces = faces - successful unions.
  size_t open = 0, nonmanifold = 0, inconsistent = 0;
  uint64_t open_ex = UINT64_MAX, nonmanifold_ex = UINT64_MAX, inconsistent_ex = UINT64_MAX;
  UnionFind components{0};
  size_t unions = 0;
  RawVector<std::array<uint32_t, 2>> face_pairs;

  // find_shared_positions (run before the edge check, reported by check_shared_positions after
  // it): the unused vertices, whether two used vertices share a position, the bounding box of
  // the used vertices (its zero bounds' signs set by take_bounding_box).
  size_t unused = 0;
  bool positions_distinct = false;  // (prepare_mesh's argument: no search needed)
  bool shared_position = false;
  double lo3[3], hi3[3];

  // sum_fan_volume: the box centre, its largest side, six times the volume of the fans about the
  // centre and the sum of its terms' magnitudes; the leading run of faces kept as they are.
  double c[3] = {0, 0, 0}, ext = 0;
  double vol6 = 0, vol6_abs = 0;
  size_t first_general = 0;
  bool volume_summed = false;  // by pair_edges, for a verdict's triangles (in its pass over them)
  bool fans_enclose_nothing = false, flip = false;
  // A verdict without several shells to judge reads no representative: when every face is in
  // the leading run they are not written (m.rep holds cf unset entries; only their number is
  // read, and none is added: build_plane_faces has nothing left to walk).
  bool reps_unwritten = false;

  // build_plane_faces
  size_t degenerate = 0, nonplanar = 0;
  double split_abs = 0;  // sum of |terms| of the split polygons' volume corrections
  bool renumbered = false;
  std::vector<uint32_t> face_of_clean;  // used once renumbered

  bool fail(Error e, const std::string& msg) {
    m.error = e;
    m.message = msg;
    m.rep = {};  // (its storage may hold the edge check's scratch)
    return false;
  }
  const double* P(uint32_t v) const { return &m.points[3 * size_t(v)]; }
  size_t face_size(size_t f) const { return mesh.face_sizes ? mesh.face_sizes[f] : 3; }

  // Six times the signed volume of the tetrahedron (c, p0, p1, p2).
  KERGEN_INLINE double vol6_about_centre(uint32_t i0, uint32_t i1, uint32_t i2) const {
    const double *p0 = P(i0), *p1 = P(i1), *p2 = P(i2);
    double a[3], bb[3], cc[3];
    for (int k = 0; k < 3; ++k) {
      a[k] = p0[k] - c[k];
      bb[k] = p1[k] - c[k];
      cc[k] = p2[k] - c[k];
    }
    return a[0] * (bb[1] * cc[2] - bb[2] * cc[1]) - a[1] * (bb[0] * cc[2] - bb[2] * cc[0]) +
           a[2] * (bb[0] * cc[1] - bb[1] * cc[0]);
  }
};

// prep_coordinates.cpp: the raw arrays, the coordinates and indices, the exact scale.
bool check_arrays(Prep& s);
bool check_coordinates(Prep& s);
bool scale_points(Prep& s);

// prep_topology.cpp: clean faces (and indices in range), the edge check, connected pieces,
// shared positions.
bool clean_faces(Prep& s);
bool check_faces_left(Prep& s);
void pair_edges(Prep& s);
bool report_edge_faults(Prep& s);
bool count_components(Prep& s);
void find_shared_positions(Prep& s);
bool check_shared_positions(Prep& s);

// prep_volume.cpp: bounding box, enclosed volume, orientation.
// The volume terms (vol6_about_centre) of the triangles tri[3 j..3 j + 3), j < n, n a multiple
// of 4 and at most 64, into d, and bit j set when certainly_not_collinear does not certify
// triangle j: the same bits as the scalar functions, four triangles at a time.
uint64_t triangle_terms(const double* pts, const uint32_t* tri, size_t n, const double c[3], double* d);
// The same for any n up to kTermBlock, about s.c (the last n % 4 by the scalar functions).
constexpr size_t kTermBlock = 64;
uint64_t triangle_block_terms(const Prep& s, const uint32_t* tri, size_t n, double* d);
void take_bounding_box(Prep& s);
void take_centre(Prep& s);
void sum_fan_volume(Prep& s);
bool orient_by_volume(Prep& s);
bool check_split_volume(Prep& s);
bool needs_thin_certificate(const Prep& s);
bool certify_thin_volume(Prep& s);

// prep_plane_faces.cpp: the faces that carry planes (non-planar polygons split).
bool build_plane_faces(Prep& s);
void move_loops(Prep& s);

}  // namespace kergen::prep
