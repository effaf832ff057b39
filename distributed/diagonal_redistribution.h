// The exchange between the block-cyclic layout and whole diagonals (docs/design/distributed.md):
// diagonal m = j − i of an N×N matrix, an independent tridiagonal system of the Hoppe–Yau
// Laplacian, is owned by one rank, rank q(m) mod P with q(0) = 0, q(m) = 2m − 1 and
// q(−m) = 2m for m > 0, so the 2N − 1 diagonals, taken longest first, are dealt to the
// ranks in turn. On its owner diagonal m is stored contiguously, entry k = min(i, j) at
// offset(m) + k. The plan (which local entry goes to which rank and where it lands) is
// built once; each exchange is then one MPI_Alltoallv of packed values, and the way back
// uses the same plan reversed.
#pragma once

#include <ddb/distributed/block_cyclic_layout.h>
#include <mpi.h>

#include <Eigen/Core>
#include <algorithm>
#include <complex>
#include <cstdint>
#include <cstdlib>
#include <utility>
#include <vector>

namespace ddb {

class DiagonalRedistribution {
 public:
  explicit DiagonalRedistribution(const BlockCyclicLayout& layout)
      : comm_(layout.grid().comm()), rank_(layout.grid().rank()) {
    const int n = layout.size(), ranks = layout.grid().size();
    for (int m = -(n - 1); m < n; ++m) {
      if (ownerOf(m, ranks) != rank_) continue;
      diagonals_.push_back(m);
      offsets_.push_back(owned_entries_);
      owned_entries_ += n - std::abs(m);
    }
    // Sending: this rank's local entries in column-major order, grouped by the owner of
    // their diagonal.
    std::vector<std::vector<int>> to_rank(static_cast<std::size_t>(ranks));
    for (int lj = 0; lj < layout.localCols(); ++lj) {
      for (int li = 0; li < layout.localRows(); ++li) {
        const int m = layout.globalCol(lj) - layout.globalRow(li);
        to_rank[static_cast<std::size_t>(ownerOf(m, ranks))].push_back(li +
                                                                       lj * layout.localRows());
      }
    }
    // Receiving: the entries of this rank's diagonals, grouped by the rank that holds them
    // and in that rank's local column-major order, so they arrive in the order sent.
    std::vector<std::vector<std::pair<int, int>>> from_rank(static_cast<std::size_t>(ranks));
    for (std::size_t d = 0; d < diagonals_.size(); ++d) {
      const int m = diagonals_[d];
      for (int k = 0; k < n - std::abs(m); ++k) {
        const int i = m >= 0 ? k : k - m, j = m >= 0 ? k + m : k;
        const int grid_row = layout.ownerRow(i), grid_col = layout.ownerCol(j);
        const int source_index =
            layout.localRow(i) + layout.localCol(j) * std::max(1, layout.localRowsOn(grid_row));
        from_rank[static_cast<std::size_t>(layout.grid().rankAt(grid_row, grid_col))].emplace_back(
            source_index, offsets_[d] + k);
      }
    }
    for (int r = 0; r < ranks; ++r) {
      const auto& sent = to_rank[static_cast<std::size_t>(r)];
      auto& received = from_rank[static_cast<std::size_t>(r)];
      std::sort(received.begin(), received.end());
      send_counts_.push_back(static_cast<int>(sent.size()));
      receive_counts_.push_back(static_cast<int>(received.size()));
      send_displacements_.push_back(static_cast<int>(local_order_.size()));
      receive_displacements_.push_back(static_cast<int>(diagonal_order_.size()));
      local_order_.insert(local_order_.end(), sent.begin(), sent.end());
      for (const auto& entry : received) diagonal_order_.push_back(entry.second);
      if (r != rank_) {
        bytes_to_diagonals_ += std::int64_t(sent.size()) * std::int64_t(sizeof(Scalar));
        bytes_to_block_cyclic_ += std::int64_t(received.size()) * std::int64_t(sizeof(Scalar));
      }
    }
    packed_local_.resize(static_cast<Eigen::Index>(local_order_.size()));
    packed_diagonals_.resize(static_cast<Eigen::Index>(diagonal_order_.size()));
  }

