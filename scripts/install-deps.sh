#!/usr/bin/env bash
# Installs the Debian 12 packages this project builds with (run as root): all of them, or
# with `quickstart` only what scripts/run.sh builds and runs (the apps' libraries and
# matplotlib for the figures). Skips apt-get entirely when everything is already present.
set -euo pipefail
packages=(cmake g++ make libeigen3-dev libceres-dev libspdlog-dev libboost-dev libcli11-dev
          libopenblas-dev liblapacke-dev nlohmann-json3-dev libhdf5-dev python3-matplotlib)
if [ "${1:-}" != quickstart ]; then
  packages+=(libgtest-dev libgmock-dev libbenchmark-dev python3-scipy locales-all
             pybind11-dev python3-dev python3-numpy python3-pytest python3-h5py ffmpeg
             libopenmpi-dev openmpi-bin libscalapack-openmpi-dev doxygen
             clang-14 libclang-rt-14-dev llvm-14)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ "${#missing[@]}" -gt 0 ]; then
  echo "installing: ${missing[*]}"
  apt-get update
  DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${missing[@]}"
fi
