#!/usr/bin/env bash
# Regenerates the atlas quality table (the paper's Table 1 layout) on the
# shipped meshes:
#
#   bash scripts/quality_table.sh [extra quality_table options]
#
# Builds the project with the benchmarks (scripts/build.sh, which installs
# only the Debian packages that are missing: none on a machine that already
# builds the project), then runs
#
#   build/bin/quality_table benchmark/Disk_segmentation/meshes --out benchmark/results --jobs $(nproc)
#
# and leaves benchmark/results/quality_table.md and quality_per_mesh.csv.
# Extra arguments go to quality_table (e.g. --methods conformal,lscm,arap,mvc
# or --time-limit 120). BUILD_DIR selects the build folder (default build/),
# MESH_DIR and OUT_DIR the input and output folders. About 3 minutes on a
# 2-core VM, plus the build.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$root/build}
# Relative to the repository root, so that the table names the folder portably.
meshes=${MESH_DIR:-benchmark/Disk_segmentation/meshes}
out=${OUT_DIR:-benchmark/results}

if ! bash "$root/scripts/build.sh" -DDISK_SEGMENTATION_BUILD_BENCHMARKS=ON; then
  # Another program of the project may be broken while this one is fine.
  echo "quality_table.sh: the full build failed; building only quality_table" >&2
  cmake --build "$build" -j "$(nproc)" --target quality_table
fi

cd "$root"
"$build/bin/quality_table" "$meshes" --out "$out" --jobs "$(nproc)" --time-limit 60 \
  --peers benchmark/Disk_segmentation/peers.csv "$@"
