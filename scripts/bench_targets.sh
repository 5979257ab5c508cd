#!/usr/bin/env bash
# The SIMD kernel pairs on the CPU's default Highway target and on AVX2 forced, back to back in
# one run of this script, each `motorbench bench` process with its own STREAM probe, and one table
# of both (the targets: every SIMD kernel <= its scalar GLM counterpart, out-of-cache
# point, direction and vertex_frame >= 0.7 of STREAM copy, skinned_vertex >= 0.5 or explained).
# Run it on a quiet machine: the CPU/real column shows where other work shared the cores.
#
# usage: scripts/bench_targets.sh [BUILD_DIR [OUT_DIR]]   (defaults: build, build/bench-targets)
# env:   REPS (repetitions, default 3), MIN_TIME (seconds per benchmark, default 0.1)
# Writes OUT_DIR/bench-<target>.json (Google Benchmark JSON) and OUT_DIR/targets.txt (the table).
#
# Columns (all read from the JSON files; medians of the repetitions):
#   time      CPU time per call (us; a call is one pass over the kernel's items)
#   GB/s      bytes the kernel reads and writes per CPU second (harness/bench/bench_common.h)
#   copy      out of cache: GB/s over the same process's STREAM copy (counter copy_fraction)
#   cache/copy  out of cache: the same side's in-cache GB/s over that copy (the arithmetic's
#             ceiling: below the copy, the kernel cannot stream at the copy's rate)
#   x GLM     time per item over GLM's on the same kernel and working set (< 1: faster than GLM;
#             skinned_vertex_gather against skinned_vertex's GLM)
#   CPU/real  CPU time over real time (< 0.9: the cores were shared, harness/timing/disturbance.h)
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD=${1:-build}
OUT=${2:-$BUILD/bench-targets}
MB=$BUILD/harness/motorbench
REPS=${REPS:-3}
MIN_TIME=${MIN_TIME:-0.1}
[ -x "$MB" ] || { echo "bench_targets: no $MB (build the motorbench target first)" >&2; exit 2; }
mkdir -p "$OUT"

FILTER='^(stream/copy|(point|direction|vertex_frame|skinned_vertex|skinned_vertex_gather)/(in_cache|out_of_cache)/(glm|simd_matrix|simd_motor)|(compose|palette|palette/out_of_cache|hierarchy|hierarchy_wide|hierarchy_skeleton)/(glm|simd_matrix|simd_affine|simd_motor))$'

run() {  # run NAME [--simd-target T]
  local name=$1
  shift
  echo "bench_targets: $name ($*)" >&2
  "$MB" bench "$@" --out "$OUT/bench-$name.json" --benchmark_filter="$FILTER" \
    --benchmark_min_time="$MIN_TIME" --benchmark_repetitions="$REPS" --benchmark_color=false \
    > "$OUT/bench-$name.txt"
}

uptime >&2
run default
DEFAULT=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["context"].get("simd_target", "?"))' \
  "$OUT/bench-default.json")
FILES=("$OUT/bench-default.json")
if [ "$DEFAULT" != AVX2 ]; then
  if run AVX2 --simd-target AVX2; then FILES+=("$OUT/bench-AVX2.json")
  else echo "bench_targets: AVX2 not available here; default target only" >&2; fi
fi
uptime >&2

python3 - "${FILES[@]}" <<'EOF' | tee "$OUT/targets.txt"
import json, sys

def medians(path):
    data = json.load(open(path))
    rows = {}
    for b in data["benchmarks"]:
        name = b.get("run_name", b["name"])
        if b.get("run_type") == "aggregate":
            if b.get("aggregate_name") == "median":
                rows[name] = b
        elif name not in rows or rows[name].get("run_type") != "aggregate":
            rows[name] = b
    return data["context"], rows

for path in sys.argv[1:]:
    ctx, rows = medians(path)
    copy = rows.get("stream/copy", {}).get("bytes_per_second", 0) / 1e9
    print(f"\n{ctx.get('cpu_model', '?')}, {ctx.get('logical_cores', '?')} logical cores; Highway target "
          f"{ctx.get('simd_target', '?')}; STREAM copy {copy:.2f} GB/s (stream/copy, this process); {path}")
    print(f"{'kernel':40s} {'side':12s} {'target':6s} {'time us':>10s} {'GB/s':>7s} {'copy':>5s} "
          f"{'cache/copy':>10s} {'x GLM':>6s} {'CPU/real':>8s}")
    for name, b in rows.items():
        parts = name.split("/")
        side = parts[-1]
        if not side.startswith("simd") and side != "glm":
            continue
        kernel = "/".join(parts[:-1])
        glm = rows.get(kernel.replace("skinned_vertex_gather", "skinned_vertex") + "/glm")
        xglm = glm["items_per_second"] / b["items_per_second"] if glm and side != "glm" else None
        cell = lambda v, f: format(v, f) if v is not None else "-"
        frac = b.get("copy_fraction")
        inCache = None
        if "out_of_cache" in kernel and copy > 0:
            c = rows.get(name.replace("out_of_cache", "in_cache"))
            inCache = c["bytes_per_second"] / 1e9 / copy if c and c.get("bytes_per_second") else None
        gbs = b.get("bytes_per_second")
        print(f"{kernel:40s} {side:12s} {b.get('label', '-'):6s} {b['cpu_time']:10.3f} "
              f"{cell(gbs / 1e9 if gbs else None, '7.2f')} {cell(frac, '5.2f')} {cell(inCache, '10.2f')} "
              f"{cell(xglm, '6.2f')} {b['cpu_time'] / b['real_time']:8.2f}")
EOF
