// cells.h — `kergen --cells MESH ...`: the kernel of every cell of a volume mesh (cells.cpp).
#pragma once

// Runs the command when argv holds --cells (its own options; docs/cli.md, "Volume meshes").
// Returns the exit code: 0 every cell computed, 1 some cell refused or the file unreadable,
// 2 usage error.
int run_cells(int argc, char** argv);
