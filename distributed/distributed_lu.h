// DistributedLu: the LU factorisation of a block-cyclic A (pzgetrf_) and solves with it
// (pzgetrs_), the Cayley conjugation's factor and solves on distributed matrices
// (MatrixBackend<DistributedMatrix>::Lu). Pivots are kept between calls and sized again
// when the layout changes.
#pragma once

#include <ddb/distributed/block_cyclic_layout.h>
#include <ddb/distributed/distributed_matrix.h>
#include <ddb/distributed/scalapack.h>

#include <vector>

namespace ddb {

class DistributedLu {
 public:
  /// A ← its LU factors (solve() takes the same A). Returns false on every rank when A is
  /// exactly singular.
  bool factor(DistributedMatrix& A) {
    const int n = A.size(), one = 1;
    const BlockCyclicLayout& layout = A.layout();
    pivots_.resize(static_cast<std::size_t>(layout.localRows() + layout.block()));
    int info = 0;
    pzgetrf_(&n, &n, A.data(), &one, &one, A.descriptor(), pivots_.data(), &info);
    return !failedOnAnyRank(A, info);
  }

  /// X ← A⁻¹X, given the A of the last successful factor() (X of A's layout); collective.
  void solve(const DistributedMatrix& A, DistributedMatrix& X) {
    const int n = X.size(), one = 1;
    int info = 0;
    pzgetrs_("N", &n, &n, A.data(), &one, &one, A.descriptor(), pivots_.data(), X.data(), &one,
             &one, X.descriptor(), &info);
  }

 private:
  // A nonzero info on any rank is a failure on all: every rank must return alike.
  static bool failedOnAnyRank(const DistributedMatrix& A, int info) {
    return A.layout().grid().max(info != 0 ? 1.0 : 0.0) > 0.0;
  }

  std::vector<int> pivots_;
};

}  // namespace ddb
