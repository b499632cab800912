#!/usr/bin/env bash
# Native tests under AddressSanitizer + LeakSanitizer + UndefinedBehaviorSanitizer, then a
# valgrind memcheck pass over a subset (the kergen CLI on a few fixtures and the core gtest binary
# with a filter that keeps it to a few minutes) using an optimized build with debug info.
#   bash scripts/sanitize.sh            both passes
#   bash scripts/sanitize.sh asan       sanitizers only
#   bash scripts/sanitize.sh valgrind   valgrind only
# Build folders: build-asan (KERGEN_SANITIZE=ON), build-vg (RelWithDebInfo). Exit status 1 on any
# sanitizer report, test failure or valgrind error.
set -euo pipefail
cd "$(dirname "$0")/.."
WHAT=${1:-all}
SHARED=${KERGEN_SHARED_MESHES:-../shared/meshes}
status=0

if [ "$WHAT" = all ] || [ "$WHAT" = asan ]; then
  echo "== ASan + LSan + UBSan build (build-asan)"
  cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DKERGEN_SANITIZE=ON >/dev/null
  nice cmake --build build-asan -j2 --target kergen kergen_tests >/dev/null
  echo "== ctest under sanitizers (-LE long)"
  export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  # Only the core gtest binary (the CGAL oracle and benchmarks are not instrumented here).
  if ! nice ctest --test-dir build-asan -L core -LE long -j2 --timeout 600 --output-on-failure >build-asan/ctest.log 2>&1; then
    status=1
    grep -E "FAILED|ERROR: (Address|Leak)Sanitizer|runtime error" build-asan/ctest.log | head -40 || true
  fi
  tail -3 build-asan/ctest.log
  if [ -d "$SHARED/fixtures" ]; then
    echo "== kergen CLI under sanitizers on every shared fixture"
    set +e
    nice build-asan/kergen --json "$SHARED"/fixtures "$SHARED"/fixtures/bad "$SHARED"/fixtures/formats >build-asan/cli.jsonl 2>build-asan/cli.err
    rc=$?
    set -e
    if [ $rc -gt 1 ] || grep -qE "Sanitizer|runtime error" build-asan/cli.err; then
      status=1; grep -E "Sanitizer|runtime error" build-asan/cli.err | head -20
    fi
    echo "   $(wc -l <build-asan/cli.jsonl) meshes, exit $rc (1 = some inputs rejected, as expected)"
  fi
fi

if [ "$WHAT" = all ] || [ "$WHAT" = valgrind ]; then
  command -v valgrind >/dev/null || { echo "sanitize: valgrind not found (apt-get install valgrind)" >&2; exit 1; }
  echo "== valgrind memcheck (build-vg, RelWithDebInfo)"
  cmake -S . -B build-vg -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
  nice cmake --build build-vg -j2 --target kergen kergen_tests >/dev/null
  VG=(valgrind --tool=memcheck --leak-check=full --show-leak-kinds=definite,indirect,possible --errors-for-leak-kinds=definite,indirect,possible --error-exitcode=99 --quiet)
  files=()
  for f in fixtures/cube.off fixtures/star.off fixtures/cross.off fixtures/u.off fixtures/open_cube.off fixtures/sphere.stl \
           fixtures/bad/issue1580-back-to-back.stl fixtures/bad/invalidvertex.stl fixtures/formats/box.obj princeton/350.off; do
    [ -f "$SHARED/$f" ] && files+=("$SHARED/$f")
  done
  if [ ${#files[@]} -gt 0 ]; then
    set +e
    nice "${VG[@]}" build-vg/kergen --json --deepest "${files[@]}" >build-vg/cli.jsonl 2>build-vg/cli-valgrind.log
    rc=$?
    set -e
    if [ $rc -eq 99 ]; then status=1; echo "   valgrind errors in the CLI run:"; head -40 build-vg/cli-valgrind.log; fi
    echo "   CLI on ${#files[@]} files: exit $rc ($( [ $rc -eq 99 ] && echo 'valgrind errors' || echo 'no valgrind errors'))"
  else
    echo "   shared meshes not found: CLI pass skipped"
  fi
  FILTER=${KERGEN_VALGRIND_FILTER:-'BadInput*:Table/BadInput.*:Regression*:Kernel.*:Io*:Lp*:Exact*-*Shared*:*Princeton*'}
  set +e
  nice "${VG[@]}" build-vg/kergen_tests --gtest_filter="$FILTER" >build-vg/gtest.log 2>build-vg/gtest-valgrind.log
  rc=$?
  set -e
  tail -3 build-vg/gtest.log
  if [ $rc -ne 0 ]; then status=1; echo "   valgrind/gtest exit $rc"; head -40 build-vg/gtest-valgrind.log; fi
  echo "   gtest ($FILTER): exit $rc"
fi
exit $status
