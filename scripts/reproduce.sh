#!/usr/bin/env bash
# The main job: installs packages, builds motorbench and measures the built-in scenes into
# results/ (committed): ops.json/.txt (op counts), bench.json/.txt (Google Benchmark kernel
# pairs), report.json/.md/.html + images/ + plots/ (motorbench report: the built-in scenes, the
# curved s3_tiling / h3_tiling included, skinned_tube with its bend and candy_wrapper
# animations), isa.json/.txt (motorbench isa: AMD ISA statistics from RADV's null device),
# morph.json/.txt (motorbench morph), accuracy.json/.txt (motorbench accuracy: handedness rule,
# blend vs slerp, skin volume, quaternion bits, camera drift), claims.md/.json (motorbench
# claims). Budget: under 15 minutes on 2 cores.
#
# Committed inputs (results/inputs.json: each one's source folder, its files' sha256, the commit
# and date that measured it; scripts/committed_inputs.py): figures over corpora a clone does not
# have. Where the folder is present they are measured again and their provenance recorded; where
# it is absent (every user's clone) the committed files are read as they are and never deleted,
# so that a clone's run gives the committed results:
#   corpus/ (+ corpus/accuracy.json)  the report over ../shared/corpus (real glTF files) and the
#                                 skinned-file volumes measured on it (motorbench accuracy --skinned-files)
#   corpus-graph.json             motorbench inspect over ../shared/corpus-graph (~960 scene graphs)
#   morph-corpus-wide.json        motorbench morph over ../shared/corpus-wide's morph files, counted
#                                 into morph.json with morph_torus
#
# Progress on stderr: each step with its number, the seconds so far and an estimate of what is
# left (this machine's last run, build/reproduce-steps.tsv, else the figures of a fresh 2-core
# run). The steps that time nothing (ops, isa, morph, accuracy, inspect) run side by side; a
# timed step (bench, report: frame timing) always runs alone, so nothing else competes for the
# cores it measures on.
set -euo pipefail
cd "$(dirname "$0")/.."
# shellcheck source=scripts/build_fallback.sh
. scripts/build_fallback.sh

# Timed figures need quiet cores: warn now when other work runs. The tools mark each
# figure taken on shared cores (harness/timing/disturbance.h) and keep it out of the verdicts.
read -r load1 _ _ runq _ < /proc/loadavg
if [ "${runq%%/*}" -gt "$(nproc)" ] || awk -v l="$load1" -v n="$(nproc)" 'BEGIN { exit !(l > n) }'; then
  echo "reproduce: WARNING: the machine is busy (load average $load1, ${runq%%/*} runnable threads on $(nproc) cores):" \
    "timed figures will be marked disturbed and left out of the verdicts; run again on a quiet machine" >&2
fi

BUILD=build
MB=$BUILD/harness/motorbench
OUT=results
CORPUS=../shared/corpus
GRAPHS=../shared/corpus-graph
WIDE=../shared/corpus-wide
MORPH_WIDE=$OUT/morph-corpus-wide.json
INPUTS=(python3 scripts/committed_inputs.py)
JOBS=$(nproc)
STEPS=(setup build untimed bench report corpus claims)
# Seconds per step of a fresh clone on a shared 2-core Debian 12 machine (the build
# still with debug information; ops, isa and inspect one after the other; the two reports as
# one 425 s): the estimate until this machine has run the script once.
declare -A EXPECT=([setup]=170 [build]=685 [untimed]=150 [bench]=55 [report]=300 [corpus]=125 [claims]=15)
TIMES=$BUILD/reproduce-steps.tsv
if [ -s "$TIMES" ]; then
  while read -r name secs; do EXPECT[$name]=$secs; done < "$TIMES"
fi
declare -A TOOK=()
start=$(date +%s)
step_start=$start
current=""
done_steps=0

