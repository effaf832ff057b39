// CudaMatrix: a complex N×M matrix whose entries live in one GPU's memory, column-major like
// Eigen's, owned (allocated on construction, freed on destruction, copied device to device).
// It is the state and workspace type of the CUDA backend (cuda/cuda_backend.h,
// docs/design/matrix-backend.md): no host code reads its entries; they come and go through
// toDevice/toHost (cuda/cuda_device.h), the backend's save/load and its reductions. It carries
// the CudaContext it was made in (cuda/cuda_context.h), in whose stream every operation on it
// runs; a copy is made in the same context.
#pragma once

#include <ddb/cuda/cuda_context.h>

#include <complex>
#include <cstddef>
#include <memory>
#include <utility>

namespace ddb {

class CudaMatrix {
 public:
  using Scalar = std::complex<double>;  // the entries' type, for the class templates

  CudaMatrix() = default;
  /// rows × cols in `context` (this thread's, CudaContext::ofThisThread(), when none is
  /// given), entries not set; throws CudaError with the size when it does not fit.
  CudaMatrix(long rows, long cols, std::shared_ptr<CudaContext> context = nullptr);
  CudaMatrix(const CudaMatrix& other);
  CudaMatrix(CudaMatrix&& other) noexcept { swap(other); }
  CudaMatrix& operator=(const CudaMatrix& other);
  CudaMatrix& operator=(CudaMatrix&& other) noexcept {
    swap(other);
    return *this;
  }
  ~CudaMatrix();

  void swap(CudaMatrix& other) noexcept {
    std::swap(rows_, other.rows_);
    std::swap(cols_, other.cols_);
    std::swap(data_, other.data_);
    context_.swap(other.context_);
  }

  long rows() const { return rows_; }
  long cols() const { return cols_; }
  long size() const { return rows_ * cols_; }
  /// The device address of entry (0, 0); entry (i, j) at i + j·rows. Kernels only.
  Scalar* deviceData() { return data_; }
  const Scalar* deviceData() const { return data_; }
  /// The context it was made in; none for a matrix made empty (CudaMatrix()).
  const std::shared_ptr<CudaContext>& context() const { return context_; }

 private:
  long rows_ = 0, cols_ = 0;
  Scalar* data_ = nullptr;
  std::shared_ptr<CudaContext> context_;
};

}  // namespace ddb
