#!/usr/bin/env bash
# Installs every Debian package motorbench needs, then the Khronos glTF-Validator (npm) for
# scripts/gltf_validate.mjs. Idempotent: only what is missing is installed. Run as root (or with
# sudo available) on Debian 12.
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/.." && pwd)"

PACKAGES=(
  build-essential cmake ninja-build pkg-config git   # ninja: the scripts' generator (faster than make)
  clang libclang-rt-14-dev          # sanitizers and libFuzzer
  libglm-dev                        # matrix pipeline, test reference
  libtinygltf-dev nlohmann-json3-dev libstb-dev
  libegl-dev libgl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri libosmesa6-dev
  libopenimageio-dev openimageio-tools
  libbenchmark-dev libgtest-dev libgmock-dev
  libhwy-dev                        # Google Highway: SIMD kernels with runtime dispatch (kernels/simd)
  glslang-dev spirv-tools           # SPIR-V compiled in-process (harness/ops/spirv_compile.h)
  glslang-tools                     # glslangValidator: the reference tests/ops/test_spirv_compile.cpp compares with
  libvulkan-dev mesa-vulkan-drivers  # motorbench isa: AMD's compiler (ACO) through RADV's null device
  libdraco-dev libmeshoptimizer-dev  # KHR_draco_mesh_compression, EXT_meshopt_compression decode
  libwebp-dev                        # tests/scene: libwebp's own decoder as the WebP reference
  python3 python3-matplotlib
  parallel python3-yaml              # sharded runs (motorbench --shard, tests/cli, README examples)
  chromium                          # the report opened in a real browser (tests/cli/test_cli_browser.cpp)
  python3-markdown                  # scripts/screenshot.sh: claims.md's answer block as a page
  fonts-dejavu-core                 # the numbers on diff_legend.png (OpenImageIO's render_text)
  python3-junitparser python3-xmlschema  # tests/cli: --junit files read by a real consumer and checked by a JUnit XSD
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

# node and npm run the glTF-Validator (scripts/gltf_validate.mjs). Looked for as commands: a
# nodejs build that bundles npm (not Debian's) is kept, since Debian's npm would conflict with it.
command -v node >/dev/null && command -v npm >/dev/null || missing+=(nodejs npm)

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#PACKAGES[@]} packages present"
else
  SUDO=""
  [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  echo "setup: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# The validator at the version scripts/package-lock.json pins, into scripts/node_modules (ignored).
cd "$ROOT/scripts"
pinned=$(node -p "require('./package-lock.json').packages['node_modules/gltf-validator'].version")
installed=$(node -p "require('./node_modules/gltf-validator/package.json').version" 2>/dev/null || true)
if [ "$installed" = "$pinned" ]; then
  echo "setup: gltf-validator $pinned present"
else
  echo "setup: npm ci (gltf-validator $pinned)"
  npm ci --no-audit --no-fund --loglevel=error
fi
