// The passes of the CUDA Poisson solve and apply (cuda/cuda_poisson_solver.h) on device addresses,
// complex entries as (re, im) pairs, the sheared layout of cuda/detail/skewed_diagonals.h.
#pragma once

#include <ddb/cuda/cuda_context.h>

namespace ddb::cuda_kernels {

/// skewed ← W sheared, the complex mean subtracted from the diagonal (W N×N).
void toSkewed(CudaContext::State& ctx, long n, const double* w, double mean_real, double mean_imag,
              double* skewed);
/// Every diagonal's sweep (skewed::sweepColumn), one thread per column of the sheared array.
void sweepDiagonals(CudaContext::State& ctx, long n, double* skewed, const double* lower,
                    const double* inverse_pivot);
/// out ← the N×N matrix of the sheared array.
void fromSkewed(CudaContext::State& ctx, long n, const double* skewed, double* out);
/// out ← (Δ − κ²) p, entry by entry (laplacian_entries::applyAt); out is not p.
void applyLaplacian(CudaContext::State& ctx, long n, double kappa_squared, const double* p,
                    double* out);

}  // namespace ddb::cuda_kernels
