#!/usr/bin/env bash
# Sets everything up, builds in Release and runs the whole test suite through ctest;
# then uses the library the two ways others do: installed into a temporary prefix
# (the examples/ configured with find_package, built and run, examples/distributed under
# mpiexec when the distributed layer was built; each exits non-zero if its check fails)
# and added with add_subdirectory by tests/subproject_consumer.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2
ctest --test-dir build --output-on-failure -j2
# The library's numerical suites again under two OpenBLAS kernels: OpenBLAS picks its kernels
# by the CPU (one it does not recognise gets the generic Prescott ones), and every test must
# hold on every path of rounding (issue 42). The apps' end-to-end, MPI and Python tests,
# whose numbers come from the same library code, and the tree's checks (check_*: includes,
# layers, citations, the configure-only install, which builds the library again) run once above.
for core in Prescott Haswell; do
  echo "== the numerical suites with OPENBLAS_CORETYPE=$core"
  OPENBLAS_CORETYPE=$core ctest --test-dir build --output-on-failure -j2 \
    -E "^check_|_np[0-9]|python|Checkpoint|RunFolder|IoFaults|BadInputs|Plot|FluidRelax|DdbCompare|Determinism|EnergyRises|Cli\\."
done

# The API reference (docs/CMakeLists.txt): the headers, the docs/ pages and the Python module's
# docstrings, with Doxygen's warnings as errors.
echo "== the API reference"
cmake --build build --target docs

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cmake --install build --prefix "$scratch/prefix"
for example in custom_system hamiltonian_observer; do
  echo "== examples/$example against the installed package"
  cmake -S "examples/$example" -B "$scratch/$example" -DCMAKE_BUILD_TYPE=Release \
        -DCMAKE_PREFIX_PATH="$scratch/prefix"
  cmake --build "$scratch/$example" -j2
  "$scratch/$example/app"
done
# The distributed layer's example on 2 ranks, with the environment of the MPI tests in ctest
# (tests/mpi/tests.cmake): root allowed, oversubscribed, idle ranks yield, Open MPI's own
# point-to-point layer, one BLAS thread.
if [[ -f "$scratch/prefix/share/ddb/cmake/ddbDistributedTargets.cmake" ]]; then
  echo "== examples/distributed against the installed package, on 2 ranks"
  cmake -S examples/distributed -B "$scratch/distributed" -DCMAKE_BUILD_TYPE=Release \
        -DCMAKE_PREFIX_PATH="$scratch/prefix"
  cmake --build "$scratch/distributed" -j2
  OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1 \
    OMPI_MCA_mpi_yield_when_idle=1 OMPI_MCA_pml=ob1 OPENBLAS_NUM_THREADS=1 \
    mpiexec -n 2 "$scratch/distributed/app"
else
  echo "== examples/distributed skipped: the distributed layer was not built" \
    "(docs/design/distributed.md)"
fi

# The CUDA backend's example against the installed component (it checks on a GPU, and where
# none can be used says so and checks nothing: docs/guide/gpu.md).
if [[ -f "$scratch/prefix/share/ddb/cmake/ddbCudaTargets.cmake" ]]; then
  echo "== examples/gpu against the installed package"
  cmake -S examples/gpu -B "$scratch/gpu" -DCMAKE_BUILD_TYPE=Release \
        -DCMAKE_PREFIX_PATH="$scratch/prefix"
  cmake --build "$scratch/gpu" -j2
  "$scratch/gpu/app"
else
  echo "== examples/gpu skipped: the CUDA backend was not built (docs/guide/gpu.md)"
fi

# Debug catches a build type overwritten unconditionally, the empty one a default
# imposed on the parent; the disabled packages make any REQUIRED lookup of them fail.
for build_type in Debug ""; do
  echo "== ddb as a subproject, parent build type '$build_type'"
  cmake --no-warn-unused-cli -S tests/subproject_consumer -B "$scratch/subproject-$build_type" \
        -DDDB_SOURCE_DIR="$PWD" -DCMAKE_BUILD_TYPE="$build_type" \
        -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON -DCMAKE_DISABLE_FIND_PACKAGE_benchmark=ON \
        -DCMAKE_DISABLE_FIND_PACKAGE_spdlog=ON -DCMAKE_DISABLE_FIND_PACKAGE_CLI11=ON \
        -DCMAKE_DISABLE_FIND_PACKAGE_nlohmann_json=ON
done
# The library's failure-mode and randomised tests (every system and DDB method, the small
# and the matrix-free Legendre solvers, the matrix groups' OpenBLAS products) again under
# AddressSanitizer and UndefinedBehaviorSanitizer (docs/reference/guarantees.md §4): -O1 with
# Eigen's own assertions on (no NDEBUG), and -g1, the line tables a sanitizer's stack trace
# names file:line from, inlined frames included, without -g's descriptions of every local and
# type, which took a third of this stage's compile time (method_table_so3.cc: 64 s against 41 s
# with GCC). Compiled by Clang 14 (Debian 12's clang-14; llvm-14's llvm-symbolizer names the
# frames): everything above builds with GCC, so this stage is also the check that the library
# and these tests compile with the other compiler a user may have, and Clang builds it in two
# thirds of GCC's time (153 s against 234 s, docs/results/compile-costs.md, "The sanitizer stage
# with Clang"). Only these two programs: a sanitized file takes about 3× its Release compile time.
# The library compiles only the method tables they run (DDB_METHOD_TABLES, CMakeLists.txt), those
# of SO(3), SE(3), SO(N) and SU(N); the others' methods no test here would call. Any finding stops
# the run. DDB_EXPECT_SANITIZERS turns on the positive controls (tests/unit/
# test_sanitizer_controls.cc): the compile must have AddressSanitizer, and both sanitizers must
# stop a planted error.
echo "== tests under ASan and UBSan, compiled by Clang"
cmake -S . -B build-sanitize -DCMAKE_CXX_COMPILER=clang++-14 -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DDDB_BUILD_APPS=OFF -DDDB_BUILD_BENCH=OFF -DDDB_BUILD_PYTHON=OFF -DDDB_BUILD_MPI=OFF \
      -DDDB_BUILD_CUDA=OFF \
      -DDDB_METHOD_TABLES="so3;se3;son;sun" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" \
      -DCMAKE_CXX_FLAGS="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined -DDDB_EXPECT_SANITIZERS" \
      -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined"
cmake --build build-sanitize -j2 --target sanitizer_tests  # unit_failures, tests/CMakeLists.txt
UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1 ASAN_OPTIONS=detect_leaks=1 \
  ctest --test-dir build-sanitize --output-on-failure -j2 -E "_NOT_BUILT|^check_"
echo "== all checks passed"
