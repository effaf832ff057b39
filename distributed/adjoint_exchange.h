// The conjugate transpose of a block-cyclic matrix (docs/design/distributed.md, "Adjoints"): block
// (I, J) of x, conjugate-transposed, is block (J, I) of xᴴ, which lies on the rank at grid
// position (J mod rows, I mod cols). Each rank packs the adjoints of its blocks, grouped by
// destination, exchanges them in one MPI_Alltoallv and combines each received block with
// its own. The plan (which block goes where, and in which order) is built once per layout;
// an exchange then allocates nothing. It replaces ScaLAPACK's pztranc_, whose local kernel
// (zmmtcadd_) walks each block with a stride of its leading dimension.
#pragma once

#include <ddb/distributed/block_cyclic_layout.h>
#include <mpi.h>

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <complex>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <vector>

namespace ddb {

class AdjointExchange {
 public:
  using Scalar = std::complex<double>;

  AdjointExchange() = default;
  explicit AdjointExchange(const BlockCyclicLayout& layout)
      : layout_(layout),
        grid_shape_{layout.grid().rows(), layout.grid().cols(), layout.grid().rank()} {
    const ProcessGrid& grid = layout.grid();
    const int b = layout.block(), ranks = grid.size();
    const int local_block_rows = (layout.localRows() + b - 1) / b;
    const int local_block_cols = (layout.localCols() + b - 1) / b;
    // Sending: this rank's blocks, column-major over its local blocks, grouped by the rank
    // that holds their adjoint's place.
    std::vector<std::vector<Block>> to_rank(static_cast<std::size_t>(ranks));
    for (int lj = 0; lj < local_block_cols; ++lj) {
      for (int li = 0; li < local_block_rows; ++li) {
        const Block block = localBlock(li * b, lj * b);
        const int global_row = layout.globalRow(block.row),
                  global_col = layout.globalCol(block.col);
        const int destination =
            grid.rankAt(layout.ownerRow(global_col), layout.ownerCol(global_row));
        to_rank[static_cast<std::size_t>(destination)].push_back(block);
      }
    }
    // Receiving: this rank's blocks of xᴴ, grouped by the rank that holds their transpose
    // in x. That rank sends them in its column-major order of x's blocks (J, I), that is
    // ordered by I then J: by this block's global row, then column.
    std::vector<std::vector<std::tuple<int, int, Block>>> from_rank(
        static_cast<std::size_t>(ranks));
    for (int lj = 0; lj < local_block_cols; ++lj) {
      for (int li = 0; li < local_block_rows; ++li) {
        const Block block = localBlock(li * b, lj * b);
        const int global_row = layout.globalRow(block.row),
                  global_col = layout.globalCol(block.col);
        const int source = grid.rankAt(layout.ownerRow(global_col), layout.ownerCol(global_row));
        from_rank[static_cast<std::size_t>(source)].emplace_back(global_row, global_col, block);
      }
    }
    int sent = 0, received = 0;
    for (int r = 0; r < ranks; ++r) {
      auto& incoming = from_rank[static_cast<std::size_t>(r)];
      std::sort(incoming.begin(), incoming.end(), [](const auto& x, const auto& y) {
        return std::tie(std::get<0>(x), std::get<1>(x)) < std::tie(std::get<0>(y), std::get<1>(y));
      });
      send_displacements_.push_back(sent);
      receive_displacements_.push_back(received);
      for (const Block& block : to_rank[static_cast<std::size_t>(r)]) {
        send_blocks_.push_back({block.row, block.col, block.rows, block.cols, sent});
        sent += block.rows * block.cols;
      }
      for (const auto& entry : incoming) {
        const Block& block = std::get<2>(entry);
        receive_blocks_.push_back({block.row, block.col, block.rows, block.cols, received});
        received += block.rows * block.cols;
      }
      send_counts_.push_back(sent - send_displacements_.back());
      receive_counts_.push_back(received - receive_displacements_.back());
      if (r != grid.rank()) bytes_sent_ += std::int64_t(send_counts_.back()) * sizeof(Scalar);
    }
    send_.resize(sent);
    receive_.resize(received);
  }

  /// Whether this plan is for `layout` (its grid compared by shape and rank too, in case a
  /// grid was made anew where an old one was).
  bool isFor(const BlockCyclicLayout& layout) const {
    if (!(layout_ == layout)) return false;
    const ProcessGrid& grid = layout.grid();
    return grid_shape_ == std::array<int, 3>{grid.rows(), grid.cols(), grid.rank()};
  }

  /// Collective: out ← out + scale·xᴴ (out is not x), as pztranc_ with β = 1.
  void addAdjoint(double scale, const Eigen::MatrixXcd& x, Eigen::MatrixXcd& out) {
    exchange(x);
    forEachReceived([&](auto& place, const auto& adjoint) { place += scale * adjoint; }, out);
  }

  /// Collective: x ← (x − xᴴ)/2 entry by entry, so that entry (j, i) is −conj of entry (i, j)
  /// bit for bit (fl(a − b) = −fl(b − a)) but for the sign of a zero.
  void makeSkewHermitian(Eigen::MatrixXcd& x) {
    exchange(x);
    forEachReceived([](auto& place, const auto& adjoint) { place = 0.5 * (place - adjoint); }, x);
  }

  /// Bytes this rank sends to other ranks in one exchange.
  std::int64_t bytesSent() const { return bytes_sent_; }

 private:
  struct Block {
    int row, col, rows, cols;  // local position and size
    int offset = 0;            // in the packed buffer
  };

  Block localBlock(int row, int col) const {
    const int b = layout_.block();
    return {row, col, std::min(b, layout_.localRows() - row),
            std::min(b, layout_.localCols() - col)};
  }

  // Packs the adjoint of every local block of x (a block of r × c entries becomes c × r) and
  // exchanges them.
  void exchange(const Eigen::MatrixXcd& x) {
    for (const Block& block : send_blocks_) {
      Eigen::Map<Eigen::MatrixXcd>(send_.data() + block.offset, block.cols, block.rows) =
          x.block(block.row, block.col, block.rows, block.cols).adjoint();
    }
    Scalar unused{};
    MPI_Alltoallv(send_.size() > 0 ? send_.data() : &unused, send_counts_.data(),
                  send_displacements_.data(), MPI_C_DOUBLE_COMPLEX,
                  receive_.size() > 0 ? receive_.data() : &unused, receive_counts_.data(),
                  receive_displacements_.data(), MPI_C_DOUBLE_COMPLEX, layout_.grid().comm());
  }

  // combine(local block of out, the received adjoint of the same size) for every block.
  template <class Combine>
  void forEachReceived(Combine combine, Eigen::MatrixXcd& out) const {
    for (const Block& block : receive_blocks_) {
      auto place = out.block(block.row, block.col, block.rows, block.cols);
      const Eigen::Map<const Eigen::MatrixXcd> adjoint(receive_.data() + block.offset, block.rows,
                                                       block.cols);
      combine(place, adjoint);
    }
  }

  BlockCyclicLayout layout_;
  std::array<int, 3> grid_shape_{};  // rows, columns, this rank
  std::vector<Block> send_blocks_, receive_blocks_;
  std::vector<int> send_counts_, send_displacements_, receive_counts_, receive_displacements_;
  std::vector<Scalar> send_, receive_;
  std::int64_t bytes_sent_ = 0;
};

}  // namespace ddb
