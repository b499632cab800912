// kergen — exact kernel of a closed 3D polygon mesh.
//
// The kernel of a shape is the set of points that see every point of it; for a closed polygon mesh
// it is the intersection of the inner half-spaces of all face planes (a convex set, empty when the
// shape is not star-shaped). This library computes it with KerGen (Asiler & Sahillioglu, 2024):
// one kernel vertex from Seidel's randomized LP, then additive tracing of kernel edges along the
// lines where two face planes meet, until the boundary closes (a closed input of at most 64
// distinct planes is instead clipped from a box plane by plane, with the same result). Topology is decided by exact
// (filtered) predicates; no tolerance depends on the mesh's scale.
//
// Conventions used by every function in this header:
//   positions  flat xyz, double, `3 * num_vertices` values.
//   indices    flat uint32 vertex indices of the faces, concatenated.
//   face_sizes vertices per face; nullptr / empty = every face is a triangle.
//   Faces are counter-clockwise seen from outside (outward normals). A mesh whose faces are all
//   clockwise is accepted and flipped (reported as a warning).
//   Output faces are convex polygons, counter-clockwise seen from outside the kernel.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace kergen {

// ---------------------------------------------------------------------------------------------
// Status values. User errors (bad input) are reported through these, never by exceptions or
// crashes. The JS package exposes the same names in SCREAMING_SNAKE_CASE as `KergenError.code`.
enum class Error : int {
  Ok = 0,
  EmptyInput,               // no vertices or no faces
  NonFiniteCoordinate,      // NaN or infinity in positions
  IndexOutOfRange,          // a face refers to a vertex that does not exist
  FaceTooSmall,             // a face with fewer than 3 vertices
  OpenMesh,                 // an edge used by one face only (a hole); see Options::allow_open
  NonManifoldEdge,          // an edge used by more than two faces, two vertices at one position
                            // (the surface touches itself), or a polygon face that crosses itself
                            // (a non-planar one: that folds over itself)
  InconsistentOrientation,  // two faces traverse a shared edge in the same direction
  MultipleComponents,       // more than one connected piece, where that leaves no solid: an open mesh
                            // of several pieces, or closed pieces nested with the same orientation.
                            // (Closed pieces that neither cross nor touch, disjoint or a solid with
                            // a void, have an empty kernel: Warning::Kind::SeparateShells; pieces
                            // that cross or touch: SelfIntersection.)
  DegenerateInput,          // encloses no volume (flat, or only zero-area faces)
  TooLarge,                 // exceeds Options::max_faces / max_vertices
  ParseError,               // a mesh file could not be read (io.h)
  IoError,                  // a file could not be opened or written (io.h)
  InvalidArgument,          // a programmer-supplied argument is malformed (sizes disagree, etc.)
  CoordinateRange,          // coordinates span too many binary orders of magnitude for exact
                            // evaluation in double-based arithmetic (e.g. 1 next to 1e-60)
  Internal,                 // a failure inside the library (a bug, not a verdict on the input):
                            // please report the mesh; the message says what failed
  SelfIntersection,         // the surface crosses or touches itself: a ray from a point strictly
                            // inside the half-spaces' intersection crosses it more than once, or
                            // (flat or unbounded kernels, open meshes, find_kernel_point) two faces
                            // meet away from the vertices and edges they share, by exact tests
};

// Shape of the kernel (meaningful when error == Error::Ok).
enum class KernelType : int {
  Empty = 0,   // not star-shaped
  Point,       // one vertex
  Segment,     // two vertices, one edge
  Polygon,     // a flat convex polygon (one face, no volume)
  Polyhedron,  // a closed convex polyhedron
  Unbounded,   // only for an open mesh (allow_open, open_boundary): the half-spaces do not bound
               // a region; the result is clipped to a large box around the mesh
};

