// summary.cpp — what a run of compute_cell_kernels says about the mesh as a whole (volume.h:
// summarize_cells): counts by kernel type and by error, the spread of the kernel ratio and of
// rho / h, the worst cells.
#include <algorithm>
#include <map>
#include <vector>

#include "kergen/volume.h"

namespace kergen {

namespace {

// min, lower median, max of a non-empty list (sorted in place).
void spread(std::vector<double>& values, double& lo, double& mid, double& hi) {
  if (values.empty()) return;
  std::sort(values.begin(), values.end());
  lo = values.front();
  mid = values[(values.size() - 1) / 2];
  hi = values.back();
}

}  // namespace

CellSummary summarize_cells(const std::vector<CellKernel>& cells, size_t worst, size_t cell_base) {
  CellSummary s;
  s.cells = cells.size();
  std::map<Error, size_t> errors;
  std::vector<double> ratios, rho_h;
  for (const CellKernel& c : cells) {
    s.reoriented_cells += c.reoriented;
    if (!c.ok()) {
      ++errors[c.error];
      continue;
    }
    ++s.ok_cells;
    ++s.by_type[static_cast<size_t>(c.type)];
    ratios.push_back(c.kernel_ratio);
    s.has_rho_over_h = s.has_rho_over_h || c.has_deepest_point;
  }
  s.by_error.assign(errors.begin(), errors.end());
  // rho / h over every Ok cell once any has a deepest point (cells without a full-dimensional
  // kernel count as 0: no ball fits).
  if (s.has_rho_over_h)
    for (const CellKernel& c : cells)
      if (c.ok()) rho_h.push_back(c.rho_over_h);
  spread(ratios, s.min_ratio, s.median_ratio, s.max_ratio);
  spread(rho_h, s.min_rho_over_h, s.median_rho_over_h, s.max_rho_over_h);

  std::vector<size_t> order;
  for (size_t i = 0; i < cells.size(); ++i)
    if (cells[i].ok()) order.push_back(i);
  const bool by_rho = s.has_rho_over_h;
  auto key = [&](size_t i) { return by_rho ? cells[i].rho_over_h : cells[i].kernel_ratio; };
  const size_t n = std::min(worst, order.size());
  std::partial_sort(order.begin(), order.begin() + n, order.end(),
                    [&](size_t a, size_t b) { return key(a) < key(b) || (key(a) == key(b) && a < b); });
  for (size_t i = 0; i < n; ++i) s.worst_cells.push_back(cell_base + order[i]);
  return s;
}

}  // namespace kergen
