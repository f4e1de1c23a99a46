#!/usr/bin/env bash
# README command 2: installs what is missing, builds, runs the whole test suite.
# With CI=true (as CI sets it), the suite then runs once more under
# AddressSanitizer + UndefinedBehaviorSanitizer (scripts/run_sanitized_tests.sh).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$root/build}
# Every part is named ON: command 1 (scripts/main_job.sh) turns off in the
# same build folder what the tool does not need.
bash "$root/scripts/build.sh" --all -DDISK_SEGMENTATION_BUILD_TESTS=ON -DDISK_SEGMENTATION_BUILD_EXAMPLES=ON \
  -DDISK_SEGMENTATION_BUILD_PYTHON=ON -DDISK_SEGMENTATION_BUILD_DOC=ON
cd "$build"
ctest --output-on-failure -j "$(nproc)"
if [ "${CI:-}" = "true" ]; then
  BUILD_DIR="$root/build-sanitize" bash "$root/scripts/run_sanitized_tests.sh"
fi
