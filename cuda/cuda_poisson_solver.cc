// CudaPoissonSolver (cuda/cuda_poisson_solver.h), in its context (cuda/cuda_context.h).
#include <cuda_runtime.h>
#include <ddb/core/errors.h>
#include <ddb/cuda/cuda_backend.h>
#include <ddb/cuda/cuda_poisson_solver.h>
#include <ddb/cuda/detail/cuda_check.h>
#include <ddb/cuda/detail/cuda_context_state.h>
#include <ddb/cuda/detail/poisson_kernels.h>
#include <ddb/cuda/detail/sheared_factors.h>
#include <ddb/cuda/detail/skewed_diagonals.h>

#include <string>
#include <vector>

namespace ddb {

struct CudaPoissonSolver::Device {
  long n = 0;
  double kappa_squared = 0.0;
  CudaMatrix sheared;  // (2N − 1) × N: column c of the layout is row c of this matrix
  double* lower = nullptr;
  double* inverse_pivot = nullptr;

  ~Device() {
    cudaFree(lower);
    cudaFree(inverse_pivot);
  }
};

CudaPoissonSolver::CudaPoissonSolver(long n, double kappa_squared,
                                     std::shared_ptr<CudaContext> context)
    : device_(std::make_unique<Device>()) {
  if (n < 2) throwInvalid("N", std::to_string(n), "must be >= 2");
  HoppeYauLaplacian::requireShift(kappa_squared);
  Device& d = *device_;
  d.n = n;
  d.kappa_squared = kappa_squared;
  d.sheared = CudaMatrix(skewed::width(n), n, std::move(context));
  std::vector<double> lower, inverse_pivot;
  skewed::shearedFactors(n, kappa_squared, lower, inverse_pivot);
  const std::size_t entries = lower.size();
  for (auto [host, device] : {std::pair{&lower, &d.lower}, {&inverse_pivot, &d.inverse_pivot}}) {
    checkCuda(cudaMalloc(device, sizeof(double) * entries), "cudaMalloc");
    copyToDevice(d.sheared.context()->state(), *device, host->data(), sizeof(double) * entries);
  }
}

CudaPoissonSolver::~CudaPoissonSolver() = default;
CudaPoissonSolver::CudaPoissonSolver(CudaPoissonSolver&&) noexcept = default;
CudaPoissonSolver& CudaPoissonSolver::operator=(CudaPoissonSolver&&) noexcept = default;

long CudaPoissonSolver::size() const { return device_->n; }
const std::shared_ptr<CudaContext>& CudaPoissonSolver::context() const {
  return device_->sheared.context();
}

void CudaPoissonSolver::requireOperand(const CudaMatrix& x, const char* name) const {
  const Device& d = *device_;
  if (x.rows() != d.n || x.cols() != d.n) {
    throwInvalid(
        "matrix", std::to_string(x.rows()) + "x" + std::to_string(x.cols()),
        "must be " + std::to_string(d.n) + "x" + std::to_string(d.n) + " for this Poisson solver");
  }
  requireContext(x, d.sheared.context(), name, "the Poisson solver's context");
}

void CudaPoissonSolver::solve(const CudaMatrix& W, CudaMatrix& out) {
  using B = MatrixBackend<CudaMatrix>;
  Device& d = *device_;
  requireOperand(W, "W");
  CudaContext::State& state = d.sheared.context()->state();
  // The means as parts divided by N (tr/N rounded once in each part).
  const auto meanOf = [&](const CudaMatrix& x) {
    const std::complex<double> trace = B::trace(x);
    return std::complex<double>(trace.real() / double(d.n), trace.imag() / double(d.n));
  };
  const std::complex<double> mean = meanOf(W);
  auto* sheared = reinterpret_cast<double*>(d.sheared.deviceData());
  cuda_kernels::toSkewed(state, d.n, reinterpret_cast<const double*>(W.deviceData()), mean.real(),
                         mean.imag(), sheared);
  cuda_kernels::sweepDiagonals(state, d.n, sheared, d.lower, d.inverse_pivot);
  if (!B::sameShape(out, W) || out.context() != W.context())
    out = CudaMatrix(d.n, d.n, W.context());
  cuda_kernels::fromSkewed(state, d.n, sheared, reinterpret_cast<double*>(out.deviceData()));
  B::addToDiagonal(out, -meanOf(out));
}

void CudaPoissonSolver::apply(const CudaMatrix& P, CudaMatrix& out) {
  Device& d = *device_;
  requireOperand(P, "P");
  if (&out == &P) throwInvalid("out", "P itself", "must be another matrix than P");
  if (!MatrixBackend<CudaMatrix>::sameShape(out, P) || out.context() != P.context())
    out = CudaMatrix(d.n, d.n, P.context());
  cuda_kernels::applyLaplacian(d.sheared.context()->state(), d.n, d.kappa_squared,
                               reinterpret_cast<const double*>(P.deviceData()),
                               reinterpret_cast<double*>(out.deviceData()));
}

}  // namespace ddb
