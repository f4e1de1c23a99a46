#!/usr/bin/env bash
# The disk_uv tool's readers are strict and bounded: inputs that are not
# regular files are refused at once (a FIFO without a writer must not
# block, a device must not be read forever) unless --allow-special-input
# is given, counts larger than the file are refused before anything is
# allocated, and each bad file gets one line naming the line and token.
# Every run is under `timeout 20`, so that a hang fails instead of blocking.
# usage: test_disk_uv_inputs.sh PATH/TO/disk_uv DATA_DIR
set -u
tool=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
data=$2
work=$(mktemp -d)
writer=
trap '[ -n "$writer" ] && kill "$writer" 2> /dev/null; rm -rf "$work"' EXIT
cd "$work" || exit 1
failures=0
passed=0

fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
pass() { passed=$((passed + 1)); }
# A run's memory is limited to memory_limit_kb when that is set: by
# `ulimit -v`, or, for a tool built with AddressSanitizer (which reserves
# terabytes of virtual memory at start), by ASan's own limits on one
# allocation and on the resident size (a run over them aborts, not exit 1).
if grep -qa -e __asan_init -e AddressSanitizer "$tool" 2> /dev/null; then sanitized=1; else sanitized=0; fi
run() {
  ( if [ -n "${memory_limit_kb:-}" ]; then
      if [ "$sanitized" -eq 1 ]; then
        limit_mb=$((memory_limit_kb / 1024))
        export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}max_allocation_size_mb=$limit_mb:hard_rss_limit_mb=$limit_mb"
      else
        ulimit -v "$memory_limit_kb"
      fi
    fi
    exec timeout 20 "$tool" "$@" --patch-ids ids.txt ) > out.txt 2> err.txt
}
# expect_error MESSAGE ARGS...: exit status 1 and one line on stderr matching MESSAGE.
expect_error() {
  local message=$1
  shift
  rm -f ids.txt
  run "$@"
  local got=$?
  if [ "$got" -eq 124 ]; then fail "'$*' still ran after 20 s"; return; fi
  if [ "$got" -ne 1 ]; then fail "'$*' exited $got, expected 1 ($(cat err.txt))"; return; fi
  if ! grep -qiE -- "$message" err.txt; then fail "'$*' said '$(cat err.txt)', expected '$message'"; return; fi
  if [ "$(wc -l < err.txt)" -ne 1 ]; then fail "'$*' printed more than one line: $(cat err.txt)"; return; fi
  if [ -e ids.txt ]; then fail "'$*' wrote an output"; return; fi
  pass
}
# expect_faces COUNT ARGS...: the run succeeds with COUNT faces.
expect_faces() {
  local faces=$1
  shift
  rm -f ids.txt
  if ! run "$@"; then fail "'$*' failed: $(cat err.txt)"; return; fi
  if [ "$(wc -l < ids.txt)" -ne "$faces" ]; then fail "'$*': $(wc -l < ids.txt) faces, expected $faces"; return; fi
  pass
}

# An octahedron, the valid mesh of the accepted cases.
octahedron='OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n'

# --- inputs that are not regular files; the extension picks the format.
for ext in off obj ply stl ts; do
  ln -s /dev/zero "zero.$ext"
  expect_error "'zero.$ext' is not a regular file \(it is a character device\)" "zero.$ext"
done
ln -s /dev/urandom random.stl
ln -s /dev/urandom random.ply
expect_error "not a regular file" random.stl
expect_error "not a regular file" random.ply
mkfifo pipe.off
expect_error "'pipe.off' is not a regular file \(it is a FIFO\).*--allow-special-input" pipe.off
mkdir folder.off
expect_error "'folder.off' is a directory" folder.off
expect_error "cannot open 'missing.off'" missing.off

# --- --allow-special-input reads a FIFO to its end, with the same checks.
printf "$octahedron" > pipe.off &
writer=$!
expect_faces 8 pipe.off --allow-special-input
wait "$writer" 2> /dev/null
head -c 10000000 /dev/zero | tr '\0' ' ' > pipe.off &
writer=$!
expect_error "line 1: longer than 1 MiB without a line break" pipe.off --allow-special-input
kill "$writer" 2> /dev/null
wait "$writer" 2> /dev/null
writer=

# --- counts larger than the file: refused before allocating. Under a 2 GB
# limit on virtual memory, allocating for the declared count would fail
# with another message.
ply_header='ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n'
{ printf "${ply_header}element face 1\nproperty list uint int vertex_indices\nend_header\n"
  head -c 36 /dev/zero; printf '\x00\xca\x9a\x3b'; head -c 1000 /dev/zero; } > long_list.ply
