# The CUDA backend (docs/guide/gpu.md): Zeitlin's fluid and the methods of the method table's
# kBackendMatrixGroups family on one GPU, a compiled library (kernels, cuBLAS, cuSOLVER) beside
# the main one; the target ddb::cuda and the package's component `cuda` (cmake/DdbBackend.cmake).
# Built by default when ddb is the top-level project and CMake's CUDAToolkit and nvcc are found
# (no GPU is needed to build it; its device tests skip without one); as a subproject only when
# asked, so that a parent's languages stay its own.
set(ddb_cuda_found OFF)
if(PROJECT_IS_TOP_LEVEL OR DDB_BUILD_CUDA)
  include(CheckLanguage)
  check_language(CUDA)
  find_package(CUDAToolkit QUIET)
  if(CMAKE_CUDA_COMPILER AND CUDAToolkit_FOUND)
    set(ddb_cuda_found ON)
  endif()
endif()
option(DDB_BUILD_CUDA "Build the CUDA backend (cuda/) when CUDA's toolkit is found" ${ddb_cuda_found})
if(DDB_BUILD_CUDA AND NOT ddb_cuda_found)
  message(FATAL_ERROR "DDB_BUILD_CUDA needs CUDA's toolkit with nvcc (CMake's CUDAToolkit)")
endif()
ddb_declare_backend(cuda TITLE "CUDA backend" WITHOUT
  "this ddb was installed without its CUDA backend: configure ddb where CUDA's toolkit and nvcc are found (DDB_BUILD_CUDA) and install it again")
if(DDB_BUILD_CUDA)
  # Hopper (H100, H200) unless asked otherwise, e.g. -DCMAKE_CUDA_ARCHITECTURES="80;90".
  if(NOT DEFINED CMAKE_CUDA_ARCHITECTURES)
    set(CMAKE_CUDA_ARCHITECTURES 90)
  endif()
  # Here, in the top-level directory's scope: CMake wants a language enabled where every target
  # that compiles or links it is below (the tests and the apps link ddb::cuda).
  enable_language(CUDA)
  ddb_add_backend(cuda
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/cuda_backend.cc ${CMAKE_CURRENT_LIST_DIR}/cuda_context.cc
            ${CMAKE_CURRENT_LIST_DIR}/cuda_device.cc ${CMAKE_CURRENT_LIST_DIR}/cuda_method_table.cc
            ${CMAKE_CURRENT_LIST_DIR}/cuda_eigenbasis.cc ${CMAKE_CURRENT_LIST_DIR}/cuda_lu.cc
            ${CMAKE_CURRENT_LIST_DIR}/cuda_poisson_solver.cc
            ${CMAKE_CURRENT_LIST_DIR}/detail/cuda_kernels.cu
    LINK CUDA::cudart CUDA::cublas CUDA::cusolver
    TESTS cuda/tests.cmake)
  set_target_properties(ddb_cuda PROPERTIES CUDA_STANDARD 17 CUDA_STANDARD_REQUIRED ON)
  # No fused multiply-add: the element-wise kernels round as the dense backend does
  # (cuda/cuda_backend.h); device lambdas for the kernels' passes.
  target_compile_options(ddb_cuda PRIVATE
                         $<$<COMPILE_LANGUAGE:CUDA>:--fmad=false --extended-lambda>)
  message(STATUS "The CUDA backend is built (CUDA ${CUDAToolkit_VERSION}, architectures "
                 "${CMAKE_CUDA_ARCHITECTURES})")
elseif(ddb_cuda_found)
  message(STATUS "The CUDA backend is not built (DDB_BUILD_CUDA is OFF)")
else()
  message(STATUS "The CUDA backend is not built: it needs CUDA's toolkit with nvcc")
endif()
