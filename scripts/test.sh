#!/usr/bin/env bash
# The test command: installs packages, configures, builds and runs the whole test suite.
#   scripts/test.sh              Release-ish build in build/, all tests
#   scripts/test.sh --sanitize   ASan+UBSan build in build-asan/, all tests
set -euo pipefail
cd "$(dirname "$0")/.."

BUILD=build
CMAKE_ARGS=(-DCMAKE_BUILD_TYPE=RelWithDebInfo)
for a in "$@"; do
  case "$a" in
    --sanitize) BUILD=build-asan; CMAKE_ARGS+=(-DMB_SANITIZE=ON) ;;
    *) echo "test.sh: unknown option $a" >&2; exit 2 ;;
  esac
done

scripts/setup.sh
JOBS=$(nproc)
cmake -S . -B "$BUILD" "${CMAKE_ARGS[@]}"
cmake --build "$BUILD" -j "$JOBS"
ctest --test-dir "$BUILD" --output-on-failure -j "$JOBS"
