#!/usr/bin/env bash
# examples/cpp-consumer built the two ways CMake users take the library, each run on analytic cases:
#   (a) this checkout configured, built and installed to a temporary prefix (Release, library +
#       CLI only), the consumer built against it with find_package(kergen CONFIG REQUIRED);
#   (b) the consumer built with FetchContent of this checkout (no install, no network);
#   (c) the consumer built with FetchContent's GIT_REPOSITORY (this checkout's repository, as a
#       file:// URL) and GIT_TAG (its HEAD commit): the snippet of the README, with values that work
#       (skipped when the checkout is not a git repository).
# Every configure runs with GoogleTest, CGAL, Google Benchmark and Qhull disabled
# (CMAKE_DISABLE_FIND_PACKAGE_*: a find_package(... REQUIRED) of them would fail the configure,
# a QUIET one would find nothing), and the configures' traces show no find_package of them at all:
# neither way needs more than a C++17 compiler.
# (b) also sets the parent's CMAKE_CXX_FLAGS_RELEASE to -O2 and checks from the compile commands
# that kergen does not override it and that its exactness flags stay on its own sources.
#   bash tests/cmake/consumer.sh SOURCE_DIR WORK_DIR [CMAKE] [CXX_COMPILER] [SHARED_MESHES]
# Run by ctest as `cpp_consumer` (label consumer); WORK_DIR is emptied first.
set -euo pipefail
SRC=$(cd "$1" && pwd)
WORK=$2
CMAKE=${3:-cmake}
CXX=${4:-c++}
SHARED=${5:-$SRC/../shared/meshes}
START=$(date +%s)

fail() {
  echo "consumer: FAIL: $*" >&2
  exit 1
}
rm -rf "$WORK"
mkdir -p "$WORK"
WORK=$(cd "$WORK" && pwd)

COMMON=(-DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_COMPILER=$CXX"
  -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON -DCMAKE_DISABLE_FIND_PACKAGE_CGAL=ON
  -DCMAKE_DISABLE_FIND_PACKAGE_benchmark=ON -DCMAKE_DISABLE_FIND_PACKAGE_Qhull=ON)

# The L-shaped prism of examples/api_example.cpp as an OFF file: the L (0,0)-(2,0)-(2,1)-(1,1)-
# (1,2)-(0,2) over z in [0, 1]; its kernel is the unit cube [0,1]^3 (8 vertices, volume 1).
cat >"$WORK/l_prism.off" <<'END'
OFF
12 8 0
0 0 0
2 0 0
2 1 0
1 1 0
1 2 0
0 2 0
0 0 1
2 0 1
2 1 1
1 1 1
1 2 1
0 2 1
6 5 4 3 2 1 0
6 6 7 8 9 10 11
4 0 1 7 6
4 1 2 8 7
4 2 3 9 8
4 3 4 10 9
4 4 5 11 10
4 5 0 6 11
END

# run_consumer LABEL BINARY: the built-in cube [-1,1]^3 (volume 8), the L prism (volume 1) and,
# when the shared meshes are there, fixtures/cube.off (the cube [-1,1]^3 as 12 triangles).
run_consumer() {
  local label=$1 bin=$2 got
  expect() {
    got=$("$bin" "$@") || fail "$label: kernel_info $* exited with an error"
    [ "$got" = "$want" ] || fail "$label: kernel_info $*: expected '$want', got '$got'"
  }
  want=$'type: POLYHEDRON\nvertices: 8\nvolume: 8'
  expect
  want=$'type: POLYHEDRON\nvertices: 8\nvolume: 1'
  expect "$WORK/l_prism.off"
  local cases="built-in cube: volume 8; l_prism.off: volume 1"
  if [ -f "$SHARED/fixtures/cube.off" ]; then
    want=$'type: POLYHEDRON\nvertices: 8\nvolume: 8'
    expect "$SHARED/fixtures/cube.off"
    cases+="; fixtures/cube.off: volume 8"
  fi
  echo "consumer: $label: $cases (8 kernel vertices each, POLYHEDRON)"
}

# The command line of FILE in BUILD's compile_commands.json (one "command" line before each "file").
compile_command() {
  grep -B1 "\"file\": \".*$2\"" "$1/compile_commands.json" | head -1
}

# The configure's trace (--trace-redirect) shows no find_package of a test or benchmark
# dependency at all, not even a QUIET one.
no_lookups() {
  if grep -E "find_package\( *(GTest|CGAL|benchmark|Qhull)[ )]" "$1"; then
    fail "$2 looked up a test or benchmark dependency (above)"
  fi
}

# ---- (a) installed, find_package ----------------------------------------------------------
echo "consumer: (a) build and install kergen to $WORK/prefix"
"$CMAKE" -S "$SRC" -B "$WORK/kergen-build" "${COMMON[@]}" -DKERGEN_BUILD_TESTS=OFF -DKERGEN_BUILD_BENCH=OFF \
  -DKERGEN_BUILD_EXAMPLES=OFF --trace-redirect="$WORK/kergen-build.trace" >"$WORK/kergen-configure.log" || fail "configure of kergen (see $WORK/kergen-configure.log)"
"$CMAKE" --build "$WORK/kergen-build" -j2 >"$WORK/kergen-build.log" || fail "build of kergen (see $WORK/kergen-build.log)"
"$CMAKE" --install "$WORK/kergen-build" --prefix "$WORK/prefix" >"$WORK/kergen-install.log"
no_lookups "$WORK/kergen-build.trace" "the library build"
(cd "$WORK/prefix" && find . -type f | sort) >"$WORK/installed.txt"
for f in include/kergen/kergen.h include/kergen/io.h bin/kergen; do
  [ -f "$WORK/prefix/$f" ] || fail "not installed: $f"
