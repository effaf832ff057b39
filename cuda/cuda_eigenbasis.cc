// CudaEigenbasis (cuda/cuda_eigenbasis.h): cuSOLVER's zheevd with kept workspaces, cuBLAS's
// zgemm and the weighing kernel of cuda/detail/cuda_kernels.cu.
#include <cuda_runtime.h>
#include <ddb/cuda/cuda_eigenbasis.h>
#include <ddb/cuda/detail/cuda_check.h>
#include <ddb/cuda/detail/cuda_kernels.h>
#include <ddb/cuda/detail/cuda_libraries.h>

#include <stdexcept>
#include <string>

namespace ddb {

namespace {

cuDoubleComplex* complexData(CudaMatrix& x) {
  return reinterpret_cast<cuDoubleComplex*>(x.deviceData());
}
const cuDoubleComplex* complexData(const CudaMatrix& x) {
  return reinterpret_cast<const cuDoubleComplex*>(x.deviceData());
}

// out = op_a(a) op_b(b), all n×n (n > 0).
void gemm(cublasOperation_t op_a, const CudaMatrix& a, cublasOperation_t op_b, const CudaMatrix& b,
          CudaMatrix& out) {
  const cuDoubleComplex one = make_cuDoubleComplex(1.0, 0.0), zero = make_cuDoubleComplex(0.0, 0.0);
  const int n = static_cast<int>(a.rows());
  checkCublas(cublasZgemm(cublasHandle(), op_a, op_b, n, n, n, &one, complexData(a), n,
                          complexData(b), n, &zero, complexData(out), n),
              "cublasZgemm");
}

}  // namespace

struct CudaEigenbasis::Workspace {
  long n = -1;
  CudaMatrix vectors, product, hat;
  double* phases = nullptr;
  double* diagonal = nullptr;  // n, for diagonalPhasesOf
  double* weights = nullptr;   // n², for applyWeights, allocated on its first use
  bool weighted = false;       // weights are those of the current basis
  int* info = nullptr;
  cuDoubleComplex* scratch = nullptr;
  int scratch_length = 0;

