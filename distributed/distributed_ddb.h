// DistributedDdb: the DDB Cayley step (integrators/methods/ddb.h, paper Section 4.1) of Zeitlin's
// fluid on matrices distributed over MPI ranks. It holds the same solver
// (MatrixLegendreSolver) and update (MatrixCayleyTransport) as the dense step, instantiated
// with DistributedZeitlinFluid, and advances by the same function, advanceMatrixDdb: one
// step formula (docs/distributed.md, "One step formula"). Every call is collective.
#pragma once

#include <ddb/distributed/distributed_zeitlin_fluid.h>
#include <ddb/integrators/methods/ddb.h>

namespace ddb {

class DistributedDdb {
 public:
  using Solver = MatrixLegendreSolver<Cayley<SUN>, DistributedZeitlinFluid>;

  DistributedDdb(const BlockCyclicLayout& layout, double alpha, SolverOptions options = {})
      : system_(layout, alpha),
        legendre_(system_, retraction_, LegendreForm::kHamiltonian, options) {}
  DistributedDdb(const DistributedDdb&) = delete;  // legendre_ refers to system_, retraction_
  DistributedDdb& operator=(const DistributedDdb&) = delete;

  const DistributedZeitlinFluid& system() const { return system_; }
  const Solver& legendreSolver() const { return legendre_; }
  void reset() { legendre_.reset(); }

  /// The Legendre solver's warm start, in the dense solver's record (its matrices gathered
  /// whole into rank 0's record; MatrixBackend<DistributedMatrix>::save), so that a resumed
  /// run continues the uninterrupted one to the bit (docs/distributed.md, "Checkpoints").
  void saveWarmStart(BinaryRecordWriter& out) const { legendre_.saveWarmStart(out); }
  /// Restores it from such a record, dense or distributed, held by rank 0 and read on every
  /// rank through a RankZeroRecordReader, for states of `layout`.
  void loadWarmStart(BinaryRecordReader& in, const BlockCyclicLayout& layout) {
    legendre_.loadWarmStart(in, DistributedMatrix(layout));
  }

  /// W ← the DDB Cayley step of W at time t with step h.
  void advance(DistributedMatrix& W, double t, double h) {
    advanceMatrixDdb<SUN>(system_, legendre_, transport_, W, t, h);
  }

 private:
  DistributedZeitlinFluid system_;
  Cayley<SUN> retraction_;
  Solver legendre_;
  MatrixCayleyTransport<SUN, DistributedZeitlinFluid> transport_;
};

}  // namespace ddb