// What bounds the kernel of an open mesh (a surface with a boundary: edges used by one face only),
// once it is accepted (Options::allow_open, or open_boundary = Perpendicular, which accepts it by
// itself). Either way the faces keep their orientation as given (an open surface is never
// flipped): the kernel lies on their inner sides, behind their counter-clockwise fronts.
enum class OpenBoundary : int {
  // The faces' half-spaces only: where they leave the region open (through the holes) it is
  // clipped to a box twice the size of the mesh (KernelType::Unbounded).
  Clip = 0,
  // Also a wall at every boundary edge (Asiler & Sahillioglu 2024, Sec. 6.3): the plane through
  // the edge perpendicular to its face, whose inner side holds the face. The kernel is then the
  // set of points that see every face from its inner side and lie on the inner side of every
  // boundary wall: bounded where the surface and its walls close around it (a bowl, a dome), and
  // still Unbounded (clipped as above) where they leave a direction open: a flat patch (a disc,
  // a single triangle: the prism behind it), or a patch whose walls spread apart behind it (a
  // valley-shaped terrain). Empty when no point is behind every face and inside every wall.
  //
  // Exactness: a wall is the plane through the edge's two input points a, b and the point
  // c = a + n, where n is the face's exact normal rounded to double, scaled by a power of two to
  // a largest component in [1/32, 1/16) and rounded to a multiple of 2^-60 (in the units where
  // the mesh lies within [-1, 1]^3); c is rounded to double. The wall thus holds the edge exactly
  // and is within 2e-14 radians of the exact perpendicular (c - a is within 4e-16 of n, of length
  // at least 1/32), and every predicate on it is exact, as on the faces' planes. A boundary edge
  // whose face has no area (dropped: Warning::Kind::DegenerateFacesDropped) gets no wall. The
  // walls count as planes in Stats (distinct_planes, active_planes), not as input faces. Like any
  // open mesh, the surface (without its walls) is certified not to cross or touch itself by the
  // exact contact test (Error::SelfIntersection).
  Perpendicular = 1,
};
const char* open_boundary_name(OpenBoundary o);  // "clip", "perpendicular" (CLI --open, JS `open`)

const char* error_name(Error e);             // "OPEN_MESH", ...
const char* kernel_type_name(KernelType t);  // "POLYHEDRON", ...

// ---------------------------------------------------------------------------------------------
// Input. A non-owning view; the arrays must outlive the call.
struct MeshView {
  const double* positions = nullptr;  // xyz, 3 * num_vertices
  size_t num_vertices = 0;
  const uint32_t* indices = nullptr;  // concatenated face loops
  size_t num_indices = 0;
  const uint32_t* face_sizes = nullptr;  // nullptr = triangles (num_indices / 3 faces)
  size_t num_faces = 0;                  // used only when face_sizes != nullptr
};

// An owning mesh (what the readers in io.h return).
struct Mesh {
  std::vector<double> positions;     // xyz
  std::vector<uint32_t> indices;     // concatenated face loops
  std::vector<uint32_t> face_sizes;  // empty = all triangles
  size_t num_vertices() const { return positions.size() / 3; }
  size_t num_faces() const { return face_sizes.empty() ? indices.size() / 3 : face_sizes.size(); }
  MeshView view() const;
};

// ---------------------------------------------------------------------------------------------
// Streaming. Events arrive in the order KerGen's additive tracing discovers the kernel: the start
// vertex (the LP vertex, Kernel::kernel_point) first, then breadth-first (with Options::from, the
// vertex nearest to `from` first): a Vertex event when a vertex is found, an Edge event when an
// edge to it is traced, then one Face event per facet. Every prefix describes a subset of the
// kernel's boundary (each reported vertex is an exact kernel vertex, each edge a whole kernel
// edge, between vertices reported before it), and ids index the result's arrays.
//
// Cost: asking for steps never changes the algorithm. The kernel is computed by the same fast path
// (culling, incremental cuts) as without a callback, and the events are then replayed from its
// vertex graph in tracing order: O(V + E) more, plus the callbacks. The result's arrays are
// numbered in event order (without steps, the same kernel may come numbered otherwise).
//
// Stopping (the callback returns false, or Options::max_steps events were emitted):
// complete = false. Stopped at a Vertex or Edge event, the result holds exactly the vertices
// and edges reported so far, under their event ids, and the facets whose edges close among them
// (not announced), with volume 0. Stopped at a Face event, the kernel is whole (every facet is
// in the result, the later ones not announced). A stopped run costs what the whole run costs:
// the kernel was complete before the first event.
struct StepEvent {
  enum class Kind : uint8_t { Vertex, Edge, Face };
  Kind kind = Kind::Vertex;
  uint32_t id = 0;                   // index into Kernel::vertices / edges / faces of the result
  uint32_t a = 0, b = 0;             // Edge: endpoint vertex ids
  std::array<double, 3> position{};  // Vertex: coordinates
  const uint32_t* loop = nullptr;    // Face: vertex ids, CCW from outside (valid during the call)
  uint32_t loop_size = 0;
};
// Return false to stop; the result then holds the partial kernel reported so far (see above).
using StepCallback = std::function<bool(const StepEvent&)>;

