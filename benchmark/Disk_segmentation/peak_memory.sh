#!/usr/bin/env bash
# Peak memory and stage times of the whole disk_uv pipeline (read, segment,
# parameterize, pack, write the report), one row per mesh and thread count,
# as a Markdown table on stdout. Peak RSS is the process's own (getrusage),
# written by disk_uv into its JSON report.
#
#   bash benchmark/Disk_segmentation/peak_memory.sh MESH... [-- DISK_UV_OPTIONS]
#
# Builds nothing: uses build/bin/disk_uv (or $DISK_UV). The README's
# 2.2M-face run used CGAL's man.off after 3 Loop subdivision steps.
set -euo pipefail
tool=${DISK_UV:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)/build/bin/disk_uv}
meshes=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do meshes+=("$1"); shift; done
[ $# -gt 0 ] && shift
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "| mesh | faces | threads | charts | largest chart | read s | segment s | parameterize s | pack s | peak RSS MB |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for mesh in "${meshes[@]}"; do
  for threads in 1 0; do
    "$tool" "$mesh" -q --threads "$threads" --report "$tmp/r.json" "$@"
    python3 - "$tmp/r.json" "$(basename "$mesh")" "$threads" <<'PY'
import json, sys
r = json.load(open(sys.argv[1])); s = r["seconds"]
largest = max(c["faces"] for c in r["charts"])
threads = "all" if sys.argv[3] == "0" else sys.argv[3]
print("| %s | %d | %s | %d | %d | %.2f | %.2f | %.2f | %.2f | %.0f |" % (
    sys.argv[2], r["faces"], threads, r["segmentation"]["charts"], largest, s["read"],
    s["voronoi"] + s["refine"] + s["merge"], s["parameterization"], s["packing"], r["peak_rss_mb"]))
PY
  done
done