memory_limit_kb=2000000 expect_error "face #0: the list 'vertex_indices' declares 1000000000 entries, more than the 1000 bytes" long_list.ply
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1000000000\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' > many_faces.ply
memory_limit_kb=2000000 expect_error "line 7: 1000000000 items of element 'face' do not fit" many_faces.ply
{ head -c 80 /dev/zero; printf '\xff\xff\xff\x0f'; head -c 500 /dev/zero; } > many_triangles.stl
memory_limit_kb=2000000 expect_error "header declares 268435455 triangles, but its 584 bytes hold at most 10" many_triangles.stl
printf 'OFF\n100000000 1 0\n0 0 0\n' > many_vertices.off
memory_limit_kb=2000000 expect_error "line 2: 100000000 vertices and 1 faces do not fit" many_vertices.off
{ printf 'OFF\n3 1 0\n'; head -c 10000000 /dev/zero | tr '\0' '1'; } > long_line.off
expect_error "line 3: longer than 1 MiB without a line break" long_line.off
# 2 GiB (sparse: zeros) without a line break: refused at its first MiB,
# under a memory limit far below the file's size.
truncate -s 2G huge_line.obj
memory_limit_kb=500000 expect_error "line 1: longer than 1 MiB without a line break" huge_line.obj
{ printf 'ply\nformat ascii 1.0\n'; } > huge_ply_header.ply
truncate -s 2G huge_ply_header.ply
memory_limit_kb=500000 expect_error "line 3: longer than 1 MiB without a line break" huge_ply_header.ply
printf 'solid s\nfacet normal 0 0 1\n' > huge_ascii.stl
truncate -s 2G huge_ascii.stl
memory_limit_kb=500000 expect_error "line 3: longer than 1 MiB without a line break" huge_ascii.stl
rm -f huge_line.obj huge_ply_header.ply huge_ascii.stl
# Through a pipe that never ends: refused at its first long line, not at
# the end of the input (the writer stays open).
mkfifo endless.off
{ printf 'OFF\n'; head -c 3000000 /dev/zero | tr '\0' '7'; exec sleep 60; } > endless.off 2> /dev/null &
writer=$!
expect_error "line 2: longer than 1 MiB without a line break" endless.off --allow-special-input
kill "$writer" 2> /dev/null
writer=

# --- each bad file: one line of ours naming the line and the token.
printf 'ply\nformat ascii\nend_header\n' > ply_bad_format.ply
expect_error "line 2: expected 'format ascii 1.0'" ply_bad_format.ply
printf 'ply\nformat binary_middle_endian 1.0\nend_header\n' > ply_unknown_format.ply
expect_error "line 2: unknown format 'binary_middle_endian'" ply_unknown_format.ply
printf 'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list char int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n-1 0 1 2\n' > ply_negative_list_count.ply
expect_error "line 13: face #0: the list 'vertex_indices' has the length '-1', a negative count" ply_negative_list_count.ply
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 abc\n' > word.obj
expect_error "line 6: 'abc' is not a vertex index" word.obj
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 1e23\n' > exponent.obj
expect_error "line 4: '1e23' is not a vertex index" exponent.obj
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv nan 0 0\nf 1 2 3\n' > nan.obj
expect_error "line 4: vertex #3 has a non-finite coordinate 'nan'" nan.obj
printf 'v 0 0 0\nv 1 0 0\nv 0 1e400 0\nf 1 2 3\n' > overflow.obj
expect_error "line 3: vertex #2 has a non-finite coordinate '1e400'" overflow.obj
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 -7\n' > relative.obj
expect_error "line 6: index -7 refers to no vertex \(4 vertices so far\)" relative.obj
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n' > beyond.obj
expect_error "line 4: index 4 refers to no vertex \(the file has 3 vertices\)" beyond.obj
printf 'OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n' > nan.off
expect_error "line 4: vertex #1 has a non-finite coordinate 'nan'" nan.off
printf 'solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nvertex 1 1 0\nendloop\nendfacet\nendsolid s\n' > quad.stl
expect_error "line 7: facet #0 has more than 3 vertices" quad.stl
printf 'GOCAD TSurf 1\nTFACE\nVRTX 1 0 0 0\nVRTX 2 1 0 0\nTRGL 1 2 3\nEND\n' > missing_vertex.ts
expect_error "line 5: the triangle refers to vertex id 3, which no VRTX line defines" missing_vertex.ts

# --- valid files the readers used to refuse or misread
printf 'v\t1 0 0\nv\t-1 0 0\nv\t0 1 0\nv\t0 -1 0\nv\t0 0 1\nv\t0 0 -1\nf\t1\t3\t5\nf\t3\t2\t5\nf\t2\t4\t5\nf\t4\t1\t5\nf\t3\t1\t6\nf\t2\t3\t6\nf\t4\t2\t6\nf\t1\t4\t6\n' > tabs.obj
expect_faces 8 tabs.obj
printf "$octahedron" | sed 's/$/\r/' > crlf.off
expect_faces 8 crlf.off

echo "disk_uv inputs: $passed passed, $failures failed"
[ "$failures" -eq 0 ]
