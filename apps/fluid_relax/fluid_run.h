// The fluid relaxation of fluid-relax and fluid-relax-mpi, written once over a placement: where
// the states live (this process's memory, one GPU's, MPI ranks'), which process writes the files
// and how the processes agree on what happened. The run is the library's own (the method of
// --method from the method table, or the Newton search, through Relaxation); around it the
// same steps in the same order for every placement: resume, start log, history rows, checkpoints,
// stop signals, the final files, the summary and the exit status
// (docs/reference/command-lines-and-files.md, "fluid-relax"; docs/design/distributed.md).
//
// A Placement provides:
//   Group, State                    the run's group and its state type
//   n()                             N, on every process
//   kSpectrumEveryState             whether every state's spectrum drift is measured (the CPU),
//                                   or only the history rows' (no step waits for an eigensolver)
//   splitWith(method, flows)        the method Strang-split with each of the damping's and the
//                                   forcings' exact flows (zeitlinExactFlowsBy's order) for
//                                   this placement's states
//   system()                        the fluid whose states are State
//   hostFluid()                     the same fluid on this process's memory (the writer's)
//   initialState(W0)                W₀ where the states live (collective)
//   writes()                        whether this process writes the files
//   agreed(job)                     runs job on every process and agrees on its outcome (bad
//                                   input: exit status 2 everywhere)
//   onWriter(job)                   runs job on the writer and agrees on its outcome
//   write(job)                      a write during the run: on the writer; a failure ends the
//                                   run with status 1 (at once, or at the next agreement)
//   writeFailed(), writeError()     whether such a write failed, and its message
//   onHost(state, buffer)           the state whole in this process's memory, on the writer
//                                   (collective: a GPU copy, a gather)
//   loadCheckpoint(c, caps, dir, load)   the checkpoint's relaxation record, read in step
//   agree(flags)                    the largest of each flag over the processes
//   describe()                      what the start line adds ("" or " on 4 ranks (...)")
//   progressLabel()                 what the progress line's label adds ("" or " P=4")
//   commutatorText(state)           the progress line's ‖[P, W]‖ where it is cheap, or ""
//   reportWriteError()              says which write failed (the writer), where write() did not
//   device()                        summary.json's "device"
//   addToSummary(summary)           the placement's own summary entries
//   resumeCommand(out)              how to continue an interrupted run
#pragma once

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
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "common/atomic_file.h"
#include "common/cli.h"
#include "common/energy_rises.h"
#include "common/exit_status.h"
#include "common/initial_vorticity.h"
#include "common/json.h"
#include "common/logging.h"
#include "common/progress.h"
#include "common/run_folder.h"
#include "common/spectrum_drift.h"
#include "common/stop_signals.h"
#include "fluid_relax/checkpoint.h"
#include "fluid_relax/input.h"
#include "fluid_relax/options.h"
#include "fluid_relax/outputs.h"
#include "fluid_relax/run_files.h"
#include "fluid_relax/step_flags.h"
#include "fluid_relax/summary.h"

