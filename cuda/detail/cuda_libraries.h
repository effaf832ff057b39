// The cuBLAS and cuSOLVER handles of this thread, created on first use on the default stream,
// and their status checks (cuda/cuda_backend.cc, cuda/cuda_lu.cc).
#pragma once

#include <cublas_v2.h>
#include <cusolverDn.h>

namespace ddb {

cublasHandle_t cublasHandle();
cusolverDnHandle_t cusolverHandle();
void checkCublas(cublasStatus_t status, const char* call);
void checkCusolver(cusolverStatus_t status, const char* call);

}  // namespace ddb
