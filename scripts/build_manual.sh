#!/usr/bin/env bash
# Builds the Doxygen manual: installs Doxygen and what the configure step
# needs (only the missing packages), then writes
# build/doc/Disk_segmentation/html/index.html (or under $BUILD_DIR).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$root/build}
BUILD_TARGETS=doc bash "$root/scripts/build.sh" --manual -DDISK_SEGMENTATION_BUILD_DOC=ON \
  -DDISK_SEGMENTATION_BUILD_TESTS=OFF -DDISK_SEGMENTATION_BUILD_PYTHON=OFF
echo "Manual: $build/doc/Disk_segmentation/html/index.html"
