#!/usr/bin/env bash
# Fuzzes the glTF loader and scene conversion with libFuzzer (tests/fuzz/fuzz_loader.cpp).
#   scripts/fuzz.sh [SECONDS]     default 60 (what scripts/test.sh runs on CI); e.g. 600 locally
# Configures a separate clang build in build-fuzz/ (-DMB_FUZZ=ON), builds only the fuzz target
# and the seed writer, writes the seed corpus (built-in scenes + hostile catalogue), then fuzzes
# for SECONDS, growing build-fuzz/fuzz-corpus/ across runs. Exit 0 when nothing was found.
# A finding is saved under build-fuzz/fuzz-artifacts/: reproduce it with
#   build-fuzz/tests/fuzz/fuzz_loader build-fuzz/fuzz-artifacts/crash-...
# then copy it to tests/fuzz/regressions/ (replayed by test_scene_fuzz_regressions) and fix it.
# Environment: MB_FUZZ_BUILD (build dir), MB_FUZZ_JOBS (build and fuzz jobs, default 1 fuzzing
# process), MB_FUZZ_ARGS (extra libFuzzer flags).
set -euo pipefail
cd "$(dirname "$0")/.."

BUDGET=${1:-60}
case "$BUDGET" in '' | *[!0-9]*) echo "fuzz.sh: SECONDS must be a whole number, got '$BUDGET'" >&2; exit 2 ;; esac
BUILD=${MB_FUZZ_BUILD:-build-fuzz}
JOBS=${MB_FUZZ_JOBS:-$(nproc)}

command -v clang++ >/dev/null || { echo "fuzz.sh: clang++ not found (scripts/setup.sh installs clang)" >&2; exit 2; }
if [ ! -f "$BUILD/CMakeCache.txt" ]; then
  mkdir -p "$BUILD"
  CC=clang CXX=clang++ cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMB_FUZZ=ON >"$BUILD/configure.log" 2>&1 \
    || { cat "$BUILD/configure.log" >&2; exit 2; }
fi
cmake --build "$BUILD" --target fuzz_loader fuzz_seeds -j "$JOBS"

SEEDS=$BUILD/fuzz-seeds
CORPUS=$BUILD/fuzz-corpus
ARTIFACTS=$BUILD/fuzz-artifacts
rm -rf "$SEEDS"
mkdir -p "$CORPUS" "$ARTIFACTS"
ASAN_OPTIONS=detect_leaks=0 "$BUILD/tests/fuzz/fuzz_seeds" "$SEEDS"

# -rss_limit_mb / -malloc_limit_mb: a single allocation above 512 MiB, or 2 GiB resident, is a
# finding (hostile counts must not allocate). -timeout: one input may take at most 10 s.
# Inputs are capped at 1 MiB (the largest built-in scene is below that).
echo "fuzz.sh: fuzzing for ${BUDGET}s (corpus $CORPUS, findings in $ARTIFACTS/)"
set +e
"$BUILD/tests/fuzz/fuzz_loader" -max_total_time="$BUDGET" -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=512 \
  -max_len=1048576 -dict=tests/fuzz/gltf.dict -artifact_prefix="$ARTIFACTS/" -print_final_stats=1 ${MB_FUZZ_ARGS:-} \
  "$CORPUS" "$SEEDS" tests/fuzz/regressions 2>&1 | tee "$BUILD/fuzz.log" | grep -v "^#[0-9]*.*\(NEW\|REDUCE\|pulse\)"
rc=${PIPESTATUS[0]}
set -e
grep -E "stat::number_of_executed_units|stat::peak_rss_mb|Done [0-9]+ runs" "$BUILD/fuzz.log" || true
if [ "$rc" -ne 0 ]; then
  echo "fuzz.sh: FINDING (exit $rc); input saved in $ARTIFACTS/ -- see $BUILD/fuzz.log" >&2
  exit 1
fi
echo "fuzz.sh: no finding in ${BUDGET}s"
