// kergen_bench --streaming: what an on_step callback costs (see bench/README.md).
#pragma once

#include <string>
#include <vector>

namespace kergen_bench {

// One row per mesh: compute_kernel with default options against the same with an on_step
// callback that counts the events, median of `runs` each, a side stopping after one run longer
// than budget_ms, the callback stopping a run at cap_ms (the row then gives lower bounds). Without `files`: two generated near-convex spheres (40k and 200k triangles),
// refinements/vase6, refinements/spiral6 and princeton/325 from `meshes`. `json_context` is
// put into every JSON object (compiler, load). Returns the exit code.
int run_streaming_rows(const std::string& meshes, const std::vector<std::string>& files, int runs, double budget_ms,
                       double cap_ms, bool json, const std::string& json_context);

}  // namespace kergen_bench
