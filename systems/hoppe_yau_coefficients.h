// The Hoppe–Yau Laplacian's coefficients (systems/hoppe_yau_laplacian.h) at one place of one
// diagonal: the one place their formulas live, for the dense and distributed solvers (through
// HoppeYauLaplacian::blockCoefficients) and for the GPU's kernels
// (cuda/detail/laplacian_entries.h), which compute them where they use them instead of storing N²
// of each. Place k of the diagonal `offset` = |j − i| is entry (k, k + offset) or (k + offset, k);
// with i = k and j = k + offset,
//   d_k = −((N − 1)(i + j + 1) − 2ij),   c_k = √(i(N − i) j(N − j))  (c_0 = 0),
// c_k coupling places k − 1 and k. d_k is exact in doubles; c_k's product is rounded in the order
// written, on the host and on a GPU alike (no fused multiply-add there: cuda/backend.cmake).
#pragma once

#include <ddb/core/detail/host_device.h>
#include <math.h>

namespace ddb::hoppe_yau {

/// d_k, the diagonal coefficient at place k of the diagonal `offset` off the main one.
DDB_HOST_DEVICE inline double diagonalCoefficient(long n, long k, long offset) {
  const double i = double(k), j = double(k + offset), N = double(n);
  return -((N - 1) * (i + j + 1) - 2 * i * j);
}

/// c_k, the coupling of places k − 1 and k of the diagonal `offset` off the main one (0 at k = 0).
DDB_HOST_DEVICE inline double coupling(long n, long k, long offset) {
  const double i = double(k), j = double(k + offset), N = double(n);
  return k == 0 ? 0.0 : ::sqrt(i * (N - i) * j * (N - j));
}

}  // namespace ddb::hoppe_yau
