#!/usr/bin/env bash
# Installs a Disk_segmentation build tree into a fresh temporary prefix, then
# configures, builds and runs the consumer project (next to this script)
# against that prefix only, and checks that it compiled with the installed
# headers, not with the source tree's.
#
#   run_consumer_test.sh CMAKE BUILD_DIR SOURCE_INCLUDE_DIR MESH [CXX_COMPILER]
#
# CMAKE: the cmake program; BUILD_DIR: the configured build tree to install;
# SOURCE_INCLUDE_DIR: the source tree's include/ (must not be used);
# MESH: the mesh the consumer segments. The prefix is removed on success and
# kept (its path is printed) on failure.
set -euo pipefail

if [ $# -lt 4 ]; then
  echo "usage: $0 CMAKE BUILD_DIR SOURCE_INCLUDE_DIR MESH [CXX_COMPILER]" >&2
  exit 2
fi
cmake_program=$1
build_dir=$2
source_include=$(cd "$3" && pwd -P)
mesh=$4
cxx_compiler=${5:-}
consumer_source=$(cd "$(dirname "$0")" && pwd -P)

prefix=$(mktemp -d "${TMPDIR:-/tmp}/disk_segmentation_install.XXXXXX")
prefix=$(cd "$prefix" && pwd -P)
consumer_build=$prefix/consumer-build

fail() {
  echo "install_and_consume: $*" >&2
  echo "install_and_consume: prefix and consumer build kept in $prefix" >&2
  exit 1
}

echo "== install $build_dir into $prefix"
"$cmake_program" --install "$build_dir" --prefix "$prefix" >"$prefix/install.log" \
  || { cat "$prefix/install.log"; fail "cmake --install failed"; }

for header in CGAL/Disk_segmentation.h CGAL/Disk_segmentation/segment_into_disks.h \
              CGAL/Disk_segmentation/parameters.h CGAL/Disk_segmentation/internal/Segmentation/Voronoi_fps.h; do
  [ -f "$prefix/include/$header" ] || fail "$header was not installed under $prefix/include"
done
config=$(find "$prefix" -path '*/cmake/Disk_segmentation/Disk_segmentationConfig.cmake' -print -quit)
[ -n "$config" ] || fail "Disk_segmentationConfig.cmake was not installed"
for file in Disk_segmentationConfigVersion.cmake Disk_segmentationTargets.cmake; do
  [ -f "$(dirname "$config")/$file" ] || fail "$file was not installed next to $config"
done
echo "installed: $(find "$prefix/include" -name '*.h' | wc -l) headers, $config"

echo "== configure the consumer against $prefix"
configure_args=(-S "$consumer_source" -B "$consumer_build"
                -DCMAKE_BUILD_TYPE=Release
                -DCMAKE_PREFIX_PATH="$prefix"
                -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
                -DCMAKE_EXPORT_COMPILE_COMMANDS=ON)
if [ -n "$cxx_compiler" ]; then
  configure_args+=(-DCMAKE_CXX_COMPILER="$cxx_compiler")
fi
"$cmake_program" "${configure_args[@]}" || fail "the consumer does not configure"

found_dir=$(sed -n 's/^Disk_segmentation_DIR:PATH=//p' "$consumer_build/CMakeCache.txt")
[ "$found_dir" = "$(dirname "$config")" ] \
  || fail "find_package found Disk_segmentation in '$found_dir', not in the fresh prefix"

echo "== build the consumer"
"$cmake_program" --build "$consumer_build" -j2 || fail "the consumer does not build"

# The compile line must name the prefix and not the source tree; the
# compiler's dependency file says which headers were really read.
commands=$consumer_build/compile_commands.json
grep -q -- "$prefix/include" "$commands" || fail "the compile line does not use $prefix/include"
if grep -q -- "$source_include" "$commands"; then
  fail "the compile line uses the source tree's $source_include"
fi
depfile=$(find "$consumer_build" -name 'consumer.cpp.o.d' -print -quit)
if [ -n "$depfile" ]; then
  grep -q -- "$prefix/include/CGAL/Disk_segmentation/segment_into_disks.h" "$depfile" \
    || fail "the consumer did not read the installed segment_into_disks.h"
  if grep -q -- "$source_include/CGAL/Disk_segmentation" "$depfile"; then
    fail "the consumer read headers from the source tree $source_include"
  fi
  echo "headers read from $prefix/include (checked in $(basename "$depfile"))"
else
  echo "no compiler dependency file; checked the compile line only"
fi

echo "== run the consumer on $mesh"
output=$("$consumer_build/consumer" "$mesh") || { echo "$output"; fail "the consumer failed"; }
echo "$output"
echo "$output" | grep -Eq '^patches: [1-9][0-9]*' || fail "unexpected consumer output"

# TBB is optional for a consumer: without it the same project configures,
# builds and runs on one thread.
echo "== the consumer again, without TBB"
"$cmake_program" "${configure_args[@]}" -B "$consumer_build-without-tbb" -DCMAKE_DISABLE_FIND_PACKAGE_TBB=ON \
  || fail "the consumer does not configure without TBB"
"$cmake_program" --build "$consumer_build-without-tbb" -j2 || fail "the consumer does not build without TBB"
output=$("$consumer_build-without-tbb/consumer" "$mesh") || { echo "$output"; fail "the consumer without TBB failed"; }
echo "$output"
echo "$output" | grep -qx 'TBB: no' || fail "the consumer built without TBB still links it"

rm -rf "$prefix"
echo "install_and_consume: OK"
