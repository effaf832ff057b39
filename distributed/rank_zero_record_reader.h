// RankZeroRecordReader: a BinaryRecordReader on every rank of a process grid for a record
// that rank 0 alone holds (fluid-relax-mpi's --resume: docs/design/distributed.md, "Checkpoints").
// Every rank runs the same reading code in step. Each number, string or small matrix rank 0
// reads is broadcast, so every rank reads the same value and takes the same branches; a
// DistributedMatrix (MatrixBackend<DistributedMatrix>::load, getDistributed) is read whole on
// rank 0 only and scattered, so no other rank ever holds it whole. A record that ends early
// fails on every rank alike. All functions are collective.
#pragma once

#include <ddb/core/binary_record.h>
#include <ddb/distributed/distributed_matrix.h>
#include <ddb/distributed/process_grid.h>
#include <mpi.h>

#include <Eigen/Core>
#include <algorithm>
#include <complex>
#include <cstdint>
#include <utility>

namespace ddb {

class RankZeroRecordReader : public BinaryRecordReader {
 public:
  /// Reads `record` from where it stands on rank 0; the other ranks' is ignored.
  RankZeroRecordReader(const ProcessGrid& grid, BinaryRecordReader record)
      : BinaryRecordReader(grid.rank() == 0 ? std::move(record) : BinaryRecordReader("")),
        grid_(grid) {}

  /// x ← the N×N matrix that comes next (as BinaryRecordWriter::put wrote it), of x's size
  /// (else CorruptRecord on every rank): read on rank 0, scattered to x's layout.
  void getDistributed(DistributedMatrix& x) {
    const auto rows = get<std::int64_t>(), cols = get<std::int64_t>();
    if (rows != x.size() || cols != x.size()) {
      throw CorruptRecord("a matrix of another size than the state");
    }
    const auto bytes = sizeof(std::complex<double>) * static_cast<std::size_t>(rows) *
                       static_cast<std::size_t>(cols);
    require(bytes);
    Eigen::MatrixXcd whole;
    if (root()) {
      whole.resize(rows, cols);
      takeHere(whole.data(), bytes);
    }
    x.scatterFrom(whole);
  }

  /// Whether rank 0 has read every byte.
  bool atEnd() const override { return broadcast(root() && BinaryRecordReader::atEnd()); }

 protected:
  void require(std::size_t size) const override {
    if (!broadcast(root() && holds(size))) throw CorruptRecord("ends early");
  }
  void take(void* out, std::size_t size) override {
    require(size);
    if (root()) takeHere(out, size);
    // In pieces whose count fits MPI's int.
    constexpr std::size_t kPiece = std::size_t(1) << 30;
    for (std::size_t at = 0; at < size; at += kPiece) {
      MPI_Bcast(static_cast<char*>(out) + at, static_cast<int>(std::min(kPiece, size - at)),
                MPI_CHAR, 0, grid_.comm());
    }
  }

 private:
  bool root() const { return grid_.rank() == 0; }
  /// Rank 0's `value` on every rank.
  bool broadcast(bool value) const {
    int flag = value ? 1 : 0;
    MPI_Bcast(&flag, 1, MPI_INT, 0, grid_.comm());
    return flag != 0;
  }

  const ProcessGrid& grid_;
};

}  // namespace ddb