done
for f in libkergen.a cmake/kergen/kergenConfig.cmake cmake/kergen/kergenConfigVersion.cmake cmake/kergen/kergenTargets.cmake; do
  grep -q "/$f\$" "$WORK/installed.txt" || fail "not installed: <libdir>/$f"
done
echo "consumer: installed $(wc -l <"$WORK/installed.txt") files: $(tr '\n' ' ' <"$WORK/installed.txt")"
"$WORK/prefix/bin/kergen" "$WORK/l_prism.off" >"$WORK/cli.txt" || fail "the installed CLI failed on l_prism.off"
grep -qE "^ *volume +1 +\(shape 3," "$WORK/cli.txt" || fail "the installed CLI: expected volume 1 (shape 3): $(cat "$WORK/cli.txt")"

"$CMAKE" -S "$SRC/examples/cpp-consumer" -B "$WORK/consumer-installed" "${COMMON[@]}" \
  "-DCMAKE_PREFIX_PATH=$WORK/prefix" -DCMAKE_EXPORT_COMPILE_COMMANDS=ON >"$WORK/consumer-installed.log" ||
  fail "configure of the consumer with find_package (see $WORK/consumer-installed.log)"
"$CMAKE" --build "$WORK/consumer-installed" -j2 >>"$WORK/consumer-installed.log" ||
  fail "build of the consumer with find_package (see $WORK/consumer-installed.log)"
main=$(compile_command "$WORK/consumer-installed" main.cpp)
[[ "$main" == *"$WORK/prefix/include"* ]] || fail "(a) main.cpp does not use the installed headers: $main"
[[ "$main" != *"$SRC/core"* ]] || fail "(a) main.cpp sees the source tree: $main"
run_consumer "find_package" "$WORK/consumer-installed/kernel_info"

# ---- (b) FetchContent of this checkout ----------------------------------------------------
echo "consumer: (b) FetchContent of $SRC"
"$CMAKE" -S "$SRC/examples/cpp-consumer" -B "$WORK/consumer-fetch" "${COMMON[@]}" -DKERGEN_CONSUMER_FETCH=ON \
  "-DKERGEN_SOURCE_DIR=$SRC" "-DCMAKE_CXX_FLAGS_RELEASE=-O2 -DNDEBUG" -DCMAKE_EXPORT_COMPILE_COMMANDS=ON \
  --trace-redirect="$WORK/consumer-fetch.trace" >"$WORK/consumer-fetch.log" || fail "configure of the consumer with FetchContent (see $WORK/consumer-fetch.log)"
"$CMAKE" --build "$WORK/consumer-fetch" -j2 >>"$WORK/consumer-fetch.log" ||
  fail "build of the consumer with FetchContent (see $WORK/consumer-fetch.log)"
no_lookups "$WORK/consumer-fetch.trace" "FetchContent"
# Only the library was built: no CLI, tests, benchmarks or examples of kergen's.
for t in kergen kergen_tests kernel_dump input_bench api_example; do
  if [ -e "$WORK/consumer-fetch/_deps/kergen-build/$t" ] || [ -e "$WORK/consumer-fetch/_deps/kergen-build/bench/$t" ]; then
    fail "(b) FetchContent built kergen's $t"
  fi
done
main=$(compile_command "$WORK/consumer-fetch" main.cpp)
core=$(compile_command "$WORK/consumer-fetch" core/src/kergen.cpp)
[[ "$main" == *" -O2 "* && "$main" != *"-O3"* ]] || fail "(b) the parent's Release flags were overridden: $main"
[[ "$main" != *"-ffp-contract"* && "$main" != *"-fno-fast-math"* ]] || fail "(b) kergen's private flags reached main.cpp: $main"
[[ "$core" == *"-ffp-contract=off"* && "$core" == *"-fno-fast-math"* && "$core" == *"-std=c++17"* ]] ||
  fail "(b) kergen's exactness flags or -std=c++17 are missing: $core"
[[ "$core" == *" -O2 "* && "$core" != *"-O3"* ]] || fail "(b) kergen's sources do not follow the parent's Release flags: $core"
run_consumer "FetchContent" "$WORK/consumer-fetch/kernel_info"

# ---- (c) FetchContent with GIT_REPOSITORY and GIT_TAG ---------------------------------------
ways="both ways"
if commit=$(git -C "$SRC" rev-parse HEAD 2>/dev/null); then
  echo "consumer: (c) FetchContent GIT_REPOSITORY file://$SRC GIT_TAG $commit"
  "$CMAKE" -S "$SRC/examples/cpp-consumer" -B "$WORK/consumer-git" "${COMMON[@]}" -DKERGEN_CONSUMER_FETCH=ON \
    "-DKERGEN_GIT_REPOSITORY=file://$SRC" "-DKERGEN_GIT_TAG=$commit" >"$WORK/consumer-git.log" 2>&1 ||
    fail "configure of the consumer with GIT_REPOSITORY (see $WORK/consumer-git.log)"
  "$CMAKE" --build "$WORK/consumer-git" -j2 >>"$WORK/consumer-git.log" ||
    fail "build of the consumer with GIT_REPOSITORY (see $WORK/consumer-git.log)"
  got=$(git -C "$WORK/consumer-git/_deps/kergen-src" rev-parse HEAD)
  [ "$got" = "$commit" ] || fail "(c) fetched $got, not $commit"
  run_consumer "FetchContent GIT_TAG" "$WORK/consumer-git/kernel_info"
  ways="all three ways"
else
  echo "consumer: (c) skipped: $SRC is not a git checkout"
fi

echo "consumer: $ways passed in $(($(date +%s) - START)) s"
