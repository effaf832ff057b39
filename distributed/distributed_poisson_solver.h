// The Poisson solve P = Δ⁻¹(W − tr(W)/N · I) of Zeitlin's fluid on a block-cyclic W
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
#include <cstdint>
#include <cstdlib>
#include <string>

namespace ddb {

class DistributedPoissonSolver {
 public:
  /// The solver of Δ_N − κ² (κ² = 0: the Laplacian; HoppeYauLaplacian) on `layout`.
  explicit DistributedPoissonSolver(const BlockCyclicLayout& layout, double kappa_squared = 0.0)
      : n_(layout.size()), grid_(&layout.grid()), block_(layout.block()), redistribution_(layout) {
    if (n_ < 2) throwInvalid("N", std::to_string(n_), "must be >= 2");
    HoppeYauLaplacian::requireShift(kappa_squared);
    const Eigen::Index entries = redistribution_.ownedEntries();
    diagonals_.resize(entries);
    lower_.resize(entries);
    inverse_pivot_.resize(entries);
    const auto& owned = redistribution_.diagonals();
    for (std::size_t d = 0; d < owned.size(); ++d) {
      Eigen::VectorBlock<Eigen::VectorXd> lower = ownedSegment(lower_, d),
                                          inverse_pivot = ownedSegment(inverse_pivot_, d);
      HoppeYauLaplacian::factorDiagonal(n_, owned[d], kappa_squared, lower, inverse_pivot);
    }
  }

  /// out = (Δ − κ²)⁻¹(W − tr(W)/N · I); collective. out may be W; both have this solver's grid, N
  /// and block size.
  void solve(const DistributedMatrix& W, DistributedMatrix& out) {
    for (const DistributedMatrix* m : {&W, static_cast<const DistributedMatrix*>(&out)}) {
      if (m->size() != n_ || m->layout().block() != block_ || &m->layout().grid() != grid_) {
        throwInvalid(
            "matrix",
            "N = " + std::to_string(m->size()) + ", block " + std::to_string(m->layout().block()),
            "must have N = " + std::to_string(n_) + " and block " + std::to_string(block_) +
                " for this solver");
      }
    }
    redistribution_.toDiagonals(W.local(), diagonals_);
    const auto& owned = redistribution_.diagonals();
    for (std::size_t d = 0; d < owned.size(); ++d) {
      HoppeYauLaplacian::sweepDiagonal(owned[d] == 0, ownedSegment(lower_, d),
                                       ownedSegment(inverse_pivot_, d),
                                       ownedSegment(diagonals_, d));
    }
    redistribution_.toBlockCyclic(diagonals_, out.local());
  }

  /// Bytes this rank sends to other ranks in one solve (both exchanges).
  std::int64_t bytesSentPerSolve() const {
    return redistribution_.bytesSentToDiagonals() + redistribution_.bytesSentToBlockCyclic();
  }

 private:
  // The entries of this rank's d-th diagonal in a vector packed like diagonals_.
  template <class Vector>
  Eigen::VectorBlock<Vector> ownedSegment(Vector& packed, std::size_t d) const {
    const int m = redistribution_.diagonals()[d];
    return packed.segment(redistribution_.offsets()[d], n_ - std::abs(m));
  }

  int n_;
  const ProcessGrid* grid_;
  int block_;
  DiagonalRedistribution redistribution_;
  Eigen::VectorXcd diagonals_;
  Eigen::VectorXd lower_, inverse_pivot_;  // the factors of the owned diagonals, packed
};

}  // namespace ddb
