// CudaLu (cuda/cuda_lu.h): cuSOLVER's zgetrf and zgetrs with kept workspaces, in the factored
// matrix's context (cuda/cuda_context.h).
#include <cuda_runtime.h>
#include <ddb/core/errors.h>
#include <ddb/cuda/cuda_lu.h>
#include <ddb/cuda/detail/cuda_check.h>
#include <ddb/cuda/detail/cuda_context_state.h>
#include <ddb/cuda/detail/cuda_libraries.h>

#include <memory>
#include <string>

namespace ddb {

struct CudaLu::Workspace {
  long n = -1;
  std::shared_ptr<CudaContext> context;  // the factored matrix's
  int* pivots = nullptr;
  int* info = nullptr;
  cuDoubleComplex* scratch = nullptr;

  ~Workspace() {
    cudaFree(pivots);
    cudaFree(info);
    cudaFree(scratch);
  }
  // Sized for n×n factors in a's context (a new size or context frees the old buffers first:
  // cudaFree waits for the device, so no solve of another stream still reads them).
  void reserve(CudaContext::State& state, CudaMatrix& a) {
    if (a.rows() == n && a.context() == context) return;
    cudaFree(pivots);
    cudaFree(info);
    cudaFree(scratch);
    pivots = nullptr;
    info = nullptr;
    scratch = nullptr;
    n = -1;
    const int rows = static_cast<int>(a.rows());
    int length = 0;
    checkCusolver(cusolverDnZgetrf_bufferSize(state.cusolver, rows, rows,
                                              reinterpret_cast<cuDoubleComplex*>(a.deviceData()),
                                              rows, &length),
                  "cusolverDnZgetrf_bufferSize");
    checkCuda(cudaMalloc(&pivots, sizeof(int) * (rows > 0 ? rows : 1)), "cudaMalloc");
    checkCuda(cudaMalloc(&info, sizeof(int)), "cudaMalloc");
    checkCuda(cudaMalloc(&scratch, sizeof(cuDoubleComplex) * (length > 0 ? length : 1)),
              "cudaMalloc");
    n = a.rows();
    context = a.context();
  }
};

CudaLu::CudaLu() : workspace_(std::make_unique<Workspace>()) {}
CudaLu::~CudaLu() = default;
CudaLu::CudaLu(CudaLu&&) noexcept = default;
CudaLu& CudaLu::operator=(CudaLu&&) noexcept = default;

bool CudaLu::factor(CudaMatrix& a) {
  CudaContext::State& state = stateOf(a);
  workspace_->reserve(state, a);
  const int n = static_cast<int>(a.rows());
  checkCusolver(
      cusolverDnZgetrf(state.cusolver, n, n, reinterpret_cast<cuDoubleComplex*>(a.deviceData()), n,
                       workspace_->scratch, workspace_->pivots, workspace_->info),
      "cusolverDnZgetrf");
  int info = 0;
  copyToHost(state, &info, workspace_->info, sizeof(int));
  if (info < 0) {
    throw CudaError("cusolverDnZgetrf rejected its argument " + std::to_string(-info));
  }
  return info == 0;
}

void CudaLu::solve(const CudaMatrix& factored, CudaMatrix& b) {
  requireContext(factored, workspace_->context, "factored",
                 "the context of the matrix factored last");
  if (b.size() > 0) requireContext(b, factored.context(), "b", "the factored matrix's context");
  const int n = static_cast<int>(factored.rows());
  checkCusolver(
      cusolverDnZgetrs(stateOf(factored).cusolver, CUBLAS_OP_N, n, static_cast<int>(b.cols()),
                       reinterpret_cast<const cuDoubleComplex*>(factored.deviceData()), n,
                       workspace_->pivots, reinterpret_cast<cuDoubleComplex*>(b.deviceData()), n,
                       workspace_->info),
      "cusolverDnZgetrs");
}

}  // namespace ddb
