#!/usr/bin/env bash
# Installs what igaprep needs on Debian 12 (only what is missing, quietly),
# then configures and builds it in Release in ./build.
set -euo pipefail
cd "$(dirname "$0")/.."

PACKAGES=(
  build-essential cmake pkg-config
  libeigen3-dev libcgal-dev libgmp-dev libmpfr-dev libboost-dev
  libtet1.5-dev libhdf5-dev libosd-dev libsuitesparse-dev libhypre-dev libopenblas0-pthread
  libceres-dev libcli11-dev nlohmann-json3-dev libgtest-dev libbenchmark-dev libssl-dev
  python3 python3-dev pybind11-dev python3-numpy python3-scipy python3-h5py python3-vtk9
  python3-pytest python3-matplotlib xvfb xauth chromium
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  SUDO=""
  [[ $(id -u) -ne 0 ]] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

JOBS=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
echo "setup: building with $JOBS jobs (log: build/build.log)"
if ! cmake --build build -j"$JOBS" >build/build.log 2>&1; then
  grep -E "error|Error" build/build.log | head -40
  echo "setup: build failed, full log in build/build.log"
  exit 1
fi
echo "setup: built build/bin/igaprep"
