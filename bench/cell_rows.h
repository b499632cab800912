// kergen_bench --cells: polyhedral cells per second, single calls against a KernelBatch (see
// bench/README.md).
#pragma once

#include <string>
#include <vector>

namespace kergen_bench {

// One row per folder of cells (default: the four polyhedra sets of `meshes`): every mesh file is
// read once, computed once untimed (warm-up), then `runs` rounds each time the whole folder with
// single compute_kernel calls and with one KernelBatch computing into one reused Kernel, in
// alternation; the row gives the median round per cell (µs of the thread's CPU time) and cells per
// second of both.
// Returns the exit code.
int run_cell_rows(const std::string& meshes, const std::vector<std::string>& folders, int runs, bool json,
                  const std::string& json_context);

}  // namespace kergen_bench
