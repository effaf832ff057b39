// The Hoppe–Yau Laplacian Δ_N − κ² applied entry by entry (systems/hoppe_yau_laplacian.h): the
// CUDA backend's apply (CudaPoissonSolver::apply, the magnetic fluid's current B = ΔΘ), one GPU
// thread per entry of a column-major N×N matrix of complex entries stored as (re, im) pairs.
// Unlike the solve, apply has no recurrence along a diagonal, so it needs neither the sheared
// layout nor stored coefficients: each thread computes its entry's from their formulas
// (systems/hoppe_yau_coefficients.h). Compiled for the host too, so that the host tests check the
// kernels' work (tests/cuda/test_cuda_poisson_layout.cc).
#pragma once

#include <ddb/core/detail/host_device.h>
#include <ddb/systems/hoppe_yau_coefficients.h>

namespace ddb::laplacian_entries {

/// out(i, j) = ((Δ − κ²) P)(i, j): with k = min(i, j) its place along its diagonal of length L,
///   (d_k − κ²) P(i, j) + c_k P(i − 1, j − 1) + c_{k+1} P(i + 1, j + 1)
/// (the terms past the diagonal's ends left out), each part by HoppeYauLaplacian::applyBlock's
/// operations in its order, so the dense apply's bits. out is not p.
DDB_HOST_DEVICE inline void applyAt(long n, double kappa_squared, long i, long j, const double* p,
                                    double* out) {
  const long offset = i < j ? j - i : i - j, k = i < j ? i : j, length = n - offset;
  const long at = 2 * (i + j * n), step = 2 * (n + 1);  // (i ± 1, j ± 1) is N + 1 entries away
  const double d = hoppe_yau::diagonalCoefficient(n, k, offset) - kappa_squared;
  double re = d * p[at], im = d * p[at + 1];
  if (k > 0) {
    const double c = hoppe_yau::coupling(n, k, offset);
    re += c * p[at - step];
    im += c * p[at - step + 1];
  }
  if (k + 1 < length) {
    const double c = hoppe_yau::coupling(n, k + 1, offset);
    re += c * p[at + step];
    im += c * p[at + step + 1];
  }
  out[at] = re;
  out[at + 1] = im;
}

}  // namespace ddb::laplacian_entries
