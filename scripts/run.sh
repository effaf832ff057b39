#!/usr/bin/env bash
# Sets everything up, builds in Release and runs the main job: the paper's Scenario A
# comparison of every integrator, with figures, into results/scenario-A/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2
./build/bin/ddb-compare --scenario A --sweep-h 1e-3:1:13 --plot --out results/scenario-A "$@"
