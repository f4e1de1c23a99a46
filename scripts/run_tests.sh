#!/usr/bin/env bash
# README command 2: installs what is missing, builds, runs the whole test suite.
# With CI=true (as CI sets it), the suite then runs once more under
# AddressSanitizer + UndefinedBehaviorSanitizer (scripts/run_sanitized_tests.sh).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$root/build}
bash "$root/scripts/build.sh" -DDISK_SEGMENTATION_BUILD_TESTS=ON -DDISK_SEGMENTATION_BUILD_EXAMPLES=ON
cd "$build"
ctest --output-on-failure -j "$(nproc)"
if [ "${CI:-}" = "true" ]; then
  BUILD_DIR="$root/build-sanitize" bash "$root/scripts/run_sanitized_tests.sh"
fi
