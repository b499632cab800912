// kergen/volume.h — polyhedral volume meshes: the kernel of every cell, and the regularity numbers
// of the Virtual Element Method (docs/vem.md defines them, with their sources).
//
// A volume mesh is points, polygon faces and cells, each cell a closed set of faces. Every cell's
// result is exactly what compute_kernel (kergen.h) gives for that cell's surface alone
// (cell_surface below): the same kernel, volumes, witness and errors. One bad cell never stops the
// others; it gets its own error. The library starts no thread: compute_cell_kernels takes a range of
// cells, so that a caller runs ranges in parallel (the CLI's --jobs), and a mesh distributed over
// MPI ranks calls it on each rank for that rank's own cells (docs/vem.md shows how).
//
// Files (one grammar each; the CLI and the npm package run these same readers):
//   .vtu  VTK XML UnstructuredGrid: VTK_POLYHEDRON (42) cells (`faces` / `faceoffsets`), and the
//         linear cells tetra (10), hexahedron (12), wedge (13), pyramid (14), turned into their
//         faces; the other cell types are a ParseError naming the type. DataArrays in ascii, binary
//         (base64 inline) or appended (raw or base64), header_type UInt32 or UInt64, little or big
//         endian; compressed data (a `compressor` attribute) is a ParseError saying so.
//   .vtk  legacy VTK ASCII DATASET UNSTRUCTURED_GRID with the same cell types (polyhedra as
//         VTK writes them in CELLS: [n, nfaces, (npts, ids...)...]).
//   .node + .ele  the face-based pair of polyhedral VEM data sets: .node `nv 3 0 0`, then `id x y z`
//         per vertex; .ele `ncells 0`, then per cell `cell-id nfaces`, and per face
//         `face-id nverts vertex-ids...`. Ids may start at 0 or 1 (the .node's first id says which);
//         '#' starts a comment, blank lines are skipped.
// Errors name the file and the line (text) or the byte offset (binary data) and the reason, like
// the surface readers (io.h). A vertex id out of range is a ParseError of the file, naming the cell.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "kergen/kergen.h"

