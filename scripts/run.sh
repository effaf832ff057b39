#!/usr/bin/env bash
# The quick start: installs only what the main job needs (install-deps.sh quickstart),
# builds only ddb-compare, in build-quickstart/ (tests, benchmarks, the Python module and
# the MPI layer off, so that it neither needs nor builds them; build/ is scripts/test.sh's),
# and runs the main job: the paper's Scenario A comparison of every integrator, with
# figures, into results/scenario-A/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh quickstart
cmake -S . -B build-quickstart -DCMAKE_BUILD_TYPE=Release -DDDB_BUILD_TESTS=OFF \
  -DDDB_BUILD_BENCH=OFF -DDDB_BUILD_PYTHON=OFF -DDDB_BUILD_MPI=OFF
cmake --build build-quickstart -j2 --target ddb-compare
./build-quickstart/bin/ddb-compare --scenario A --sweep-h 1e-3:1:13 --plot \
  --out results/scenario-A --overwrite "$@"
