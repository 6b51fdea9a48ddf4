#!/usr/bin/env bash
# Installs what building and testing ridt needs from Debian 12, if it is missing.
# Usage: scripts/deps.sh [build|test|bench|fuzz|python]
#   bench: also Qhull, Triangle (its library and its command) and node, and delaunator from npm into build/peers/node_modules
#   (for build/ridt_bench_peers --node-modules build/peers/node_modules). Triangle
#   (libtriangle-dev) is in Debian's non-free component: where apt has no candidate for it, bench
#   adds that component in /etc/apt/sources.list.d/ridt-non-free.sources (delete it to undo).
set -euo pipefail
sudo=""
[ "$(id -u)" -ne 0 ] && sudo=sudo
packages=(g++ cmake ninja-build libcli11-dev libpng-dev libgdal-dev)  # GDAL: GIS formats (ridt tin, ridt dem)
if [ "${1:-build}" = test ] || [ "${1:-build}" = bench ]; then
  packages+=(libgtest-dev libcgal-dev python3 python3-matplotlib)
  packages+=(ccache)  # scripts/test.sh: pip's build of the library reuses the Release build's objects
  packages+=(libopenmpi-dev openmpi-bin)  # ridt-mpi and its tests
  packages+=(gdal-bin python3-gdal)  # the terrain tests read outputs back with GDAL, compare with gdal_grid
  # The Python package and its tests (Debian's interpreter, /usr/bin/python3).
  packages+=(python3-dev python3-venv python3-pip python3-setuptools python3-wheel pybind11-dev python3-pybind11
             python3-numpy python3-scipy python3-pytest python3-hypothesis python3-tqdm)
fi
if [ "${1:-build}" = test ] || [ "${1:-build}" = fuzz ]; then
  packages+=(clang libclang-rt-14-dev clang-format-14)  # libFuzzer; the layout check
fi
if [ "${1:-build}" = python ]; then
  packages+=(python3-dev python3-venv python3-pip python3-setuptools python3-wheel pybind11-dev python3-pybind11 python3-numpy)
fi
if [ "${1:-build}" = bench ]; then
  packages+=(libqhull-dev libtriangle-dev triangle-bin)  # the library for the in-process tables, the command for the whole-process ones
  if ! grep -q "Candidate: [0-9]" <<<"$(apt-cache policy libtriangle-dev 2>/dev/null)"; then
    codename=$(. /etc/os-release && echo "${VERSION_CODENAME:-bookworm}")
    echo "adding Debian's non-free component for Triangle: /etc/apt/sources.list.d/ridt-non-free.sources"
    printf 'Types: deb\nURIs: http://deb.debian.org/debian\nSuites: %s\nComponents: non-free\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' \
      "$codename" | $sudo tee /etc/apt/sources.list.d/ridt-non-free.sources >/dev/null
  fi
  command -v node >/dev/null || packages+=(nodejs)
  command -v npm >/dev/null || packages+=(npm)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
  echo "installing: ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
if [ "${1:-build}" = bench ] && [ ! -d build/peers/node_modules/delaunator ]; then
  mkdir -p build/peers
  npm install --silent --prefix build/peers delaunator@5
fi
