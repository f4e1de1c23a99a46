#!/usr/bin/env bash
# End-to-end test of the disk_uv command-line tool: a good run writes its
# outputs; each bad input or parameter gives exit status 1 (2 for usage
# errors), one line on stderr naming the problem, and no output file.
# usage: test_disk_uv.sh PATH/TO/disk_uv DATA_DIR
set -u
tool=$1
data=$2
source=$(cd "$(dirname "$0")/../.." && pwd)  # the repository: its Python atlas checker
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
passed=0

fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
pass() { passed=$((passed + 1)); }

# --- a good run
if "$tool" "$data/elephant.off" -n 12 --patch-ids "$work/ids.txt" --colored "$work/patches.ply" \
     -o "$work/atlas.obj" --glb "$work/atlas.glb" --atlas-png "$work/atlas.png" --report "$work/report.json" \
     > "$work/out.txt" 2> "$work/err.txt"; then
  pass
else
  fail "good run exited non-zero: $(cat "$work/err.txt")"
fi
faces=$(sed -n 2p "$data/elephant.off" | awk '{print $2}')
[ "$(wc -l < "$work/ids.txt")" -eq "$faces" ] && pass || fail "patch-id file has not one line per face"
patches=$(sed -E 's/.*-> ([0-9]+) charts.*/\1/' "$work/out.txt")
distinct=$(sort -n "$work/ids.txt" | uniq | wc -l)
[ "$distinct" -eq "$patches" ] && pass || fail "summary says $patches patches, file has $distinct ids"
[ "$(sort -n "$work/ids.txt" | tail -1)" -eq $((patches - 1)) ] && pass || fail "ids are not 0..P-1"
grep -q "^element face $faces$" "$work/patches.ply" && pass || fail "colored PLY lacks the faces"
[ "$(grep -c '^3 ' "$work/patches.ply")" -eq "$faces" ] && pass || fail "colored PLY has not one colored triangle per face"
ls "$work" | grep -q tmp && fail "a temporary file was left behind" || pass
[ "$(grep -c '^f ' "$work/atlas.obj")" -eq "$faces" ] && pass || fail "OBJ has not one face per input face"
[ "$(grep -c '^g chart_' "$work/atlas.obj")" -ge "$patches" ] && pass || fail "OBJ has fewer groups than charts"
[ "$(head -c 4 "$work/atlas.glb")" = "glTF" ] && pass || fail "GLB lacks the glTF magic"
[ "$(head -c 4 "$work/atlas.png" | tail -c 3)" = "PNG" ] && pass || fail "PNG lacks its signature"
grep -q '"charts"' "$work/report.json" && grep -q '"efficiency"' "$work/report.json" && pass || fail "JSON report lacks fields"
grep -q '"invalid_charts": 0' "$work/report.json" && pass || fail "report says some chart is invalid"
python3 -c "import json,sys; sys.exit(0 if json.load(open('$work/report.json'))['peak_rss_mb'] > 1 else 1)" \
  && pass || fail "report lacks a plausible peak_rss_mb"
# Started by a parent holding more memory than the tool's own peak (as
# reported above, from this small shell) plus 200 MB, the tool reports its
# own peak, not the parent's (getrusage() keeps the address space's peak
# across exec). Relative: sanitizers multiply the tool's own peak.
python3 -c "
import json, subprocess, sys
alone = json.load(open('$work/report.json'))['peak_rss_mb']
bound = 1.25 * alone + 32
hog = bytearray(int(bound + 200) * 1024 * 1024)
for i in range(0, len(hog), 4096):
    hog[i] = 1
