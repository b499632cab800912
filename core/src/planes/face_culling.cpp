// Face culling (see face_culling.h): the face-sample kernel, then a support test of every face's
// plane against it (culling.h's SupportTest, in vectorized blocks of faces).
#include "planes/face_culling.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "planes/plane_classes.h"
#include "solve/plane_culling.h"
#include "util/compiler_hints.h"

namespace kergen {

namespace {

// The planes of the representative triangles of faces first, ..., first + n - 1 (n <= kFaceBlock),
// or of faces[0], ..., faces[n - 1] when `faces` is given, as structure of arrays: the points are
// gathered first, then approx_plane runs over the block in one vectorized loop (the same
// operations per lane, so the same bounds as one at a time).
constexpr size_t kFaceBlock = 64;
struct FacePlanes {
  double nx[kFaceBlock], ny[kFaceBlock], nz[kFaceBlock], d[kFaceBlock];
  double enx[kFaceBlock], eny[kFaceBlock], enz[kFaceBlock], ed[kFaceBlock];
  PlaneArrays arrays() const { return {nx, ny, nz, d, enx, eny, enz, ed}; }
};

KERGEN_MULTIVERSION
void face_planes(const PreparedMesh& mesh, const uint32_t* faces, uint32_t first, size_t n, FacePlanes& out) {
  double xyz[9][kFaceBlock];
  for (size_t j = 0; j < n; ++j) {
    const auto& r = mesh.rep[faces ? faces[j] : first + uint32_t(j)];
    for (int t = 0; t < 3; ++t) {
      const double* q = mesh.point(r[t]);
      for (int k = 0; k < 3; ++k) xyz[3 * t + k][j] = q[k];
    }
  }
  for (size_t j = 0; j < n; ++j) {
    const double a[3] = {xyz[0][j], xyz[1][j], xyz[2][j]}, b[3] = {xyz[3][j], xyz[4][j], xyz[5][j]},
                 c[3] = {xyz[6][j], xyz[7][j], xyz[8][j]};
    const PlaneCoef<Approx> p = approx_plane(a, b, c);
    out.nx[j] = p.n[0].v;
    out.enx[j] = p.n[0].e;
    out.ny[j] = p.n[1].v;
    out.eny[j] = p.n[1].e;
    out.nz[j] = p.n[2].v;
    out.enz[j] = p.n[2].e;
    out.d[j] = p.d.v;
    out.ed[j] = p.d.e;
  }
}

// The faces whose planes may reach above the face-sample kernel (`sample_kernel`), with the sample's
// own faces, in increasing order; false when more than half the faces may (a convex shape: all of
// them; a finely tessellated flat part of the kernel's boundary): the classes of all faces then
// cost less than those of a renumbered subset. Evenly spread probes tell before the full scan.
// (Out of line, called once: profiles show the scan as one entry.)
[[gnu::noinline]] bool faces_reaching(const PreparedMesh& mesh, const TraceResult& sample_kernel,
                                      const std::vector<uint32_t>& sample, std::vector<uint32_t>& kept) {
  const size_t nf = mesh.num_faces();
  const SupportTest support(sample_kernel, nf, true);
  SupportTest::Scratch scratch;
  FacePlanes block;
  char reaching[kFaceBlock];
  // The probes in blocks too (may_reach_all answers as may_reach would, at a sixth of the cost
  // where the sample kernel has many vertices to climb).
  constexpr size_t kProbes = 256;
  static_assert(kProbes % kFaceBlock == 0, "whole blocks of probes");
  size_t probes_reaching = 0;
  for (size_t first = 0; first < kProbes; first += kFaceBlock) {
    uint32_t probe[kFaceBlock];
    for (size_t j = 0; j < kFaceBlock; ++j) probe[j] = uint32_t(((2 * (first + j) + 1) * nf) / (2 * kProbes));
    face_planes(mesh, probe, 0, kFaceBlock, block);
    support.may_reach_all(block.arrays(), kFaceBlock, scratch, reaching);
    for (size_t j = 0; j < kFaceBlock; ++j) probes_reaching += reaching[j] != 0;
  }
  if (2 * probes_reaching > kProbes) return false;
  kept.reserve(2 * sample.size());
  size_t next_sample = 0;
  for (size_t first = 0; first < nf; first += kFaceBlock) {
    const size_t n = std::min(kFaceBlock, nf - first);
    face_planes(mesh, nullptr, uint32_t(first), n, block);
    support.may_reach_all(block.arrays(), n, scratch, reaching);
    // Runs of faces up to the next sample face (kept whatever the test says) or the block's end.
    for (size_t j = 0;; ++j) {
      const size_t run_end =
          next_sample < sample.size() && sample[next_sample] < first + n ? sample[next_sample] - first : n;
      for (; j < run_end; ++j)
        if (reaching[j]) {
          kept.push_back(uint32_t(first + j));
          if (kept.size() > nf / 2) return false;  // the probes were wrong: not worth it either
        }
      if (j == n) break;
      kept.push_back(uint32_t(first + j));
      ++next_sample;
    }
  }
  return true;
}

}  // namespace

FaceCulling cull_faces(const PreparedMesh& mesh, bool cull, uint64_t seed) {
  FaceCulling out;
  const size_t nf = mesh.num_faces();
  if (mesh.boundary_edges != 0 || nf <= kFaceCullingMinFaces) return out;
  std::vector<uint32_t> sample;
  const size_t k = std::min(nf, size_t(3 * std::sqrt(double(nf))) + 32);
  for (size_t i = 0; i < k; ++i) sample.push_back(uint32_t((i * nf) / k));  // increasing
  PlaneSet sp(&mesh.points, mesh.exact_shift);
  sp.set_extent(mesh.extent());
  std::vector<uint32_t> sample_plane;
  build_planes(mesh, sample, sp, sample_plane);
  std::vector<uint32_t> sample_planes(sp.size()), sample_box;
  for (uint32_t i = 0; i < sp.size(); ++i) sample_planes[i] = i;
  add_bounding_box(sp, sample_box);
  std::vector<uint32_t> lp_planes = sample_planes;
  lp_planes.insert(lp_planes.end(), sample_box.begin(), sample_box.end());
  const auto t_lp = std::chrono::steady_clock::now();
  out.lp = solve_lp(sp, lp_planes, kDefaultDirection, kLpBound, seed);
  out.ms_lp = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t_lp).count();
  if (out.lp.outcome == LpResult::Outcome::Infeasible) {
    out.kernel_empty = true;
    out.lp.vertex = VertexGeom{};  // its cached coordinates live in sp's arenas, gone on return
    return out;
  }
  if (cull && out.lp.outcome == LpResult::Outcome::Optimal) {
    TraceOptions quiet;
    CulledTrace sample_kernel = trace_with_culling(sp, sample_planes, sample_box, out.lp.vertex, quiet, seed);
    if (!sample_kernel.trace.internal_error && sample_kernel.trace.complete && !sample_kernel.trace.vertices.empty())
      out.culled = faces_reaching(mesh, sample_kernel.trace, sample, out.kept_faces);
    if (!out.culled) out.kept_faces.clear();
  }
  out.lp.vertex = VertexGeom{};  // as above: only the outcome and the conflict planes outlive sp
  return out;
}

}  // namespace kergen