// Progress of a long run, for a UI: called once as each phase of compute_kernel begins, in this
// order (phases that do not run are skipped: a rejected mesh stops after Validating, a non-star
// one after Lp). `count` is what the phase works on.
struct Progress {
  enum class Phase : uint8_t {
    Validating,  // count = input faces
    Planes,      // count = faces left after zero-area ones are dropped
    Lp,          // count = distinct planes
    Tracing,     // count = distinct planes
    Assembling,  // count = kernel vertices found
  };
  Phase phase = Phase::Validating;
  size_t count = 0;
};
using ProgressCallback = std::function<void(const Progress&)>;
const char* progress_phase_name(Progress::Phase p);  // "validating", "planes", "lp", "tracing", "assembling"

// Every field is reachable from the CLI (docs/cli.md) and from the JS package (its options, in
// camelCase), except on_step and on_progress in the CLI, which prints one result per mesh
// (--max-steps stops the stream there), and max_faces / max_vertices there too (its readers
// refuse what they cannot hold).
struct Options {
  // Start the trace at the kernel vertex extreme towards this point (seen from the mesh's centre)
  // and expand the vertex nearest to it first, so the kernel grows around it.
  bool has_from = false;
  std::array<double, 3> from{};
  StepCallback on_step;           // optional
  ProgressCallback on_progress;   // optional
  uint64_t max_steps = 0;         // stop after this many events (0 = no limit)
  bool allow_open = false;        // accept meshes with holes: result may be Unbounded
  bool deepest_point = false;     // also compute the centre of the largest inscribed ball
  uint64_t seed = 0x4b6572476e;   // LP constraint order (the kernel does not depend on it; an
                                  // empty kernel's witness_faces, one minimal set, may)
  size_t max_faces = 20'000'000;  // larger inputs get Error::TooLarge instead of exhausting memory
  size_t max_vertices = 20'000'000;
  // Large closed meshes: drop the faces whose planes cannot reach the kernel (they hold the
  // kernel of a sample of faces strictly) before coplanar faces are merged into planes. The
  // kernel is the same either way; off, Stats::distinct_planes counts the planes of every face.
  bool cull_faces = true;
  // Merge vertices closer than `weld` (Euclidean distance, in the input's units; with
  // weld_relative, in units of the input's bounding box diagonal) before validation, so that a
  // triangle soup (an unindexed STL, a three.js geometry) or a mesh whose seams were written
  // with slightly different coordinates becomes the closed surface it describes. Vertices merge
  // transitively (a chain of close vertices becomes one), each group into its lowest-indexed
  // vertex, whose input position it keeps (no coordinate is computed: exactness downstream is
  // unaffected); faces left with fewer than three distinct corners are dropped. Reported as
  // Warning::Kind::VerticesWelded. Negative (the default): off; 0: only vertices at exactly the
  // same position. An input with non-finite coordinates, indices out of range or faces of fewer
  // than three corners is not welded: validation reports that as given.
  double weld = -1;
  bool weld_relative = false;
  // Repair what leaves a well-defined solid refused, before validation (reported as warnings with
  // counts): vertices are welded (within `weld` when it is set, else at equal positions), faces
  // repeating another's corner cycle are removed (copies: one is kept; a pair of opposite
  // orientations: both go), and T-junctions are split (a vertex lying exactly inside an edge
  // that one face uses, whose neighbours use its two halves, is inserted into that face's loop).
  // What is still open or non-manifold afterwards is refused as before.
  bool repair = false;
  // How an open mesh's kernel is bounded (see OpenBoundary); Perpendicular accepts open meshes
  // without allow_open. Closed meshes are not affected.
  OpenBoundary open_boundary = OpenBoundary::Clip;
  // Turn every face over (reverse its loop) before anything else. For an open surface given
  // inside out (Warning::Kind::FacesPointInward), which is never turned over by itself; a closed
  // surface is oriented by its volume either way.
  bool flip_faces = false;
};

