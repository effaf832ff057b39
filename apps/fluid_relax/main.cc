// fluid-relax: relaxes Zeitlin's SU(N) fluid on the sphere (docs/reference/conventions.md §2) with
// double-bracket dissipation towards a steady flow, with the command line and files of
// docs/reference/command-lines-and-files.md ("fluid-relax"). Exit status
// (apps/common/exit_status.h): 2 for bad input, checked in full before anything is written; 1 if a
// step failed (history.csv keeps every state before it) or a file could not be written; 130/143 if
// SIGINT/SIGTERM stopped it (after its step, with outputs and a checkpoint: "Checkpoints" there).
// With --device cuda the states live on one GPU (docs/guide/gpu.md): the same Relaxation on the
// fluid of the CUDA backend, the states copied to this process's memory only for the history
// rows, the checkpoints and the final files.
#include <ddb/integrators/drivers/relax.h>
#include <ddb/integrators/drivers/run.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <spdlog/fmt/chrono.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <optional>
#include <type_traits>

#ifdef DDB_FLUID_RELAX_CUDA
#include <ddb/cuda/cuda_device.h>
#include <ddb/cuda/cuda_zeitlin_fluid.h>
#endif

#include "common/atomic_file.h"
#include "common/cli.h"
#include "common/energy_rises.h"
#include "common/exit_status.h"
#include "common/json.h"
#include "common/logging.h"
#include "common/progress.h"
#include "common/run_folder.h"
#include "common/spectrum_drift.h"
#include "common/stop_signals.h"
#include "fluid_relax/checkpoint.h"
#include "fluid_relax/device.h"
#include "fluid_relax/input.h"
#include "fluid_relax/options.h"
#include "fluid_relax/outputs.h"
#include "fluid_relax/run_files.h"
#include "fluid_relax/summary.h"

