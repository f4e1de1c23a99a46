#!/usr/bin/env bash
# Regenerates the figures of the manual in doc/Disk_segmentation/fig/ from
# the package's own tool and the shipped elephant.off.
#
#   bash doc/Disk_segmentation/make_figures.sh [PATH/TO/disk_uv]
#
# disk_uv defaults to build/bin/disk_uv. Needs python3 (standard library
# only) for the 3D renderings (render_ply.py). Every figure is 512x512.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
disk_uv="${1:-$root/build/bin/disk_uv}"
mesh="$root/test/Disk_segmentation/data/elephant.off"
fig="$here/fig"
render="$here/render_ply.py"
res=512

if [ ! -x "$disk_uv" ]; then
  echo "make_figures.sh: $disk_uv is not an executable; build disk_uv or pass its path" >&2
  exit 1
fi
mkdir -p "$fig"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

# eps_N = 2 / sqrt(N cot(pi/N)): the score J of the shared side of two
# regular N-gons of equal area (see the manual).
eps() { python3 -c "import math; N=$1; print('%.4f' % (2/math.sqrt(N/math.tan(math.pi/N))))"; }

atlas() { # OUTPUT.png, then disk_uv options
  local out="$1"; shift
  "$disk_uv" "$mesh" --quiet --resolution "$res" --atlas-png "$fig/$out" "$@"
  echo "  fig/$out"
}

colored() { # OUTPUT.png, then disk_uv options; renders the charts on the mesh
  local out="$1"; shift
  "$disk_uv" "$mesh" --quiet --colored "$tmp/mesh.ply" "$@"
  python3 "$render" "$tmp/mesh.ply" "$fig/$out" --size "$res"
  echo "  fig/$out"
}

echo "The paper's charts against the distortion bound, merge-tree descent and smoothed borders:"
colored elephant_charts_paper.png --unbounded --rough-borders --crease-penalty 0
atlas elephant_atlas_paper.png --unbounded --rough-borders --crease-penalty 0
colored elephant_charts_bounded.png
atlas elephant_atlas_bounded.png

echo "Packing (default threshold eps_5):"
atlas elephant_atlas_tight.png --packer tight
atlas elephant_atlas_grid.png --packer grid

echo "Merge threshold (the paper's charts, tight packing, and the charts on the mesh):"
for N in 3 4 5 6; do
  e="$(eps "$N")"
  echo "  eps_$N = $e"
  atlas "elephant_atlas_eps$N.png" --threshold "$e" --unbounded --rough-borders --crease-penalty 0
  colored "elephant_mesh_eps$N.png" --threshold "$e" --unbounded --rough-borders --crease-penalty 0
done

echo "Pipeline stages on the mesh (the paper's segmentation: --unbounded --rough-borders --crease-penalty 0):"
# The tool writes only its final charts: merging disabled (--threshold 1e9)
# shows the disks after refinement; the default shows the merged patches.
colored elephant_stage_refined.png --threshold 1e9 --unbounded --rough-borders --crease-penalty 0
colored elephant_stage_merged.png --unbounded --rough-borders --crease-penalty 0
colored elephant_stage_charts.png

echo "Sizes:"
ls -l "$fig"/*.png | awk '{ printf "  %7d %s\n", $5, $NF }'
