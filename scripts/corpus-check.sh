#!/usr/bin/env bash
# scripts/corpus-check.sh [DIR|FILE ...] [--exe PATH] [check --rules options: --jobs N --size WxH
#   --out DIR --timeout S --pipelines p,q --min-psnr DB --max-drawn-diff F --junit FILE --quiet ...]
# `motorbench check --rules` (README: Corpus check) with this repository's defaults: the files of
# ../shared/corpus-wide when no DIR or FILE is given, OUT build/corpus-check unless --out. --exe:
# the motorbench to run (default $MB_MOTORBENCH_EXE, else build/harness/motorbench). Exit 0 every
# rule passed, 1 a rule failed, 2 bad arguments.
set -euo pipefail
REPO=$(cd "$(dirname "$0")/.." && pwd)
EXE=${MB_MOTORBENCH_EXE:-$REPO/build/harness/motorbench}
VALUED=" --jobs --size --timeout --out --o --pipelines --min-psnr --max-drawn-diff --junit --worker-exe "
args=()
paths=0
out=0
while [ $# -gt 0 ]; do
  case "$1" in
    --exe) EXE=${2:?--exe needs a path}; shift 2; continue ;;
    --exe=*) EXE=${1#--exe=}; shift; continue ;;
    --out|--out=*) out=1 ;;
  esac
  if [[ "$VALUED" == *" $1 "* && $# -ge 2 ]]; then
    args+=("$1" "$2")
    shift 2
    continue
  fi
  [[ "$1" == -* ]] || paths=1
  args+=("$1")
  shift
done
[ "$paths" = 1 ] || args+=("$REPO/../shared/corpus-wide")
[ "$out" = 1 ] || args+=(--out "$REPO/build/corpus-check")
if [ ! -x "$EXE" ]; then
  echo "corpus-check: $EXE: no motorbench executable (build it, or give --exe)" >&2
  exit 2
fi
exec "$EXE" check --rules "${args[@]}"
