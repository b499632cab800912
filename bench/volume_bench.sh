#!/usr/bin/env bash
# Volume mesh benchmark: builds a 100k-cell agglomerated mesh and times `kergen --cells` on it
# (read + every cell's kernel + write of the -o VTU), with and without --deepest, with --jobs 1 and
# 2: wall time, CPU time (user + system: what the machine's other load does not inflate) and peak
# memory from /usr/bin/time -v, cells per second. Then the "what users do
# today" baseline: meshio reads the mesh, and a loop writes each cell as its own OFF file and runs
# the surface CLI on it (on SUBSET cells, extrapolated to all).
#   bash bench/volume_bench.sh [BUILD_DIR] [MESH] [SUBSET]
# MESH: grid (the L/U cube grid of tests/volume/generators.py, 50 x 50 x 20 blocks = 100,000 cells,
# default) or tetgen (tetgen's tetrahedra of 100,000 random points agglomerated into 2 to 12
# tetrahedra per cell).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
KIND=${2:-grid}
SUBSET=${3:-300}
KERGEN="$BUILD/kergen"
PY=/usr/bin/python3
# KERGEN_BENCH_DIR: a folder kept between runs (its mesh.vtu is reused); else a temporary one.
if [ -n "${KERGEN_BENCH_DIR:-}" ]; then
  WORK=$KERGEN_BENCH_DIR
  mkdir -p "$WORK"
else
  WORK=$(mktemp -d)
  trap 'rm -rf "$WORK"' EXIT
fi

[ -f "$WORK/mesh.vtu" ] || "$PY" - "$WORK" "$KIND" <<'PYEOF'
import os, sys, time
sys.path.insert(0, "tests/volume")
import generators
work, kind = sys.argv[1], sys.argv[2]
t = time.time()
if kind == "grid":
    points, cells, _ = generators.grid_lu(50, 50, 20)
else:
    points, cells, _ = generators.tetgen_agglomerated(work, 100000)
generators.write_vtu(os.path.join(work, "mesh.vtu"), points, cells)
print("mesh: %s, %d cells, %d points, %d faces, written by meshio in %.1f s (%d bytes)" % (
    kind, len(cells), len(points), sum(len(c) for c in cells), time.time() - t, os.path.getsize(os.path.join(work, "mesh.vtu"))))
PYEOF

cells=$("$KERGEN" --cells "$WORK/mesh.vtu" --json --jobs 2 | tail -1 | sed -E 's/.*"cells":([0-9]+).*/\1/')
run() {  # label, args...
  local label=$1
  shift
  /usr/bin/time -v "$KERGEN" --cells "$WORK/mesh.vtu" "$@" -o "$WORK/out.vtu" >"$WORK/out.txt" 2>"$WORK/time.txt" || true
  local wall rss cpu
  wall=$(grep "Elapsed (wall clock)" "$WORK/time.txt" | sed -E 's/.*: //' | awk -F: '{ if (NF == 3) print $1 * 3600 + $2 * 60 + $3; else print $1 * 60 + $2 }')
  rss=$(grep "Maximum resident set size" "$WORK/time.txt" | sed -E 's/.*: //')
  cpu=$(awk -F': ' '/User time|System time/ { s += $2 } END { print s }' "$WORK/time.txt")
  printf '%-24s wall %7.2f s (%7.0f cells/s)  cpu %7.2f s (%7.0f cells/cpu-s)  peak %5.0f MB\n' "$label" "$wall" \
    "$(echo "$cells / $wall" | bc -l)" "$cpu" "$(echo "$cells / $cpu" | bc -l)" "$(echo "$rss / 1024" | bc -l)"
}
echo "kergen --cells (read + kernels + write -o), $cells cells:"
run "--jobs 1" --jobs 1
run "--jobs 2" --jobs 2
run "--jobs 1 --deepest" --jobs 1 --deepest
run "--jobs 2 --deepest" --jobs 2 --deepest

"$PY" - "$WORK" "$KERGEN" "$SUBSET" <<'PYEOF'
import os, subprocess, sys, time
import meshio
sys.path.insert(0, "tests/volume")
import generators
work, kergen, subset = sys.argv[1], sys.argv[2], int(sys.argv[3])
t = time.time()
mesh = meshio.read(os.path.join(work, "mesh.vtu"))
read = time.time() - t
cells = [c for block in mesh.cells for c in block.data]
points = [tuple(p) for p in mesh.points]
step = max(1, len(cells) // subset)
chosen = list(range(0, len(cells), step))[:subset]
t = time.time()
for i in chosen:
    path = os.path.join(work, "cell.off")
    generators.write_cell_off(path, points, [list(f) for f in cells[i]])
    subprocess.run([kergen, path, "--json"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
loop = time.time() - t
per_cell = loop / len(chosen)
print("baseline (meshio + one surface CLI call per cell): meshio.read %.1f s; %d cells in %.1f s, %.1f ms per cell;"
      " all %d cells extrapolated: %.0f s (%.0f cells/s)" % (read, len(chosen), loop, 1000 * per_cell, len(cells),
                                                             read + per_cell * len(cells), 1 / per_cell))
PYEOF
