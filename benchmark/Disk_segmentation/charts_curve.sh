#!/usr/bin/env bash
# Per-stage time of disk_uv against the number of seeds (and so of Voronoi
# cells and charts) on one mesh, 3 runs each, 1 thread, as CSV on stdout.
# usage: charts_curve.sh MESH (the README's run used CGAL's refined_elephant.off, 88,928 faces)
mesh=${1:?usage: charts_curve.sh MESH}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
tool=${DISK_UV:-$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)/build/bin/disk_uv}
echo "seeds,charts,voronoi_cells,refined,voronoi_s,refine_s,merge_s,param_s,pack_s,total_s"
for n in 10 30 100 300 1000 3000 10000 30000; do
  for rep in 1 2 3; do
    $tool "$mesh" -q -n $n --threads 1 --report "$tmp/cc_$n.json" || exit 1
    python3 -c "
import json; r=json.load(open('"$tmp/cc_$n.json"')); s=r['seconds']; g=r['segmentation']
print('$n,%d,%d,%d,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f'%(g['charts'],g['voronoi_cells'],g['refined_regions'],s['voronoi'],s['refine'],s['merge'],s['parameterization'],s['packing'],s['total']))"
  done
done
