// The Poisson solve P = Δ⁻¹(W − tr(W)/N · I) of Zeitlin's fluid (systems/hoppe_yau_laplacian.h)
// on a CudaMatrix, and the Laplacian itself (apply: cuda/detail/laplacian_entries.h). The solve:
// W is sheared so that each diagonal of the Hoppe–Yau Laplacian is a column
// (cuda/detail/skewed_diagonals.h), one GPU thread sweeps each column with the factors
// HoppeYauLaplacian computes (uploaded once, in the same layout), and the result is sheared
// back; the means are removed before and after as HoppeYauLaplacian::solve removes them.
// Workspace: the sheared array, (2N − 1)·N complex numbers, and two real arrays as large.
#pragma once

#include <ddb/cuda/cuda_matrix.h>

#include <memory>

namespace ddb {

class CudaPoissonSolver {
 public:
  /// For N×N matrices, N >= 2 (InvalidArgument naming N otherwise); the operator Δ_N − κ²
  /// (κ² = 0: the Laplacian; HoppeYauLaplacian); its factors and workspace in `context` (this
  /// thread's when none is given), whose matrices alone it solves for.
  explicit CudaPoissonSolver(long n, double kappa_squared = 0.0,
                             std::shared_ptr<CudaContext> context = nullptr);
  ~CudaPoissonSolver();
  CudaPoissonSolver(CudaPoissonSolver&&) noexcept;
  CudaPoissonSolver& operator=(CudaPoissonSolver&&) noexcept;

  /// out = (Δ − κ²)⁻¹(W − tr(W)/N · I); out may be W. InvalidArgument if W is not N×N or not
  /// in the solver's context.
  void solve(const CudaMatrix& W, CudaMatrix& out);
  /// out = (Δ − κ²) P (the magnetic fluid's current B = ΔΘ, systems/zeitlin_mhd.h), entry by
  /// entry with the dense apply's operations (HoppeYauLaplacian::apply's bits: the device's square
  /// root is correctly rounded too); out is not P. InvalidArgument if P is not N×N or not in the
  /// solver's context.
  void apply(const CudaMatrix& P, CudaMatrix& out);

  long size() const;
  /// The context its factors are in.
  const std::shared_ptr<CudaContext>& context() const;

 private:
  // InvalidArgument unless x is N×N and in the solver's context (x named `name`).
  void requireOperand(const CudaMatrix& x, const char* name) const;

  struct Device;
  std::unique_ptr<Device> device_;
};

}  // namespace ddb
