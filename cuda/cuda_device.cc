// The device, its handles and the matrix's storage (cuda/cuda_device.h, cuda/cuda_matrix.h).
#include <cuda_runtime.h>
#include <ddb/cuda/cuda_device.h>
#include <ddb/cuda/cuda_matrix.h>
#include <ddb/cuda/detail/cuda_check.h>
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

CudaMatrix::CudaMatrix(long rows, long cols) : rows_(rows), cols_(cols) {
  if (size() == 0) return;
  const cudaError_t status = cudaMalloc(&data_, sizeof(Scalar) * static_cast<std::size_t>(size()));
  if (status != cudaSuccess) {
    data_ = nullptr;
    rows_ = cols_ = 0;
    throw CudaError(
        "a " + std::to_string(rows) + "x" + std::to_string(cols) +
        " matrix does not fit on the device (cudaMalloc: " + cudaGetErrorString(status) + ")");
  }
}

CudaMatrix::CudaMatrix(const CudaMatrix& other) : CudaMatrix(other.rows_, other.cols_) {
  if (size() == 0) return;
  checkCuda(cudaMemcpy(data_, other.data_, sizeof(Scalar) * static_cast<std::size_t>(size()),
                       cudaMemcpyDeviceToDevice),
            "cudaMemcpy (device to device)");
}

CudaMatrix& CudaMatrix::operator=(const CudaMatrix& other) {
  if (this != &other) {
    CudaMatrix copy(other);
    swap(copy);
  }
  return *this;
}

// Not checked: a destructor does not throw, and a failed free leaves nothing to do.
CudaMatrix::~CudaMatrix() { cudaFree(data_); }

void toDevice(const Eigen::MatrixXcd& m, CudaMatrix& x) {
  if (x.rows() != m.rows() || x.cols() != m.cols()) x = CudaMatrix(m.rows(), m.cols());
  if (x.size() > 0) {
    checkCuda(cudaMemcpy(x.deviceData(), m.data(), sizeof(CudaMatrix::Scalar) * m.size(),
                         cudaMemcpyHostToDevice),
              "cudaMemcpy (to the device)");
  }
}

CudaMatrix toDevice(const Eigen::MatrixXcd& m) {
  CudaMatrix x;
  toDevice(m, x);
  return x;
}

void toHost(const CudaMatrix& x, Eigen::MatrixXcd& out) {
  out.resize(x.rows(), x.cols());
  if (x.size() > 0) {
    checkCuda(cudaMemcpy(out.data(), x.deviceData(), sizeof(CudaMatrix::Scalar) * x.size(),
                         cudaMemcpyDeviceToHost),
              "cudaMemcpy (to the host)");
  }
}

Eigen::MatrixXcd toHost(const CudaMatrix& x) {
  Eigen::MatrixXcd out;
  toHost(x, out);
  return out;
}

// The handles live as long as the thread: destroying them in a static destructor could run
// after the CUDA runtime has shut down at exit, and the driver frees them with the process.
cublasHandle_t cublasHandle() {
  thread_local cublasHandle_t handle = [] {
    cublasHandle_t h = nullptr;
    checkCublas(cublasCreate(&h), "cublasCreate");
    return h;
  }();
  return handle;
}

cusolverDnHandle_t cusolverHandle() {
  thread_local cusolverDnHandle_t handle = [] {
    cusolverDnHandle_t h = nullptr;
    checkCusolver(cusolverDnCreate(&h), "cusolverDnCreate");
    return h;
  }();
  return handle;
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
