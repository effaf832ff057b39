// CudaError: a CUDA runtime, cuBLAS or cuSOLVER call that failed, with the call and the
// library's reason (a device failure is an exception like any other, never an abort).
#pragma once

#include <stdexcept>

namespace ddb {

class CudaError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace ddb
