#!/usr/bin/env bash
# The main job: installs packages, builds, and measures on the built-in scenes.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=RelWithDebInfo
cmake --build build -j "$(nproc)"
mkdir -p results
build/harness/motorbench ops --json results/ops.json | tee results/ops.txt
