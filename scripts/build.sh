#!/usr/bin/env bash
# Configures and builds the project (Release) in build/ (or $BUILD_DIR).
#   build.sh [--tool|--python|--manual|--all] [CMAKE_ARGUMENT...]
# The first argument picks the Debian packages installed first (see
# scripts/install_dependencies.sh; --all by default); the others go to the
# CMake configure step. $BUILD_TARGETS (space-separated) builds only those
# targets; all by default.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${BUILD_DIR:-$root/build}
profile=--all
case "${1:-}" in
  --tool|--python|--manual|--all) profile=$1; shift ;;
esac
bash "$root/scripts/install_dependencies.sh" "$profile"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release "$@" > "$build.configure.log" 2>&1 \
  || { cat "$build.configure.log"; exit 1; }
targets=()
for target in ${BUILD_TARGETS:-}; do
  targets+=(--target "$target")
done
cmake --build "$build" -j "$(nproc)" "${targets[@]}"
