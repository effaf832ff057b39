// fluid-relax-mpi: fluid-relax's ddb-cay relaxation with every N×N matrix distributed
// block-cyclically over the ranks of an MPI job (docs/distributed.md, "fluid-relax-mpi").
// The step is the library's one DDB step on distributed matrices (DistributedDdb); the
// command line, its checks and the files are fluid-relax's (docs/file-formats.md), written
// by rank 0 from the states gathered there for the history rows and at the end; summary.json
// adds mpi_ranks, process_grid and block_size. The energy (for energy rises) and the
// residual (for --until-steady) of every step are evaluated distributed. Exit statuses as
// fluid-relax's, agreed by every rank: 2 bad input on any rank (nothing written), 1 a failed
// step or a file rank 0 could not write, 130/143 a SIGINT/SIGTERM on any rank (outputs
// written, no checkpoint); anything unexpected on one rank ends the job (MPI_Abort).
#include <ddb/distributed/distributed_ddb.h>
#include <ddb/distributed/process_grid.h>
#include <ddb/integrators/relax.h>
#include <ddb/integrators/run.h>
#include <ddb/integrators/steady_state_probe.h>
#include <ddb/systems/spherical_harmonic_basis.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <mpi.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <optional>

#include "common/atomic_file.h"
#include "common/cli.h"
#include "common/energy_rises.h"
#include "common/exit_status.h"
#include "common/json.h"
#include "common/logging.h"
#include "common/plot.h"
#include "common/progress.h"
#include "common/spectrum_drift.h"
#include "common/stop_signals.h"
#include "fluid_relax/checkpoint.h"
#include "fluid_relax/outputs.h"
#include "fluid_relax/summary.h"
#include "fluid_relax_mpi/mpi_input.h"

namespace {

using namespace ddb;
using namespace ddb::fluid;
using namespace ddb::fluid_mpi;
using B = MatrixBackend<DistributedMatrix>;

// What rank 0 makes of gathered states: fluid-relax's history rows and final files.
class RankZeroOutputs {
 public:
  RankZeroOutputs(const Settings& s, Eigen::Index n)
      : system_(makeZeitlinFluid(n, s.alpha)),
        hamiltonian_(dynamic_cast<const ZeitlinHamiltonian&>(system_->hamiltonian())),
        diagnostics_(hamiltonian_),
        drift_(s.W0),
        probe_(*system_),
        history_(s.out / "history.csv") {}

  /// One history.csv row; returns the state's spectrum drift.
  double row(double t, double h, const Matrix& W) {
    probe_.evaluate(W);
    const double drift = drift_(W);
    history_.write(t, diagnostics_.energy(W), diagnostics_.enstrophy(W),
                   diagnostics_.commutatorNorm(W), drift, h, probe_.residual());
    return drift;
  }
  void commitHistory() { history_.commit(); }
  void writeFinalState(const Settings& s, const Matrix& W) {
    const SphericalHarmonicBasis basis(hamiltonian_.laplacian());
    writeMatrixCsv(s.out / "W_final.csv", W);
    writeOmegaCsv(s.out / "omega_initial.csv", basis, s.W0);
    writeOmegaCsv(s.out / "omega_final.csv", basis, W);
  }

