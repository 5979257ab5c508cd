#!/usr/bin/env bash
# Fuzzes the glTF loader and scene conversion (tests/fuzz/fuzz_loader.cpp) and image decoding
# alone (tests/fuzz/fuzz_images.cpp) with libFuzzer, ASan and UBSan.
#   scripts/fuzz.sh [SECONDS] [both|loader|images]
# SECONDS: default 60 (scripts/test.sh, on CI, runs 30); with `both` (the default) the loader and
# the image decoder fuzz side by side, each for the whole SECONDS (one core each: the run ends
# SECONDS after the build, not twice that); e.g. `600 loader` locally.
# 0 only builds the targets and writes the seeds (to reproduce a finding).
# Configures a separate clang build in build-fuzz/ (-DMB_FUZZ=ON) and builds only the fuzz
# targets and, unless MB_FUZZ_SEEDS_EXE names one, the seed writer. The loader starts from the
# committed seed corpus (tests/fuzz/seeds/loader: varied files from seed_corpus_scenes.cpp), the
# regressions, and the run-time seeds fuzz_seeds writes (built-in scenes, hostile catalogue); the
# image decoder from tests/fuzz/seeds/images. New inputs grow build-fuzz/fuzz-corpus{,-images}/
# across runs. Exit 0 when nothing was found. A finding is saved under build-fuzz/fuzz-artifacts/:
# reproduce it with
#   build-fuzz/tests/fuzz/fuzz_loader build-fuzz/fuzz-artifacts/crash-...   (or fuzz_images)
# then copy it to tests/fuzz/regressions/ (replayed by test_scene_fuzz_regressions) and fix it.
# Environment: MB_FUZZ_BUILD (build dir), MB_FUZZ_JOBS (build jobs, default nproc; one process
# per fuzzer), MB_FUZZ_ARGS (extra libFuzzer flags), MB_FUZZ_SEEDS_EXE (a fuzz_seeds already
# built: scripts/test.sh hands over build/tests/fuzz/fuzz_seeds, which its gcc build links from
# objects it compiles anyway; the seeds are the same bytes, the seed writer is not fuzzed, and
# the clang build then compiles only the two fuzzers).
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=scripts/build_fallback.sh
. scripts/build_fallback.sh

BUDGET=${1:-60}
WHICH=${2:-both}
case "$BUDGET" in '' | *[!0-9]*) echo "fuzz.sh: SECONDS must be a whole number, got '$BUDGET'" >&2; exit 2 ;; esac
case "$WHICH" in both | loader | images) ;; *) echo "fuzz.sh: target must be both, loader or images, got '$WHICH'" >&2; exit 2 ;; esac
BUILD=${MB_FUZZ_BUILD:-build-fuzz}
JOBS=${MB_FUZZ_JOBS:-$(nproc)}

command -v clang++ >/dev/null || { echo "fuzz.sh: clang++ not found (scripts/setup.sh installs clang)" >&2; exit 2; }
if [ ! -f "$BUILD/CMakeCache.txt" ]; then
  mkdir -p "$BUILD"
  GENERATOR=()
  command -v ninja > /dev/null && GENERATOR=(-G Ninja)
  CC=clang CXX=clang++ cmake -S . -B "$BUILD" "${GENERATOR[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMB_FUZZ=ON -DMB_UNITY=ON >"$BUILD/configure.log" 2>&1 \
    || { cat "$BUILD/configure.log" >&2; exit 2; }
fi
TARGETS=(fuzz_loader fuzz_images)
SEED_WRITER=${MB_FUZZ_SEEDS_EXE:-}
if [ -n "$SEED_WRITER" ]; then
  [ -x "$SEED_WRITER" ] || { echo "fuzz.sh: MB_FUZZ_SEEDS_EXE=$SEED_WRITER is not an executable" >&2; exit 2; }
else
  TARGETS+=(fuzz_seeds)
  SEED_WRITER=$BUILD/tests/fuzz/fuzz_seeds
fi
build_unity_or_alone "$BUILD" --target "${TARGETS[@]}" -j "$JOBS"

