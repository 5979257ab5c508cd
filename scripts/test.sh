#!/usr/bin/env bash
# The test command: installs packages, configures, builds and runs the whole test suite.
#   scripts/test.sh              quick build in build/ (or build/ as it is), all tests
#   scripts/test.sh --sanitize   ASan+UBSan build in build-asan/, all tests
# The default run then fuzzes the loader and the image decoder for 30 s (scripts/fuzz.sh, its
# own clang build in build-fuzz/); MB_SKIP_FUZZ=1 skips that step.
# Progress on stderr: each step with the seconds so far; at the end the seconds of each step.
set -euo pipefail
cd "$(dirname "$0")/.."

BUILD=build
SANITIZE=0
# A fresh build/ is quick (MB_QUICK_BUILD=ON: -O1, no debug information; CMakeLists.txt says why
# the results are the same) and compiles in unity batches (MB_UNITY=ON, cmake/motorbench.cmake). A build/ already configured (scripts/reproduce.sh's -O2 measuring
# build, or an earlier run) is reused as it is: the suite passes on either, and switching the
# folder's flags would compile everything again.
CMAKE_ARGS=()
for a in "$@"; do
  case "$a" in
    --sanitize) BUILD=build-asan; SANITIZE=1 ;;
    *) echo "test.sh: unknown option $a" >&2; exit 2 ;;
  esac
done
if [ "$SANITIZE" = 1 ]; then
  CMAKE_ARGS=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DMB_SANITIZE=ON -DMB_QUICK_BUILD=OFF)
elif [ ! -f "$BUILD/CMakeCache.txt" ]; then
  CMAKE_ARGS=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DMB_QUICK_BUILD=ON -DMB_UNITY=ON)
fi
# A new folder is generated for Ninja when it is there (setup.sh installs it): it starts
# compiling sooner and keeps both cores busy across targets.
if [ ! -f "$BUILD/CMakeCache.txt" ] && command -v ninja > /dev/null; then CMAKE_ARGS+=(-G Ninja); fi

# shellcheck source=scripts/build_fallback.sh
. scripts/build_fallback.sh

start=$(date +%s)
last=$start
TOOK=""
# step NAME: closes the step before (its seconds for the summary) and announces this one.
step() {
  local now
  now=$(date +%s)
  [ -n "${current:-}" ] && TOOK+="$current $((now - last)) s, "
  current=$1 last=$now
  echo "[test $((now - start)) s] $1" >&2
}

step setup
scripts/setup.sh
if [ "$SANITIZE" = 1 ]; then
  # For ctest (and the build's gtest discovery with MB_TEST_PER_CASE=ON). Leaks inside the
  # Mesa/LLVM graphics driver are suppressed by scripts/lsan.supp (driver modules only; see there).
  export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:check_initialization_order=1:strict_init_order=1}
  export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/scripts/lsan.supp:print_suppressions=0}
  export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
fi
JOBS=$(nproc)
step "configure $BUILD/"
cmake -S . -B "$BUILD" "${CMAKE_ARGS[@]}"
step "build"
build_unity_or_alone "$BUILD" -j "$JOBS"
# ctest: one process per room shard (tests/CMakeLists.txt); the longest first (CTest's costs of
# the last run), so the two cores finish together.
step "ctest"
if [ "$SANITIZE" = 0 ]; then
  ctest --test-dir "$BUILD" --output-on-failure -j "$JOBS"
else
  # A test that passed but whose process LeakSanitizer's own exit-time tracer crashed in is run
  # once more (scripts/lsan_tracer_crashes.py says why); any other failure ends the run.
  JUNIT="$PWD/$BUILD/ctest-junit.xml"
  if ! ctest --test-dir "$BUILD" --output-on-failure -j "$JOBS" --output-junit "$JUNIT"; then
    if ! RETRY=$(python3 scripts/lsan_tracer_crashes.py "$JUNIT"); then exit 1; fi
    echo "test.sh: LeakSanitizer's tracer crashed at exit after these tests passed; running them once more:" >&2
    echo "$RETRY" >&2
    ctest --test-dir "$BUILD" --output-on-failure --rerun-failed
  fi
fi
if [ "$SANITIZE" = 0 ] && [ "${MB_SKIP_FUZZ:-0}" != 1 ]; then
  step "fuzz (its own clang build in build-fuzz/, then 30 s)"
  # The seed writer this build linked anyway: the clang build compiles only the fuzzers.
  MB_FUZZ_SEEDS_EXE="$PWD/$BUILD/tests/fuzz/fuzz_seeds" scripts/fuzz.sh 30  # CI's budget; 600 locally
fi
step done
echo "test.sh: passed in $(($(date +%s) - start)) s (${TOOK%, })" >&2
