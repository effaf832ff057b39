// A BLACS process grid over an MPI communicator: its P ranks as rows × cols, numbered
// row-major, rank r at (r / cols, r % cols) (docs/design/distributed.md, "Layouts"). By default the
// most square grid with rows ≥ cols (cols the largest divisor of P not above √P, so P = 2
// and 3 give one column), which measured faster than the wide grid: the dissipative
// factor's LU solves send fewer bytes (docs/results/distributed.md, "The grid's shape"). A caller
// may ask for any rows dividing P.
// The grid owns its BLACS context and releases it when destroyed; MPI itself is
// initialised and finalised by the program.
#pragma once

#include <ddb/core/errors.h>
#include <ddb/distributed/scalapack.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>
#include <vector>

namespace ddb {

class ProcessGrid {
 public:
  /// The default shape, or `grid_rows` process rows (a divisor of P) when it is positive;
  /// another value is an InvalidArgument naming it, thrown on every rank (all see the same P).
  explicit ProcessGrid(MPI_Comm comm = MPI_COMM_WORLD, int grid_rows = 0) : comm_(comm) {
    MPI_Comm_rank(comm_, &rank_);
    MPI_Comm_size(comm_, &size_);
    if (grid_rows < 0 || (grid_rows > 0 && size_ % grid_rows != 0)) {
      throwInvalid("grid rows", std::to_string(grid_rows),
                   "must divide the number of ranks, " + std::to_string(size_));
    }
    rows_ = grid_rows > 0 ? grid_rows : defaultRows(size_);
    cols_ = size_ / rows_;
    system_handle_ = Csys2blacs_handle(comm_);
    context_ = system_handle_;
    Cblacs_gridinit(&context_, "Row", rows_, cols_);
    int rows = 0, cols = 0;
    Cblacs_gridinfo(context_, &rows, &cols, &row_, &col_);
    if (rows != rows_ || cols != cols_ || row_ != rank_ / cols_ || col_ != rank_ % cols_) {
      release();
      throw std::runtime_error(
          "BLACS placed rank " + std::to_string(rank_) + " at (" + std::to_string(row_) + ", " +
          std::to_string(col_) + ") of a " + std::to_string(rows) + "x" + std::to_string(cols) +
          " grid, not row-major on " + std::to_string(rows_) + "x" + std::to_string(cols_));
    }
  }
  ProcessGrid(const ProcessGrid&) = delete;
  ProcessGrid& operator=(const ProcessGrid&) = delete;
  ~ProcessGrid() { release(); }

  /// The default number of rows for P ranks: P over the largest divisor of P not above √P.
  static int defaultRows(int ranks) {
    int cols = 1;
    for (int c = 1; c * c <= ranks; ++c) {
      if (ranks % c == 0) cols = c;
    }
    return ranks / cols;
  }

  MPI_Comm comm() const { return comm_; }
  int context() const { return context_; }
  int rank() const { return rank_; }
  int size() const { return size_; }
  int rows() const { return rows_; }
  int cols() const { return cols_; }
  int row() const { return row_; }
  int col() const { return col_; }
  /// The rank at grid position (row, col).
  int rankAt(int row, int col) const { return row * cols_ + col; }

  /// The sum over the ranks of each rank's `local`, added in rank order on every rank, so
  /// that every rank gets the same bits (an MPI_Allreduce may add in a different order on
  /// different ranks, and a branch on the result could then part ways).
  double sum(double local) const {
    gathered_.resize(static_cast<std::size_t>(size_));
    MPI_Allgather(&local, 1, MPI_DOUBLE, gathered_.data(), 1, MPI_DOUBLE, comm_);
    double total = 0.0;
    for (const double value : gathered_) total += value;
    return total;
  }
  std::complex<double> sum(std::complex<double> local) const {
    return {sum(local.real()), sum(local.imag())};
  }
  /// The largest of the ranks' `local` (a NaN anywhere gives NaN everywhere).
  double max(double local) const {
    gathered_.resize(static_cast<std::size_t>(size_));
    MPI_Allgather(&local, 1, MPI_DOUBLE, gathered_.data(), 1, MPI_DOUBLE, comm_);
    double largest = gathered_[0];
    for (const double value : gathered_) {
      if (std::isnan(value)) return value;
      largest = std::max(largest, value);
    }
    return largest;
  }

 private:
  void release() {
    if (context_ >= 0) Cblacs_gridexit(context_);
    Cfree_blacs_system_handle(system_handle_);
    context_ = -1;
  }

  MPI_Comm comm_;
  int rank_ = 0, size_ = 1, rows_ = 1, cols_ = 1, row_ = 0, col_ = 0;
  int system_handle_ = -1, context_ = -1;
  mutable std::vector<double> gathered_;
};

}  // namespace ddb