SEEDS=$BUILD/fuzz-seeds
ARTIFACTS=$BUILD/fuzz-artifacts
rm -rf "$SEEDS"
mkdir -p "$BUILD/fuzz-corpus" "$BUILD/fuzz-corpus-images" "$ARTIFACTS"
ASAN_OPTIONS=detect_leaks=0 "$SEED_WRITER" "$SEEDS"
[ "$BUDGET" -eq 0 ] && { echo "fuzz.sh: built; seeds in $SEEDS"; exit 0; }

LOADER_S=0 IMAGES_S=0
[ "$WHICH" != images ] && LOADER_S=$BUDGET
[ "$WHICH" != loader ] && IMAGES_S=$BUDGET

# fuzz NAME SECONDS LOG CORPUS...: one libFuzzer run, its output in LOG; its exit status.
# -rss_limit_mb / -malloc_limit_mb: a single allocation above 512 MiB, or 2 GiB resident, is a
# finding (hostile counts must not allocate). -timeout: one input may take at most 10 s.
# Inputs are capped at 1 MiB (the largest built-in scene is below that).
fuzz() {
  local name=$1 seconds=$2 log=$3 dict=()
  shift 3
  [ "$name" = fuzz_loader ] && dict=(-dict=tests/fuzz/gltf.dict)
  "$BUILD/tests/fuzz/$name" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=512 \
    -max_len=1048576 "${dict[@]}" -artifact_prefix="$ARTIFACTS/" -print_final_stats=1 ${MB_FUZZ_ARGS:-} \
    "$@" > "$log" 2>&1
}

# report NAME LOG STATUS: the run's output without the per-input lines, its summary lines, and
# the finding's message when STATUS is not 0. Printed after both runs, one run at a time.
report() {
  local name=$1 log=$2 status=$3
  grep -v "^#[0-9]*.*\(NEW\|REDUCE\|pulse\)" "$log" || true
  grep -E "INITED|stat::number_of_executed_units|stat::peak_rss_mb|Done [0-9]+ runs" "$log" || true
  [ "$status" -eq 0 ] || echo "fuzz.sh: FINDING in $name (exit $status); input saved in $ARTIFACTS/ -- see $log" >&2
}

LOADER_LOG=$BUILD/fuzz.log IMAGES_LOG=$BUILD/fuzz-images.log
loader_pid="" images_pid="" loader_rc=0 images_rc=0
if [ "$LOADER_S" -gt 0 ]; then
  echo "fuzz.sh: fuzz_loader for ${LOADER_S}s (corpus $BUILD/fuzz-corpus, findings in $ARTIFACTS/)"
  fuzz fuzz_loader "$LOADER_S" "$LOADER_LOG" "$BUILD/fuzz-corpus" tests/fuzz/seeds/loader "$SEEDS" tests/fuzz/regressions &
  loader_pid=$!
fi
if [ "$IMAGES_S" -gt 0 ]; then
  echo "fuzz.sh: fuzz_images for ${IMAGES_S}s (corpus $BUILD/fuzz-corpus-images, findings in $ARTIFACTS/)"
  fuzz fuzz_images "$IMAGES_S" "$IMAGES_LOG" "$BUILD/fuzz-corpus-images" tests/fuzz/seeds/images tests/fuzz/regressions/images &
  images_pid=$!
fi
# A finding in one fuzzer does not stop the other: both logs are reported.
if [ -n "$loader_pid" ]; then wait "$loader_pid" || loader_rc=$?; fi
if [ -n "$images_pid" ]; then wait "$images_pid" || images_rc=$?; fi
[ -n "$loader_pid" ] && report fuzz_loader "$LOADER_LOG" "$loader_rc"
[ -n "$images_pid" ] && report fuzz_images "$IMAGES_LOG" "$images_rc"
[ "$loader_rc" -ne 0 ] || [ "$images_rc" -ne 0 ] && exit 1
echo "fuzz.sh: no finding in ${BUDGET}s ($WHICH)"