subprocess.run(['$tool', '$data/elephant.off', '-q', '--threads', '1', '--report', '$work/hog.json'], check=True)
sys.exit(0 if 1 < json.load(open('$work/hog.json'))['peak_rss_mb'] < bound else 1)
" && pass || fail "the report's peak_rss_mb counts the parent process's memory"
# The solve count: at least every face once, the per-face ratio its own
# division, and elephant's merges (ARAP from the glued maps) counted.
python3 -c "
import json, sys
r = json.load(open('$work/report.json'))
p = r['parameterization']
ok = p['solved_faces'] >= r['faces'] and abs(p['solves_per_face'] - p['solved_faces'] / r['faces']) < 1e-9 \\
     and p['solved_faces_in_merges'] + p['solved_faces_in_reroutes'] <= p['solved_faces'] - r['faces'] \\
     and p['solved_faces_in_merges'] > 0
sys.exit(0 if ok else 1)" && pass || fail "report's solve count is implausible"

# --- same input, same output
"$tool" "$data/elephant.off" -n 12 --patch-ids "$work/ids2.txt" > /dev/null 2>&1
cmp -s "$work/ids.txt" "$work/ids2.txt" && pass || fail "two runs differ"

# --- each error: status, one-line message naming the problem, no output written
expect_error() { # expected_status expected_message_part args...
  local status=$1 message=$2
  shift 2
  rm -f "$work/never.txt"
  "$tool" "$@" --patch-ids "$work/never.txt" > "$work/out.txt" 2> "$work/err.txt"
  local got=$?
  if [ "$got" -ne "$status" ]; then fail "'$*' exited $got, expected $status"; return; fi
  if ! grep -qiE -- "$message" "$work/err.txt"; then fail "'$*' said '$(cat "$work/err.txt")', expected '$message'"; return; fi
  if [ "$status" -eq 1 ] && [ "$(wc -l < "$work/err.txt")" -ne 1 ]; then fail "'$*' printed more than one line"; return; fi
  if [ -e "$work/never.txt" ]; then fail "'$*' wrote an output"; return; fi
  pass
}

printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n' > "$work/truncated.off"
: > "$work/empty.off"
printf 'OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n' > "$work/quad.off"
printf 'OFF\n3 1 0\n0 0 0\nnan 0 0\n1 1 0\n3 0 1 2\n' > "$work/nan.off"
printf 'OFF\n3 1 0\n0 0 0\n1e400 0 0\n1 1 0\n3 0 1 2\n' > "$work/overflow.off"
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n1 1 0\n3 0 1 7\n' > "$work/badindex.off"
# Three triangles on one edge.
printf 'OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n' > "$work/nonmanifold_edge.off"
# Two triangles sharing only a vertex.
printf 'OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n-1 0 0\n-1 -1 0\n3 0 1 2\n3 0 3 4\n' > "$work/pinched.off"
# Two triangles with opposite orientations across their common edge.
printf 'OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 2 3\n' > "$work/flipped.off"
cp "$data/elephant.off" "$work/mesh.txt"

expect_error 1 "cannot open" "$work/does_not_exist.off"
expect_error 1 "not a valid" "$work/empty.off"
expect_error 1 "not a valid" "$work/truncated.off"
expect_error 1 "unknown mesh format" "$work/mesh.txt"
expect_error 1 "4 vertices" "$work/quad.off"
expect_error 1 "refers to vertex|not a valid" "$work/badindex.off"
expect_error 1 "not manifold" "$work/nonmanifold_edge.off"
expect_error 1 "oriented inconsistently" "$work/flipped.off"
expect_error 2 "-n/--seeds must be at least 1" "$data/elephant.off" -n 0
expect_error 2 "-k/--subsamples must be at least 2" "$data/elephant.off" -k 1
expect_error 2 "--threshold must be" "$data/elephant.off" --threshold -1
expect_error 2 "--crease-penalty must be a finite number >= 0" "$data/elephant.off" --crease-penalty -1
expect_error 2 "unknown parameterization method" "$data/elephant.off" --method harmonic2
expect_error 2 "unknown packer" "$data/elephant.off" --packer best
expect_error 2 "--resolution must be at least 1" "$data/elephant.off" --resolution 0
expect_error 2 "padding" "$data/elephant.off" --padding -3
expect_error 2 "" "$data/elephant.off" -n abc
expect_error 2 "" "$data/elephant.off" --no-such-option
# NaN: the reader may refuse the number or the checker names it; either way a clear error.
"$tool" "$work/nan.off" > /dev/null 2> "$work/err.txt"
[ $? -eq 1 ] && grep -qiE "non-finite|not a valid" "$work/err.txt" && pass || fail "NaN input: $(cat "$work/err.txt")"

