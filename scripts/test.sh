#!/usr/bin/env bash
# The test command: installs packages, configures, builds and runs the whole test suite.
#   scripts/test.sh              Release-ish build in build/, all tests
#   scripts/test.sh --sanitize   ASan+UBSan build in build-asan/, all tests
# The default run then fuzzes the loader and the image decoder for 30 s (scripts/fuzz.sh, its
# own clang build in build-fuzz/); MB_SKIP_FUZZ=1 skips that step.
set -euo pipefail
cd "$(dirname "$0")/.."

BUILD=build
SANITIZE=0
# MB_QUICK_BUILD: -O1 without debug info, about 40 % less build time on CI's 2 cores (CMakeLists.txt
# says why the results are the same).
CMAKE_ARGS=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DMB_QUICK_BUILD=ON)
for a in "$@"; do
  case "$a" in
    --sanitize) BUILD=build-asan; SANITIZE=1; CMAKE_ARGS+=(-DMB_SANITIZE=ON -DMB_QUICK_BUILD=OFF) ;;
    *) echo "test.sh: unknown option $a" >&2; exit 2 ;;
  esac
done

scripts/setup.sh
if [ "$SANITIZE" = 1 ]; then
  # For the build (gtest discovery runs the test executables) and for ctest. Leaks inside the
  # Mesa/LLVM graphics driver are suppressed by scripts/lsan.supp (driver modules only; see there).
  export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:check_initialization_order=1:strict_init_order=1}
  export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$PWD/scripts/lsan.supp:print_suppressions=0}
  export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
fi
JOBS=$(nproc)
cmake -S . -B "$BUILD" "${CMAKE_ARGS[@]}"
cmake --build "$BUILD" -j "$JOBS"
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
  scripts/fuzz.sh 30  # CI's budget; scripts/fuzz.sh 600 locally for a longer run
fi
