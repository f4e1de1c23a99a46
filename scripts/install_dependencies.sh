#!/usr/bin/env bash
# Installs the Debian 12 packages a part of the project needs, only those
# missing, plus any package named as an argument (scripts/run_fuzzer.sh adds
# clang). Needs root (or sudo) when something is missing; does nothing
# otherwise.
#   install_dependencies.sh [--tool|--python|--manual|--all] [PACKAGE...]
# --tool: the C++ headers' dependencies and the disk_uv tool's (README
# command 1); --python: those and the Python module's, the batch's and
# Blender; --manual: Doxygen; --all (the default): everything the test suite
# builds and runs (README command 2).
set -euo pipefail

tool=(
  g++ cmake make
  libcgal-dev libeigen3-dev libboost-dev libtbb-dev libgmp-dev libmpfr-dev
  libcli11-dev nlohmann-json3-dev libtinygltf-dev libstb-dev pkg-config
)
python=(pybind11-dev python3-dev python3-numpy python3-pytest python3-distributed blender)
manual=(doxygen graphviz libjs-mathjax)
tests=(libgtest-dev libbenchmark-dev)

profile=all
extra=()
for arg in "$@"; do
  case "$arg" in
    --tool|--python|--manual|--all) profile=${arg#--} ;;
    --*) echo "usage: $0 [--tool|--python|--manual|--all] [PACKAGE...]" >&2; exit 2 ;;
    *) extra+=("$arg") ;;
  esac
done
case "$profile" in
  tool) packages=("${tool[@]}") ;;
  python) packages=("${tool[@]}" "${python[@]}") ;;
  manual) packages=("${tool[@]}" "${manual[@]}") ;;
  all) packages=("${tool[@]}" "${tests[@]}" "${manual[@]}" "${python[@]}") ;;
esac
packages+=("${extra[@]}")

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "Installing missing Debian packages: ${missing[*]}"
if [ "$(id -u)" -eq 0 ]; then
  sudo=()
elif command -v sudo >/dev/null 2>&1; then
  sudo=(sudo)
else
  echo "error: missing packages (${missing[*]}) and not root; install them as root" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -q
"${sudo[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