expect_error 2 "--max-chart-faces must be" "$data/elephant.off" --max-chart-faces 0
expect_error 2 "--max-charts: '-1' is not a non-negative" "$data/elephant.off" --max-charts -1
# A chart budget: met (as many charts as asked) or, when no merge is left, a
# warning; the report says which.
"$tool" "$data/elephant.off" --max-charts 30 --report "$work/budget.json" > "$work/out.txt" 2> "$work/err.txt"
python3 -c "import json,sys; r=json.load(open('$work/budget.json')); p=r['parameterization']
sys.exit(0 if r['segmentation']['charts'] == 30 and p['chart_budget_met'] and p['charts_before_budget'] > 30 else 1)" \
  && [ ! -s "$work/err.txt" ] && pass || fail "--max-charts 30: $(cat "$work/err.txt")"
"$tool" "$data/elephant.off" --max-charts 1 --report "$work/budget.json" > "$work/out.txt" 2> "$work/err.txt"
grep -q "warning: .* over --max-charts (1)" "$work/err.txt" && grep -q '"chart_budget_met": false' "$work/budget.json" \
  && pass || fail "an unmet --max-charts is not said: $(cat "$work/err.txt")"
expect_error 1 "vertex #1 has a non-finite" "$work/overflow.off"
# Materials: one id per face; no chart holds two.
python3 -c "
n = int(open('$data/elephant.off').read().split()[2])
open('$work/materials.txt', 'w').write(''.join('%d\\n' % (3 * f // n) for f in range(n)))"
"$tool" "$data/elephant.off" --material-ids "$work/materials.txt" --patch-ids "$work/m_ids.txt" > /dev/null 2>&1
python3 -c "
import sys
materials = [int(x) for x in open('$work/materials.txt')]
charts = [int(x) for x in open('$work/m_ids.txt')]
seen = {}
for c, m in zip(charts, materials): seen.setdefault(c, set()).add(m)
sys.exit(0 if len(materials) == len(charts) and all(len(s) == 1 for s in seen.values()) else 1)" \
  && pass || fail "a chart holds two materials"
head -n 10 "$work/materials.txt" > "$work/few.txt"
expect_error 1 "--material-ids: .* has 10 ids for 5558 faces" "$data/elephant.off" --material-ids "$work/few.txt"
printf '0\n1\nx2\n' > "$work/bad_ids.txt"
expect_error 1 "--material-ids: .* line 3: 'x2' is not an integer" "$data/elephant.off" --material-ids "$work/bad_ids.txt"
expect_error 1 "--material-ids: .*cannot open" "$data/elephant.off" --material-ids "$work/no_such_ids.txt"
printf 'OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n' > "$work/x8.off"
{ printf '\357\273\277'; seq 1 8; } > "$work/bom_ids.txt"
expect_error 1 "--material-ids: .* starts with a UTF-8 byte-order mark \(BOM\)" "$work/x8.off" \
  --material-ids "$work/bom_ids.txt"
# A texture too small for the charts and their padding: packed, and said.
"$tool" "$data/elephant.off" --resolution 32 -o "$work/small.obj" > /dev/null 2> "$work/err.txt"
[ $? -eq 0 ] && grep -qE "warning: the charts cover only [0-9.]+% of the texture: at --resolution 32, --padding 2" \
  "$work/err.txt" && [ -s "$work/small.obj" ] && pass || fail "a sparse packing is not said: $(cat "$work/err.txt")"
# A fixed texel density: twice the one-page fit needs several pages, written
# as UDIM tiles: every corner of every face of chart c (the OBJ's group
# chart_c) lies in the tile of the report's page of c, one picture per tile.
# (That each page is a valid atlas is checked in test_packing.cpp and, on
# the files, in test_module.py.)
"$tool" "$data/elephant.off" --report "$work/fit.json" > /dev/null 2>&1
density=$(python3 -c "import json; print(2 * json.load(open('$work/fit.json'))['packing']['texels_per_unit'])")
"$tool" "$data/elephant.off" --texels-per-unit "$density" -o "$work/pages.obj" --atlas-png "$work/pages.png" \
  --report "$work/pages.json" > "$work/out.txt" 2> "$work/err.txt"
python3 -c "
import json, math, os, sys
p = json.load(open('$work/pages.json'))['packing']
vt, chart, bad, tiles = [], None, 0, set()
for line in open('$work/pages.obj'):
    f = line.split()
    if not f: continue
    if f[0] == 'vt': vt.append((float(f[1]), float(f[2])))
    elif f[0] == 'g': chart = int(f[1][len('chart_'):])
    elif f[0] == 'f':
        page = p['page_of_chart'][chart]
        i, j = page % 10, page // 10
        tiles.add(1001 + i + 10 * j)
        corners = [vt[int(c.split('/')[1]) - 1] for c in f[1:]]
        bad += sum(not (i <= u <= i + 1 and j <= v <= j + 1) for u, v in corners)
pictures = sorted(f for f in os.listdir('$work') if f.startswith('pages.') and f.endswith('.png'))
ok = (bad == 0 and p['pages'] >= 2 and p['udim_tiles'] and sorted(tiles) == list(range(1001, 1001 + p['pages']))
      and abs(p['texels_per_unit'] - $density) < 1e-6 * $density and len(p['page_efficiency']) == p['pages']
      and pictures == ['pages.%d.png' % t for t in sorted(tiles)])
print(bad, sorted(tiles), pictures, p['pages']) if not ok else None
sys.exit(0 if ok else 1)" && grep -q "pages at .* texels per unit, as UDIM tiles 1001 to" "$work/out.txt" \
  && pass || fail "--texels-per-unit pages: $(cat "$work/err.txt")"
# A non-square texture: the picture has its size, the UVs span the unit
# square and the report's density is per texel of width.
"$tool" "$data/elephant.off" --resolution 2048x512 --atlas-png "$work/wide.png" -o "$work/wide.obj" \
  --report "$work/wide.json" > /dev/null 2> "$work/err.txt"
python3 -c "
import json, struct, sys
png = open('$work/wide.png', 'rb').read(24)
size = struct.unpack('>II', png[16:24])
uv = [tuple(map(float, l.split()[1:3])) for l in open('$work/wide.obj') if l.startswith('vt ')]
p = json.load(open('$work/wide.json'))['packing']
sys.exit(0 if size == (2048, 512) and uv and all(0 <= u <= 1 and 0 <= v <= 1 for u, v in uv)
         and p['efficiency'] > 0.3 and p['pages'] == 1 else 1)" && [ ! -s "$work/err.txt" ] \
  && pass || fail "--resolution 2048x512: $(cat "$work/err.txt")"
expect_error 2 "is not a non-negative integer or WIDTHxHEIGHT" "$data/elephant.off" --resolution 2048x
expect_error 2 "--resolution 512x256 is not square: .*--packer tight" "$data/elephant.off" --resolution 512x256 \
  --packer grid
expect_error 2 "--resolution \(its height\) must be at least 1" "$data/elephant.off" --resolution 512x0
# The same UDIM tiles without the pictures.
"$tool" "$data/elephant.off" --texels-per-unit "$density" -o "$work/pages_only.obj" -q 2> "$work/err.txt"
cmp -s "$work/pages.obj" "$work/pages_only.obj" && pass || fail "the OBJ's UDIM tiles depend on --atlas-png"
expect_error 1 "patch #[0-9]+ is [0-9]+ x [0-9]+ texels and does not fit a page" "$data/elephant.off" \
  --texels-per-unit "$(python3 -c "print(10 * $density)")" --max-pages 999
expect_error 1 "need more than 2 pages .*--max-pages" "$data/elephant.off" --texels-per-unit "$density" --max-pages 2
expect_error 2 "--texels-per-unit must be a finite number" "$data/elephant.off" --texels-per-unit -1
expect_error 2 "--texels-per-unit needs --packer tight " "$data/elephant.off" --texels-per-unit 100 --packer grid
# Every bad command-line value is a usage error (2), before any input is read.
expect_error 2 "--max-pages must be at least 1" "$work/no_such.off" --max-pages 0
expect_error 2 "--max-pages must be at most 999: .*UDIM tiles 1001 to 1999" "$work/no_such.off" --max-pages 1000
expect_error 2 "--resolution must be at least 1" "$work/no_such.off" --resolution 0x0
expect_error 2 "--texels-per-unit: the value is empty" "$data/elephant.off" --texels-per-unit ""
expect_error 2 "--padding: '1x' is not a number" "$data/elephant.off" --padding 1x
expect_error 1 "need more than 1 page of" "$data/elephant.off" --texels-per-unit "$density" --max-pages 1
# A density at which rounding collapses triangles: refused, nothing
# written, whatever the output's precision (double in OBJ, float in glTF).
expect_error 1 "too small for double precision at --texels-per-unit 1e-13; raise --texels-per-unit" \
  "$data/elephant.off" --texels-per-unit 1e-13 -o "$work/never.obj"
expect_error 1 "too small for double precision" "$data/elephant.off" --texels-per-unit 1e-300 -o "$work/never.obj"
expect_error 1 "glTF file: [0-9]+ triangles .* degenerate or flipped in 32-bit float UVs.*raise --texels-per-unit" \
  "$data/elephant.off" --texels-per-unit 1e-3 -o "$work/never.obj" --glb "$work/never.glb"
[ -e "$work/never.obj" ] || [ -e "$work/never.glb" ] && fail "an atlas was written at a density its UVs cannot hold" || pass
# OBJ keeps doubles: written, every triangle still positive, and the
# charts below a texel are said.
"$tool" "$data/elephant.off" --texels-per-unit 1e-3 -o "$work/tiny.obj" > /dev/null 2> "$work/err.txt"
python3 -c "
import sys
vt, bad = [], 0
for line in open('$work/tiny.obj'):
    f = line.split()
    if f and f[0] == 'vt': vt.append((float(f[1]), float(f[2])))
    elif f and f[0] == 'f':
        (a, b), (c, d), (e, g) = [vt[int(x.split('/')[1]) - 1] for x in f[1:4]]
        bad += not (c - a) * (g - b) - (d - b) * (e - a) > 0
sys.exit(1 if bad or not vt else 0)" && grep -q "warning: 59 of 59 charts are smaller than one texel of a --resolution 1024 texture at this --texels-per-unit" "$work/err.txt" \
  && pass || fail "--texels-per-unit 1e-3 OBJ: $(cat "$work/err.txt")"
# Several inputs, one atlas: each mesh keeps the charts it gets alone.
"$tool" "$data/elephant.off" --patch-ids "$work/alone_a.txt" > /dev/null 2>&1
"$tool" "$data/eight.off" --patch-ids "$work/alone_b.txt" > /dev/null 2>&1
"$tool" "$data/elephant.off" "$data/eight.off" --patch-ids "$work/both.txt" --report "$work/both.json" \
  -o "$work/both.obj" > /dev/null 2>&1
python3 -c "
import json, sys
a = [int(x) for x in open('$work/alone_a.txt')]
b = [int(x) for x in open('$work/alone_b.txt')]
both = [int(x) for x in open('$work/both.txt')]
r = json.load(open('$work/both.json'))
first = r['inputs'][1]['first_chart']
ok = both == a + [first + x for x in b] and first == max(a) + 1 and r['charts'] == first + max(b) + 1
ok = ok and len(r['inputs']) == 2 and sum(l.startswith('f ') for l in open('$work/both.obj')) == len(both)
sys.exit(0 if ok else 1)" && pass || fail "two inputs: not the charts each gets alone, in one atlas"
expect_error 1 "cannot open .*no_such.off" "$data/elephant.off" "$work/no_such.off"
expect_error 2 "--material-ids takes one INPUT, not 2" "$data/elephant.off" "$data/eight.off" \
  --material-ids "$work/materials.txt"
# Polygons: with --triangulate, a quad split between charts is moved whole.
python3 -c "
import math
n, m = 40, 12
lines = ['OFF', '%d %d 0' % (n * m, n * m)]
for a in range(n):
    for b in range(m):
        u, v = 2 * math.pi * a / n, 2 * math.pi * b / m
        lines.append('%f %f %f' % ((2 + .7 * math.cos(v)) * math.cos(u), (2 + .7 * math.cos(v)) * math.sin(u), .7 * math.sin(v)))
for a in range(n):
    for b in range(m):
        lines.append('4 %d %d %d %d' % (a * m + b, (a + 1) % n * m + b, (a + 1) % n * m + (b + 1) % m, a * m + (b + 1) % m))
open('$work/quad_torus.off', 'w').write('\\n'.join(lines) + '\\n')"
"$tool" "$work/quad_torus.off" --triangulate --patch-ids "$work/q_ids.txt" --report "$work/q.json" > /dev/null 2>&1
python3 -c "
import json, sys
charts = [int(x) for x in open('$work/q_ids.txt')]
polygons = json.load(open('$work/q.json'))['polygons']
cut = sum(charts[2 * q] != charts[2 * q + 1] for q in range(len(charts) // 2))
sys.exit(0 if polygons['moved_whole_into_one_chart'] > 0 and cut == polygons['left_across_charts'] else 1)" \
  && pass || fail "--triangulate: polygons not kept whole: $(cat "$work/q.json" | grep -A3 polygons)"
# Inputs that broke CGAL's own readers (see fuzz/regressions/README.md).
cp "$data/../fuzz/regressions/ply_property_before_element" "$work/prop.ply"
expect_error 1 "property comes before any element" "$work/prop.ply"
cp "$data/../fuzz/regressions/off_negative_face_size" "$work/negative.off"
expect_error 1 "face #0 does not start with its number of vertices" "$work/negative.off"
# A face listed twice, inside a two-face strip.
printf 'OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 2 1 3\n3 0 1 2\n' > "$work/duplicated_face.off"
expect_error 1 "face #2 duplicates face #0" "$work/duplicated_face.off"

# --- repairs on request: each bad mesh above becomes a valid atlas, and
# every output follows the repaired mesh (one patch id per output face).
expect_repaired() { # expected_faces file options...
  local expected=$1 file=$2
  shift 2
  rm -f "$work/r_ids.txt" "$work/r.obj" "$work/r.json"
  if ! "$tool" "$file" "$@" --patch-ids "$work/r_ids.txt" -o "$work/r.obj" --report "$work/r.json" \
       > "$work/out.txt" 2> "$work/err.txt"; then
    fail "'$file $*' failed: $(cat "$work/err.txt")"; return
  fi
  local faces
  faces=$(grep -c '^f ' "$work/r.obj")
  if [ "$faces" -ne "$expected" ]; then fail "'$file $*': $faces faces, expected $expected"; return; fi
  if [ "$(wc -l < "$work/r_ids.txt")" -ne "$faces" ]; then fail "'$file $*': patch ids do not match the faces"; return; fi
  if ! grep -q '"invalid_charts": 0' "$work/r.json"; then fail "'$file $*': invalid charts"; return; fi
  pass
}
expect_repaired 2 "$work/duplicated_face.off" --repair
grep -q '"faces_removed": 1' "$work/r.json" && pass || fail "report does not count the removed duplicate"
expect_repaired 3 "$work/nonmanifold_edge.off" --repair
grep -q '"vertices_added": 0' "$work/r.json" && fail "cutting the non-manifold edge added no vertex" || pass
expect_repaired 2 "$work/pinched.off" --repair
expect_repaired 2 "$work/flipped.off" --repair
# A pinched vertex is no error, and kept: same faces, in order, and the
# file's vertices (the charts cut the mesh there, each fan with its own UVs).
expect_repaired 2 "$work/pinched.off"
grep -q '"pinched_vertices_split": 1' "$work/r.json" && pass || fail "report does not count the split vertex"
[ "$(grep -c '^v ' "$work/r.obj")" -eq 5 ] && pass || fail "the pinched vertex was copied in the OBJ"
grep -q "1 pinched vertices split by the charts" "$work/out.txt" && pass || fail "the summary does not say the vertex was split"
grep -q "input changed" "$work/out.txt" && fail "the summary says a pinched vertex changed the input" || pass
expect_repaired 2 "$work/quad.off" --triangulate
# An L-shaped hexagon: a fan from its reflex corner's neighbour would leave
# the polygon; the planar triangulation stays inside it.
printf 'OFF\n6 1 0\n0 0 0\n2 0 0\n2 1 0\n1 1 0\n1 2 0\n0 2 0\n6 0 1 2 3 4 5\n' > "$work/l_shape.off"
expect_repaired 4 "$work/l_shape.off" --triangulate
grep -q '"fan_triangulations": 0' "$work/r.json" && pass || fail "the L-shaped hexagon fell back to a fan"
# A cube of quads, closed: 12 triangles after triangulation.
printf 'OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n' > "$work/cube.off"
expect_repaired 12 "$work/cube.off" --triangulate
expect_repaired 12 "$work/cube.off" --triangulate --repair
# A cap on chart size: no chart above it, every chart still valid.
"$tool" "$data/elephant.off" --max-chart-faces 300 --patch-ids "$work/cap_ids.txt" --report "$work/cap.json" \
  > /dev/null 2> "$work/err.txt" || fail "capped run failed: $(cat "$work/err.txt")"
largest=$(sort -n "$work/cap_ids.txt" | uniq -c | sort -n | tail -1 | awk '{print $1}')
[ "$largest" -le 300 ] && pass || fail "a chart has $largest faces, above the cap of 300"
grep -q '"invalid_charts": 0' "$work/cap.json" && pass || fail "capped run has invalid charts"

# --- the input is never overwritten
cp "$data/elephant.off" "$work/keep.off"
"$tool" "$work/keep.off" --colored "$work/keep.off" > /dev/null 2> "$work/err.txt"
[ $? -eq 1 ] && cmp -s "$data/elephant.off" "$work/keep.off" && pass || fail "input file was overwritten"

# --- SIGINT and SIGTERM stop the run at its next progress report; nothing is
# written. The input comes through a FIFO: the tool has opened it (and
# installed its handler) when the writer's open returns, and the signal
# arrives before the mesh is whole, so the run is still ahead.
# Job control, so that the background run does not start with SIGINT ignored.
set -m
for signal in INT TERM; do
  rm -f "$work/signal.off" "$work/signal.obj"
  mkfifo "$work/signal.off"
  "$tool" "$work/signal.off" --allow-special-input -o "$work/signal.obj" > /dev/null 2> "$work/err.txt" &
  pid=$!
  # Bounded: should the tool end without opening the FIFO, the open would wait forever.
  timeout 120 bash -c 'exec 3> "$1" && kill -s "$2" "$3" && cat "$4" >&3' _ \
    "$work/signal.off" "$signal" "$pid" "$data/elephant.off" || kill "$pid" 2> /dev/null
  wait "$pid"
  status=$?
  expected=$((128 + $(kill -l "$signal")))
  [ "$status" -eq "$expected" ] && pass || fail "SIG$signal: exit status $status, expected $expected"
  grep -q "^disk_uv: stopped by SIG$signal.* during the segmentation; no output was written$" "$work/err.txt" \
    && pass || fail "SIG$signal: message '$(cat "$work/err.txt")'"
  left=$(ls -a "$work" | grep "signal" | grep -vx "signal.off")
  [ -z "$left" ] && pass || fail "SIG$signal: an output or temporary was left: $left"
done
# The same in the writing, with many outputs (one picture per page: more
# than the 16 temporaries an earlier version could remove): the run stops
# at its next block written, every temporary file is removed and the same
# line is printed; a second signal ends it at once, also removing them all.
# The OBJ goes to a FIFO that nobody reads yet, so the tool waits in that
# write (write-through outputs come after every temporary file): the test
# sends its signals once the kernel says the tool waits in a pipe write,
# then reads the FIFO to its end (the end comes when the tool is gone).
mkdir -p "$work/w"
python3 -c "
n = 2000
lines = ['OFF', '%d %d 0' % (3 * n, n)]
for i in range(n):
    x, y = 3.0 * (i % 50), 3.0 * (i // 50)
    lines += ['%g %g 0' % (x, y), '%g %g 0' % (x + 1, y), '%g %g 0' % (x + .5, y + .866)]
lines += ['3 %d %d %d' % (3 * i, 3 * i + 1, 3 * i + 2) for i in range(n)]
open('$work/w/triangles.off', 'w').write('\\n'.join(lines) + '\\n')"
for signals in "INT" "INT TERM"; do
  rm -f "$work/w/fifo.obj"
  mkfifo "$work/w/fifo.obj"
  # Held open for reading and writing: the tool's open finds a reader.
  exec 3<> "$work/w/fifo.obj"
  "$tool" "$work/w/triangles.off" --resolution 64 --padding 1 --texels-per-unit 5 -o "$work/w/fifo.obj" \
    --atlas-png "$work/w/page.png" --glb "$work/w/atlas.glb" --report "$work/w/report.json" -q \
    > /dev/null 2> "$work/err.txt" 3>&- &
  pid=$!
  waiting=0
  for i in $(seq 1 1200); do
    if grep -q pipe_write "/proc/$pid/wchan" 2> /dev/null; then waiting=1; break; fi
    sleep 0.1
  done
  temporaries=$(ls -A "$work/w" | grep -c 'disk_uv-')
  [ "$waiting" -eq 1 ] && [ "$temporaries" -gt 16 ] && pass \
    || fail "signal while writing: the tool did not wait in the FIFO with its temporaries ($temporaries)"
  for signal in $signals; do kill -s "$signal" "$pid"; sleep 0.3; done
  # A read end of the shell's own (opened at once: fd 3 writes), handed to
  # the reader; the end of the input comes once the tool is gone.
  exec 4< "$work/w/fifo.obj"
  cat <&4 3>&- 4<&- > /dev/null &
  reader=$!
  exec 3>&- 4<&-
  wait "$pid"
  status=$?
  wait "$reader"
  last_signal=${signals##* }
  expected=$((128 + $(kill -l "$last_signal")))
  [ "$status" -eq "$expected" ] && pass || fail "SIG$signals while writing: exit status $status, expected $expected"
  if [ "$signals" = INT ]; then
    message="^disk_uv: stopped by SIGINT.* during the writing of the outputs; no output was written$"
  else
    message="^disk_uv: stopped at once by a second signal; its temporary files were removed$"
  fi
  grep -q "$message" "$work/err.txt" && pass || fail "SIG$signals while writing: message '$(cat "$work/err.txt")'"
  left=$(ls -A "$work/w" | grep -v -x -e triangles.off -e fifo.obj)
  [ -z "$left" ] && pass || fail "SIG$signals while writing: left $(echo "$left" | wc -l) files: $(echo "$left" | head -3)"
done
set +m

echo "disk_uv: $passed passed, $failures failed"
[ "$failures" -eq 0 ]
