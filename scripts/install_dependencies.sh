#!/usr/bin/env bash
# Installs the Debian 12 packages the project needs, only those missing,
# plus any package named as an argument (scripts/run_fuzzer.sh adds clang).
# Needs root (or sudo) when something is missing; does nothing otherwise.
set -euo pipefail

packages=(
  g++ cmake make
  libcgal-dev libeigen3-dev libboost-dev libtbb-dev libgmp-dev libmpfr-dev
  libgtest-dev libbenchmark-dev
  libcli11-dev nlohmann-json3-dev libtinygltf-dev libstb-dev pkg-config
  doxygen graphviz libjs-mathjax
  pybind11-dev python3-dev python3-numpy python3-pytest python3-distributed blender
  "$@"
)

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