namespace {

using namespace ddb;
using namespace ddb::fluid;

// A state of the run as a host matrix: itself on the CPU; on the GPU, copied into `buffer`.
const Matrix& onHost(const Matrix& W, Matrix&) { return W; }
#ifdef DDB_FLUID_RELAX_CUDA
const Matrix& onHost(const CudaMatrix& W, Matrix& buffer) {
  toHost(W, buffer);
  return buffer;
}
#endif

// The run's result with its final state in this process's memory: what the summary and the
// final files read.
const RelaxResult<SUN>& resultOnHost(const RelaxResult<SUN>& result) { return result; }
#ifdef DDB_FLUID_RELAX_CUDA
RelaxResult<SUN> resultOnHost(const RelaxResult<CudaSUN>& result) {
  return resultWithFinal(result, toHost(result.final));
}
#endif

// The initial state where the run's states live.
template <class G>
typename G::template Dual<double> stateOf(const Matrix& W) {
  if constexpr (std::is_same_v<G, SUN>) {
    return W;
  } else {
    return toDevice(W);
  }
}

// The run on the fluid `system` whose states are G's (SUN: this process's memory; CudaSUN: one
// GPU's), `host_fluid` the same fluid on the CPU for the diagnostics, the files and the summary.
// On the CPU every state's spectrum drift is measured; on the GPU the drift of the states the
// history rows hold (as fluid-relax-mpi does), so that no step waits for an eigensolver.
template <class G>
int relax(const std::shared_ptr<const LiePoissonSystem<G>>& system,
          const std::shared_ptr<const LiePoissonSystem<SUN>>& host_fluid, Device device,
          const Options& o, const Settings& s, const GivenFlags& given, Checkpoint* resume) {
  constexpr bool kOnHost = std::is_same_v<G, SUN>;
  using State = typename G::template Dual<double>;
  const auto start = std::chrono::steady_clock::now();
  const Eigen::Index n = s.W0.rows();
  const auto& hamiltonian = dynamic_cast<const ZeitlinHamiltonian&>(host_fluid->hamiltonian());
  const ZeitlinDiagnostics diagnostics(hamiltonian);
  const bool newton = s.relax.newton;
  const std::string method_name = newton ? "newton" : o.method;
  const auto method = makeMethod<G>(o.method, system);  // not used by a Newton search
  // Every method that solves equations reports its iterations; rk4 and a Newton search none.
  const bool counts_iterations = !newton && method->solvesEquations();
  const State W0 = stateOf<G>(s.W0);
  Relaxation<G> run = newton ? Relaxation<G>(*system, W0, s.relax)
                             : Relaxation<G>(*method, *system, W0, s.h, s.relax);
  Matrix host_state;  // a GPU state copied for a row, a progress line or the end
  Tally tally;
  if (resume != nullptr) {
    resumeRelaxation(resume->relaxation, resume->settings.relax, o.resume,
                     [&](BinaryRecordReader& in) {
                       run.load(in);
                       return run.state();
                     });
    tally = resume->tally;
  }
  if (resume != nullptr) {
    app::prepareOutputFolder("--resume", o.resume, s.out);
    app::removeTemporaries(s.out, runFiles());
  }
  // ---- from here on, files are written: failures are exit status 1 ----

  if (resume != nullptr) {
    spdlog::info("resuming {} at step {}, t = {}", s.out.string(), run.state().k, run.state().t);
  }
  const std::string init_text = s.init + " init" + (s.init == "file" ? " " + o.init_file : "");
  if (newton) {
    spdlog::info("N = {}, alpha = {}, {}, Newton search to r <= {}, at most {} iterations", n,
                 s.alpha, init_text, s.relax.tolerance, s.steps);
  } else {
    // With --adaptive h changes, so the cap is a number of steps, not a time.
    const std::string steps_text =
        s.relax.control.adaptive
            ? fmt::format("adaptive steps from h = {}{}, {}", s.h, s.default_h ? " (default)" : "",
                          std::isfinite(s.relax.t_end) ? fmt::format("to t = {}", s.relax.t_end)
                                                       : fmt::format("at most {}", s.steps))
            : fmt::format("{} steps of h = {}{} to t = {}", s.steps, s.h,
                          s.default_h ? " (default)" : "", static_cast<double>(s.steps) * s.h);
    spdlog::info("N = {}, alpha = {}, {}, {}: {}", n, s.alpha, init_text, o.method, steps_text);
  }
  app::warnAboutSlowBlasKernels();
  const app::SpectrumDrift<SUN> spectrumDrift(s.W0);

  HistoryFiles files(o, s, *host_fluid, resume);
  // A row points at the run's current state; the one EveryKth holds back for finish() is
  // the last, which they still point to then.
  auto historyRow = [&](long k, double t, const std::pair<const RelaxState*, const State*>& at) {
    const Matrix& W = onHost(*at.second, host_state);
    if constexpr (!kOnHost) {
      tally.drift = spectrumDrift(W);
      tally.drift_max = std::max(tally.drift_max, tally.drift);
    }
    files.write(k, t, at.first->h, W, tally.drift);
  };
  EveryKth<std::pair<const RelaxState*, const State*>, decltype(historyRow)> history(o.every,
                                                                                     historyRow);

  const bool watch_energy =
      app::EnergyRises::applies(newton || findMethod(o.method)->keeps_casimirs, s.alpha);
  app::Progress progress(o.log.quiet);
  const std::string label = method_name + " N=" + std::to_string(n);
  auto last_checkpoint = std::chrono::steady_clock::now();
  std::string checkpoint_time = "none yet";
  long checkpointed_at = -1;  // the step of the last checkpoint
  const auto observe = [&](const RelaxState& at, const State& W) {
    if (at.k > 0 && counts_iterations) {
      const long iterations = method->lastStepIterations();
      tally.iterations_total += iterations;
      tally.iterations_max = std::max(tally.iterations_max, iterations);
    }
    if (watch_energy) tally.rises.observe(at.k, at.t, at.energy);
    if constexpr (kOnHost) {
      tally.drift = spectrumDrift(W);
      tally.drift_max = std::max(tally.drift_max, tally.drift);
    }
    history(at.k, at.t, {&at, &W});
    progress.update(label, at.k, s.relax.max_steps, [&] {
      // ‖[P, W]‖ on the CPU only: on the GPU it would copy the state and take two products.
      const std::string commutator =
          kOnHost
              ? fmt::format("  |[P,W]| {:.3g}", diagnostics.commutatorNorm(onHost(W, host_state)))
              : "";
      return fmt::format("t {:.6g}  E {:.6g}{}  h {:.3g}  checkpoint {}", at.t, at.energy,
                         commutator, at.h, checkpoint_time);
    });
  };
  // The files that grow are on disk up to the lengths the checkpoint records.
  const auto checkpoint = [&](const HistoryFiles::Lengths& lengths) {
    const auto begin = std::chrono::steady_clock::now();
    BinaryRecordWriter record = beginCheckpoint(o, given, s, tally, lengths);
    run.save(record);
    writeCheckpoint(s.out, record);
    last_checkpoint = std::chrono::steady_clock::now();
    const std::time_t now = std::time(nullptr);
    checkpoint_time = fmt::format("{:%H:%M:%S} (step {})", fmt::localtime(now), run.state().k);
    checkpointed_at = run.state().k;
    spdlog::debug("checkpoint at step {}: {} bytes in {:.3f} s", run.state().k,
                  std::filesystem::file_size(s.out / kCheckpointFile),
                  std::chrono::duration<double>(last_checkpoint - begin).count());
  };
  if (resume == nullptr) {
    observe(run.state(), run.current());
  } else if (run.state().k % o.every != 0) {
    // The checkpoint's state is the last row, held back (its length excludes that row).
    history(run.state().k, run.state().t, {&run.state(), &run.current()});
  }
  app::StopSignals signals;
  int stopped_by = 0;
  while (run.advance()) {
    observe(run.state(), run.current());
    if ((stopped_by = signals.received()) != 0) {
      run.interrupt();
      break;
    }
    const bool due = o.checkpoint_every > 0 ? run.state().k % o.checkpoint_every == 0
                                            : std::chrono::steady_clock::now() - last_checkpoint >=
                                                  std::chrono::duration<double>(kCheckpointSeconds);
    if (due) checkpoint(files.sync());
  }
  progress.clear();
  // The checkpoint of the final state records history.csv and fluid.hdf5 without the
  // held-back last row, which a run resumed from it writes again (or not, if it goes past it).
  const HistoryFiles::Lengths lengths = files.sync();
  history.finish();
  files.commit();
  if (checkpointed_at != run.state().k) checkpoint(lengths);
  tally.rises.warnIfAny(method_name);

  const RelaxResult<SUN> result = resultOnHost(run.result());
  const double runtime_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const app::Json summary =
      runSummary(o, s, *host_fluid, result, tally, method_name, counts_iterations, watch_energy,
                 runtime_s, deviceDescription(device));
  const bool interrupted = result.stop == RelaxStop::kInterrupted;
  if (!result.ok()) {
    // A failed run writes no final state: W_final.csv and omega_final.csv would claim a
    // time the run did not reach (docs/reference/command-lines-and-files.md).
    app::writeJsonFile(s.out / "summary.json", summary);
    spdlog::error("{}", result.failure);
    spdlog::error("history.csv holds the {} steps before the failure; wrote {}", result.last.k,
                  s.out.string());
    return app::kExitFailed;
  }
  writeMatrixCsv(s.out / "W_final.csv", result.final);
  writeOmegaCsv(s.out / "omega_initial.csv", files.basis(), s.W0);
  writeOmegaCsv(s.out / "omega_final.csv", files.basis(), result.final);
  app::writeJsonFile(s.out / "summary.json", summary);
  if (interrupted) {
    spdlog::warn(
        "stopped by {} after step {} (t = {}): wrote the outputs and a checkpoint to {}; "
        "continue with: fluid-relax --resume {}",
        app::StopSignals::name(stopped_by), result.last.k, result.last.t, s.out.string(),
        s.out.string());
    return app::StopSignals::exitStatus(stopped_by);
  }
  spdlog::info(
      "{} at step {}, t = {} ({} rejected): E {} -> {}, |[P,W]| {} -> {}, r {:.3g}, spectrum "
      "drift <= {:.2e}, {:.3g} s; wrote {}",
      relaxStopName(result.stop), result.last.k, result.last.t, result.steps_rejected,
      diagnostics.energy(s.W0), diagnostics.energy(result.final), diagnostics.commutatorNorm(s.W0),
      summary["commutator_final"].get<double>(), summary["residual_final"].get<double>(),
      tally.drift_max, runtime_s, s.out.string());
  return app::kExitOk;
}

// The run on `device`: the fluid where the states live, and on the CPU for the files.
int relaxOn(Device device, const Options& o, const Settings& s, const GivenFlags& given,
            Checkpoint* resume) {
  const Eigen::Index n = s.W0.rows();
  const auto host_fluid = makeZeitlinFluid(n, s.alpha);
#ifdef DDB_FLUID_RELAX_CUDA
  if (device == Device::kCuda) {
    return relax<CudaSUN>(makeCudaZeitlinFluid(n, s.alpha), host_fluid, device, o, s, given,
                          resume);
  }
#endif
  return relax<SUN>(host_fluid, host_fluid, device, o, s, given, resume);
}

int runRelax(int argc, char** argv) {
  CLI::App cli{"Relax Zeitlin's SU(N) fluid on the sphere with double-bracket dissipation", kApp};
  Options o;
  addOptions(cli, o, kMaxN);
  cli.add_option("--device", o.device,
                 "where the states live: cpu, or cuda (one GPU, N <= " +
                     std::to_string(maxN(Device::kCuda)) +
                     ", every --method and --newton; docs/guide/gpu.md); a checkpoint resumes "
                     "on either")
      ->capture_default_str();
  if (const auto status = app::parseCommandLine(cli, argc, argv)) return *status;
  app::setupLogging(o.log);
  const Device device = deviceOf(o.device);
  if (!o.resume.empty()) {
    // The lock first: the checkpoint and the files are read as their one writer left them.
    const app::RunFolderLock lock = lockResumeFolder(o.resume);
    Checkpoint c = readCheckpoint(o.resume);
    resumeSettings(cli, o, c);
    requireRunsOn(device, c.settings.W0.rows());
    checkResumeFolder(o.resume, c);
    const int status = relaxOn(device, c.options, c.settings, c.given, &c);
    return makeFigures(c.options, c.settings.out, status, DDB_PLOT_SCRIPT, DDB_ANIMATE_SCRIPT);
  }
  const Settings s = settings(cli, o, maxN(device));
  requireRunsOn(device, s.W0.rows());
  const app::RunFolderLock lock = app::claimNewRunFolder("--out", o.out, s.out, runFiles(),
                                                         o.overwrite, "--overwrite", "--resume");
  const int status = relaxOn(device, o, s, givenFlags(cli), nullptr);
  return makeFigures(o, s.out, status, DDB_PLOT_SCRIPT, DDB_ANIMATE_SCRIPT);
}

}  // namespace

int main(int argc, char** argv) {
  return ddb::app::runMain(ddb::fluid::kApp, runRelax, argc, argv);
}
