#!/usr/bin/env bash
# README command 1: installs what the C++ tool needs (only the missing
# packages), builds the tool alone, and makes the UV atlas of a shipped mesh.
# The tests, the Python module and the manual have their own scripts.
#   scripts/main_job.sh [MESH [OUTPUT_DIR]]
# Defaults: test/Disk_segmentation/data/elephant.off, output in out/.
# Writes into OUTPUT_DIR: NAME_atlas.obj, NAME_atlas.glb, NAME_atlas.png,
# NAME_report.json, NAME_patches.ply (one color per chart), NAME_patch_ids.txt
# and NAME_summary.txt.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$root/build}
mesh=${1:-$root/test/Disk_segmentation/data/elephant.off}
out=${2:-$root/out}
BUILD_TARGETS=disk_uv bash "$root/scripts/build.sh" --tool -DDISK_SEGMENTATION_BUILD_EXAMPLES=ON \
  -DDISK_SEGMENTATION_BUILD_TESTS=OFF -DDISK_SEGMENTATION_BUILD_PYTHON=OFF -DDISK_SEGMENTATION_BUILD_DOC=OFF \
  > "$build.build.log" 2>&1 || { tail -n 30 "$build.build.log"; exit 1; }
mkdir -p "$out"
name=$(basename "${mesh%.*}")
"$build/bin/disk_uv" "$mesh" -o "$out/${name}_atlas.obj" --glb "$out/${name}_atlas.glb" \
  --atlas-png "$out/${name}_atlas.png" --report "$out/${name}_report.json" \
  --patch-ids "$out/${name}_patch_ids.txt" --colored "$out/${name}_patches.ply" \
  | tee "$out/${name}_summary.txt"
echo "Results in $out: ${name}_atlas.{obj,glb,png}, ${name}_report.json, ${name}_patches.ply, ${name}_patch_ids.txt"
