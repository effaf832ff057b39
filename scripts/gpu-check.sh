#!/usr/bin/env bash
# The whole GPU check of the CUDA backend in one command (docs/guide/gpu.md): the device tests
# (tests/cuda/test_cuda_backend.cc, none may be skipped) and the step benchmark table
# (bench/cuda_step_bench.cc: N = 1024 … 16384, alpha = 0 and 0.5, with the same step on this
# machine's CPU up to N = 4096), written as JSON into OUT_DIR. Not yet timed on a GPU: estimated
# at 6 to 8 minutes on an H200 with 16 cores, most of it the CPU's side of the comparisons.
#
#   scripts/gpu-check.sh OUT_DIR                  build here (build-gpu/), then check
#   scripts/gpu-check.sh --prebuilt DIR OUT_DIR   check with DIR/bin and DIR/lib from --pack
#   scripts/gpu-check.sh --pack DIR               build here and put the two programs and the
#                                                 libraries they need (not CUDA's, not libc's)
#                                                 into DIR (e.g. build-gpu-pack, which git
#                                                 ignores; about 53 MB), for a GPU machine
#                                                 without the Debian packages
# Exit status: 0 if every test passed on a GPU; 1 if a test failed, or if the tests were skipped
# (no usable GPU), which ends the check before the benchmark.
set -euo pipefail
cd "$(dirname "$0")/.."

build() {
  cmake -S . -B build-gpu -DCMAKE_BUILD_TYPE=Release -DDDB_BUILD_CUDA=ON -DDDB_BUILD_APPS=OFF \
        -DDDB_BUILD_PYTHON=OFF -DDDB_BUILD_MPI=OFF >/dev/null
  cmake --build build-gpu -j"$(nproc)" --target test_cuda_backend cuda-step-bench
}

if [[ "${1:-}" == "--pack" ]]; then
  pack=${2:?usage: scripts/gpu-check.sh --pack DIR}
  build
  mkdir -p "$pack/bin" "$pack/lib"
  cp build-gpu/bin/test_cuda_backend build-gpu/bin/cuda-step-bench "$pack/bin/"
  ldd build-gpu/bin/test_cuda_backend build-gpu/bin/cuda-step-bench | awk '/=> \//{print $3}' |
    sort -u | grep -v -E '/(libc|libm|libpthread|libdl|librt|ld-linux[^/]*)\.so|/cuda' |
    xargs -I{} cp -L {} "$pack/lib/"
  du -sh "$pack"
  exit 0
fi

if [[ "${1:-}" == "--prebuilt" ]]; then
  bin="${2:?usage: scripts/gpu-check.sh --prebuilt DIR OUT_DIR}/bin"
  export LD_LIBRARY_PATH="$2/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
  out=${3:?usage: scripts/gpu-check.sh --prebuilt DIR OUT_DIR}
else
  out=${1:?usage: scripts/gpu-check.sh OUT_DIR}
  build
  bin=build-gpu/bin
fi
mkdir -p "$out"
command -v nvidia-smi >/dev/null && nvidia-smi --query-gpu=name,memory.total,driver_version \
  --format=csv,noheader | tee "$out/nvidia-smi.txt" || true

status=0
echo "== the device tests"
"$bin/test_cuda_backend" --gtest_output="json:$out/gpu-tests.json" 2>&1 | tee "$out/gpu-tests.log" ||
  status=1
if grep -q '^\[  SKIPPED \]' "$out/gpu-tests.log"; then
  echo "gpu-check: tests were skipped (no usable GPU): the check did not run" >&2
  exit 1
fi

echo "== the step benchmark"
rows="$out/gpu-bench.jsonl"
: >"$rows"
bench() {  # N steps alpha method cpu_steps
  timeout 180 "$bin/cuda-step-bench" "$@" | tee -a "$rows" ||
    echo "{\"n\": $1, \"alpha\": $3, \"method\": \"$4\", \"failed\": true}" | tee -a "$rows"
}
for n in 1024 2048 4096; do
  for alpha in 0 0.5; do bench "$n" 10 "$alpha" ddb-cay "$([[ $n -le 2048 ]] && echo 3 || echo 1)"; done
done
for alpha in 0 0.5; do bench 4096 5 "$alpha" sddb-cay 0; done
for alpha in 0 0.5; do bench 8192 5 "$alpha" ddb-cay 0; done
bench 16384 2 0 ddb-cay 0
echo "gpu-check: wrote $out (status $status)"
exit $status
