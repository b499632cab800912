// cell_surface.cpp — one cell of a volume mesh as a closed surface (volume.h: cell_surface): its
// vertices renumbered, its faces in the cell's order, turned outward.
//
// Why the faces are turned here: a file's faces need not face out of every cell (a face shared by
// two cells, stored once, faces out of one of them and into the other; some writers list inward
// faces), and compute_kernel only flips a surface as a whole. Faces are made to agree across
// shared edges first (two faces sharing an edge traverse it in opposite directions when they agree),
// then the cell as a whole is turned so that it encloses a positive volume.
#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "kergen/volume.h"
#include "volume/cell_orientation.h"

namespace kergen {

namespace {

std::string cell_prefix(size_t cell) { return "cell " + std::to_string(cell) + ": "; }

// Checks the cell's own entries of the offset arrays and indices (no whole-mesh pass), and
// collects its corners' global vertex ids. Returns false with `out` holding the error.
bool gather_cell(const VolumeMesh& mesh, size_t cell, CellSurface& out, std::vector<uint32_t>& corners) {
  const size_t cells = mesh.num_cells();
  if (cell >= cells) {
    out.error = Error::InvalidArgument;
    out.message = cell_prefix(cell) + "out of range (the mesh has " + std::to_string(cells) + " cells)";
    return false;
  }
  const uint32_t begin = mesh.cell_offsets[cell], end = mesh.cell_offsets[cell + 1];
  if (begin > end || end > mesh.cell_faces.size()) {
    out.error = Error::InvalidArgument;
    out.message = cell_prefix(cell) + "cell_offsets do not describe a range of cell_faces";
    return false;
  }
  const size_t faces = mesh.num_faces();
  corners.clear();
  for (uint32_t k = begin; k < end; ++k) {
    const uint32_t face = mesh.cell_faces[k];
    if (face >= faces) {
      out.error = Error::IndexOutOfRange;
      out.message = cell_prefix(cell) + "face " + std::to_string(face) + " does not exist (the mesh has " +
                    std::to_string(faces) + " faces)";
      return false;
    }
    const uint32_t fb = mesh.face_offsets[face], fe = mesh.face_offsets[face + 1];
    if (fb > fe || fe > mesh.face_indices.size()) {
      out.error = Error::InvalidArgument;
      out.message = cell_prefix(cell) + "face_offsets of face " + std::to_string(face) +
                    " do not describe a range of face_indices";
      return false;
    }
    for (uint32_t i = fb; i < fe; ++i) {
      if (mesh.face_indices[i] >= mesh.num_vertices()) {
        out.error = Error::IndexOutOfRange;
        out.message = cell_prefix(cell) + "face " + std::to_string(face) + " uses vertex " +
                      std::to_string(mesh.face_indices[i]) + ", which does not exist (the mesh has " +
                      std::to_string(mesh.num_vertices()) + " vertices)";
        return false;
      }
      corners.push_back(mesh.face_indices[i]);
    }
  }
  return true;
}

}  // namespace

CellSurface cell_surface(const VolumeMesh& mesh, size_t cell) {
  CellSurface out;
  std::vector<uint32_t> corners;
  if (!gather_cell(mesh, cell, out, corners)) return out;

  // Local vertices: the cell's global ids, sorted (the order the header promises).
  out.global_vertices = corners;
  std::sort(out.global_vertices.begin(), out.global_vertices.end());
  out.global_vertices.erase(std::unique(out.global_vertices.begin(), out.global_vertices.end()),
                            out.global_vertices.end());
  Mesh& m = out.mesh;
  m.positions.resize(3 * out.global_vertices.size());
  for (size_t i = 0; i < out.global_vertices.size(); ++i)
    for (int a = 0; a < 3; ++a) m.positions[3 * i + a] = mesh.positions[3 * size_t(out.global_vertices[i]) + a];

  const uint32_t begin = mesh.cell_offsets[cell], end = mesh.cell_offsets[cell + 1];
  m.indices.reserve(corners.size());
  m.face_sizes.reserve(end - begin);
  for (uint32_t k = begin; k < end; ++k) {
    const uint32_t face = mesh.cell_faces[k];
    const uint32_t fb = mesh.face_offsets[face], fe = mesh.face_offsets[face + 1];
    for (uint32_t i = fb; i < fe; ++i) {
      auto it = std::lower_bound(out.global_vertices.begin(), out.global_vertices.end(), mesh.face_indices[i]);
      m.indices.push_back(static_cast<uint32_t>(it - out.global_vertices.begin()));
    }
    m.face_sizes.push_back(fe - fb);
  }
  out.reoriented = volume::orient_cell_outward(m);
  return out;
}

}  // namespace kergen