# step NAME TEXT: closes the step before (its seconds kept for the next run's estimate) and
# announces this one with what is left, this step included.
step() {
  local now left=0 s
  now=$(date +%s)
  [ -n "$current" ] && TOOK[$current]=$((now - step_start)) && done_steps=$((done_steps + 1))
  current=$1 step_start=$now
  for s in "${STEPS[@]:$done_steps}"; do left=$((left + ${EXPECT[$s]:-0})); done
  if [ "$left" -ge 120 ]; then left="$(((left + 59) / 60)) min"; else left="$left s"; fi
  echo "[reproduce $((now - start)) s, step $((done_steps + 1))/${#STEPS[@]}, about $left left] $2" >&2
}
finish() {
  local now s
  now=$(date +%s)
  TOOK[$current]=$((now - step_start))
  mkdir -p "$BUILD"
  for s in "${STEPS[@]}"; do [ -n "${TOOK[$s]:-}" ] && echo "$s ${TOOK[$s]}"; done > "$TIMES"
  echo "[reproduce $((now - start)) s] done: $OUT/report.html, $OUT/claims.md; seconds per step:" \
    "$(for s in "${STEPS[@]}"; do printf '%s %s, ' "$s" "${TOOK[$s]:-0}"; done | sed 's/, $//')" >&2
}

step setup "setup (Debian packages)"
scripts/setup.sh >&2
# Each committed input is regenerated where its folder is present, else read: it must be there.
"${INPUTS[@]}" check "$OUT" >&2

step build "configure and build motorbench (-O2, no debug information: the measuring build)"
# Unity batches (MB_UNITY=ON) only for the rooms that time nothing: the code bench and time
# measure is compiled file by file, as before (cmake/motorbench.cmake, MB_MEASURED_DIRS).
# scripts/test.sh reuses this folder as it is; its own fresh build is -O1 (MB_QUICK_BUILD=ON),
# which this step turns back to -O2 (everything is compiled again).
GENERATOR=()
[ ! -f "$BUILD/CMakeCache.txt" ] && command -v ninja > /dev/null && GENERATOR=(-G Ninja)
cmake -S . -B "$BUILD" "${GENERATOR[@]}" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMB_QUICK_BUILD=OFF -DMB_UNITY=ON >&2
build_unity_or_alone "$BUILD" --target motorbench -j "$JOBS" >&2

mkdir -p "$OUT"
# Generated by every run; other files are overwritten. A committed input goes only when its
# source folder is there to measure it again.
rm -rf "$OUT/images" "$OUT/plots"
[ -d "$CORPUS" ] && rm -rf "$OUT/corpus"
[ -d "$GRAPHS" ] && rm -f "$OUT/corpus-graph.json"
[ -d "$WIDE" ] && rm -f "$MORPH_WIDE"

# Untimed: op counts (with the SPIR-V compiles), the AMD ISA statistics and the corpus scene
# graphs, side by side; each writes its own files. A line every 30 s says which are still running.
step untimed "ops -> $OUT/ops.json, isa -> $OUT/isa.json, morph -> $OUT/morph.json, accuracy -> $OUT/accuracy.json, inspect -> $OUT/corpus-graph.json (side by side: none is timed)"
declare -A UNTIMED=()
"$MB" ops --json "$OUT/ops.json" > "$OUT/ops.txt" & UNTIMED[ops]=$!
"$MB" isa --json "$OUT/isa.json" > "$OUT/isa.txt" & UNTIMED[isa]=$!
# The accuracy figures of the built-in scenes (handedness rule, blend vs slerp, candy wrapper,
# quaternion bits, camera drift over 10^6 steps): a few seconds of CPU.
"$MB" accuracy --json "$OUT/accuracy.json" > "$OUT/accuracy.txt" & UNTIMED[accuracy]=$!
# Morph methods' image and byte cost: morph_torus measured now, with corpus-wide's
# morph files: measured into $MORPH_WIDE where that folder is, else its committed figures.
# (Exit 1 of morph or inspect: some file failed, recorded in their JSON with the reason.)
(
  if [ -d "$WIDE" ]; then "$MB" morph "$WIDE" --json "$MORPH_WIDE" > /dev/null || { rc=$?; [ "$rc" -eq 1 ] || exit "$rc"; }; fi
  "$MB" morph morph_torus "$MORPH_WIDE" --json "$OUT/morph.json" > "$OUT/morph.txt"
) & UNTIMED[morph]=$!
# Scene graphs of ~960 real files (meshes stripped; provenance and kind in its MANIFEST.tsv):
# the scale statistics the two corpus claims are judged on.
if [ -d "$GRAPHS" ]; then
  "$MB" inspect "$GRAPHS" --json "$OUT/corpus-graph.json" > /dev/null & UNTIMED[inspect]=$!
