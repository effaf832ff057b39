// The Hoppe–Yau Laplacian's LDLᵀ factors of every diagonal (HoppeYauLaplacian::factorBlock,
// systems/hoppe_yau_laplacian.h) in the sheared layout of cuda/detail/skewed_diagonals.h: what
// CudaPoissonSolver uploads once and its sweeps read. Host code.
#pragma once

#include <ddb/cuda/detail/skewed_diagonals.h>
#include <ddb/systems/hoppe_yau_laplacian.h>

#include <Eigen/Core>
#include <cstddef>
#include <vector>

namespace ddb::skewed {

/// lower and inverse_pivot ← the factors of every diagonal of the N×N Δ_N − κ²
/// (HoppeYauLaplacian::factorDiagonal), (2N − 1)·N entries each, zero where no diagonal reaches.
inline void shearedFactors(long n, double kappa_squared, std::vector<double>& lower,
                           std::vector<double>& inverse_pivot) {
  const auto entries = static_cast<std::size_t>(width(n) * n);
  lower.assign(entries, 0.0);
  inverse_pivot.assign(entries, 0.0);
  Eigen::VectorXd block_lower, block_inverse_pivot;
  for (long m = -(n - 1); m < n; ++m) {
    const long length = n - (m >= 0 ? m : -m);
    block_lower.resize(length);
    block_inverse_pivot.resize(length);
    HoppeYauLaplacian::factorDiagonal(n, m, kappa_squared, block_lower, block_inverse_pivot);
    for (long k = 0; k < length; ++k) {
      // Entry k of diagonal m: (k, k + m) for m >= 0, (k − m, k) for m < 0.
      const auto at = static_cast<std::size_t>(indexOf(n, m >= 0 ? k : k - m, m >= 0 ? k + m : k));
      lower[at] = block_lower(k);
      inverse_pivot[at] = block_inverse_pivot(k);
    }
  }
}

}  // namespace ddb::skewed
