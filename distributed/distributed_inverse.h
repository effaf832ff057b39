// DistributedInverse: A ← A⁻¹ for a block-cyclic A (pzgetrf_, pzgetri_), the Cayley
// conjugation's inverse on distributed matrices (MatrixBackend<DistributedMatrix>::Inverse).
// Pivots and workspaces are kept between calls and sized again when the layout changes.
#pragma once

#include <ddb/distributed/block_cyclic_layout.h>
#include <ddb/distributed/distributed_matrix.h>
#include <ddb/distributed/scalapack.h>

#include <algorithm>
#include <complex>
#include <vector>

namespace ddb {

/// A ← A⁻¹ for a distributed A (pzgetrf_, pzgetri_), with pivots and workspaces kept
/// between calls of one layout.
class DistributedInverse {
 public:
  /// Returns false, leaving A unspecified, when A is exactly singular (on every rank).
  bool invert(DistributedMatrix& A) {
    const int n = A.size(), one = 1;
    const BlockCyclicLayout& layout = A.layout();
    pivots_.resize(static_cast<std::size_t>(layout.localRows() + layout.block()));
    int info = 0;
    pzgetrf_(&n, &n, A.data(), &one, &one, A.descriptor(), pivots_.data(), &info);
    if (failedOnAnyRank(A, info)) return false;
    if (!(queried_for_ == layout)) {  // the workspace query, once per layout
      const int query = -1;
      std::complex<double> lwork;
      int liwork = 0;
      pzgetri_(&n, A.data(), &one, &one, A.descriptor(), pivots_.data(), &lwork, &query, &liwork,
               &query, &info);
      work_.resize(static_cast<std::size_t>(std::max(1.0, lwork.real())));
      iwork_.resize(static_cast<std::size_t>(std::max(1, liwork)));
      queried_for_ = layout;
    }
    const int lwork = static_cast<int>(work_.size()), liwork = static_cast<int>(iwork_.size());
    pzgetri_(&n, A.data(), &one, &one, A.descriptor(), pivots_.data(), work_.data(), &lwork,
             iwork_.data(), &liwork, &info);
    return !failedOnAnyRank(A, info);
  }

 private:
  // A nonzero info on any rank is a failure on all: every rank must return alike.
  static bool failedOnAnyRank(const DistributedMatrix& A, int info) {
    return A.layout().grid().max(info != 0 ? 1.0 : 0.0) > 0.0;
  }

  std::vector<int> pivots_, iwork_;
  std::vector<std::complex<double>> work_;
  BlockCyclicLayout queried_for_;  // the layout the workspaces were sized for
};

}  // namespace ddb