  /// The rank that owns diagonal m when there are `ranks` ranks.
  static int ownerOf(int m, int ranks) { return (m > 0 ? 2 * m - 1 : -2 * m) % ranks; }

  /// This rank's diagonals, in storage order, and where each starts.
  const std::vector<int>& diagonals() const { return diagonals_; }
  const std::vector<Eigen::Index>& offsets() const { return offsets_; }
  /// The length of this rank's diagonal storage, Σ (N − |m|) over its diagonals.
  Eigen::Index ownedEntries() const { return owned_entries_; }

  /// Collective: `local` (this rank's block-cyclic array) into `diagonals`.
  void toDiagonals(const Eigen::MatrixXcd& local, Eigen::VectorXcd& diagonals) {
    diagonals.resize(owned_entries_);
    for (std::size_t e = 0; e < local_order_.size(); ++e) {
      packed_local_(Eigen::Index(e)) = local.data()[local_order_[e]];
    }
    exchange(packed_local_, send_counts_, send_displacements_, packed_diagonals_, receive_counts_,
             receive_displacements_);
    for (std::size_t e = 0; e < diagonal_order_.size(); ++e) {
      diagonals(diagonal_order_[e]) = packed_diagonals_(Eigen::Index(e));
    }
  }

  /// Collective: `diagonals` back into `local` (sized as the block-cyclic array already).
  void toBlockCyclic(const Eigen::VectorXcd& diagonals, Eigen::MatrixXcd& local) {
    for (std::size_t e = 0; e < diagonal_order_.size(); ++e) {
      packed_diagonals_(Eigen::Index(e)) = diagonals(diagonal_order_[e]);
    }
    exchange(packed_diagonals_, receive_counts_, receive_displacements_, packed_local_,
             send_counts_, send_displacements_);
    for (std::size_t e = 0; e < local_order_.size(); ++e) {
      local.data()[local_order_[e]] = packed_local_(Eigen::Index(e));
    }
  }

  /// Bytes this rank sends to other ranks (not to itself) in toDiagonals and in
  /// toBlockCyclic.
  std::int64_t bytesSentToDiagonals() const { return bytes_to_diagonals_; }
  std::int64_t bytesSentToBlockCyclic() const { return bytes_to_block_cyclic_; }

 private:
  using Scalar = std::complex<double>;

  void exchange(const Eigen::VectorXcd& send, const std::vector<int>& send_counts,
                const std::vector<int>& send_displacements, Eigen::VectorXcd& receive,
                const std::vector<int>& receive_counts,
                const std::vector<int>& receive_displacements) const {
    Scalar unused{};
    MPI_Alltoallv(send.size() > 0 ? send.data() : &unused, send_counts.data(),
                  send_displacements.data(), MPI_C_DOUBLE_COMPLEX,
                  receive.size() > 0 ? receive.data() : &unused, receive_counts.data(),
                  receive_displacements.data(), MPI_C_DOUBLE_COMPLEX, comm_);
  }

  MPI_Comm comm_;
  int rank_;
  std::vector<int> diagonals_;
  std::vector<Eigen::Index> offsets_;
  Eigen::Index owned_entries_ = 0;
  // Entry e of the packed send buffer is local.data()[local_order_[e]]; entry e of the
  // packed receive buffer is diagonals(diagonal_order_[e]).
  std::vector<int> local_order_, diagonal_order_;
  std::vector<int> send_counts_, send_displacements_, receive_counts_, receive_displacements_;
  Eigen::VectorXcd packed_local_, packed_diagonals_;
  std::int64_t bytes_to_diagonals_ = 0, bytes_to_block_cyclic_ = 0;
};

}  // namespace ddb
