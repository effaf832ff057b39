// CudaEigenbasis (cuda/cuda_eigenbasis.h): cuSOLVER's zheevd with kept workspaces, cuBLAS's
// zgemm and the weighing kernel of cuda/detail/cuda_kernels.cu, in the decomposed matrix's context
// (cuda/cuda_context.h).
#include <cuda_runtime.h>
#include <ddb/core/errors.h>
#include <ddb/cuda/cuda_eigenbasis.h>
#include <ddb/cuda/detail/cuda_check.h>
#include <ddb/cuda/detail/cuda_context_state.h>
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

// out = op_a(a) op_b(b), all n×n (n > 0), in `state`.
void gemm(CudaContext::State& state, cublasOperation_t op_a, const CudaMatrix& a,
          cublasOperation_t op_b, const CudaMatrix& b, CudaMatrix& out) {
  const cuDoubleComplex one = make_cuDoubleComplex(1.0, 0.0), zero = make_cuDoubleComplex(0.0, 0.0);
  const int n = static_cast<int>(a.rows());
  checkCublas(cublasZgemm(state.cublas, op_a, op_b, n, n, n, &one, complexData(a), n,
                          complexData(b), n, &zero, complexData(out), n),
              "cublasZgemm");
}

}  // namespace

struct CudaEigenbasis::Workspace {
  long n = -1;
  std::shared_ptr<CudaContext> context;  // the decomposed matrix's
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
  CudaContext::State& state() { return context->state(); }
  // Sized for n×n matrices in `in` (a new size or context frees the old buffers first).
  void reserve(long size, const std::shared_ptr<CudaContext>& in) {
    if (size == n && in == context) return;
    release();
    context = in;
    vectors = CudaMatrix(size, size, context);
    product = CudaMatrix(size, size, context);
    hat = CudaMatrix(size, size, context);
    const int rows = static_cast<int>(size);
    checkCusolver(cusolverDnZheevd_bufferSize(state().cusolver, CUSOLVER_EIG_MODE_VECTOR,
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
  const int n = static_cast<int>(x.rows());
  phases_.resize(n);
  if (n == 0) return true;  // cuSOLVER asks lda ≥ 1
  Workspace& w = *workspace_;
  w.reserve(x.rows(), x.context());
  CudaContext::State& state = w.state();
  const long count = 2 * x.size();
  if (cuda_kernels::countNotFinite(state, count, reinterpret_cast<const double*>(x.deviceData())) >
      0) {
    return false;
  }
  w.weighted = false;  // a new basis takes new weights
  // −ix, exactly: (re, im)·(0, −1) = (im, −re).
  checkCuda(
      cudaMemcpyAsync(w.vectors.deviceData(), x.deviceData(), sizeof(CudaMatrix::Scalar) * x.size(),
                      cudaMemcpyDeviceToDevice, state.stream),
      "cudaMemcpyAsync (on the device)");
  const cuDoubleComplex minus_i = make_cuDoubleComplex(0.0, -1.0);
  checkCublas(
      cublasZscal(state.cublas, static_cast<int>(x.size()), &minus_i, complexData(w.vectors), 1),
      "cublasZscal");
  checkCusolver(
      cusolverDnZheevd(state.cusolver, CUSOLVER_EIG_MODE_VECTOR, CUBLAS_FILL_MODE_LOWER, n,
                       complexData(w.vectors), n, w.phases, w.scratch, w.scratch_length, w.info),
      "cusolverDnZheevd");
  int info = 0;
  copyToHost(state, &info, w.info, sizeof(int));
  if (info < 0) throw CudaError("cusolverDnZheevd rejected its argument " + std::to_string(-info));
  if (info > 0) return false;
  copyToHost(state, phases_.data(), w.phases, sizeof(double) * n);
  return true;
}

void CudaEigenbasis::apply(PhaseFunction f, double scale, const CudaMatrix& in, CudaMatrix& out) {
  transform(
      in, out,
      [&] {
        weigh(PhaseFunctionWeights{f, scale}, workspace_->hat);
      },
      "apply");
}

void CudaEigenbasis::uploadWeights(const Eigen::MatrixXd& weights) {
  requireDecomposedSize(weights.rows(), weights.cols(), "setWeights");
  Workspace& w = *workspace_;
  if (weights.size() > 0) {
    if (w.weights == nullptr) {
      checkCuda(cudaMalloc(&w.weights, sizeof(double) * weights.size()), "cudaMalloc");
    }
    copyToDevice(w.state(), w.weights, weights.data(), sizeof(double) * weights.size());
  }
  w.weighted = true;
}

void CudaEigenbasis::applyWeights(const CudaMatrix& in, CudaMatrix& out) {
  Workspace& w = *workspace_;
  if (!w.weighted) {
    throw std::logic_error("CudaEigenbasis::applyWeights: no weights for this basis");
  }
  const auto weigh = [&] {
    cuda_kernels::weighEntrywise(w.state(), in.size(), w.weights,
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
  requireDecomposedContext(y, "diagonalPhasesOf");
  CudaContext::State& state = w.state();
  gemm(state, CUBLAS_OP_N, y, CUBLAS_OP_N, w.vectors, w.product);      // y V
  gemm(state, CUBLAS_OP_C, w.vectors, CUBLAS_OP_N, w.product, w.hat);  // Vᴴ y V
  cuda_kernels::imaginaryDiagonal(state, n, reinterpret_cast<const double*>(w.hat.deviceData()),
                                  w.diagonal);
  copyToHost(state, out.data(), w.diagonal, sizeof(double) * n);
}

void CudaEigenbasis::requireDecomposedSize(long rows, long cols, const char* function) const {
  if (rows != phases_.size() || cols != rows) {
    throw std::logic_error(std::string("CudaEigenbasis::") + function +
                           ": a matrix of another size than the decomposed one");
  }
}

void CudaEigenbasis::requireDecomposedContext(const CudaMatrix& x, const char* function) const {
  requireContext(x, workspace_->context, std::string("CudaEigenbasis::") + function,
                 "the decomposed matrix's context");
}

void CudaEigenbasis::toBasis(const CudaMatrix& in, CudaMatrix& hat) {
  conjugate(in, hat, CUBLAS_OP_C, "toBasis");
}

void CudaEigenbasis::fromBasis(const CudaMatrix& hat, CudaMatrix& out) {
  conjugate(hat, out, CUBLAS_OP_N, "fromBasis");
  if (out.rows() > 0) {
    cuda_kernels::makeSkewHermitian(workspace_->state(), out.rows(),
                                    reinterpret_cast<double*>(out.deviceData()));
  }
}

void CudaEigenbasis::conjugate(const CudaMatrix& in, CudaMatrix& out, int op_a,
                               const char* function) {
  Workspace& w = *workspace_;
  requireDecomposedSize(in.rows(), in.cols(), function);
  if (out.rows() != in.rows() || out.cols() != in.cols() || out.context() != w.context) {
    out = CudaMatrix(in.rows(), in.cols(), w.context);
  }
  if (in.rows() == 0) return;
  requireDecomposedContext(in, function);
  const auto op = static_cast<cublasOperation_t>(op_a);
  const cublasOperation_t adjoint_op = op == CUBLAS_OP_N ? CUBLAS_OP_C : CUBLAS_OP_N;
  gemm(w.state(), CUBLAS_OP_N, in, adjoint_op, w.vectors, w.product);  // in Aᴴ
  gemm(w.state(), op, w.vectors, CUBLAS_OP_N, w.product, out);         // A in Aᴴ
}

template <class Kernel>
void CudaEigenbasis::weighEntries(CudaMatrix& m, const Kernel& kernel) {
  requireDecomposedSize(m.rows(), m.cols(), "weigh");
  if (m.rows() == 0) return;
  requireDecomposedContext(m, "weigh");
  Workspace& w = *workspace_;
  kernel(w.state(), m.rows(), w.phases, reinterpret_cast<double*>(m.deviceData()));
}

void CudaEigenbasis::weigh(const PhaseFunctionWeights& weights, CudaMatrix& m) {
  weighEntries(m, [&](CudaContext::State& state, long n, const double* phases, double* x) {
    cuda_kernels::weighByPhases(state, n, phases, weights.scale, weights.f, x);
  });
}

void CudaEigenbasis::weigh(const ConjugationDerivativeWeights& weights, CudaMatrix& m) {
  weighEntries(m, [&](CudaContext::State& state, long n, const double* phases, double* x) {
    cuda_kernels::weighByConjugationDerivative(state, n, phases, weights.tau, x);
  });
}

void CudaEigenbasis::weigh(const RowPhaseWeights& weights, CudaMatrix& m) {
  weighEntries(m, [&](CudaContext::State& state, long n, const double* phases, double* x) {
    cuda_kernels::weighRowsByPhase(state, n, phases, weights.tau, x);
  });
}

template <class Weigh>
void CudaEigenbasis::transform(const CudaMatrix& in, CudaMatrix& out, const Weigh& weigh,
                               const char* function) {
  Workspace& w = *workspace_;
  requireDecomposedSize(in.rows(), in.cols(), function);
  if (in.rows() == 0) return;
  requireDecomposedContext(in, function);
  toBasis(in, w.hat);  // Â = Vᴴ in V
  weigh();             // Â ← F ∘ Â
  fromBasis(w.hat, out);
}

}  // namespace ddb
