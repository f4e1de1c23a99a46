#!/usr/bin/env bash
# Fuzzes the whole disk_uv pipeline (reader, checks, repair, segmentation,
# parameterization, packing, independent atlas checks) with libFuzzer,
# AddressSanitizer and UndefinedBehaviorSanitizer, for SECONDS (default 60).
#
#   bash scripts/run_fuzzer.sh [SECONDS]
#
# Builds with clang in build-fuzz/ (or $BUILD_DIR), starts from the seed
# corpus test/Disk_segmentation/fuzz/corpus plus the inputs found by earlier
# runs (kept in build-fuzz/corpus), and writes any crashing input to
# build-fuzz/artifacts/. Exits non-zero if one was found: copy it into
# test/Disk_segmentation/fuzz/regressions/ so that the test suite replays it.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
seconds=${1:-60}
build=${BUILD_DIR:-$root/build-fuzz}
bash "$root/scripts/install_dependencies.sh" clang libclang-rt-dev
CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DDISK_SEGMENTATION_BUILD_FUZZER=ON -DDISK_SEGMENTATION_BUILD_TESTS=ON \
  -DDISK_SEGMENTATION_BUILD_EXAMPLES=OFF -DDISK_SEGMENTATION_BUILD_DOC=OFF > "$build.configure.log"
cmake --build "$build" --target fuzz_disk_uv -j "$(nproc)"
mkdir -p "$build/corpus" "$build/artifacts"
cd "$build"
status=0
# One process; -timeout flags a single input running over 20 s as a hang.
./bin/fuzz_disk_uv -max_total_time="$seconds" -max_len=4096 -timeout=20 -rss_limit_mb=4096 \
  -artifact_prefix="$build/artifacts/" -print_final_stats=1 \
  "$build/corpus" "$root/test/Disk_segmentation/fuzz/corpus" 2>&1 | tee "$build/fuzz.log" | grep -E "^#|stat::|ERROR|SUMMARY|invariant" || true
if ls "$build/artifacts/" | grep -q .; then
  echo "run_fuzzer.sh: crashing inputs in $build/artifacts/ (see $build/fuzz.log)"
  status=1
fi
exit $status
