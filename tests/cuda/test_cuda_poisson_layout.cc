// The CUDA Poisson solve's per-diagonal work and the apply's per-entry work on the host (no GPU
// needed): the sheared layout
// (cuda/detail/skewed_diagonals.h) holds every entry of an N×N matrix once, at its diagonal's
// column and its place along it, and sweeping every column with HoppeYauLaplacian's factors,
// the means removed as its solve removes them, gives that solve's bits; applying Δ − κ² entry by
// entry gives HoppeYauLaplacian::apply's bits. The kernels run these
// same functions (cuda/detail/cuda_kernels.cu).
#include <ddb/cuda/detail/laplacian_entries.h>
#include <ddb/cuda/detail/sheared_factors.h>
#include <ddb/cuda/detail/skewed_diagonals.h>
#include <ddb/systems/hoppe_yau_laplacian.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstring>
#include <set>
#include <vector>

namespace ddb {
namespace {

TEST(SkewedDiagonals, EveryEntryHasItsOwnPlaceAlongItsDiagonal) {
  for (const long n : {1L, 2L, 5L, 16L}) {
    std::set<long> places;
    for (long j = 0; j < n; ++j) {
      for (long i = 0; i < n; ++i) {
        const long at = skewed::indexOf(n, i, j), c = at % skewed::width(n),
                   k = at / skewed::width(n);
        EXPECT_EQ(c, j - i + n - 1);           // the diagonal's column
        EXPECT_EQ(k, std::min(i, j));          // the place along it
        EXPECT_LT(k, skewed::lengthOf(n, c));  // within the diagonal's length
        EXPECT_TRUE(places.insert(at).second) << i << ", " << j;
      }
    }
    long entries = 0;
    for (long c = 0; c < skewed::width(n); ++c) entries += skewed::lengthOf(n, c);
    EXPECT_EQ(entries, n * n);
  }
}

// The sheared sweeps with the host solve's means: HoppeYauLaplacian::solve to the bit.
TEST(SkewedDiagonals, SweepingEveryColumnGivesTheHostSolvesBits) {
  // The Laplacian and quasi-geostrophy's Δ − κ² (every block definite, nothing pinned).
  for (const double kappa_squared : {0.0, 0.7})
    for (const long n : {2L, 3L, 16L, 33L, 70L}) {
      const Eigen::MatrixXcd W =
          randomVorticity(n, 5) + Eigen::MatrixXcd::Identity(n, n) * std::complex<double>(0.1, 0.2);
      const HoppeYauLaplacian laplacian(n, kappa_squared);
      Eigen::MatrixXcd expected;
      laplacian.solve(W, expected);

      // The factors as CudaPoissonSolver lays them out.
      const long width = skewed::width(n);
      std::vector<double> lower, inverse_pivot;
      skewed::shearedFactors(n, kappa_squared, lower, inverse_pivot);
      // Sheared, the mean off the diagonal, as solve() does it.
      const std::complex<double> mean = W.trace() / std::complex<double>(double(n));
      std::vector<double> values(2 * lower.size());
      for (long j = 0; j < n; ++j) {
        for (long i = 0; i < n; ++i) {
          const std::complex<double> w = i == j ? W(i, j) - mean : W(i, j);
          const long at = skewed::indexOf(n, i, j);
          values[2 * at] = w.real();
          values[2 * at + 1] = w.imag();
        }
      }
      for (long c = 0; c < width; ++c) {
        skewed::sweepColumn(n, c, values.data(), lower.data(), inverse_pivot.data());
      }
      Eigen::MatrixXcd solved(n, n);
      for (long j = 0; j < n; ++j) {
        for (long i = 0; i < n; ++i) {
          const long at = skewed::indexOf(n, i, j);
          solved(i, j) = {values[2 * at], values[2 * at + 1]};
        }
      }
      solved.diagonal().array() -= solved.diagonal().mean();
      EXPECT_EQ(std::memcmp(solved.data(), expected.data(), sizeof(solved(0)) * solved.size()), 0)
          << "N = " << n << ", kappa^2 = " << kappa_squared << ", largest difference "
          << (solved - expected).cwiseAbs().maxCoeff();
    }
}

// Every entry's apply (the magnetic fluid's current B = ΔΘ on the GPU) on a column-major array of
// (re, im) pairs: HoppeYauLaplacian::apply to the bit, for the Laplacian and for Δ − κ².
TEST(LaplacianEntries, ApplyingEveryEntryGivesTheHostApplysBits) {
  for (const double kappa_squared : {0.0, 0.7})
    for (const long n : {2L, 3L, 16L, 33L, 70L}) {
      const Eigen::MatrixXcd P =
          randomVorticity(n, 6) + Eigen::MatrixXcd::Identity(n, n) * std::complex<double>(0.1, 0.2);
      Eigen::MatrixXcd expected(n, n);
      HoppeYauLaplacian(n, kappa_squared).apply(P, expected);
      Eigen::MatrixXcd applied = Eigen::MatrixXcd::Constant(n, n, {NAN, NAN});
      for (long j = 0; j < n; ++j)
        for (long i = 0; i < n; ++i) {
          laplacian_entries::applyAt(n, kappa_squared, i, j,
                                     reinterpret_cast<const double*>(P.data()),
                                     reinterpret_cast<double*>(applied.data()));
        }
      EXPECT_EQ(std::memcmp(applied.data(), expected.data(), sizeof(applied(0)) * applied.size()),
                0)
          << "N = " << n << ", kappa^2 = " << kappa_squared << ", largest difference "
          << (applied - expected).cwiseAbs().maxCoeff();
    }
}

}  // namespace
}  // namespace ddb
