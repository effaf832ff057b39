# Included by tests/CMakeLists.txt, in its scope, where the CUDA backend is built
# (cuda/backend.cmake).
# Every public name of the backend, compiled (as public_names, tests/CMakeLists.txt).
add_library(public_names_cuda OBJECT api/public_names_cuda.cc)
target_link_libraries(public_names_cuda PRIVATE ddb::cuda ddb_warnings)
target_compile_options(public_names_cuda PRIVATE -O0)
# The CUDA backend (cuda/, docs/guide/gpu.md). test_cuda_poisson_layout checks the Poisson
# kernels' per-diagonal work on the host; test_cuda_backend needs a GPU and, without one,
# reports its tests skipped (GTEST_SKIP, which ctest counts as skipped, not passed), naming why.
ddb_test(cuda test_cuda_poisson_layout)
ddb_test(cuda test_cuda_backend PROPERTIES TIMEOUT 600 LABELS gpu)
target_link_libraries(test_cuda_backend PRIVATE ddb::cuda)
# The host's references that the device must match to the bit are computed in this unit: no fused
# multiply-add there either (GCC contracts by default on aarch64 hosts, e.g. Grace Hopper), as the
# kernels have none (--fmad=false, cuda/backend.cmake).
target_compile_options(test_cuda_backend PRIVATE $<$<CXX_COMPILER_ID:GNU,Clang>:-ffp-contract=off>)
