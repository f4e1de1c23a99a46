#!/usr/bin/env bash
# README command 1: installs what is missing, builds, and segments a shipped
# mesh into topological disks.
#   scripts/main_job.sh [MESH [OUTPUT_DIR]]
# Defaults: test/Disk_segmentation/data/elephant.off, output in out/.
# Writes OUTPUT_DIR/NAME_patches.ply (one color per patch: open it in any
# mesh viewer), NAME_patch_ids.txt (one id per face) and NAME_summary.txt.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$root/build}
mesh=${1:-$root/test/Disk_segmentation/data/elephant.off}
out=${2:-$root/out}
bash "$root/scripts/build.sh" -DDISK_SEGMENTATION_BUILD_EXAMPLES=ON > "$build.build.log" 2>&1 \
  || { tail -n 30 "$build.build.log"; exit 1; }
mkdir -p "$out"
name=$(basename "${mesh%.*}")
"$build/bin/disk_uv" "$mesh" --patch-ids "$out/${name}_patch_ids.txt" --colored "$out/${name}_patches.ply" \
  | tee "$out/${name}_summary.txt"
echo "Results in $out: ${name}_patches.ply, ${name}_patch_ids.txt, ${name}_summary.txt"
