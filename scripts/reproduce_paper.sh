#!/usr/bin/env bash
# Reproduces every figure and the runtime table of the paper's Section 5 into
# results/scenario-{A,B,C}/ and copies the figures docs/results/paper-reproduction.md shows to
# docs/figures/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2
./build/bin/ddb-compare --scenario A --sweep-h 1e-3:1:13 --plot --out results/scenario-A --overwrite
./build/bin/ddb-compare --scenario B --sweep-h 1e-3:1:13 --plot --out results/scenario-B --overwrite
./build/bin/ddb-compare --scenario C --plot --out results/scenario-C --overwrite
mkdir -p docs/figures
for s in A B C; do
  for f in results/scenario-$s/*.png; do cp "$f" "docs/figures/$s-$(basename "$f")"; done
  cp results/scenario-$s/runtime_table.md "docs/figures/$s-runtime_table.md"
done
