// A complex N×N matrix distributed block-cyclically over a process grid
// (BlockCyclicLayout): each rank keeps its local blocks as one column-major Eigen matrix,
// the local array of ScaLAPACK's descriptor. Scatter and gather move a whole matrix held
// by rank 0 in or out with pzgemr2d_; the Frobenius norm is pzlange_'s, returned on every
// rank. All of them are collective: every rank of the grid calls them.
#pragma once

#include <ddb/distributed/block_cyclic_layout.h>
#include <ddb/distributed/process_grid.h>
#include <ddb/distributed/scalapack.h>
#include <mpi.h>

#include <Eigen/Core>
#include <string>

namespace ddb {

class DistributedMatrix {
 public:
  using Scalar = std::complex<double>;

  /// No matrix yet (a workspace before its first use).
  DistributedMatrix() = default;
  DistributedMatrix(const ProcessGrid& grid, int n, int block)
      : DistributedMatrix(BlockCyclicLayout(grid, n, block)) {}
  /// The zero matrix of a layout.
  explicit DistributedMatrix(const BlockCyclicLayout& layout)
      : layout_(layout), local_(Eigen::MatrixXcd::Zero(layout_.localRows(), layout_.localCols())) {}

  const BlockCyclicLayout& layout() const { return layout_; }
  int size() const { return layout_.size(); }
  /// Whether `other` has this matrix's grid, N and block size (so that their local arrays
  /// hold the same entries).
  bool sameLayout(const DistributedMatrix& other) const { return other.layout_ == layout_; }
  /// Exchanges the entries of two matrices of one layout.
  void swap(DistributedMatrix& other) {
    if (!sameLayout(other))
      throwInvalid("matrix", "another layout", "must share the layout to swap");
    local_.swap(other.local_);
  }
  Eigen::MatrixXcd& local() { return local_; }
  const Eigen::MatrixXcd& local() const { return local_; }
  /// The local array as ScaLAPACK reads it (a 1×1 dummy when this rank holds nothing).
  std::complex<double>* data() { return local_.size() > 0 ? local_.data() : &empty_; }
  const std::complex<double>* data() const { return local_.size() > 0 ? local_.data() : &empty_; }
  const int* descriptor() const { return layout_.descriptor(); }

  /// Distributes `global`, read on rank 0 only (N×N there; ignored elsewhere). A wrong
  /// size on rank 0 is refused on every rank, so that none waits in the exchange.
  void scatterFrom(const Eigen::MatrixXcd& global) {
    const ProcessGrid& grid = layout_.grid();
    long rows = global.rows(), cols = global.cols();
    MPI_Bcast(&rows, 1, MPI_LONG, 0, grid.comm());
    MPI_Bcast(&cols, 1, MPI_LONG, 0, grid.comm());
    if (rows != size() || cols != size()) {
      throwInvalid("matrix", std::to_string(rows) + "x" + std::to_string(cols),
                   "must be " + std::to_string(size()) + "x" + std::to_string(size()) +
                       " on rank 0 to scatter");
    }
    const BlockCyclicLayout whole(grid, size(), size());
    copy(grid.rank() == 0 ? global.data() : &empty_, whole.descriptor(), data(), descriptor());
  }

  /// The whole matrix on rank 0 (an empty matrix on the other ranks).
  Eigen::MatrixXcd gather() const {
    const BlockCyclicLayout whole(layout_.grid(), size(), size());
    Eigen::MatrixXcd global(whole.localRows(), whole.localCols());
    std::complex<double> empty;
    copy(data(), descriptor(), global.size() > 0 ? global.data() : &empty, whole.descriptor());
    if (layout_.grid().rank() != 0) global.resize(0, 0);
    return global;
  }

  /// ‖A‖_F, on every rank.
  double frobeniusNorm() const {
    const int n = size(), one = 1;
    double unused_work = 0.0;
    return pzlange_("F", &n, &n, data(), &one, &one, descriptor(), &unused_work);
  }

 private:
  void copy(const std::complex<double>* from, const int* from_descriptor, std::complex<double>* to,
            const int* to_descriptor) const {
    const int n = size(), one = 1, context = layout_.grid().context();
    pzgemr2d_(&n, &n, from, &one, &one, from_descriptor, to, &one, &one, to_descriptor, &context);
  }

  BlockCyclicLayout layout_;
  Eigen::MatrixXcd local_;
  mutable std::complex<double> empty_{};
};

}  // namespace ddb
