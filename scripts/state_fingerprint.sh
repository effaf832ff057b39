#!/bin/bash
# Builds tools/state_fingerprint.cc against a built tree's headers and libddb.a (Debian 12's
# LAPACK and OpenBLAS; of Ceres only its Jet header, so no Ceres library) and runs it: one line per method and system with the
# hash of its states' bits (see the program's header).
#   scripts/state_fingerprint.sh BUILD_DIR
set -euo pipefail
build=${1:?usage: scripts/state_fingerprint.sh BUILD_DIR}
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
c++ -O3 -DNDEBUG -std=c++17 -DDDB_USE_LAPACK -DEIGEN_USE_BLAS -I"$build/include" \
  -isystem /usr/include/eigen3 "$root/tools/state_fingerprint.cc" -o "$out/state_fingerprint" \
  "$build/libddb.a" -lpthread -llapack -lopenblas -llapacke -lm -ldl
"$out/state_fingerprint"
