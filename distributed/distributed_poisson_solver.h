// The Poisson solve P = Δ⁻¹(W − tr(W)/N · I) of Zeitlin's fluid on a block-cyclic W
// (docs/distributed.md): whole diagonals are gathered on their owners
// (DiagonalRedistribution), each is solved there by the serial HoppeYauLaplacian's
// per-diagonal sweep, and the result goes back to the block-cyclic layout.
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
  explicit DistributedPoissonSolver(const BlockCyclicLayout& layout)
      : laplacian_(layout.size()),
        grid_(&layout.grid()),
        block_(layout.block()),
        redistribution_(layout) {
    diagonals_.resize(redistribution_.ownedEntries());
  }

  /// out = Δ⁻¹(W − tr(W)/N · I); collective. out may be W; both have this solver's grid, N
  /// and block size.
  void solve(const DistributedMatrix& W, DistributedMatrix& out) {
    for (const DistributedMatrix* m : {&W, static_cast<const DistributedMatrix*>(&out)}) {
      if (m->size() != laplacian_.size() || m->layout().block() != block_ ||
          &m->layout().grid() != grid_) {
        throwInvalid(
            "matrix",
            "N = " + std::to_string(m->size()) + ", block " + std::to_string(m->layout().block()),
            "must have N = " + std::to_string(laplacian_.size()) + " and block " +
                std::to_string(block_) + " for this solver");
      }
    }
    redistribution_.toDiagonals(W.local(), diagonals_);
    const auto& owned = redistribution_.diagonals();
    for (std::size_t d = 0; d < owned.size(); ++d) {
      const int m = owned[d];
      laplacian_.solveDiagonal(
          m, diagonals_.segment(redistribution_.offsets()[d], laplacian_.size() - std::abs(m)));
    }
    redistribution_.toBlockCyclic(diagonals_, out.local());
  }

  /// Bytes this rank sends to other ranks in one solve (both exchanges).
  std::int64_t bytesSentPerSolve() const {
    return redistribution_.bytesSentToDiagonals() + redistribution_.bytesSentToBlockCyclic();
  }

 private:
  HoppeYauLaplacian laplacian_;
  const ProcessGrid* grid_;
  int block_;
  DiagonalRedistribution redistribution_;
  Eigen::VectorXcd diagonals_;
};

}  // namespace ddb
