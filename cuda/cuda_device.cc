// The device, the matrix's storage and the transfers (cuda/cuda_device.h, cuda/cuda_matrix.h).
#include <cuda_runtime.h>
#include <ddb/cuda/cuda_device.h>
#include <ddb/cuda/cuda_matrix.h>
#include <ddb/cuda/detail/cuda_check.h>
#include <ddb/cuda/detail/cuda_context_state.h>
#include <ddb/cuda/detail/cuda_libraries.h>

#include <string>

namespace ddb {

std::optional<std::string> cudaUnavailable() {
  int count = 0;
  const cudaError_t status = cudaGetDeviceCount(&count);
  if (status != cudaSuccess) {
    return std::string("no CUDA device can be used: ") + cudaGetErrorString(status);
  }
  if (count == 0) return std::string("no CUDA device can be used: the runtime found none");
  return std::nullopt;
}

std::string cudaDeviceName() {
  cudaDeviceProp properties{};
  checkCuda(cudaGetDeviceProperties(&properties, 0), "cudaGetDeviceProperties");
  return properties.name;
}

CudaMemory cudaMemory() {
  std::size_t free = 0, total = 0;
  checkCuda(cudaMemGetInfo(&free, &total), "cudaMemGetInfo");
  return {static_cast<long long>(total - free), static_cast<long long>(total)};
}

void cudaSynchronize() { checkCuda(cudaDeviceSynchronize(), "cudaDeviceSynchronize"); }

// ---- CudaMatrix (cuda/cuda_matrix.h). ----

CudaMatrix::CudaMatrix(long rows, long cols, std::shared_ptr<CudaContext> context)
    : rows_(rows), cols_(cols), context_(std::move(context)) {
  if (size() == 0) return;
  if (context_ == nullptr) context_ = CudaContext::ofThisThread();
  const cudaError_t status = cudaMalloc(&data_, sizeof(Scalar) * static_cast<std::size_t>(size()));
  if (status != cudaSuccess) {
    data_ = nullptr;
    rows_ = cols_ = 0;
    throw CudaError(
        "a " + std::to_string(rows) + "x" + std::to_string(cols) +
        " matrix does not fit on the device (cudaMalloc: " + cudaGetErrorString(status) + ")");
  }
}

CudaMatrix::CudaMatrix(const CudaMatrix& other)
    : CudaMatrix(other.rows_, other.cols_, other.context_) {
  if (size() == 0) return;
  checkCuda(cudaMemcpyAsync(data_, other.data_, sizeof(Scalar) * static_cast<std::size_t>(size()),
                            cudaMemcpyDeviceToDevice, context_->state().stream),
            "cudaMemcpyAsync (device to device)");
}

CudaMatrix& CudaMatrix::operator=(const CudaMatrix& other) {
  if (this != &other) {
    CudaMatrix copy(other);
    swap(copy);
  }
  return *this;
}

// Not checked: a destructor does not throw, and a failed free leaves nothing to do. cudaFree
// waits for the device, so no kernel of any stream still reads the entries.
CudaMatrix::~CudaMatrix() { cudaFree(data_); }

// ---- Transfers (cuda/cuda_device.h). ----

void toDevice(const Eigen::MatrixXcd& m, CudaMatrix& x) {
  if (x.rows() != m.rows() || x.cols() != m.cols()) x = CudaMatrix(m.rows(), m.cols(), x.context());
  if (x.size() > 0) {
    copyToDevice(x.context()->state(), x.deviceData(), m.data(),
                 sizeof(CudaMatrix::Scalar) * m.size());
  }
}

CudaMatrix toDevice(const Eigen::MatrixXcd& m, const std::shared_ptr<CudaContext>& context) {
  CudaMatrix x(m.rows(), m.cols(), context);
  toDevice(m, x);
  return x;
}

CudaMatrix toDevice(const Eigen::MatrixXcd& m) {
  CudaMatrix x;
  toDevice(m, x);
  return x;
}

void toHost(const CudaMatrix& x, Eigen::MatrixXcd& out) {
  out.resize(x.rows(), x.cols());
  if (x.size() > 0) {
    copyToHost(x.context()->state(), out.data(), x.deviceData(),
               sizeof(CudaMatrix::Scalar) * x.size());
  }
}

Eigen::MatrixXcd toHost(const CudaMatrix& x) {
  Eigen::MatrixXcd out;
  toHost(x, out);
  return out;
}

void checkCublas(cublasStatus_t status, const char* call) {
  if (status != CUBLAS_STATUS_SUCCESS) {
    throw CudaError(std::string(call) + " failed: " + cublasGetStatusString(status));
  }
}

void checkCusolver(cusolverStatus_t status, const char* call) {
  if (status != CUSOLVER_STATUS_SUCCESS) {
    throw CudaError(std::string(call) + " failed: cuSOLVER status " + std::to_string(int(status)));
  }
}

}  // namespace ddb
