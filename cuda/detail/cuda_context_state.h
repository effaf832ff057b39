// CudaContext's state (cuda/cuda_context.h): its stream, the cuBLAS and cuSOLVER handles bound
// to it, and the scratch of the kernels that need some, each grown to the largest size asked and
// freed with the context. What cuda/cuda_backend.cc, cuda/cuda_lu.cc, cuda/cuda_eigenbasis.cc,
// cuda/cuda_poisson_solver.cc and the kernels (cuda/detail/cuda_kernels.cu) run in.
#pragma once

#include <cublas_v2.h>
#include <cuda_runtime.h>
#include <cusolverDn.h>
#include <ddb/cuda/cuda_context.h>
#include <ddb/cuda/cuda_error.h>
#include <ddb/cuda/cuda_matrix.h>

#include <complex>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace ddb {

/// Device memory of `bytes` that grows on demand (its contents are not kept when it grows).
class DeviceScratch {
 public:
  DeviceScratch() = default;
  DeviceScratch(const DeviceScratch&) = delete;
  DeviceScratch& operator=(const DeviceScratch&) = delete;
  ~DeviceScratch() { cudaFree(data_); }  // not checked: a destructor does not throw
  /// At least `count` T's; CudaError when they do not fit.
  template <class T>
  T* reserve(std::size_t count) {
    const std::size_t bytes = sizeof(T) * (count > 0 ? count : 1);
    if (bytes > bytes_) grow(bytes);
    return static_cast<T*>(data_);
  }

 private:
  void grow(std::size_t bytes);
  void* data_ = nullptr;
  std::size_t bytes_ = 0;
};

struct CudaContext::State {
  cudaStream_t stream = nullptr;
  cublasHandle_t cublas = nullptr;
  cusolverDnHandle_t cusolver = nullptr;
  DeviceScratch reduction;    // the reductions' partials and result
  DeviceScratch column_sums;  // oneNorm's
  DeviceScratch sample_indices, sample_values;
  std::vector<long> host_indices;  // sampleEntries' on the host
  std::vector<std::complex<double>> host_values;

  State();
  ~State();
  State(const State&) = delete;
  State& operator=(const State&) = delete;
};

/// The state of x's context; this thread's for an empty matrix, which has none.
inline CudaContext::State& stateOf(const CudaMatrix& x) {
  return (x.context() ? x.context() : CudaContext::ofThisThread())->state();
}

/// Refuses x (InvalidArgument naming `parameter`) unless it is in `context`, which `whose` names:
/// the operations of two contexts' streams are not ordered with each other.
void requireContext(const CudaMatrix& x, const std::shared_ptr<CudaContext>& context,
                    const std::string& parameter, const std::string& whose);

/// host ← device's `bytes`, once what is queued in `state` before has run.
void copyToHost(CudaContext::State& state, void* host, const void* device, std::size_t bytes);
/// device ← host's `bytes`, in `state`'s order; `host` may be reused on return.
void copyToDevice(CudaContext::State& state, void* device, const void* host, std::size_t bytes);

}  // namespace ddb