// How each front end names an Options field, for messages that suggest one: the library's
// messages say `Options::<field>`, and the CLI and the JS package put their own words in its
// place (a flag, or a JS option as it would be written; nullptr: that front end has none).
struct OptionName {
  const char* field;  // "allow_open"
  const char* cli;    // "--allow-open"
  const char* js;     // "allowOpen: true"
};
const std::vector<OptionName>& option_names();

struct Warning {
  enum class Kind : int {
    OrientationFlipped,      // faces were clockwise seen from outside; the mesh was flipped
    DegenerateFacesDropped,  // zero-area faces (exactly collinear vertices) were ignored
    NonPlanarFacesSplit,     // polygons whose vertices are not coplanar were split into triangles
    UnusedVertices,          // vertices not referenced by any face
    VerticesWelded,          // Options::weld merged vertices (count) and dropped collapsed faces
    DuplicateFacesRemoved,   // Options::repair removed copies of faces
    CancellingFacesRemoved,  // Options::repair removed pairs of faces of opposite orientation
    TJunctionsSplit,         // Options::repair inserted vertices lying on edges into their faces
    SeparateShells,          // a closed mesh of several pieces that neither cross nor touch (count):
                             // disjoint solids or a solid with a void, whose kernel is empty
    FacesPointInward,        // an open surface (accepted) whose faces point inward: closed over its
                             // holes (each capped by a fan from its centroid) it encloses a negative
                             // volume; kept as given (an open surface is never flipped), see
                             // Options::flip_faces. count = input faces
    CrossingsUnchecked,      // a polygon face is not a simple polygon in its plane, so the exact test
                             // that the surface does not cross itself (where the kernel has no point
                             // inside it, see Error::SelfIntersection) could not run: not certified
  };
  Kind kind;
  size_t count;
  std::string message;
};

// Its name in SCREAMING_SNAKE_CASE ("ORIENTATION_FLIPPED", ...), as the CLI's JSON and the JS
// package's `warnings[].kind` give it.
const char* warning_kind_name(Warning::Kind k);

struct Stats {
  size_t input_vertices = 0;
  size_t input_faces = 0;
  size_t dropped_faces = 0;  // zero-area faces
  size_t culled_faces = 0;   // faces dropped before planes are merged: their planes cannot reach the kernel
  size_t distinct_planes =
      0;  // after merging the other faces' coplanar planes (a plane used from both sides counts twice)
  size_t active_planes = 0;  // planes left after culling (those that can touch the kernel)
  size_t traced_lines = 0;
  size_t exact_fallbacks = 0;  // predicate evaluations the floating-point filter could not decide (the
                               // search for an empty kernel's witness not counted)
  double ms_validate = 0, ms_planes = 0, ms_lp = 0, ms_trace = 0, ms_assemble = 0, ms_total = 0;
};

// The fields of Stats by name (snake_case, as declared) and value, in declaration order: what
// serializers (the JS package's `stats`) list instead of naming each field again.
struct StatsField {
  const char* name;
  double value;
};
std::array<StatsField, 14> stats_fields(const Stats& s);

