// The Poisson solve P = Δ⁻¹(W − tr(W)/N · I) of Zeitlin's fluid on a block-cyclic W, and the
// Laplacian itself (apply: the magnetic fluid's current B = ΔΘ, systems/zeitlin_mhd.h)
// (docs/design/distributed.md): whole diagonals are gathered on their owners
// (DiagonalRedistribution), each is solved there by the serial HoppeYauLaplacian's
// per-diagonal sweep, and the result goes back to the block-cyclic layout. Each rank keeps
// the factors of its own diagonals only, packed as its diagonals are (two vectors of about
// N²/P numbers, not the serial class's N×N matrices).
#pragma once

#include <ddb/distributed/diagonal_redistribution.h>
#include <ddb/distributed/distributed_matrix.h>
#include <ddb/systems/hoppe_yau_laplacian.h>

#include <Eigen/Core>
#include <complex>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace ddb {

class DistributedPoissonSolver {
 public:
  /// The solver of Δ_N − κ² (κ² = 0: the Laplacian; HoppeYauLaplacian) on `layout`.
  explicit DistributedPoissonSolver(const BlockCyclicLayout& layout, double kappa_squared = 0.0)
      : n_(layout.size()),
        grid_(&layout.grid()),
        block_(layout.block()),
        kappa_squared_(kappa_squared),
        redistribution_(layout) {
    if (n_ < 2) throwInvalid("N", std::to_string(n_), "must be >= 2");
    HoppeYauLaplacian::requireShift(kappa_squared);
    const Eigen::Index entries = redistribution_.ownedEntries();
    diagonals_.resize(entries);
    applied_.resize(entries);
    lower_.resize(entries);
    inverse_pivot_.resize(entries);
    block_diagonal_.resize(entries);
    off_.resize(entries);
    const auto& owned = redistribution_.diagonals();
    Eigen::VectorXd diagonal, off;
    for (std::size_t d = 0; d < owned.size(); ++d) {
      Eigen::VectorBlock<Eigen::VectorXd> lower = ownedSegment(lower_, d),
                                          inverse_pivot = ownedSegment(inverse_pivot_, d);
      HoppeYauLaplacian::factorDiagonal(n_, owned[d], kappa_squared, lower, inverse_pivot);
      HoppeYauLaplacian::blockCoefficients(n_, owned[d], diagonal, off);
      ownedSegment(block_diagonal_, d) = diagonal;
      ownedSegment(off_, d) = off;
    }
  }

  /// out = (Δ − κ²)⁻¹(W − tr(W)/N · I); collective. out may be W; both have this solver's grid, N
  /// and block size.
  void solve(const DistributedMatrix& W, DistributedMatrix& out) {
    requireLayout(W, out);
    redistribution_.toDiagonals(W.local(), diagonals_);
    const auto& owned = redistribution_.diagonals();
    for (std::size_t d = 0; d < owned.size(); ++d) {
      HoppeYauLaplacian::sweepDiagonal(owned[d] == 0, ownedSegment(lower_, d),
                                       ownedSegment(inverse_pivot_, d),
                                       ownedSegment(diagonals_, d));
    }
    redistribution_.toBlockCyclic(diagonals_, out.local());
  }

  /// out = (Δ − κ²) P, each owned diagonal by its block (HoppeYauLaplacian::applyBlock, so the
  /// dense apply's bits); collective. out is not P.
  void apply(const DistributedMatrix& P, DistributedMatrix& out) {
    requireLayout(P, out);
    redistribution_.toDiagonals(P.local(), diagonals_);
    const auto& owned = redistribution_.diagonals();
    for (std::size_t d = 0; d < owned.size(); ++d) {
      const auto in = ownedSegment(diagonals_, d);
      auto result = ownedSegment(applied_, d);
      HoppeYauLaplacian::applyBlock(
          ownedSegment(block_diagonal_, d), ownedSegment(off_, d), kappa_squared_,
          [&](Eigen::Index k) { return in(k); },
          [&](Eigen::Index k, const std::complex<double>& value) { result(k) = value; });
    }
    redistribution_.toBlockCyclic(applied_, out.local());
  }

  /// Bytes this rank sends to other ranks in one solve (both exchanges).
  std::int64_t bytesSentPerSolve() const {
    return redistribution_.bytesSentToDiagonals() + redistribution_.bytesSentToBlockCyclic();
  }

 private:
  void requireLayout(const DistributedMatrix& in, const DistributedMatrix& out) const {
    for (const DistributedMatrix* m : {&in, &out}) {
      if (m->size() != n_ || m->layout().block() != block_ || &m->layout().grid() != grid_) {
        throwInvalid(
            "matrix",
            "N = " + std::to_string(m->size()) + ", block " + std::to_string(m->layout().block()),
            "must have N = " + std::to_string(n_) + " and block " + std::to_string(block_) +
                " for this solver");
      }
    }
  }

  // The entries of this rank's d-th diagonal in a vector packed like diagonals_.
  template <class Vector>
  Eigen::VectorBlock<Vector> ownedSegment(Vector& packed, std::size_t d) const {
    const int m = redistribution_.diagonals()[d];
    return packed.segment(redistribution_.offsets()[d], n_ - std::abs(m));
  }

  int n_;
  const ProcessGrid* grid_;
  int block_;
  double kappa_squared_;
  DiagonalRedistribution redistribution_;
  Eigen::VectorXcd diagonals_, applied_;
  Eigen::VectorXd lower_, inverse_pivot_;  // the factors of the owned diagonals, packed
  Eigen::VectorXd block_diagonal_, off_;   // their blocks of Δ (apply), packed
};

}  // namespace ddb