namespace ddb::fluid {

/// The run of `o`, `s` (a new one, or with `resume` the checkpoint's) on `where`; returns the
/// exit status. A resumed run's folder is locked by the caller; a new run's is claimed here into
/// `lock` (by the writer) once the run is known to start: bad input leaves no folder behind.
template <class Placement>
int runFluidRelaxation(Placement& where, const Options& o, const Settings& s,
                       const GivenFlags& given, Checkpoint* resume,
                       std::optional<app::RunFolderLock>& lock) {
  using G = typename Placement::Group;
  using State = typename Placement::State;
  const auto start = std::chrono::steady_clock::now();
  const bool newton = s.relax.newton;
  const std::string method_name = newton ? "newton" : o.method;
  const auto& system = where.system();
  // The state is the absolute vorticity Q = W + F (W itself on a resting sphere).
  const Matrix Q0 = s.initialState();
  const State W0 = where.initialState(Q0);
  // The library's checks of the run (InvalidArgument) are bad input, on every process alike.
  std::unique_ptr<OneStepMethod<G>> method;  // none for a Newton search
  std::optional<Relaxation<G>> relaxing;
  where.agreed([&] {
    try {
      if (newton) {
        relaxing.emplace(*system, W0, s.relax);
      } else {
        method = makeMethod<G>(o.method, system);
        // The damping and forcing the run has, Strang-split around the method in their order.
        method = where.splitWith(std::move(method), {s.viscosity, s.forcing, s.fixed_forcing});
        relaxing.emplace(*method, *system, W0, s.h, s.relax);
      }
    } catch (const InvalidArgument& e) {
      throw app::UsageError(e.what());
    }
  });
  Relaxation<G>& run = *relaxing;
  // Every method that solves equations reports its iterations; rk4 and a Newton search none.
  const bool counts_iterations = !newton && method->solvesEquations();
  Tally tally;
  if (resume != nullptr) {
    where.loadCheckpoint(*resume, s.relax, o.resume, [&](BinaryRecordReader& in) {
      run.load(in);
      return run.state();
    });
    tally = resume->tally;
  }
  where.onWriter([&] {
    if (resume != nullptr) {
      app::prepareOutputFolder("--resume", o.resume, s.out);
      app::removeTemporaries(s.out, runFiles());
    } else {
      lock.emplace(app::claimNewRunFolder("--out", o.out, s.out, runFiles(), o.overwrite,
                                          "--overwrite", "--resume"));
    }
  });
  // ---- from here on, files are written: failures are exit status 1 ----
  const RelaxState& at = run.state();
  const Eigen::Index n = where.n();
  std::optional<HistoryFiles> files;
  std::optional<app::SpectrumDrift<SUN>> spectrumDrift;
  where.onWriter([&] {
    files.emplace(o, s, *where.hostFluid(), resume);
    spectrumDrift.emplace(Q0);
  });
  if (resume != nullptr) spdlog::info("resuming {} at step {}, t = {}", s.out.string(), at.k, at.t);
  const std::string init_text = s.init + " init" + (s.init == "file" ? " " + o.init_file : "");
  if (newton) {
    spdlog::info("N = {}, alpha = {}, {}, Newton search{} to r <= {}, at most {} iterations", n,
                 s.alpha, init_text, where.describe(), s.relax.tolerance, s.steps);
  } else {
    // With --adaptive h changes, so the cap is a number of steps, not a time.
    const std::string steps_text =
        s.relax.control.adaptive
            ? fmt::format("adaptive steps from h = {}{}, {}", s.h, s.default_h ? " (default)" : "",
                          std::isfinite(s.relax.t_end) ? fmt::format("to t = {}", s.relax.t_end)
                                                       : fmt::format("at most {}", s.steps))
            : fmt::format("{} steps of h = {}{} to t = {}", s.steps, s.h,
                          s.default_h ? " (default)" : "", static_cast<double>(s.steps) * s.h);
    const ZeitlinViscosity& damping = s.viscosity;
    const ZeitlinStochasticForcing& forcing = s.forcing;
    std::string stepping = o.method;
    if (damping.damps()) {
      stepping += fmt::format(" with viscosity {} (order {}) and drag {}", damping.viscosity,
                              damping.order, damping.drag);
    }
    if (forcing.forces()) {
      stepping += fmt::format(
          "{} forcing of l = {}..{} at rate {} (seed {})", damping.damps() ? ", and" : " with",
          forcing.band_centre - forcing.band_half_width,
          forcing.band_centre + forcing.band_half_width, forcing.rate, forcing.seed);
    }
    if (s.fixed_forcing.size() > 0) {
      stepping +=
          fmt::format("{} the fixed forcing of {}",
                      damping.damps() || forcing.forces() ? ", and" : " with", o.forcing_file);
    }
    spdlog::info("N = {}, alpha = {}, {}, {}{}: {}", n, s.alpha, init_text, stepping,
                 where.describe(), steps_text);
  }
  app::warnAboutSlowBlasKernels();

  Matrix host_state;  // a state copied or gathered for a row, a progress line or the end
  const auto measureDrift = [&](const Matrix& W) {
    tally.drift = (*spectrumDrift)(W);
    tally.drift_max = std::max(tally.drift_max, tally.drift);
  };
  // Rows are states k = 0, every, 2·every, ... and the last, read when written: the row EveryKth
  // holds back for finish() is the last state, which run.state() and run.current() still are.
  const auto historyRow = [&](long k, double t, bool) {
    const Matrix& W = where.onHost(run.current(), host_state);
    where.write([&] {
      if constexpr (!Placement::kSpectrumEveryState) measureDrift(W);
      files->write(k, t, at.h, W, tally.drift);
    });
  };
  EveryKth<bool, decltype(historyRow)> history(o.every, historyRow);

  // A forced run's energy rises by design (the forcing injects it): no rise is a sign of h.
  const bool watch_energy =
      app::EnergyRises::applies(newton || findMethod(o.method)->keeps_casimirs, s.alpha) &&
      !s.forced();
  // What the summary accumulates over every accepted state.
  const auto observe = [&] {
    if (at.k > 0 && counts_iterations) {
      const long iterations = method->lastStepIterations();
      tally.iterations_total += iterations;
      tally.iterations_max = std::max(tally.iterations_max, iterations);
    }
    if (watch_energy) tally.rises.observe(at.k, at.t, at.energy);
    if constexpr (Placement::kSpectrumEveryState)
      measureDrift(where.onHost(run.current(), host_state));
    history(at.k, at.t, true);
  };

  // A checkpoint of the current state: Relaxation's record (collective), written by the writer;
  // the files that grow are on disk up to `lengths`.
  auto last_checkpoint = std::chrono::steady_clock::now();
  std::string checkpoint_time = "none yet";
  long checkpointed_at = -1;  // the step of the last checkpoint
  const auto checkpoint = [&](const HistoryFiles::Lengths& lengths) {
    const auto begin = std::chrono::steady_clock::now();
    BinaryRecordWriter record;
    if (where.writes()) record = beginCheckpoint(o, given, s, tally, lengths);
    run.save(record);
    where.write([&] {
      writeCheckpoint(s.out, record);
      spdlog::debug(
          "checkpoint at step {}: {} bytes in {:.3f} s", at.k,
          std::filesystem::file_size(s.out / kCheckpointFile),
          std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count());
    });
    last_checkpoint = std::chrono::steady_clock::now();
    checkpoint_time =
        fmt::format("{:%H:%M:%S} (step {})", fmt::localtime(std::time(nullptr)), at.k);
    checkpointed_at = at.k;
  };
  const auto syncedLengths = [&] {
    HistoryFiles::Lengths lengths;
    where.write([&] { lengths = files->sync(); });
    return lengths;
  };

  if (resume == nullptr) {
    observe();
  } else if (at.k % o.every != 0) {
    // The checkpoint's state is the last row, held back (its length excludes that row).
    history(at.k, at.t, true);
  }
  app::Progress progress(o.log.quiet || !where.writes());
  const std::string label = method_name + " N=" + std::to_string(n) + where.progressLabel();
  app::StopSignals signals;
  StepFlags flags;
  // Relaxation decides every step from values reduced alike on every process, so every process
  // takes the same steps and stops alike.
  while (run.advance()) {
    observe();
    const bool due = o.checkpoint_every > 0 ? at.k % o.checkpoint_every == 0
                                            : std::chrono::steady_clock::now() - last_checkpoint >=
                                                  std::chrono::duration<double>(kCheckpointSeconds);
    flags = where.agree(
        {signals.received(), where.writeFailed() ? 1 : 0, where.writes() && due ? 1 : 0});
    if (flags.write_failed != 0) break;
    if (flags.signal != 0) {
      run.interrupt();
      break;
    }
    if (flags.checkpoint_due != 0) checkpoint(syncedLengths());
    progress.update(label, at.k, s.relax.max_steps, [&] {
      return fmt::format("t {:.6g}  E {:.6g}{}  h {:.3g}  checkpoint {}", at.t, at.energy,
                         where.commutatorText(run.current()), at.h, checkpoint_time);
    });
  }
  progress.clear();
  // The checkpoint of the final state records the files without the held-back last row, which a
  // run resumed from it writes again (or not, if it goes past it).
  const HistoryFiles::Lengths lengths = syncedLengths();
  history.finish();
  where.write([&] { files->commit(); });
  if (checkpointed_at != at.k) checkpoint(lengths);
  // The final state whole in this process's memory (on the writer): what the summary reads.
  const RelaxResult<G> ended = run.result();
  const RelaxResult<SUN> result = resultWithFinal(ended, where.onHost(ended.final, host_state));
  const double runtime_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::optional<app::Json> summary;
  where.write([&] {
    tally.rises.warnIfAny(method_name);
    summary = runSummary(o, s, *where.hostFluid(), result, tally, method_name, counts_iterations,
                         watch_energy, runtime_s, where.device());
    where.addToSummary(*summary);
    // A failed run writes no final state: W_final.csv and omega_final.csv would claim a time
    // the run did not reach (docs/reference/command-lines-and-files.md).
    // The relative vorticity W = Q − F, as --init-file reads it.
    if (result.ok()) {
      const Matrix W_final = result.final - (Q0 - s.W0);
      app::writeMatrixCsv(s.out / "W_final.csv", W_final);
      writeOmegaCsv(s.out / "omega_initial.csv", files->basis(), s.W0);
      writeOmegaCsv(s.out / "omega_final.csv", files->basis(), W_final);
    }
    app::writeJsonFile(s.out / "summary.json", *summary);
  });
  flags = where.agree({flags.signal, where.writeFailed() ? 1 : 0, 0});
  if (flags.write_failed != 0) {
    where.reportWriteError();
    return app::kExitFailed;
  }
  if (!result.ok()) {
    spdlog::error("{}", result.failure);
    spdlog::error("history.csv holds the {} steps before the failure; wrote {}", at.k,
                  s.out.string());
    return app::kExitFailed;
  }
  if (result.stop == RelaxStop::kInterrupted) {
    spdlog::warn(
        "stopped by {} after step {} (t = {}): wrote the outputs and a checkpoint to {}; "
        "continue with: {}",
        app::StopSignals::name(flags.signal), at.k, at.t, s.out.string(),
        where.resumeCommand(s.out.string()));
    return app::StopSignals::exitStatus(flags.signal);
  }
  if (where.writes()) {
    const ZeitlinDiagnostics diagnostics(
        dynamic_cast<const ZeitlinHamiltonian&>(where.hostFluid()->hamiltonian()));
    spdlog::info(
        "{} at step {}, t = {} ({} rejected): E {} -> {}, |[P,W]| {} -> {}, r {:.3g}, spectrum "
        "drift <= {:.2e}, {:.3g} s; wrote {}",
        relaxStopName(result.stop), at.k, at.t, result.steps_rejected, diagnostics.energy(Q0),
        diagnostics.energy(result.final), diagnostics.commutatorNorm(Q0),
        (*summary)["commutator_final"].template get<double>(),
        (*summary)["residual_final"].template get<double>(), tally.drift_max, runtime_s,
        s.out.string());
  }
  return app::kExitOk;
}

}  // namespace ddb::fluid