// The witness of an empty kernel (Kernel::witness_faces, KernelPoint::witness_faces, and with
// OpenBoundary::Perpendicular witness_boundary_edges): at most four half-spaces, the inner sides
// of faces and of boundary walls, that have no common point, so that no point sees all of those
// faces from the inside and lies inside those walls. By Helly's theorem four suffice in 3D; the
// set is minimal (each one is needed), found from the LP's infeasible constraints and checked
// with exact arithmetic before it is given (Farkas weights: a positive combination of the plane
// equations that is positive everywhere). One face per plane: the lowest-indexed face lying in it
// with the same inner side (a wall only when no face does).
//   Faces: indices of the faces given in the MeshView, also with Options::weld and repair (the
// plane is then that of the welded, repaired face); a non-planar polygon split into triangles
// (Warning::Kind::NonPlanarFacesSplit) is named for its triangles' planes, once even if two of
// them are in the set. Separate pieces (Warning::Kind::SeparateShells) get one too.
//   Walls (OpenBoundary::Perpendicular): each named by the boundary edge it stands on, as the
// input vertex ids (a, b) in the order its face's loop runs from a to b (after weld and repair:
// the ids of the vertices kept), pairs in increasing order of their face.
//   Empty when the kernel is not empty, and when no set of faces and walls alone shows it: for
// an open mesh (allow_open or walls), half-spaces that meet only outside the box the kernel is
// clipped to (a bowl whose faces face its centre, walled: they meet far below it); and, in
// theory, planes that meet only beyond ~2^100 times the mesh's size. Computed only for an empty
// kernel (no cost otherwise).

// Kernel::face_sources values that name no input face: a face of the box that clips an
// Unbounded kernel, and a face lying on a boundary wall of OpenBoundary::Perpendicular (on no
// input face's plane).
constexpr int32_t kFaceSourceBox = -1;
constexpr int32_t kFaceSourceWall = -2;

// The result arrays come in one canonical order, so that the same mesh gives the same arrays
// whatever order the computation found the kernel in (a different seed, culling on or off,
// Options::from, another algorithm or version):
//   vertices: in lexicographic order of their coordinates (x, then y, then z; vertices that
//     round to the same doubles in the order of their exact coordinates);
//   edges: (low, high) vertex id pairs, in increasing order;
//   faces: each loop starts at its lowest vertex id (and runs CCW from outside), the loops in
//     increasing lexicographic order of their vertex ids; triangles: each face's fan from its
//     first corner, in face order; face_sources follows the faces;
//   volume and area: summed in that order, from each vertex's coordinates to ~1e-30 relative;
//     their last bits can still depend on which three planes a vertex was found on (the low
//     parts of its coordinates are not rounded canonically): over the shared test meshes they
//     were equal to the last bit between seeds, culling, `from` and algorithm versions.
// With Options::on_step or max_steps, vertices and edges instead keep the numbering and
// orientation of the step events (the order the trace discovered them); the faces are still
// sorted as above, by the vertices' canonical order, and volume and area are the same as without
// steps. kernel_point (an LP vertex) and stats are not part of this order and may change; so may
// an empty kernel's witness_faces with Options::seed (any minimal set; the same for the same seed).
struct Kernel {
  Error error = Error::Ok;
  std::string message;  // human-readable reason when error != Ok
  KernelType type = KernelType::Empty;
  bool complete = true;  // false when stopped early by on_step / max_steps

  std::vector<double> vertices;        // xyz, 3 * V
  std::vector<uint32_t> edges;         // vertex id pairs, 2 * E
  std::vector<uint32_t> face_indices;  // concatenated convex polygon loops, CCW from outside
  std::vector<uint32_t> face_sizes;    // one per face
  std::vector<uint32_t> triangles;     // the faces fan-triangulated, 3 * T (ready for rendering)

  double volume = 0;        // kernel volume (0 unless Polyhedron and complete)
  double area = 0;          // kernel surface area (Polygon: the polygon's area)
  double shape_volume = 0;  // volume enclosed by the input mesh; for an open mesh, by the surface
                            // closed over its holes, each capped by a fan from its centroid
                            // (negative when its faces point inward: Warning::Kind::FacesPointInward)
  double volume_ratio = 0;  // volume / shape_volume; 0 for an open mesh, whose kernel may reach
                            // beyond the caps of its holes (a wall leaning outward)