 private:
  std::shared_ptr<const LiePoissonSystem<SUN>> system_;
  const ZeitlinHamiltonian& hamiltonian_;
  ZeitlinDiagnostics diagnostics_;
  app::SpectrumDrift<SUN> drift_;
  SteadyStateProbe<SUN> probe_;
  HistoryCsv history_;
};

// Once per step every rank learns whether any rank received a stop signal and whether rank
// 0 failed to write a file: the largest of each over the ranks.
struct StepFlags {
  int signal = 0, write_failed = 0;
};
StepFlags agreeOnFlags(const ProcessGrid& grid, StepFlags mine) {
  int values[2] = {mine.signal, mine.write_failed};
  MPI_Allreduce(MPI_IN_PLACE, values, 2, MPI_INT, MPI_MAX, grid.comm());
  return {values[0], values[1]};
}

int relax(const MpiOptions& mo, const Settings& s, int block, const ProcessGrid& grid) {
  const auto start = std::chrono::steady_clock::now();
  const Options& o = mo.relax;
  const bool root = grid.rank() == 0;
  const Eigen::Index n = s.W0.rows();
  if (const int status = onRankZero(grid, [&] { app::prepareOutputFolder("--out", o.out, s.out); }))
    throw Reported{status};
  // ---- from here on, files are written: failures are exit status 1 ----
  std::optional<RankZeroOutputs> outputs;
  if (const int status = onRankZero(grid, [&] { outputs.emplace(s, n); })) throw Reported{status};
  spdlog::info(
      "N = {}, alpha = {}, {} init, ddb-cay on {} ranks ({}x{} grid, block {}): {} steps of h = "
      "{}{}",
      n, s.alpha, s.init, grid.size(), grid.rows(), grid.cols(), block, s.steps, s.h,
      s.default_h ? " (default)" : "");

  DistributedMatrix W(grid, static_cast<int>(n), block);
  W.scatterFrom(s.W0);
  DistributedMatrix trial(W.layout()), P(W.layout()), product(W.layout()), commutator(W.layout());
  DistributedDdb ddb(W.layout(), s.alpha);
  const DistributedZeitlinFluid& fluid = ddb.system();
  const bool watch_energy = app::EnergyRises::applies(true, s.alpha);
  const bool probing = s.relax.tolerance > 0;

  Tally tally;
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
      tally.drift = outputs->row(t, k == 0 ? 0.0 : s.h, whole);
      tally.drift_max = std::max(tally.drift_max, tally.drift);
    });
  };
  EveryKth<const DistributedMatrix*, decltype(historyRow)> history(o.every, historyRow);

  RelaxResult<SUN> result;
  RelaxState& at = result.last;
  // The current state's H = N·E/ħ (the energy fluid-relax watches for rises) and
  // r = ‖[P, W]‖/(‖P‖ ‖W‖) (0 where ‖P‖ ‖W‖ = 0, SteadyStateProbe's convention), from one
  // Poisson solve, distributed; only what the run reads.
  const auto observeState = [&] {
    if (!watch_energy && !probing) return;
    fluid.streamMatrixInto(W, P);
    if (watch_energy) {
      at.energy = DistributedZeitlinFluid::energy(W, P) * static_cast<double>(n) / fluid.hbar();
      tally.rises.observe(at.k, at.t, at.energy);
    }
    if (probing) {
      const double scale = B::frobeniusNorm(P) * B::frobeniusNorm(W);
      const double norm = DistributedZeitlinFluid::commutatorNorm(W, P, product, commutator);
      at.residual = scale > 0.0 ? norm / scale : 0.0;
    }
  };
  at.residual = NAN;
  observeState();
  history(0, 0.0, &W);
  app::Progress progress(o.log.quiet || !root);
  const std::string label = "ddb-cay N=" + std::to_string(n) + " P=" + std::to_string(grid.size());
  app::StopSignals signals;
  StepFlags flags;
  while (true) {
    if (probing && at.residual <= s.relax.tolerance) {
      result.stop = RelaxStop::kSteady;
      break;
    }
    if (at.k >= s.relax.max_steps) {
      result.stop = RelaxStop::kStepCap;
      break;
    }
    // The step from a copy, so that a failed step keeps the state before it. Its decisions
    // use values reduced alike on every rank, so every rank fails alike.
    B::entries(trial) = B::entries(W);
    try {
      ddb.advance(trial, at.t, s.h);
      if (!std::isfinite(B::frobeniusNorm(trial))) {
        throw NonFiniteState("ddb-cay", -1, at.t, s.h, B::entries(trial));
      }
    } catch (const SolveFailure& failure) {
      result.failure = detail::messageAtStep(failure, at.k, at.t, s.h);
      result.failed_step = at.k;
      result.stop = RelaxStop::kFailure;
      break;
    }
    W.swap(trial);
    ++at.k;
    at.t = static_cast<double>(at.k) * s.h;
    at.h = s.h;
    const LegendreStats& stats = ddb.legendreSolver().stats();
    const long iterations = stats.fixed_point + stats.newton;
    tally.iterations_total += iterations;
    tally.iterations_max = std::max(tally.iterations_max, iterations);
    observeState();
    history(at.k, at.t, &W);
    flags = agreeOnFlags(grid, {signals.received(), write_error.empty() ? 0 : 1});
    if (flags.write_failed != 0) break;
    if (flags.signal != 0) {
      result.stop = RelaxStop::kInterrupted;
      break;
    }
    progress.update(label, at.k, s.relax.max_steps,
                    [&] { return fmt::format("t {:.6g}  h {:.3g}", at.t, s.h); });
  }
  progress.clear();
  history.finish();
  result.final = W.gather();
  const double runtime_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  onRoot([&] {
    outputs->commitHistory();
    tally.rises.warnIfAny("ddb-cay");
    app::Json summary = runSummary(o, s, result, tally, "ddb-cay", watch_energy, runtime_s);
    summary["mpi_ranks"] = grid.size();
    summary["process_grid"] = {grid.rows(), grid.cols()};
    summary["block_size"] = block;
    // A failed run writes no final state (docs/file-formats.md), as fluid-relax.
    if (result.ok()) outputs->writeFinalState(s, result.final);
    app::writeJsonFile(s.out / "summary.json", summary);
  });
  if (flags.write_failed == 0) {
    flags = agreeOnFlags(grid, {flags.signal, write_error.empty() ? 0 : 1});
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
    spdlog::warn("stopped by {} after step {} (t = {}): wrote the outputs to {}",
                 app::StopSignals::name(flags.signal), at.k, at.t, s.out.string());
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
  int block = 0;
  const Settings s = mpiSettings(cli, o, grid, block);
  int result = relax(o, s, block, grid);
  if (result == app::kExitOk && o.relax.plot && grid.rank() == 0) {
    result = app::runPlotScript(DDB_PLOT_SCRIPT, s.out);
  }
  return result;
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
