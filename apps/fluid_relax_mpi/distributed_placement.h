// fluid-relax-mpi's placement (fluid_relax/fluid_run.h): every N×N matrix distributed
// block-cyclically over the ranks of an MPI job (docs/design/distributed.md, "fluid-relax-mpi").
// Rank 0 writes the files from the states gathered there; every outcome is agreed by every rank:
// bad input or a failure in a job of every rank or of rank 0 is Reported alike on all, a write
// that failed on rank 0 during the run is carried to the next agreement (StepFlags) so that no
// rank waits alone in a collective call.
#pragma once

#include <ddb/distributed/distributed_zeitlin_exact_flows.h>
#include <ddb/distributed/distributed_zeitlin_fluid.h>
#include <ddb/distributed/process_grid.h>
#include <ddb/distributed/rank_zero_record_reader.h>
#include <ddb/integrators/methods/strang_splitting.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <mpi.h>
#include <spdlog/fmt/fmt.h>

#include <cstdio>
#include <exception>
#include <memory>
#include <string>
#include <utility>

#include "common/json.h"
#include "common/resume.h"
#include "fluid_relax/checkpoint.h"
#include "fluid_relax/fluid_run.h"
#include "fluid_relax_mpi/mpi_input.h"

namespace ddb::fluid_mpi {

class DistributedPlacement {
 public:
  using Group = DistributedSUN;
  using State = DistributedMatrix;
  /// Only the rows' states are gathered: every state's spectrum would gather every state.
  static constexpr bool kSpectrumEveryState = false;

  /// The fluid of `run` on `grid` with blocks of run.block; rank 0's fluid for the files.
  DistributedPlacement(const MpiRun& run, const ProcessGrid& grid)
      : grid_(grid),
        n_(run.n),
        block_(run.block),
        layout_(DistributedMatrix(grid, static_cast<int>(run.n), run.block).layout()),
        physics_(run.settings.physics),
        fluid_(makeDistributedZeitlinFluid(layout_, run.settings.alpha, run.settings.physics)),
        host_fluid_(grid.rank() == 0
                        ? makeZeitlinFluid(run.n, run.settings.alpha, run.settings.physics)
                        : nullptr) {}

  Eigen::Index n() const { return n_; }
  const std::shared_ptr<const LiePoissonSystem<DistributedSUN>>& system() const { return fluid_; }
  const std::shared_ptr<const LiePoissonSystem<SUN>>& hostFluid() const { return host_fluid_; }
  /// W₀ (rank 0's) scattered over the ranks.
  DistributedMatrix initialState(const fluid::Matrix& W0) const {
    DistributedMatrix W(layout_);
    W.scatterFrom(W0);
    return W;
  }
  /// `method` Strang-split with each of distributedZeitlinExactFlows (the CPU placement's order).
  std::unique_ptr<OneStepMethod<Group>> splitWith(std::unique_ptr<OneStepMethod<Group>> method,
                                                  const ZeitlinDampingAndForcing& flows) const {
    for (auto& flow : distributedZeitlinExactFlows(layout_, physics_, flows)) {
      method = std::make_unique<StrangSplitting<Group>>(std::move(method), std::move(flow));
    }
    return method;
  }
  bool writes() const { return grid_.rank() == 0; }
  template <class Job>
  void agreed(const Job& job) {
    if (const int status = onEveryRank(grid_, job)) throw Reported{status};
  }
  template <class Job>
  void onWriter(const Job& job) {
    if (const int status = onRankZero(grid_, job)) throw Reported{status};
  }
  template <class Job>
  void write(const Job& job) {
    if (!writes() || !write_error_.empty()) return;
    try {
      job();
    } catch (const std::exception& e) {
      write_error_ = e.what();
    }
  }
  bool writeFailed() const { return !write_error_.empty(); }
  void reportWriteError() const {
    if (writes()) std::fprintf(stderr, "%s: %s\n", kApp, write_error_.c_str());
  }
  /// The largest of each flag over the ranks.
  fluid::StepFlags agree(fluid::StepFlags mine) const {
    int values[3] = {mine.signal, mine.write_failed, mine.checkpoint_due};
    MPI_Allreduce(MPI_IN_PLACE, values, 3, MPI_INT, MPI_MAX, grid_.comm());
    return {values[0], values[1], values[2]};
  }
  /// The whole matrix on rank 0 (collective).
  const fluid::Matrix& onHost(const DistributedMatrix& W, fluid::Matrix& buffer) const {
    buffer = W.gather();
    return buffer;
  }
  /// Rank 0's record, read on every rank in step: its numbers broadcast, its matrices (the
  /// state, the warm start's corrections) scattered, so that every rank fails alike and only
  /// rank 0 holds them whole (docs/design/distributed.md, "Checkpoints").
  template <class Load>
  void loadCheckpoint(fluid::Checkpoint& c, const RelaxOptions& caps, const std::string& dir,
                      const Load& load) {
    RankZeroRecordReader record(grid_, std::move(c.relaxation));
    agreed([&] { app::resumeRelaxation(record, caps, dir, fluid::kCheckpointFile, load); });
  }
  std::string describe() const {
    return fmt::format(" on {} ranks ({}x{} grid, block {})", grid_.size(), grid_.rows(),
                       grid_.cols(), block_);
  }
  std::string progressLabel() const { return " P=" + std::to_string(grid_.size()); }
  std::string commutatorText(const DistributedMatrix&) const { return ""; }
  std::string device() const { return "cpu"; }
  void addToSummary(app::Json& summary) const {
    summary["mpi_ranks"] = grid_.size();
    summary["process_grid"] = {grid_.rows(), grid_.cols()};
    summary["block_size"] = block_;
  }
  /// The same grid shape continues the run to the bit (docs/design/distributed.md,
  /// "Checkpoints").
  std::string resumeCommand(const std::string& out) const {
    const std::string shape = grid_.rows() == ProcessGrid::defaultRows(grid_.size())
                                  ? ""
                                  : " --grid-rows " + std::to_string(grid_.rows());
    return "mpirun -np " + std::to_string(grid_.size()) + " fluid-relax-mpi --resume " + out +
           shape;
  }

 private:
  const ProcessGrid& grid_;
  Eigen::Index n_;
  int block_;
  BlockCyclicLayout layout_;
  ZeitlinPhysics physics_;
  std::shared_ptr<const LiePoissonSystem<DistributedSUN>> fluid_;
  std::shared_ptr<const LiePoissonSystem<SUN>> host_fluid_;  // rank 0's
  std::string write_error_;                                  // rank 0's first failed write
};

}  // namespace ddb::fluid_mpi
