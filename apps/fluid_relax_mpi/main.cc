// fluid-relax-mpi: fluid-relax's relaxation with every N×N matrix distributed block-cyclically
// over the ranks of an MPI job (docs/design/distributed.md, "fluid-relax-mpi"). The run is the
// library's own: the distributed fluid (makeDistributedZeitlinFluid, a LiePoissonSystem on
// DistributedSUN), the method of --method built by makeMethod (the method table's methods for
// any backend) and Relaxation (fixed steps, --adaptive's energy step control, --until-steady),
// as fluid-relax calls them; the command line, its checks and the files are fluid-relax's
// (docs/reference/command-lines-and-files.md), written by rank 0 from the states gathered there for
// the history rows and at the end; summary.json adds mpi_ranks, process_grid and block_size. Exit
// statuses as fluid-relax's, agreed by every rank: 2 bad input on any rank (nothing written),
// 1 a failed step or a file rank 0 could not write, 130/143 a SIGINT/SIGTERM on any rank
// (outputs and a checkpoint written); anything unexpected on one rank ends the job
// (MPI_Abort). Checkpoints are Relaxation's record (docs/design/distributed.md, "Checkpoints"), so
// either app resumes the other's; with --h5, rank 0 appends fluid.hdf5's frames as fluid-relax
// does.
#include <ddb/distributed/distributed_zeitlin_fluid.h>
#include <ddb/distributed/process_grid.h>
#include <ddb/distributed/rank_zero_record_reader.h>
#include <ddb/integrators/drivers/relax.h>
#include <ddb/integrators/drivers/run.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <mpi.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <optional>

#include "common/atomic_file.h"
#include "common/cli.h"
#include "common/energy_rises.h"
#include "common/exit_status.h"
#include "common/json.h"
#include "common/logging.h"
#include "common/progress.h"
#include "common/spectrum_drift.h"
#include "common/stop_signals.h"
#include "fluid_relax/checkpoint.h"
#include "fluid_relax/outputs.h"
#include "fluid_relax/run_files.h"
#include "fluid_relax/summary.h"
#include "fluid_relax_mpi/mpi_input.h"

namespace {

using namespace ddb;
using namespace ddb::fluid;
using namespace ddb::fluid_mpi;

// What rank 0 makes of gathered states: fluid-relax's history rows (history.csv, and
// fluid.hdf5 with --h5) and final files.
class RankZeroOutputs {
 public:
  RankZeroOutputs(const Options& o, const Settings& s, const Checkpoint* resume)
      : system_(makeZeitlinFluid(s.W0.rows(), s.alpha)),
        drift_(s.W0),
        files_(o, s, *system_, resume) {}

  /// One history row; returns the state's spectrum drift.
  double row(long k, double t, double h, const Matrix& W) {
    const double drift = drift_(W);
    files_.write(k, t, h, W, drift);
    return drift;
  }
  const LiePoissonSystem<SUN>& system() const { return *system_; }
  HistoryFiles::Lengths sync() { return files_.sync(); }
  void commit() { files_.commit(); }
  void writeFinalState(const Settings& s, const Matrix& W) {
    writeMatrixCsv(s.out / "W_final.csv", W);
    writeOmegaCsv(s.out / "omega_initial.csv", files_.basis(), s.W0);
    writeOmegaCsv(s.out / "omega_final.csv", files_.basis(), W);
  }

