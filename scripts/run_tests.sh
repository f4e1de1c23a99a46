#!/usr/bin/env bash
# README command 2: installs what is missing, builds, runs the whole test suite.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$root/build}
bash "$root/scripts/build.sh" -DDISK_SEGMENTATION_BUILD_TESTS=ON -DDISK_SEGMENTATION_BUILD_EXAMPLES=ON
cd "$build"
ctest --output-on-failure -j "$(nproc)"