namespace kergen {

// ---------------------------------------------------------------------------------------------
// The mesh. Offsets are CSR style: face f's loop is face_indices[face_offsets[f] ..
// face_offsets[f + 1]), cell c's faces are cell_faces[cell_offsets[c] .. cell_offsets[c + 1]);
// both offset arrays start with 0 and have one entry more than there are faces / cells (or are
// empty when there are none). Faces are kept as the file lists them: a VTU
// polyhedron lists its own faces, so a face shared by two cells is stored twice; each
// orientation is as written (cells are turned outward for the computation, see cell_surface).
struct VolumeMesh {
  std::vector<double> positions;       // xyz, 3 * num_vertices
  std::vector<uint32_t> face_indices;  // concatenated polygon loops (vertex ids)
  std::vector<uint32_t> face_offsets;  // num_faces + 1 entries, face_offsets[0] = 0
  std::vector<uint32_t> cell_faces;    // concatenated face ids of the cells
  std::vector<uint32_t> cell_offsets;  // num_cells + 1 entries, cell_offsets[0] = 0
  size_t num_vertices() const { return positions.size() / 3; }
  size_t num_faces() const { return face_offsets.empty() ? 0 : face_offsets.size() - 1; }
  size_t num_cells() const { return cell_offsets.empty() ? 0 : cell_offsets.size() - 1; }
};

struct VolumeReadResult {
  Error error = Error::Ok;  // Ok, IoError, ParseError, EmptyInput, TooLarge, InvalidArgument
  std::string message;      // "<file>:<line>: <reason>" or "<file>: byte <offset>: <reason>"
  VolumeMesh mesh;
  bool ok() const { return error == Error::Ok; }
};

enum class VolumeFormat { Unknown, Vtu, VtkLegacy, NodeEle };
// By extension, case-insensitive: .vtu, .vtk, and .node or .ele for the pair.
VolumeFormat volume_format_from_path(const std::string& path);
// By content: "<?xml" / "<VTKFile" → Vtu, "# vtk DataFile" → VtkLegacy, else Unknown (a .node or
// .ele file alone cannot be told from content).
VolumeFormat detect_volume_format(std::string_view bytes);

// Parses one file's bytes (Vtu or VtkLegacy; Unknown detects from the content). NodeEle needs two
// files: this returns InvalidArgument for it (use read_node_ele). `name` is used in messages.
VolumeReadResult read_volume_mesh(std::string_view bytes, VolumeFormat format, const std::string& name = "<memory>");
VolumeReadResult read_vtu(std::string_view bytes, const std::string& name = "<memory>");
VolumeReadResult read_vtk_legacy(std::string_view bytes, const std::string& name = "<memory>");
VolumeReadResult read_node_ele(std::string_view node_text, std::string_view ele_text,
                               const std::string& node_name = "<node>", const std::string& ele_name = "<ele>");
// Reads a file, the format from its extension (then from its content). For the pair, give either
// the .node or the .ele path: the other is the same path with the other extension.
VolumeReadResult read_volume_mesh_file(const std::string& path, size_t max_bytes = SIZE_MAX);  // 0 = no limit

// ---------------------------------------------------------------------------------------------
// One cell as a surface mesh: what compute_cell_kernels computes each cell's kernel on.
//   Vertices: the cell's vertices only, in increasing global id (global_vertices[i] is the id
//     in the VolumeMesh of local vertex i).
//   Faces: the cell's faces in the cell's order (local face i is the cell's i-th face, global id
//     cell_faces[cell_offsets[cell] + i]), always with face_sizes.
//   Orientation: faces are turned to agree with their neighbours across shared edges (a face
//     that traverses an edge in the same direction as its neighbour is reversed, starting from the
//     cell's first face), then the whole cell is reversed if its enclosed volume is negative, so
//     faces are counter-clockwise seen from outside whatever the file says. `reoriented` says
//     whether any face was reversed. Where the faces do not pair up (an open or non-manifold cell)
//     they are left as they are and compute_kernel reports it (Error::OpenMesh, NonManifoldEdge).
//   error: IndexOutOfRange when the cell names a face or a face names a vertex that does not
//     exist, InvalidArgument when `cell` is out of range or the offsets are malformed; the message
//     names the cell.
struct CellSurface {
  Error error = Error::Ok;
  std::string message;
  Mesh mesh;
  std::vector<uint32_t> global_vertices;
  bool reoriented = false;
  bool ok() const { return error == Error::Ok; }
};
CellSurface cell_surface(const VolumeMesh& mesh, size_t cell);

// ---------------------------------------------------------------------------------------------
// Per-cell results.
struct CellOptions {
  // Also the inscribed ball of each kernel (Options::deepest_point): its centre, radius rho and
  // rho / h. Costs a bisection over exact LPs per cell (several times the kernel itself).
  bool deepest_point = false;
  // Called after every `progress_every` cells of the range and once at its end, with the number
  // of cells of the range done so far (from the calling thread, for a progress bar).
  std::function<void(size_t cells_done, size_t cells_total)> on_progress;
  size_t progress_every = 1000;
};

struct CellKernel {
  // Ok, or why this cell has no kernel: the error compute_kernel gives for its surface (OpenMesh
  // for a cell whose faces do not close, NonManifoldEdge, InconsistentOrientation when its faces
  // cannot be oriented, DegenerateInput, ...), or cell_surface's IndexOutOfRange. The message
  // starts with "cell <index>: " and is compute_kernel's without its advice about Options fields
  // (vertex ids in it are the cell's local ids, cell_surface's numbering).
  Error error = Error::Ok;
  std::string message;
  KernelType type = KernelType::Empty;  // when error == Ok
  double kernel_volume = 0;             // Kernel::volume (0 unless Polyhedron)
  double cell_volume = 0;               // the volume the cell encloses (Kernel::shape_volume; 0 on error)
  double kernel_ratio = 0;              // kernel_volume / cell_volume (Kernel::volume_ratio; 1 for a convex cell)
  double diameter = 0;                  // h: the largest distance between two of the cell's vertices (also on error)
  // With CellOptions::deepest_point and a full-dimensional kernel: the centre of the largest ball
  // inside the kernel and its radius rho (the cell is star-shaped with respect to that ball).
  bool has_deepest_point = false;
  std::array<double, 3> deepest_point{};
  double inscribed_radius = 0;  // rho (0 without a full-dimensional kernel)
  double rho_over_h = 0;        // inscribed_radius / diameter
  // An Empty kernel's witness (kergen.h: Kernel::witness_faces): at most four faces whose inner
  // half-spaces have no common point. Local: indices into the cell's faces (cell_surface's face
  // order); global: the same faces as face ids of the VolumeMesh.
  std::vector<uint32_t> witness_faces;
  std::vector<uint32_t> witness_global_faces;
  bool reoriented = false;        // cell_surface reversed faces, or compute_kernel flipped the cell
  std::vector<Warning> warnings;  // compute_kernel's warnings for the cell (OrientationFlipped omitted)
  bool ok() const { return error == Error::Ok; }
};

// The status code of a cell for files and arrays (the CLI's -o VTU `kernel_status`, the npm
// package's status array): the KernelType value (0 Empty ... 5 Unbounded) when the cell's error
// is Ok, else minus the Error value (-5 OpenMesh, ...).
int32_t cell_status_code(const CellKernel& cell);

struct CellKernels {
  // Ok, or InvalidArgument when the range starts past the mesh's end or its cells' entries of
  // cell_offsets are malformed (no cell computed). Errors of single cells (a face or vertex that
  // does not exist, malformed face offsets: cell_surface's errors) are in their records, not here.
  Error error = Error::Ok;
  std::string message;
  std::vector<CellKernel> cells;  // cells[i] is cell first_cell + i
  // Warning::Kind::OrientationFlipped with the count of reoriented cells, when there are any.
  std::vector<Warning> warnings;
  bool ok() const { return error == Error::Ok; }
};

// The kernel of cells first_cell .. first_cell + count - 1 (count is clipped to the mesh's end;
// SIZE_MAX = all the rest), one at a time, each exactly compute_kernel(cell_surface(mesh, c))
// (computed through one KernelBatch per call, batch.h, whose results are compute_kernel's).
// Never throws for bad input. Safe to call from several threads at once on the same mesh.
CellKernels compute_cell_kernels(const VolumeMesh& mesh, const CellOptions& options = {}, size_t first_cell = 0,
                                 size_t count = SIZE_MAX);

// What a run says about the mesh as a whole. Ratios and rho/h are taken over the cells whose
// error is Ok (rho/h once any cell has a deepest point: has_rho_over_h; an Ok cell without one,
// whose kernel is empty or flat, counts as 0); the median of an even count is the lower middle
// value (a value of some cell, not an average).
struct CellSummary {
  size_t cells = 0;
  size_t ok_cells = 0;
  std::array<size_t, 6> by_type{};                 // indexed by KernelType value (Ok cells)
  std::vector<std::pair<Error, size_t>> by_error;  // errors present, in Error order
  size_t reoriented_cells = 0;
  double min_ratio = 0, median_ratio = 0, max_ratio = 0;
  bool has_rho_over_h = false;
  double min_rho_over_h = 0, median_rho_over_h = 0, max_rho_over_h = 0;
  // Up to `worst` Ok cells with the smallest rho/h (the smallest kernel_ratio without deepest
  // points), worst first, ties by cell index. Indices are cell_base + position in `cells`.
  std::vector<size_t> worst_cells;
};
CellSummary summarize_cells(const std::vector<CellKernel>& cells, size_t worst = 10, size_t cell_base = 0);

// ---------------------------------------------------------------------------------------------
// The mesh as a VTK XML UnstructuredGrid for ParaView: every cell a VTK_POLYHEDRON with its faces
// as stored, arrays appended as raw little-endian binary (header_type UInt64, every double kept
// exactly), and CellData arrays kernel_status (Int32, cell_status_code) and Float64
// kernel_volume, cell_volume, kernel_ratio, inscribed_radius, rho_over_h (0 for a cell without a
// deepest point: no --deepest, or an empty or flat kernel) and diameter. A cell with an error has
// NaN in the Float64 arrays (diameter too when it could not be measured). `cells` holds one record
// per cell (cells.size() == mesh.num_cells()); otherwise, or when a cell names a face or vertex
// that does not exist, std::invalid_argument (the _file form: InvalidArgument with `message`).
std::string write_vtu_with_cell_data(const VolumeMesh& mesh, const std::vector<CellKernel>& cells);
Error write_vtu_with_cell_data_file(const std::string& path, const VolumeMesh& mesh,
                                    const std::vector<CellKernel>& cells, std::string* message = nullptr);

}  // namespace kergen
