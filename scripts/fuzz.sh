#!/usr/bin/env bash
# Builds the libFuzzer targets (clang++, ASan + UBSan) and runs each for SECONDS (default 60),
# one after the other, then prints executions and crashes per target.
#   bash scripts/fuzz.sh [SECONDS] [TARGET...]
# Environment: KERGEN_FUZZ_JOBS=2 runs two targets at a time (default 1; the machine is shared),
# KERGEN_FUZZ_BUILD (default build-fuzz), KERGEN_SHARED_MESHES (default ../shared/meshes).
# Seed corpus: fuzz/corpus/<target>/ (gitignored), made at run time from the shared fixtures (and
# turned prisms with large polygon caps from bench/turned_meshes.mjs) and kept between runs
# (libFuzzer adds what it finds). Crash inputs and logs: fuzz/corpus/crashes/ (also gitignored);
# reproduce with build-fuzz/fuzz/<target> <file>.
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_PER_TARGET=${1:-60}
shift || true
TARGETS=("$@")
[ ${#TARGETS[@]} -gt 0 ] || TARGETS=(fuzz_off fuzz_obj fuzz_stl_ascii fuzz_stl_binary fuzz_ply fuzz_kernel fuzz_batch fuzz_small_path fuzz_vtu fuzz_vtk_legacy fuzz_node_ele)
BUILD=${KERGEN_FUZZ_BUILD:-build-fuzz}
SHARED=${KERGEN_SHARED_MESHES:-../shared/meshes}
JOBS=${KERGEN_FUZZ_JOBS:-1}

command -v clang++ >/dev/null || { echo "fuzz: clang++ not found (apt-get install clang)" >&2; exit 1; }
if ! ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a >/dev/null 2>&1; then
  echo "fuzz: libFuzzer runtime missing (apt-get install libclang-rt-14-dev)" >&2; exit 1
fi
cmake -S . -B "$BUILD" -DCMAKE_CXX_COMPILER=clang++ -DKERGEN_BUILD_FUZZERS=ON -DKERGEN_BUILD_TESTS=OFF -DKERGEN_BUILD_BENCH=OFF -DKERGEN_BUILD_EXAMPLES=OFF >/dev/null
cmake --build "$BUILD" -j2 --target "${TARGETS[@]}" fuzz_make_seeds >/dev/null

mkdir -p fuzz/corpus fuzz/corpus/crashes
# Seeds with large non-planar polygon faces (turned prisms over 150- to 300-corner gear, star and
# spiral caps) for the validation's polygon split, when node is there to write them.
GENERATED=()
if command -v node >/dev/null; then
  GEN_DIR=$(mktemp -d)
  trap 'rm -rf "$GEN_DIR"' EXIT
  node bench/turned_meshes.mjs "$GEN_DIR" --gear 150 --star 200 --spiral 300 >/dev/null
  GENERATED=("$GEN_DIR"/*.off)
fi
if [ -d "$SHARED/fixtures" ]; then
  shopt -s nullglob
  "$BUILD/fuzz/fuzz_make_seeds" fuzz/corpus "$SHARED"/fixtures/*.{off,obj,stl,ply} "$SHARED"/fixtures/formats/* "$SHARED"/fixtures/bad/*.stl "${GENERATED[@]}"
  shopt -u nullglob
else
  echo "fuzz: $SHARED/fixtures not found: fuzzing without the shared seed meshes" >&2
  "$BUILD/fuzz/fuzz_make_seeds" fuzz/corpus "${GENERATED[@]}"
fi

run_one() {
  local t=$1
  mkdir -p "fuzz/corpus/$t" "fuzz/corpus/crashes/$t"
  # Fork mode with -ignore_*: keeps fuzzing after a crash, so one run reports every crash it finds.
  nice -n 10 "$BUILD/fuzz/$t" "fuzz/corpus/$t" -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
    -max_total_time="$SECONDS_PER_TARGET" -max_len=65536 -timeout=20 -rss_limit_mb=2048 \
    -artifact_prefix="fuzz/corpus/crashes/$t/" >"fuzz/corpus/crashes/$t.log" 2>&1 || true
}

running=0
for t in "${TARGETS[@]}"; do
  run_one "$t" &
  running=$((running + 1))
  if [ "$running" -ge "$JOBS" ]; then wait -n || true; running=$((running - 1)); fi
done
wait || true

printf '%-16s %12s %8s %8s  %s\n' target executions exec/s crashes corpus
status=0
for t in "${TARGETS[@]}"; do
  log="fuzz/corpus/crashes/$t.log"
  # fork mode's progress lines: "#<execs>: cov: ... exec/s: <rate> oom/timeout/crash: ..."
  last=$(grep -E '^#[0-9]+: cov' "$log" | tail -1 || true)
  execs=$(sed -E 's/^#([0-9]+):.*/\1/' <<<"$last")
  rate=$(sed -nE 's/.*exec\/s:? ([0-9]+).*/\1/p' <<<"$last")
  crashes=$(find "fuzz/corpus/crashes/$t" -type f \( -name 'crash-*' -o -name 'timeout-*' -o -name 'oom-*' -o -name 'leak-*' \) | wc -l)
  corpus=$(find "fuzz/corpus/$t" -type f | wc -l)
  printf '%-16s %12s %8s %8s  %s\n' "$t" "${execs:-?}" "${rate:-?}" "$crashes" "$corpus files"
  [ "$crashes" -eq 0 ] || status=1
done
[ $status -eq 0 ] || echo "fuzz: crash inputs in fuzz/corpus/crashes/<target>/ (logs: fuzz/corpus/crashes/<target>.log)"
exit $status
