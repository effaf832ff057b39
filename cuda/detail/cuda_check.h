// Checks a CUDA runtime, cuBLAS or cuSOLVER status and throws CudaError with the call's name
// and the library's words: a failure on the device is an exception like any other solve
// failure, never an abort.
#pragma once

#include <cuda_runtime.h>
#include <ddb/cuda/cuda_error.h>

#include <string>

namespace ddb {

inline void checkCuda(cudaError_t status, const char* call) {
  if (status != cudaSuccess) {
    throw CudaError(std::string(call) + " failed: " + cudaGetErrorString(status));
  }
}

}  // namespace ddb