else
  echo "reproduce: no $GRAPHS: $OUT/corpus-graph.json is the committed input, read as it is" >&2
fi
failed=""
while [ ${#UNTIMED[@]} -gt 0 ]; do
  sleep 1
  for name in "${!UNTIMED[@]}"; do
    kill -0 "${UNTIMED[$name]}" 2>/dev/null && continue
    rc=0
    wait "${UNTIMED[$name]}" || rc=$?
    { [ "$rc" -eq 0 ] || { [ "$rc" -eq 1 ] && { [ "$name" = inspect ] || [ "$name" = morph ]; }; }; } || failed+=" $name"
    unset "UNTIMED[$name]"
  done
  [ $((($(date +%s) - step_start) % 30)) -eq 0 ] && [ ${#UNTIMED[@]} -gt 0 ] &&
    echo "[reproduce $(($(date +%s) - start)) s] still running: ${!UNTIMED[*]}" >&2
done
[ -n "$failed" ] && { echo "reproduce: failed:$failed" >&2; exit 1; }

step bench "bench: kernel pairs in and out of cache, 3 repetitions -> $OUT/bench.json (timed: alone)"
"$MB" bench --out "$OUT/bench.json" --benchmark_min_time=0.1 --benchmark_repetitions=3 \
  --benchmark_color=false > "$OUT/bench.txt"

step report "report: built-in scenes -> $OUT/report.html (frame timing: alone)"
# skinned_tube also shows candy_wrapper: the half turn where linear blend skinning collapses the
# ring and motor blending keeps it; every other scene its first animation.
"$MB" report -o "$OUT" --bench-json "$OUT/bench.json" --isa-json "$OUT/isa.json" --morph-json "$OUT/morph.json" --jobs "$JOBS" \
  --anim skinned_tube:bend,skinned_tube:candy_wrapper

# Real content apart from the generated scenes (barrel.glb: the paper's normal-mapped case;
# stip.glb: non-uniform scale on an inner node).
if [ -d "$CORPUS" ]; then
  step corpus "report: $CORPUS -> $OUT/corpus/report.html (frame timing: alone)"
  "$MB" report "$CORPUS" -o "$OUT/corpus" --bench-json "$OUT/bench.json" --isa-json "$OUT/isa.json" --jobs "$JOBS"
  # The skin volumes (LBS vs motor) of its skinned files: skinning_volume_file's figures. (Exit 1:
  # a file failed to load, recorded in the JSON with the reason.)
  "$MB" accuracy --skinned-files "$CORPUS" --json "$OUT/corpus/accuracy.json" > /dev/null || { rc=$?; [ "$rc" -eq 1 ] || exit "$rc"; }
else
  step corpus "report: no $CORPUS: $OUT/corpus/ is the committed input, read as it is"
fi

step claims "claims -> $OUT/claims.md (the declared rows judged on the figures above; nothing measured)"
"$MB" claims --results "$OUT" -o "$OUT/claims.md" --json "$OUT/claims.json"
# The provenance of each committed input measured again in this run.
if [ -d "$CORPUS" ]; then
  "${INPUTS[@]}" record "$OUT" corpus --source "$CORPUS" --outputs corpus/ \
    --what "motorbench report over ../shared/corpus (real glTF files: thumbnails, diffs, memory, ops, frame timing) and the skinned-file volumes skinning_volume_file is judged on (corpus/accuracy.json)" \
    --command "motorbench report $CORPUS -o $OUT/corpus --bench-json $OUT/bench.json --isa-json $OUT/isa.json; motorbench accuracy --skinned-files $CORPUS --json $OUT/corpus/accuracy.json"
fi
if [ -d "$GRAPHS" ]; then
  "${INPUTS[@]}" record "$OUT" corpus-graph --source "$GRAPHS" --outputs corpus-graph.json \
    --what "motorbench inspect over ../shared/corpus-graph (~960 real files' scene graphs, meshes stripped): the scale statistics of the two corpus claims, by source kind" \
    --command "motorbench inspect $GRAPHS --json $OUT/corpus-graph.json"
fi
if [ -d "$WIDE" ]; then
  "${INPUTS[@]}" record "$OUT" morph-corpus-wide --source "$WIDE" --outputs morph-corpus-wide.json \
    --what "motorbench morph over the files ../shared/corpus-wide's MANIFEST.tsv marks morph-targets: counted into morph.json with morph_torus" \
    --command "motorbench morph $WIDE --json $MORPH_WIDE" --used-morph "$MORPH_WIDE"
fi
# The README's figure tables and results/curved/README.md from the figures just written
# (tests/document/test_documents_agree.py: every document quotes one value per figure).
python3 scripts/document_figures.py --results "$OUT"

# An index for the repository page (GitHub shows a folder's README.md).
cat > "$OUT/README.md" <<INDEX
# results

Written by \`scripts/reproduce.sh\` in $(($(date +%s) - start)) s on $(nproc) cores
($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//'), $(date -u +%Y-%m-%d)).

## Measured by every run (a clone makes them)

- [report.md](report.md) / [report.html](report.html): every built-in scene with every pipeline
  of its space (the curved s3_tiling / h3_tiling in their own section): thumbnails, diffs,
  memory, ops per vertex, frame timing, kernel ratios, plots ([plots/](plots)); all figures in
  [report.json](report.json) (schema in the top README).
- [claims.md](claims.md) ([claims.json](claims.json)): each quantitative claim of the paper,
  measured, with a verdict; our own rows (baselines, vs strongest, curved) counted apart. The
  rows on real files are judged on the committed inputs below.
- [bench.txt](bench.txt) ([bench.json](bench.json)): \`motorbench bench\` (Google Benchmark).
- [ops.txt](ops.txt) ([ops.json](ops.json)): \`motorbench ops\`, counted arithmetic per kernel.
- [isa.txt](isa.txt) ([isa.json](isa.json)): \`motorbench isa\`, AMD ISA instructions, registers
  and occupancy of every pipeline's shaders from Mesa RADV's null device (GCN 1 to RDNA 3).
- [morph.txt](morph.txt) ([morph.json](morph.json)): \`motorbench morph\`, the image and byte
  cost of each morph method: morph_torus measured, with the corpus-wide files of
  [morph-corpus-wide.json](morph-corpus-wide.json) (below).
- [accuracy.txt](accuracy.txt) ([accuracy.json](accuracy.json)): \`motorbench accuracy\`, the
  paper's handedness rule, motor blend vs slerp, the candy wrapper's LBS vs motor skin, the
  quaternion's bits and the curved camera's drift, as named figures.

## Committed inputs ([inputs.json](inputs.json))

Figures over corpora that are not in the repository (../shared beside the project's checkout).
A run where the folder is present measures them again and records their provenance in
inputs.json (the source files' sha256, the commit and date that measured them); a run where it
is absent, as in a clone, reads the committed files as they are and never deletes them.
[corpus/report.md](corpus/report.md) is the report over ../shared/corpus.

$("${INPUTS[@]}" markdown "$OUT")
INDEX

finish
