// CudaContext (cuda/cuda_context.h): its stream, handles and scratch
// (cuda/detail/cuda_context_state.h), and the transfers in a context's order.
#include <cuda_runtime.h>
#include <ddb/core/errors.h>
#include <ddb/cuda/cuda_context.h>
#include <ddb/cuda/cuda_device.h>
#include <ddb/cuda/detail/cuda_check.h>
#include <ddb/cuda/detail/cuda_context_state.h>
#include <ddb/cuda/detail/cuda_libraries.h>

#include <memory>

namespace ddb {

void DeviceScratch::grow(std::size_t bytes) {
  cudaFree(data_);  // nothing to do if it fails: the buffer is dropped either way
  data_ = nullptr;
  bytes_ = 0;
  checkCuda(cudaMalloc(&data_, bytes), "cudaMalloc (scratch)");
  bytes_ = bytes;
}

// A blocking stream (cudaStreamDefault): ordered with the legacy default stream too, on which
// cudaMalloc and cudaFree synchronise, so that a buffer is never freed under a kernel.
CudaContext::State::State() {
  if (const auto why = cudaUnavailable()) throw CudaError(*why);
  checkCuda(cudaStreamCreateWithFlags(&stream, cudaStreamDefault), "cudaStreamCreateWithFlags");
  try {
    checkCublas(cublasCreate(&cublas), "cublasCreate");
    checkCublas(cublasSetStream(cublas, stream), "cublasSetStream");
    checkCusolver(cusolverDnCreate(&cusolver), "cusolverDnCreate");
    checkCusolver(cusolverDnSetStream(cusolver, stream), "cusolverDnSetStream");
  } catch (...) {
    if (cusolver != nullptr) cusolverDnDestroy(cusolver);
    if (cublas != nullptr) cublasDestroy(cublas);
    cudaStreamDestroy(stream);
    throw;
  }
}

// Not checked: a destructor does not throw. What is queued finishes before the handles go.
CudaContext::State::~State() {
  cudaStreamSynchronize(stream);
  cusolverDnDestroy(cusolver);
  cublasDestroy(cublas);
  cudaStreamDestroy(stream);
}

CudaContext::CudaContext() : state_(std::make_unique<State>()) {}
CudaContext::~CudaContext() = default;

std::shared_ptr<CudaContext> CudaContext::create() {
  return std::shared_ptr<CudaContext>(new CudaContext());
}

const std::shared_ptr<CudaContext>& CudaContext::ofThisThread() {
  // Made on first use and never destroyed (cuda/cuda_context.h): the pointer is leaked, not the
  // context of a thread that ends while its matrices live on (they hold it too).
  thread_local const std::shared_ptr<CudaContext>* context =
      new std::shared_ptr<CudaContext>(create());
  return *context;
}

void CudaContext::synchronize() {
  checkCuda(cudaStreamSynchronize(state_->stream), "cudaStreamSynchronize");
}

void requireContext(const CudaMatrix& x, const std::shared_ptr<CudaContext>& context,
                    const std::string& parameter, const std::string& whose) {
  if (x.context() != context) {
    throwInvalid(parameter, "a matrix of another CudaContext",
                 "must be in " + whose + " (cuda/cuda_context.h)");
  }
}

void copyToHost(CudaContext::State& state, void* host, const void* device, std::size_t bytes) {
  if (bytes == 0) return;
  checkCuda(cudaMemcpyAsync(host, device, bytes, cudaMemcpyDeviceToHost, state.stream),
            "cudaMemcpyAsync (to the host)");
  checkCuda(cudaStreamSynchronize(state.stream), "cudaStreamSynchronize (to the host)");
}

void copyToDevice(CudaContext::State& state, void* device, const void* host, std::size_t bytes) {
  if (bytes == 0) return;
  // Waited for: CUDA guarantees that an asynchronous copy from pageable memory has read `host`
  // on return only for the synchronous cudaMemcpy, and the callers free or reuse it at once.
  checkCuda(cudaMemcpyAsync(device, host, bytes, cudaMemcpyHostToDevice, state.stream),
            "cudaMemcpyAsync (to the device)");
  checkCuda(cudaStreamSynchronize(state.stream), "cudaStreamSynchronize (to the device)");
}

}  // namespace ddb
