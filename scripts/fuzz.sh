#!/usr/bin/env bash
# Fuzzes the glTF loader and scene conversion (tests/fuzz/fuzz_loader.cpp) and image decoding
# alone (tests/fuzz/fuzz_images.cpp) with libFuzzer, ASan and UBSan.
#   scripts/fuzz.sh [SECONDS] [both|loader|images]
# SECONDS: default 60 (scripts/test.sh, on CI, runs 30); with `both` (the default) the loader gets
# three quarters of it and the image decoder the rest (60 -> 45 + 15); e.g. `600 loader` locally.
# 0 only builds the targets and writes the seeds (to reproduce a finding).
# Configures a separate clang build in build-fuzz/ (-DMB_FUZZ=ON) and builds only the fuzz
# targets and the seed writer. The loader starts from the committed seed corpus
# (tests/fuzz/seeds/loader: varied files from tests/fuzz/seed_corpus_scenes.h), the regressions,
# and the run-time seeds fuzz_seeds writes (built-in scenes, hostile catalogue); the image
# decoder from tests/fuzz/seeds/images. New inputs grow build-fuzz/fuzz-corpus{,-images}/ across
# runs. Exit 0 when nothing was found. A finding is saved under build-fuzz/fuzz-artifacts/:
# reproduce it with
#   build-fuzz/tests/fuzz/fuzz_loader build-fuzz/fuzz-artifacts/crash-...   (or fuzz_images)
# then copy it to tests/fuzz/regressions/ (replayed by test_scene_fuzz_regressions) and fix it.
# Environment: MB_FUZZ_BUILD (build dir), MB_FUZZ_JOBS (build jobs, default nproc; one fuzzing
# process), MB_FUZZ_ARGS (extra libFuzzer flags).
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
build_unity_or_alone "$BUILD" --target fuzz_loader fuzz_images fuzz_seeds -j "$JOBS"

SEEDS=$BUILD/fuzz-seeds
ARTIFACTS=$BUILD/fuzz-artifacts
rm -rf "$SEEDS"
mkdir -p "$BUILD/fuzz-corpus" "$BUILD/fuzz-corpus-images" "$ARTIFACTS"
ASAN_OPTIONS=detect_leaks=0 "$BUILD/tests/fuzz/fuzz_seeds" "$SEEDS"
[ "$BUDGET" -eq 0 ] && { echo "fuzz.sh: built; seeds in $SEEDS"; exit 0; }

LOADER_S=$BUDGET IMAGES_S=0
if [ "$WHICH" = both ]; then LOADER_S=$((BUDGET * 3 / 4)) IMAGES_S=$((BUDGET - BUDGET * 3 / 4)); fi
if [ "$WHICH" = images ]; then LOADER_S=0 IMAGES_S=$BUDGET; fi

# fuzz NAME SECONDS LOG CORPUS...: one libFuzzer run; its exit status.
# -rss_limit_mb / -malloc_limit_mb: a single allocation above 512 MiB, or 2 GiB resident, is a
# finding (hostile counts must not allocate). -timeout: one input may take at most 10 s.
# Inputs are capped at 1 MiB (the largest built-in scene is below that).
fuzz() {
  local name=$1 seconds=$2 log=$3 dict=()
  shift 3
  [ "$name" = fuzz_loader ] && dict=(-dict=tests/fuzz/gltf.dict)
  echo "fuzz.sh: $name for ${seconds}s (corpus $1, findings in $ARTIFACTS/)"
  set +e
  "$BUILD/tests/fuzz/$name" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=512 \
    -max_len=1048576 "${dict[@]}" -artifact_prefix="$ARTIFACTS/" -print_final_stats=1 ${MB_FUZZ_ARGS:-} \
    "$@" 2>&1 | tee "$log" | grep -v "^#[0-9]*.*\(NEW\|REDUCE\|pulse\)"
  local rc=${PIPESTATUS[0]}
  set -e
  grep -E "INITED|stat::number_of_executed_units|stat::peak_rss_mb|Done [0-9]+ runs" "$log" || true
  return "$rc"
}

rc=0
if [ "$LOADER_S" -gt 0 ]; then
  fuzz fuzz_loader "$LOADER_S" "$BUILD/fuzz.log" "$BUILD/fuzz-corpus" tests/fuzz/seeds/loader "$SEEDS" tests/fuzz/regressions \
    || { rc=$?; echo "fuzz.sh: FINDING in fuzz_loader (exit $rc); input saved in $ARTIFACTS/ -- see $BUILD/fuzz.log" >&2; }
fi
if [ "$rc" -eq 0 ] && [ "$IMAGES_S" -gt 0 ]; then
  fuzz fuzz_images "$IMAGES_S" "$BUILD/fuzz-images.log" "$BUILD/fuzz-corpus-images" tests/fuzz/seeds/images tests/fuzz/regressions/images \
    || { rc=$?; echo "fuzz.sh: FINDING in fuzz_images (exit $rc); input saved in $ARTIFACTS/ -- see $BUILD/fuzz-images.log" >&2; }
fi
[ "$rc" -ne 0 ] && exit 1
echo "fuzz.sh: no finding in ${BUDGET}s ($WHICH)"
