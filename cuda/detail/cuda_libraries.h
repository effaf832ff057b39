// The status checks of cuBLAS and cuSOLVER calls (cuda/cuda_backend.cc, cuda/cuda_lu.cc,
// cuda/cuda_eigenbasis.cc); their handles are a context's (cuda/detail/cuda_context_state.h).
#pragma once

#include <cublas_v2.h>
#include <cusolverDn.h>

namespace ddb {

void checkCublas(cublasStatus_t status, const char* call);
void checkCusolver(cusolverStatus_t status, const char* call);

}  // namespace ddb
