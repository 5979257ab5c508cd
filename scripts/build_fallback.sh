# build_unity_or_alone BUILD [cmake --build options...]: builds BUILD; when that fails in a
# folder configured with unity batches (MB_UNITY=ON), says so and builds it again file by file.
# A unity batch fails where two of its files define the same file-local name (a helper in an
# anonymous namespace): the everyday build (MB_UNITY=OFF) never sees that clash, so a clean
# tree must still build and test; the message names the cause so the clash gets fixed.
# Sourced by scripts/test.sh and scripts/reproduce.sh.
build_unity_or_alone() {
  local dir=$1
  shift
  cmake --build "$dir" "$@" && return 0
  grep -q '^MB_UNITY:BOOL=ON' "$dir/CMakeCache.txt" 2>/dev/null || return 1
  echo "build: FAILED in unity batches (MB_UNITY=ON; often two files of one library defining the same" \
    "file-local name: see the errors above); building file by file (MB_UNITY=OFF) instead" >&2
  cmake -S . -B "$dir" -DMB_UNITY=OFF >&2 && cmake --build "$dir" "$@"
}