  ~Workspace() { release(); }
  void release() {
    for (double* buffer : {phases, diagonal, weights}) cudaFree(buffer);
    cudaFree(info);
    cudaFree(scratch);
    phases = nullptr;
    diagonal = nullptr;
    weights = nullptr;
    info = nullptr;
    scratch = nullptr;
    n = -1;
  }
  // Sized for n×n matrices (a new size frees the old buffers first).
  void reserve(long size) {
    if (size == n) return;
    release();
    vectors = CudaMatrix(size, size);
    product = CudaMatrix(size, size);
    hat = CudaMatrix(size, size);
    const int rows = static_cast<int>(size);
    checkCusolver(cusolverDnZheevd_bufferSize(cusolverHandle(), CUSOLVER_EIG_MODE_VECTOR,
                                              CUBLAS_FILL_MODE_LOWER, rows, complexData(vectors),
                                              rows, phases, &scratch_length),
                  "cusolverDnZheevd_bufferSize");
    const std::size_t length = rows > 0 ? rows : 1;
    checkCuda(cudaMalloc(&phases, sizeof(double) * length), "cudaMalloc");
    checkCuda(cudaMalloc(&diagonal, sizeof(double) * length), "cudaMalloc");
    checkCuda(cudaMalloc(&info, sizeof(int)), "cudaMalloc");
    checkCuda(
        cudaMalloc(&scratch, sizeof(cuDoubleComplex) * (scratch_length > 0 ? scratch_length : 1)),
        "cudaMalloc");
    n = size;
  }
};

CudaEigenbasis::CudaEigenbasis() : workspace_(std::make_unique<Workspace>()) {}
CudaEigenbasis::~CudaEigenbasis() = default;
CudaEigenbasis::CudaEigenbasis(CudaEigenbasis&&) noexcept = default;
CudaEigenbasis& CudaEigenbasis::operator=(CudaEigenbasis&&) noexcept = default;

bool CudaEigenbasis::compute(const CudaMatrix& x) {
  const long count = 2 * x.size();
  if (cuda_kernels::countNotFinite(count, reinterpret_cast<const double*>(x.deviceData())) > 0) {
    return false;
  }
  const int n = static_cast<int>(x.rows());
  phases_.resize(n);
  if (n == 0) return true;  // cuSOLVER asks lda ≥ 1
  Workspace& w = *workspace_;
  w.reserve(x.rows());
  w.weighted = false;  // a new basis takes new weights
  // −ix, exactly: (re, im)·(0, −1) = (im, −re).
  checkCuda(cudaMemcpy(w.vectors.deviceData(), x.deviceData(),
                       sizeof(CudaMatrix::Scalar) * x.size(), cudaMemcpyDeviceToDevice),
            "cudaMemcpy (on the device)");
  const cuDoubleComplex minus_i = make_cuDoubleComplex(0.0, -1.0);
  checkCublas(
      cublasZscal(cublasHandle(), static_cast<int>(x.size()), &minus_i, complexData(w.vectors), 1),
      "cublasZscal");
  checkCusolver(
      cusolverDnZheevd(cusolverHandle(), CUSOLVER_EIG_MODE_VECTOR, CUBLAS_FILL_MODE_LOWER, n,
                       complexData(w.vectors), n, w.phases, w.scratch, w.scratch_length, w.info),
      "cusolverDnZheevd");
  int info = 0;
  checkCuda(cudaMemcpy(&info, w.info, sizeof(int), cudaMemcpyDeviceToHost),
            "cudaMemcpy (to the host)");
  if (info < 0) throw CudaError("cusolverDnZheevd rejected its argument " + std::to_string(-info));
  if (info > 0) return false;
  checkCuda(cudaMemcpy(phases_.data(), w.phases, sizeof(double) * n, cudaMemcpyDeviceToHost),
            "cudaMemcpy (to the host)");
  return true;
}

void CudaEigenbasis::apply(PhaseFunction f, double scale, const CudaMatrix& in, CudaMatrix& out) {
  Workspace& w = *workspace_;
  const auto weigh = [&] {
    cuda_kernels::weighByPhases(in.rows(), w.phases, scale, f,
                                reinterpret_cast<double*>(w.hat.deviceData()));
  };
  transform(in, out, weigh, "apply");
}

void CudaEigenbasis::uploadWeights(const Eigen::MatrixXd& weights) {
  requireDecomposedSize(weights.rows(), weights.cols(), "setWeights");
  Workspace& w = *workspace_;
  if (weights.size() > 0) {
    if (w.weights == nullptr) {
      checkCuda(cudaMalloc(&w.weights, sizeof(double) * weights.size()), "cudaMalloc");
    }
    checkCuda(cudaMemcpy(w.weights, weights.data(), sizeof(double) * weights.size(),
                         cudaMemcpyHostToDevice),
              "cudaMemcpy (to the device)");
  }
  w.weighted = true;
}

void CudaEigenbasis::applyWeights(const CudaMatrix& in, CudaMatrix& out) {
  Workspace& w = *workspace_;
  if (!w.weighted) {
    throw std::logic_error("CudaEigenbasis::applyWeights: no weights for this basis");
  }
  const auto weigh = [&] {
    cuda_kernels::weighEntrywise(in.size(), w.weights,
                                 reinterpret_cast<double*>(w.hat.deviceData()));
  };
  transform(in, out, weigh, "applyWeights");
}

void CudaEigenbasis::diagonalPhasesOf(const CudaMatrix& y, Eigen::VectorXd& out) {
  requireDecomposedSize(y.rows(), y.cols(), "diagonalPhasesOf");
  const long n = y.rows();
  out.resize(n);
  if (n == 0) return;
  Workspace& w = *workspace_;
  gemm(CUBLAS_OP_N, y, CUBLAS_OP_N, w.vectors, w.product);      // y V
  gemm(CUBLAS_OP_C, w.vectors, CUBLAS_OP_N, w.product, w.hat);  // Vᴴ y V
  cuda_kernels::imaginaryDiagonal(n, reinterpret_cast<const double*>(w.hat.deviceData()),
                                  w.diagonal);
  checkCuda(cudaMemcpy(out.data(), w.diagonal, sizeof(double) * n, cudaMemcpyDeviceToHost),
            "cudaMemcpy (to the host)");
}

void CudaEigenbasis::requireDecomposedSize(long rows, long cols, const char* function) const {
  if (rows != phases_.size() || cols != rows) {
    throw std::logic_error(std::string("CudaEigenbasis::") + function +
                           ": a matrix of another size than the decomposed one");
  }
}

template <class Weigh>
void CudaEigenbasis::transform(const CudaMatrix& in, CudaMatrix& out, const Weigh& weigh,
                               const char* function) {
  Workspace& w = *workspace_;
  requireDecomposedSize(in.rows(), in.cols(), function);
  if (in.rows() == 0) return;
  gemm(CUBLAS_OP_N, in, CUBLAS_OP_N, w.vectors, w.product);     // in V
  gemm(CUBLAS_OP_C, w.vectors, CUBLAS_OP_N, w.product, w.hat);  // Vᴴ in V
  weigh();                                                      // Â ← F ∘ Â
  gemm(CUBLAS_OP_N, w.vectors, CUBLAS_OP_N, w.hat, w.product);  // V (F ∘ Â)
  if (out.rows() != in.rows() || out.cols() != in.cols()) out = CudaMatrix(in.rows(), in.cols());
  gemm(CUBLAS_OP_N, w.product, CUBLAS_OP_C, w.vectors, out);
  cuda_kernels::makeSkewHermitian(out.rows(), reinterpret_cast<double*>(out.deviceData()));
}

}  // namespace ddb