 private:
  std::shared_ptr<const LiePoissonSystem<SUN>> system_;
  app::SpectrumDrift<SUN> drift_;
  HistoryFiles files_;
};

// Once per step every rank learns whether any rank received a stop signal, whether rank 0
// failed to write a file and whether a checkpoint is due (rank 0's clock decides): the
// largest of each over the ranks.
struct StepFlags {
  int signal = 0, write_failed = 0, checkpoint_due = 0;
};
StepFlags agreeOnFlags(const ProcessGrid& grid, StepFlags mine) {
  int values[3] = {mine.signal, mine.write_failed, mine.checkpoint_due};
  MPI_Allreduce(MPI_IN_PLACE, values, 3, MPI_INT, MPI_MAX, grid.comm());
  return {values[0], values[1], values[2]};
}

int relax(MpiRun& run, const ProcessGrid& grid) {
  const auto start = std::chrono::steady_clock::now();
  const Options& o = run.options;
  const Settings& s = run.settings;
  Checkpoint* resume = run.resume ? &*run.resume : nullptr;
  const bool root = grid.rank() == 0;
  const Eigen::Index n = run.n;

  // fluid-relax's run, on distributed states: the library's fluid, method and Relaxation
  // (docs/design/distributed.md, "One step formula"). A resumed run starts from W₀ too (rank
  // 0's, from the checkpoint), which the checkpoint's state replaces: the Newton search takes
  // its direction from W₀'s energy rate, as fluid-relax's resumed search does.
  DistributedMatrix W0(grid, static_cast<int>(n), run.block);
  W0.scatterFrom(s.W0);  // rank 0's
  const auto system = makeDistributedZeitlinFluid(W0.layout(), s.alpha);
  std::unique_ptr<OneStepMethod<DistributedSUN>> method;
  std::optional<Relaxation<DistributedSUN>> relaxing;
  // The library's checks of the run (InvalidArgument) are bad input, agreed by every rank.
  if (const int status = onEveryRank(grid, [&] {
        try {
          method = makeMethod<DistributedSUN>(o.method, system);  // not used by a Newton search
          if (s.relax.newton) {
            relaxing.emplace(*system, W0, s.relax);
          } else {
            relaxing.emplace(*method, *system, W0, s.h, s.relax);
          }
        } catch (const InvalidArgument& e) {
          throw app::UsageError(e.what());
        }
      })) {
    throw Reported{status};
  }
  Relaxation<DistributedSUN>& relaxation = *relaxing;
  Tally tally;
  if (resume != nullptr) {
    // Rank 0's record, read on every rank in step: its numbers broadcast, its matrices (the
    // state, the warm start's corrections) scattered, so that every rank fails alike and
    // only rank 0 holds them whole (docs/design/distributed.md, "Checkpoints").
    RankZeroRecordReader record(grid, std::move(resume->relaxation));
    const int status = onEveryRank(grid, [&] {
      resumeRelaxation(record, s.relax, o.resume, [&](BinaryRecordReader& in) {
        relaxation.load(in);
        return relaxation.state();
      });
    });
    if (status != 0) throw Reported{status};
    tally = resume->tally;
  }
  if (const int status = onRankZero(grid, [&] {
        if (resume != nullptr) {
          app::prepareOutputFolder("--resume", o.resume, s.out);
          app::removeTemporaries(s.out, runFiles());
        } else {
          run.lock.emplace(app::claimNewRunFolder("--out", o.out, s.out, runFiles(), o.overwrite,
                                                  "--overwrite", "--resume"));
        }
      })) {
    throw Reported{status};
  }
  // ---- from here on, files are written: failures are exit status 1 ----
  std::optional<RankZeroOutputs> outputs;
  if (const int status = onRankZero(grid, [&] { outputs.emplace(o, s, resume); })) {
    throw Reported{status};
  }
  const RelaxState& at = relaxation.state();
  if (resume != nullptr) spdlog::info("resuming {} at step {}, t = {}", s.out.string(), at.k, at.t);
  const std::string method_name = s.relax.newton ? "newton" : o.method;
  const std::string ranks_text = fmt::format("{} ranks ({}x{} grid, block {})", grid.size(),
                                             grid.rows(), grid.cols(), run.block);
  if (s.relax.newton) {
    spdlog::info(
        "N = {}, alpha = {}, {} init, Newton search on {} to r <= {}, at most {} "
        "iterations",
        n, s.alpha, s.init, ranks_text, s.relax.tolerance, s.steps);
  } else {
    spdlog::info("N = {}, alpha = {}, {} init, {} on {}: {}{}{}", n, s.alpha, s.init, method_name,
                 ranks_text,
                 s.relax.control.adaptive ? "adaptive steps from h = "
                                          : fmt::format("{} steps of h = ", s.steps),
                 s.h, s.default_h && resume == nullptr ? " (default)" : "");
  }
  app::warnAboutSlowBlasKernels();

  const bool watch_energy =
      app::EnergyRises::applies(s.relax.newton || findMethod(o.method)->keeps_casimirs, s.alpha);
  // Every method that solves equations reports its iterations; rk4 and a Newton search none.
  const bool counts_iterations = !s.relax.newton && method->solvesEquations();
  std::string write_error;  // rank 0's first failed write
  const auto onRoot = [&](const std::function<void()>& write) {
    if (!root || !write_error.empty()) return;
    try {
      write();
    } catch (const std::exception& e) {
      write_error = e.what();
    }
  };
  // Rows are states k = 0, every, 2·every, ... and the last; h is 0 for the initial state.
  const auto historyRow = [&](long k, double t, const DistributedMatrix* state) {
    const Matrix whole = state->gather();
    onRoot([&] {
      tally.drift = outputs->row(k, t, k == 0 ? 0.0 : at.h, whole);
      tally.drift_max = std::max(tally.drift_max, tally.drift);
    });
  };
  EveryKth<const DistributedMatrix*, decltype(historyRow)> history(o.every, historyRow);
  // What the summary accumulates over every accepted state, as fluid-relax does.
  const auto observe = [&] {
    if (at.k > 0 && counts_iterations) {
      const long iterations = method->lastStepIterations();
      tally.iterations_total += iterations;
      tally.iterations_max = std::max(tally.iterations_max, iterations);
    }
    if (watch_energy) tally.rises.observe(at.k, at.t, at.energy);
    history(at.k, at.t, &relaxation.current());
  };

  // A checkpoint of the current state: Relaxation's record, written by rank 0 from the
  // gathered state and warm start (collective); the files that grow are on disk up to
  // `lengths` (rank 0's).
  auto last_checkpoint = std::chrono::steady_clock::now();
  long checkpointed_at = -1;  // the step of the last checkpoint
  const auto checkpoint = [&](const HistoryFiles::Lengths& lengths) {
    BinaryRecordWriter record;
    if (root) record = beginCheckpoint(o, run.given, s, tally, lengths);
    relaxation.save(record);
    onRoot([&] { writeCheckpoint(s.out, record); });
    last_checkpoint = std::chrono::steady_clock::now();
    checkpointed_at = at.k;
  };
  const auto syncedLengths = [&] {
    HistoryFiles::Lengths lengths;
    onRoot([&] { lengths = outputs->sync(); });
    return lengths;
  };

  if (resume == nullptr) {
    observe();
  } else if (at.k % o.every != 0) {
    // The checkpoint's state is the last row, held back (its length excludes that row).
    history(at.k, at.t, &relaxation.current());
  }
  app::Progress progress(o.log.quiet || !root);
  const std::string label =
      method_name + " N=" + std::to_string(n) + " P=" + std::to_string(grid.size());
  app::StopSignals signals;
  StepFlags flags;
  // Relaxation decides every step from values reduced alike on every rank, so every rank
  // takes the same steps and stops alike.
  while (relaxation.advance()) {
    observe();
    const bool due = o.checkpoint_every > 0 ? at.k % o.checkpoint_every == 0
                                            : std::chrono::steady_clock::now() - last_checkpoint >=
                                                  std::chrono::duration<double>(kCheckpointSeconds);
    flags =
        agreeOnFlags(grid, {signals.received(), write_error.empty() ? 0 : 1, root && due ? 1 : 0});
    if (flags.write_failed != 0) break;
    if (flags.signal != 0) {
      relaxation.interrupt();
      break;
    }
    if (flags.checkpoint_due != 0) checkpoint(syncedLengths());
    progress.update(label, at.k, s.relax.max_steps,
                    [&] { return fmt::format("t {:.6g}  h {:.3g}", at.t, at.h); });
  }
  progress.clear();
  // As fluid-relax: the checkpoint of the final state records the files without the
  // held-back last row, which a run resumed from it writes again (or not, if it goes past).
  const HistoryFiles::Lengths lengths = syncedLengths();
  history.finish();
  onRoot([&] { outputs->commit(); });
  if (checkpointed_at != at.k) checkpoint(lengths);
  // The final state gathered, whole on rank 0: what the summary reads.
  const RelaxResult<SUN> result =
      resultWithFinal(relaxation.result(), relaxation.result().final.gather());
  const double runtime_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  onRoot([&] {
    tally.rises.warnIfAny(method_name);
    app::Json summary = runSummary(o, s, outputs->system(), result, tally, method_name,
                                   counts_iterations, watch_energy, runtime_s, "cpu");
    summary["mpi_ranks"] = grid.size();
    summary["process_grid"] = {grid.rows(), grid.cols()};
    summary["block_size"] = run.block;
    // A failed run writes no final state (docs/reference/command-lines-and-files.md), as
    // fluid-relax.
    if (result.ok()) outputs->writeFinalState(s, result.final);
    app::writeJsonFile(s.out / "summary.json", summary);
  });
  if (flags.write_failed == 0) {
    flags = agreeOnFlags(grid, {flags.signal, write_error.empty() ? 0 : 1, 0});
  }
  if (flags.write_failed != 0) {
    if (root) std::fprintf(stderr, "%s: %s\n", fluid_mpi::kApp, write_error.c_str());
    return app::kExitFailed;
  }
  if (!result.ok()) {
    spdlog::error("{}", result.failure);
    spdlog::error("history.csv holds the {} steps before the failure; wrote {}", at.k,
                  s.out.string());
    return app::kExitFailed;
  }
  if (result.stop == RelaxStop::kInterrupted) {
    // The same grid shape continues the run to the bit (docs/design/distributed.md, "Checkpoints").
    const std::string shape = grid.rows() == ProcessGrid::defaultRows(grid.size())
                                  ? ""
                                  : " --grid-rows " + std::to_string(grid.rows());
    spdlog::warn(
        "stopped by {} after step {} (t = {}): wrote the outputs and a checkpoint to {}; "
        "continue with: mpirun -np {} fluid-relax-mpi --resume {}{}",
        app::StopSignals::name(flags.signal), at.k, at.t, s.out.string(), grid.size(),
        s.out.string(), shape);
    return app::StopSignals::exitStatus(flags.signal);
  }
  spdlog::info("{} at step {}, t = {}: spectrum drift <= {:.2e}, {:.3g} s; wrote {}",
               relaxStopName(result.stop), at.k, at.t, tally.drift_max, runtime_s, s.out.string());
  return app::kExitOk;
}

int run(int argc, char** argv, const ProcessGrid& grid) {
  CLI::App cli{
      "Relax Zeitlin's SU(N) fluid on the sphere with double-bracket dissipation, "
      "distributed over MPI ranks",
      fluid_mpi::kApp};
  MpiOptions o;
  addMpiOptions(cli, o);
  std::optional<int> status;
  try {
    status = app::parseCommandLine(cli, argc, argv);
  } catch (const app::UsageError& e) {
    // Every rank parsed the same command line: rank 0 speaks for all.
    if (grid.rank() == 0) std::fprintf(stderr, "%s: %s\n", fluid_mpi::kApp, e.what());
    return app::kExitBadInput;
  }
  if (status) return *status;
  app::setupLogging(o.relax.log);
  if (grid.rank() != 0) spdlog::set_level(spdlog::level::off);
  MpiRun run = mpiRun(cli, o, grid);
  // --grid-rows: a grid of the same ranks in the shape asked for (every rank agreed on it).
  std::optional<ProcessGrid> shaped;
  if (run.grid_rows != grid.rows()) shaped.emplace(grid.comm(), run.grid_rows);
  const int result = relax(run, shaped ? *shaped : grid);
  // Rank 0 makes the figures; every rank exits with its status.
  int exit_status = grid.rank() == 0 ? makeFigures(run.options, run.settings.out, result,
                                                   DDB_PLOT_SCRIPT, DDB_ANIMATE_SCRIPT)
                                     : result;
  MPI_Bcast(&exit_status, 1, MPI_INT, 0, grid.comm());
  return exit_status;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int status = ddb::app::kExitFailed;
  {
    const ddb::ProcessGrid grid;
    // --help and --version are printed once.
    if (grid.rank() != 0 && std::freopen("/dev/null", "w", stdout) == nullptr) {
      MPI_Abort(MPI_COMM_WORLD, ddb::app::kExitFailed);
    }
    try {
      status = run(argc, argv, grid);
    } catch (const Reported& reported) {
      status = reported.status;
    } catch (const std::exception& e) {
      // Not an outcome every rank shares: the others may wait in a collective call.
      std::fprintf(stderr, "%s: rank %d: %s\n", fluid_mpi::kApp, grid.rank(), e.what());
      MPI_Abort(MPI_COMM_WORLD, ddb::app::kExitFailed);
    }
  }
  MPI_Finalize();
  return status;
}
