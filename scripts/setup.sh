#!/usr/bin/env bash
# Installs the Debian packages rollnoise needs (if missing) and builds it into build/.
# Usage: bash scripts/setup.sh [cmake build type, default Release]
set -euo pipefail
cd "$(dirname "$0")/.."
PACKAGES=(g++ cmake make pkg-config libeigen3-dev libfftw3-dev libgsl-dev libhdf5-dev libcli11-dev
          libtomlplusplus-dev libgtest-dev libbenchmark-dev python3-numpy python3-h5py python3-matplotlib
          libgmsh-dev gmsh libspectra-dev liblapack-dev
          parallel)  # GNU parallel: the study tests run shards under it (docs/study.md)
missing=()
for p in "${PACKAGES[@]}"; do dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p"); done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}" >&2
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}" >/dev/null
fi
BUILD_TYPE=${1:-Release}
# A fresh build/ is a unity build (CMakeLists.txt, ROLLNOISE_UNITY_BUILD: each folder's sources
# compiled in batches of 8, about a third less CPU for a cold build). Only the first configure sets
# it: a build/ reconfigured with -DROLLNOISE_UNITY_BUILD=OFF (one file recompiled per edit) keeps
# that setting here.
unity=()
[ -e build/CMakeCache.txt ] || unity=(-DROLLNOISE_UNITY_BUILD=ON)
cmake -S . -B build -DCMAKE_BUILD_TYPE="$BUILD_TYPE" "${unity[@]}" >/dev/null
cmake --build build -j"$(nproc)"