  // What bounds the kernel: for each face (in face order; with a stopped run, each face
  // reported), the input face whose plane it lies on, with the same inner side: the lowest index
  // among the faces of that oriented plane (a face seen from the other side, as a flat kernel's
  // opposite faces are, does not count). Indices and planes as for witness_faces below (with
  // weld and repair, the welded, repaired face's plane; a split non-planar polygon, for its
  // triangles' planes). kFaceSourceBox for a face of the clipping box (Unbounded), and
  // kFaceSourceWall for a face lying on a boundary wall's plane only. A Polygon's one face: its
  // plane's; Empty, Point and Segment kernels have no faces. (Found with the planes: no cost.)
  std::vector<int32_t> face_sources;

  // Why the kernel is Empty (see the witness above): input face indices, increasing, and the
  // boundary walls in the conflict as the edges they stand on, (a, b) vertex id pairs, 2 * W.
  std::vector<uint32_t> witness_faces;
  std::vector<uint32_t> witness_boundary_edges;

  // The LP vertex (a kernel vertex; for a convex solid, answered without the LP, the vertex the
  // LP would have ended on: extreme in its direction); false when Empty.
  bool has_kernel_point = false;
  std::array<double, 3> kernel_point{};
  bool has_deepest_point = false;  // with Options::deepest_point and a full-dimensional kernel
  std::array<double, 3> deepest_point{};
  double inscribed_radius = 0;

  std::vector<Warning> warnings;
  Stats stats;

  size_t num_vertices() const { return vertices.size() / 3; }
  size_t num_edges() const { return edges.size() / 2; }
  size_t num_faces() const { return face_sizes.size(); }
  bool ok() const { return error == Error::Ok; }
};

// Computes the kernel. Never throws for bad input: check `error` / `message`.
Kernel compute_kernel(const MeshView& mesh, const Options& options = {});

// Emptiness test and one kernel point: validation + planes + one LP (expected O(N)). A yes is
// certified like compute_kernel's answers: by an exact test that no two faces meet away from the
// vertices and edges they share (expected O(N) too, over a grid; Error::SelfIntersection when two
// do). A no needs no certificate: no point sees every face from its inner side.
struct KernelPoint {
  Error error = Error::Ok;
  std::string message;
  bool star_shaped = false;                      // kernel non-empty
  std::array<double, 3> point{};                 // a kernel vertex (when star_shaped)
  std::vector<uint32_t> witness_faces;           // when not star_shaped: why (the witness above),
  std::vector<uint32_t> witness_boundary_edges;  // its walls: (a, b) vertex id pairs
  std::vector<Warning> warnings;
};
KernelPoint find_kernel_point(const MeshView& mesh, const Options& options = {});

// Validation only (what compute_kernel checks first).
struct Validation {
  Error error = Error::Ok;
  std::string message;
  std::vector<Warning> warnings;
  double volume = 0;  // enclosed volume after any orientation fix
};
Validation validate_mesh(const MeshView& mesh, const Options& options = {});

// The mesh compute_kernel validates: the input after Options::weld and Options::repair (as they
// are set in `options`), for saving what a kernel was computed on (io.h writes it). Faces keep
// their orientation as given (validation may still flip the whole mesh: that is a warning here
// too) and their corners (polygons are not split); vertices no face uses (the merged ones and any
// the input had) are left out, the others keep their input order and coordinates.
struct RepairedMesh {
  Error error = Error::Ok;        // validation's verdict on the repaired mesh, as compute_kernel gives it
  std::string message;            // (Ok, OpenMesh when still open, ...)
  Mesh mesh;                      // filled whatever the verdict; empty when the input is malformed
                                  // (indices out of range, non-finite coordinates, faces too small)
  std::vector<Warning> warnings;  // what weld and repair did (with counts), then validation's
  bool ok() const { return error == Error::Ok; }
};
RepairedMesh repair_mesh(const MeshView& mesh, const Options& options);

}  // namespace kergen
