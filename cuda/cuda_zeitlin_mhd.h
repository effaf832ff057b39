// Magnetohydrodynamics on the sphere (systems/zeitlin_mhd.h) on one GPU: SU(N) ⋉ su(N)* on
// DualMatrix<CudaMatrix> (W and Θ in one context's memory), with CudaPoissonSolver's solve and
// apply. Every row of the method table that runs on the dense magnetic fluid (makeMethod) and
// Relaxation with the Newton search run on it, the exponential ones through the dual numbers'
// spectral calculus (core/dual_eigenbasis.h) on CudaEigenbasis's coordinates (docs/guide/gpu.md,
// "The magnetic fluid"), as on MPI ranks (distributed/distributed_zeitlin_mhd.h).
#pragma once

#include <ddb/core/dual_matrix.h>
#include <ddb/cuda/cuda_backend.h>
#include <ddb/cuda/cuda_device.h>
#include <ddb/cuda/cuda_method_table.h>
#include <ddb/cuda/cuda_poisson_solver.h>
#include <ddb/groups/dual_number_sun.h>
#include <ddb/systems/zeitlin_mhd.h>

#include <memory>

namespace ddb {

/// SU(N) ⋉ su(N)* with its states' parts in one GPU's memory.
using CudaDualNumberSUN = DualNumberSUNOn<CudaMatrix>;

/// The magnetic fluid at resolution n with k♯ = α·swap, its Laplacian's factors on the device in
/// `context` (cuda/cuda_context.h; this thread's when none is given), whose states it takes.
/// InvalidArgument naming N or alpha.
inline std::shared_ptr<const LiePoissonSystem<CudaDualNumberSUN>> makeCudaZeitlinMhd(
    long n, double alpha, std::shared_ptr<CudaContext> context = nullptr) {
  return makeZeitlinMhdOn<CudaMatrix>(CudaPoissonSolver(n, 0.0, std::move(context)), n, alpha);
}

/// The state μ = Θ + εW on the device, in `context` (toDevice of each part).
inline DualMatrix<CudaMatrix> toDevice(const DualMatrix<Eigen::MatrixXcd>& mu,
                                       const std::shared_ptr<CudaContext>& context) {
  return {toDevice(mu.real, context), toDevice(mu.eps, context)};
}
/// ... in this thread's context (CudaContext::ofThisThread()).
inline DualMatrix<CudaMatrix> toDevice(const DualMatrix<Eigen::MatrixXcd>& mu) {
  return {toDevice(mu.real), toDevice(mu.eps)};
}
/// μ's parts in this process's memory.
inline DualMatrix<Eigen::MatrixXcd> toHost(const DualMatrix<CudaMatrix>& mu) {
  return {toHost(mu.real), toHost(mu.eps)};
}

}  // namespace ddb
