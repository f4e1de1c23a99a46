#!/usr/bin/env bash
# The disk_uv tool never destroys a file: the input is refused as an output
# under any spelling of its path, two outputs may not share a file, a failed
# run leaves every earlier output as it was, devices and links are written
# through or followed (never replaced by regular files), write errors are
# reported, and bad counts are refused before any work.
# usage: test_disk_uv_outputs.sh PATH/TO/disk_uv DATA_DIR
set -u
tool=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
data=$(cd "$2" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
failures=0
passed=0

fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
pass() { passed=$((passed + 1)); }
run() { timeout 60 "$tool" "$@" > out.txt 2> err.txt; }
no_temporary_left() { # folder
  if ls -A "$1" | grep -q 'disk_uv-'; then fail "a temporary file was left in $1: $(ls -A "$1")"; else pass; fi
}
# expect_refused STATUS MESSAGE ARGS...: exits STATUS, one line naming MESSAGE.
expect_refused() {
  local status=$1 message=$2
  shift 2
  run "$@"
  local got=$?
  if [ "$got" -ne "$status" ]; then fail "'$*' exited $got, expected $status ($(cat err.txt))"; return 1; fi
  if ! grep -qiE -- "$message" err.txt; then fail "'$*' said '$(cat err.txt)', expected '$message'"; return 1; fi
  if [ "$status" -eq 1 ] && [ "$(wc -l < err.txt)" -ne 1 ]; then fail "'$*' printed more than one line"; return 1; fi
  pass
}
same_content() { # file reference what; restores the file for the next case
  if cmp -s "$1" "$2"; then pass; else fail "$3: '$1' was changed"; cp "$2" "$1"; fi
}

# Devices written to: as root, private copies of /dev/null and /dev/full,
# so that a tool that replaces its outputs cannot replace the machine's.
# (A folder mounted nodev refuses to open them: then the real ones.)
if [ "$(id -u)" -eq 0 ] && mknod -m 666 "$work/null" c 1 3 && mknod -m 666 "$work/full" c 1 7 &&
   (echo > "$work/null") 2> /dev/null; then
  null=$work/null full=$work/full
else
  null=/dev/null full=/dev/full
fi

# A small closed mesh (octahedron) as the input.
mkdir -p dir
printf 'OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n' > dir/x.off
cp dir/x.off reference.off

# --- 1. the input under another spelling of its path
cd dir
for spelling in "./x.off" "$work/dir/x.off" "../dir/x.off" "$work/dir/../dir/./x.off"; do
  expect_refused 1 "is the input file" x.off -o "$spelling"
  same_content x.off ../reference.off "-o $spelling"
done
expect_refused 1 "is the input file" x.off --report ./x.off
same_content x.off ../reference.off "--report ./x.off"
expect_refused 1 "is the input file" x.off --patch-ids x.off
ln -s x.off l.off
expect_refused 1 "is the input file" l.off -o x.off
same_content x.off ../reference.off "input through a symbolic link"
ln x.off hard.off
expect_refused 1 "is the input file" x.off -o hard.off
same_content x.off ../reference.off "output through a hard link"
rm -f l.off hard.off
# Every file the run reads is protected: the --material-ids file too.
seq 1 8 > ids.txt
cp ids.txt ../ids.reference
for spelling in "ids.txt" "./ids.txt" "$work/dir/ids.txt" "../dir/ids.txt"; do
  for option in -o --report --patch-ids --glb --colored --atlas-png; do
    expect_refused 1 "cannot write $option '.*': it is the --material-ids file" x.off --material-ids ids.txt \
      "$option" "$spelling"
    same_content ids.txt ../ids.reference "$option $spelling over --material-ids"
  done
done
ln ids.txt ids_hard.txt
expect_refused 1 "it is the --material-ids file" x.off --material-ids ids.txt -o ids_hard.txt
same_content ids.txt ../ids.reference "-o through a hard link to --material-ids"
rm -f ids.txt ids_hard.txt
cd "$work"

# --- 2. two outputs on one file: refused before any work
expect_refused 1 "given to both -o and --report" dir/x.off -o a.obj --report a.obj
[ -e a.obj ] && fail "a.obj written although two outputs share it" || pass
[ -s out.txt ] && fail "work was done before refusing two outputs on one file" || pass
expect_refused 1 "given to both -o and --glb" dir/x.off -o a.obj --glb ./a.obj
mkdir -p sub
expect_refused 1 "given to both" dir/x.off --colored sub/c.ply --patch-ids ./sub/../sub/c.ply
# $null twice loses nothing.
run dir/x.off -o "$null" --glb "$null" && pass || fail "two outputs to $null refused: $(cat err.txt)"

# --- 3. a failed run replaces nothing
echo "old atlas" > out.obj
cp out.obj out.reference
echo "old report" > r.json
expect_refused 1 "folder '/missing/dir' does not exist" dir/x.off -o out.obj --report /missing/dir/r.json
same_content out.obj out.reference "missing output folder"
expect_refused 2 "resolution between 1 and" dir/x.off -o out.obj --atlas-png a.png --resolution 20000
same_content out.obj out.reference "too large a PNG"
[ -s out.txt ] && fail "work was done before refusing the PNG resolution" || pass
# A write that fails after other outputs were written: nothing is replaced.
expect_refused 1 "error while writing '$full'.*space" dir/x.off -o out.obj --report r.json --glb "$full"
same_content out.obj out.reference "a later output failed"
[ "$(cat r.json)" = "old report" ] && pass || fail "r.json replaced although --glb failed"
no_temporary_left "$work"
# A folder as output, a link to a missing file.
expect_refused 1 "it is a folder" dir/x.off -o sub
ln -s missing/target.obj dangling.obj
expect_refused 1 "symbolic link to a missing file" dir/x.off -o dangling.obj
# A file in a folder that cannot be written (root may write anywhere).
if [ "$(id -u)" -ne 0 ]; then
  mkdir locked && chmod 555 locked
  expect_refused 1 "not writable" dir/x.off -o locked/a.obj
  chmod 755 locked
fi

# --- 4. devices, pipes and links
run dir/x.off -o "$null" --report "$null" && pass || fail "-o $null failed: $(cat err.txt)"
[ -c "$null" ] && pass || fail "$null is no longer a character device"
ln -s "$null" null_link.obj
run dir/x.off -o null_link.obj && pass || fail "output through a link to $null failed"
[ -L null_link.obj ] && pass || fail "the link to $null was replaced"
[ -c "$null" ] && pass || fail "$null is no longer a character device"
echo "old" > real.obj
chmod 640 real.obj
ln -s real.obj link.obj
run dir/x.off -o link.obj && pass || fail "output through a link failed: $(cat err.txt)"
[ -L link.obj ] && pass || fail "the output link was replaced by a file"
grep -q '^vt ' real.obj && pass || fail "the link's target was not written"
[ "$(stat -c %a real.obj)" = "640" ] && pass || fail "the replaced file lost its permissions ($(stat -c %a real.obj))"
# Standard output through /proc/self/fd/1, here a pipe.
ln -s /proc/self/fd/1 stdout_link.obj
timeout 60 "$tool" dir/x.off -q -o stdout_link.obj 2> err.txt | cat > piped.obj
[ "${PIPESTATUS[0]}" -eq 0 ] && pass || fail "output to a pipe through /proc/self/fd/1 failed: $(cat err.txt)"
grep -q '^vt ' piped.obj && pass || fail "nothing came through the pipe"
[ -L stdout_link.obj ] && pass || fail "the link to standard output was replaced"
# A pipe nobody reads: refused at once, no block.
mkfifo fifo.obj
expect_refused 1 "pipe that nobody reads" dir/x.off -o fifo.obj
[ -p fifo.obj ] && pass || fail "the FIFO was replaced"
no_temporary_left "$work"

# --- 8. counts and names
expect_refused 2 "" dir/x.off -o ""
for bad in "-n -1" "--seeds=-1" "-n 99999999999999999999999" "--max-chart-faces -1" "--threads -1" \
           "--resolution -5" "-k -2" "-n 1.5" "-n 12abc"; do
  rm -f ids.txt
  # shellcheck disable=SC2086
  expect_refused 2 "non-negative integer|too large" dir/x.off $bad --patch-ids ids.txt
  [ -e ids.txt ] && fail "'$bad' wrote an output" || pass
done
# Parameters are checked before the input is read.
expect_refused 2 "^disk_uv: error: -k/--subsamples must be at least 2" missing.off -k 1
expect_refused 2 "^disk_uv: error: --padding must be" missing.off --padding -1
# A good run still writes everything.
run dir/x.off -o good.obj --report good.json --patch-ids good.txt && pass || fail "good run failed: $(cat err.txt)"
[ "$(wc -l < good.txt)" -eq 8 ] && pass || fail "patch ids not written"
no_temporary_left "$work"

# --- 9. long names, stale temporaries, the user's flags in messages
# The longest legal names: their temporary names must still fit NAME_MAX.
long=$(printf 'a%.0s' $(seq 1 251)).obj
run dir/x.off -o "$long" && pass || fail "a 255-byte output name was refused: $(cat err.txt)"
grep -q '^vt ' "$long" && pass || fail "the 255-byte output was not written"
accented=$(printf '\303\251%.0s' $(seq 1 120)).obj
run dir/x.off -o "$accented" --report "$accented.json" && pass || fail "a 244-byte UTF-8 output name was refused: $(cat err.txt)"
[ -s "$accented" ] && [ -s "$accented.json" ] && pass || fail "the 244-byte outputs were not written"
rm -f "$long" "$accented" "$accented.json"
no_temporary_left "$work"
# A run killed while writing left temporaries: the next run for that
# output removes them; a live process's, or another output's, stay.
dead=$(sh -c 'echo $$')
touch ".t.obj.disk_uv-$dead-0" ".t.obj.disk_uv-$$-0" ".u.obj.disk_uv-$dead-0" ".t.obj.disk_uv-x-0"
run dir/x.off -o t.obj && pass || fail "run with stale temporaries failed: $(cat err.txt)"
[ -e ".t.obj.disk_uv-$dead-0" ] && fail "a dead run's temporary was left" || pass
[ -e ".t.obj.disk_uv-$$-0" ] && pass || fail "a live process's temporary was removed"
[ -e ".u.obj.disk_uv-$dead-0" ] && pass || fail "another output's temporary was removed"
[ -e ".t.obj.disk_uv-x-0" ] && pass || fail "a file not named as a temporary was removed"
rm -f ".t.obj.disk_uv-$$-0" ".u.obj.disk_uv-$dead-0" ".t.obj.disk_uv-x-0"
# A killed run's temporaries of page pictures go with the next run to that
# picture, whatever the pages either run had; other files stay.
mkdir -p pages
touch "pages/.p.1007.png.disk_uv-$dead-0" "pages/.p.png.disk_uv-$dead-3" "pages/.q.1007.png.disk_uv-$dead-0" \
  "pages/.p.1007.png.disk_uv-$$-0" "pages/.p.10077.png.disk_uv-$dead-0"
run dir/x.off --atlas-png pages/p.png && pass || fail "run beside page temporaries failed: $(cat err.txt)"
[ -e "pages/.p.1007.png.disk_uv-$dead-0" ] || [ -e "pages/.p.png.disk_uv-$dead-3" ] \
  && fail "a dead run's page-picture temporary was left: $(ls -A pages)" || pass
[ -e "pages/.q.1007.png.disk_uv-$dead-0" ] && [ -e "pages/.p.1007.png.disk_uv-$$-0" ] \
  && [ -e "pages/.p.10077.png.disk_uv-$dead-0" ] && pass || fail "another picture's or a live run's temporary was removed"
# Page pictures that are not of this atlas (an earlier run's, with more
# pages) stay, and are said: a UDIM reader would take them for its pages.
touch pages/p.1001.png pages/p.1003.png pages/p.0999.png pages/p.1001.jpg
run dir/x.off --atlas-png pages/p.png && pass || fail "run beside page pictures failed: $(cat err.txt)"
grep -q "warning: 2 UDIM page pictures not of this atlas are beside --atlas-png 'pages/p.png' (p.1001.png, p.1003.png)" \
  err.txt && [ -e pages/p.1001.png ] && [ -e pages/p.1003.png ] && pass \
  || fail "earlier page pictures not said or removed: $(cat err.txt)"
rm -rf pages
# Several inputs: the chart budget is each input's, and said; a tiny mesh
# among large ones gets charts below a texel, and said.
awk 'NR <= 2 || NF != 3 || /^3 / { print; next } { print $1 * 1e-6, $2 * 1e-6, $3 * 1e-6 }' dir/x.off > tiny.off
run "$data/eight.off" tiny.off --max-charts 2 -o both.obj && pass || fail "two inputs failed: $(cat err.txt)"
grep -qE "warning: [0-9]+ charts in all: --max-charts \(2\) is a budget for each of the 2 inputs" err.txt \
  && grep -qE "warning: [0-9]+ of [0-9]+ charts are smaller than one texel of a --resolution 1024 texture: " err.txt \
  && pass || fail "per-input budget or sub-texel charts not said: $(cat err.txt)"

# Messages name the options as typed, not the library's parameters.
expect_refused 1 "^disk_uv: error: --padding \(3\) is too large" dir/x.off --resolution 8 --padding 3
expect_refused 2 "^disk_uv: error: --max-stretch must be > 1" dir/x.off --max-stretch 0.5
expect_refused 2 "^disk_uv: error: -n/--seeds must be at least 1" dir/x.off -n 0

echo "disk_uv_outputs: $passed passed, $failures failed"
[ "$failures" -eq 0 ]
