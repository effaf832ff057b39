// ScaLAPACK's two-dimensional block-cyclic layout of an N×N matrix with square blocks of
// size b on a process grid (docs/design/distributed.md): global row i lies on grid row
// (i / b) mod rows at local row (i / (b·rows))·b + i mod b, and columns likewise. The
// descriptor and the local sizes come from ScaLAPACK's own descinit_ and numroc_.
#pragma once

#include <ddb/core/errors.h>
#include <ddb/distributed/process_grid.h>
#include <ddb/distributed/scalapack.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>

namespace ddb {

class BlockCyclicLayout {
 public:
  /// No matrix (N = 0) on no grid: what a default-constructed DistributedMatrix has.
  BlockCyclicLayout() = default;
  BlockCyclicLayout(const ProcessGrid& grid, int n, int block)
      : grid_(&grid), n_(n), block_(block) {
    if (n < 1) throwInvalid("N", std::to_string(n), "must be >= 1");
    if (block < 1) throwInvalid("block size", std::to_string(block), "must be >= 1");
    const int source = 0, row = grid.row(), col = grid.col(), cols = grid.cols();
    local_rows_ = localRowsOn(row);
    local_cols_ = numroc_(&n_, &block_, &col, &source, &cols);
    const int leading = std::max(1, local_rows_), context = grid.context();
    int info = 0;
    descinit_(descriptor_.data(), &n_, &n_, &block_, &block_, &source, &source, &context, &leading,
              &info);
    if (info != 0) {
      throw std::runtime_error("descinit_ refused an N = " + std::to_string(n) +
                               " matrix with block size " + std::to_string(block) +
                               " (info = " + std::to_string(info) + ")");
    }
  }

  const ProcessGrid& grid() const { return *grid_; }
  /// Whether `other` lays out the same N in the same blocks on the same grid.
  bool operator==(const BlockCyclicLayout& other) const {
    return grid_ == other.grid_ && n_ == other.n_ && block_ == other.block_;
  }
  int size() const { return n_; }
  int block() const { return block_; }
  int localRows() const { return local_rows_; }
  int localCols() const { return local_cols_; }
  const int* descriptor() const { return descriptor_.data(); }
  /// The local row count of the ranks on grid row `row`.
  int localRowsOn(int row) const {
    const int source = 0, rows = grid_->rows();
    return numroc_(&n_, &block_, &row, &source, &rows);
  }

  /// The global row (column) of this rank's local row (column) l.
  int globalRow(int l) const { return toGlobal(l, grid_->row(), grid_->rows()); }
  int globalCol(int l) const { return toGlobal(l, grid_->col(), grid_->cols()); }
  /// The grid row (column) that holds global row (column) i, and its local index there.
  int ownerRow(int i) const { return (i / block_) % grid_->rows(); }
  int ownerCol(int j) const { return (j / block_) % grid_->cols(); }
  int localRow(int i) const { return toLocal(i, grid_->rows()); }
  int localCol(int j) const { return toLocal(j, grid_->cols()); }

 private:
  int toGlobal(int l, int coordinate, int processes) const {
    return (l / block_ * processes + coordinate) * block_ + l % block_;
  }
  int toLocal(int i, int processes) const { return i / (block_ * processes) * block_ + i % block_; }

  const ProcessGrid* grid_ = nullptr;
  int n_ = 0, block_ = 1, local_rows_ = 0, local_cols_ = 0;
  std::array<int, 9> descriptor_{};
};

}  // namespace ddb
