// mhd-relax: relaxes Zeitlin's magnetic fluid on the sphere (magnetohydrodynamics on SU(N) ⋉
// su(N)*, systems/zeitlin_mhd.h) by the double bracket towards a magnetic equilibrium, with the
// command line and files of docs/reference/command-lines-and-files.md ("mhd-relax"). The run is the
// library's Relaxation of the method of --method; every method of the DDB family keeps tr Θᵏ and
// tr(WΘᵏ) for every k while α > 0 lowers E_kin + E_mag. Exit status (apps/common/exit_status.h):
// 2 for bad input, checked in full before anything is written; 1 if a step failed (history.csv
// and fluid.hdf5 keep every row before it) or a file could not be written; 130/143 if
// SIGINT/SIGTERM stopped it (after its step, with its outputs and a checkpoint, from which
// --resume continues the run to the bit, as after a kill).
#include <ddb/integrators/drivers/relax.h>
#include <ddb/integrators/drivers/run.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/systems/zeitlin_mhd.h>
#include <spdlog/spdlog.h>

#include <chrono>
#include <memory>
#include <optional>
#include <string>

#include "common/atomic_file.h"
#include "common/cli.h"
#include "common/energy_rises.h"
#include "common/exit_status.h"
#include "common/initial_vorticity.h"
#include "common/journal_file.h"
#include "common/json.h"
#include "common/plot.h"
#include "common/progress.h"
#include "common/resume.h"
#include "common/run_folder.h"
#include "common/stop_signals.h"
#include "mhd_relax/checkpoint.h"
#include "mhd_relax/history.h"
#include "mhd_relax/options.h"

namespace {

using namespace ddb;
using namespace ddb::mhd;

/// The files of a run (a replaced run's, and the temporaries of a killed one).
const app::RunFiles& runFiles() {
  static const app::RunFiles files{
      {"history.csv", app::JournalFile::partialOf("history.csv").string(), "fluid.hdf5",
       "fluid.hdf5.partial", kCheckpointFile, "summary.json", "W_final.csv", "theta_final.csv",
       "mhd.png", "mhd.png.tmp.png"}};
  return files;
}

/// What summary.json says of the run; `first` and `last` are the first and last rows' numbers.
app::Json runSummary(const Options& o, const Settings& s, const RelaxResult<DualNumberSUN>& result,
                     const Tally& tally, const MhdFrameNumbers& last, bool watch_energy,
                     double runtime_s) {
  const MhdFrameNumbers& first = tally.first;
  app::Json j;
  j["version"] = app::projectVersion();
  j["status"] = !result.ok()                             ? "FAILED"
                : result.stop == RelaxStop::kInterrupted ? "interrupted"
                                                         : "ok";
  j["n"] = s.W0.rows();
  j["alpha"] = s.alpha;
  j["h"] = s.h;
  j["method"] = o.method;
  j["steps"] = result.last.k;
  j["steps_requested"] = s.relax.max_steps;
  j["t_end"] = result.last.t;
  j["stop"] = relaxStopName(result.stop);
  j["steady"] = result.steady();
  j["until_steady"] = s.relax.tolerance > 0 ? app::Json(s.relax.tolerance) : app::Json();
  j["adaptive"] = s.relax.control.adaptive;
  j["adaptive_tol"] = s.relax.control.adaptive ? app::Json(s.relax.control.tolerance) : app::Json();
  j["steps_rejected"] = result.steps_rejected;
  j["h_final"] = result.last.h;
  j["every"] = o.every;
  j["init"] = s.init;
  j["seed"] = s.init == "file" ? app::Json() : app::Json(o.seed);
  j["init_file"] = s.init == "file" ? app::Json(o.init_file) : app::Json();
  j["theta_init"] = s.theta_init;
  const bool generated = s.theta_init != "file";
  j["theta_scale"] =
      generated ? app::Json(app::parseNumber("--theta-scale", o.theta_scale, o.theta_scale))
                : app::Json();
  j["theta_lmax"] = generated ? app::Json(o.theta_lmax) : app::Json();
  j["theta_seed"] = generated ? app::Json(o.theta_seed) : app::Json();
  j["theta_file"] = generated ? app::Json() : app::Json(o.theta_file);
  const auto both = [&](const char* name, double initial, double final_value) {
    j[std::string(name) + "_initial"] = initial;
    j[std::string(name) + "_final"] = final_value;
  };
  both("kinetic_energy", first.kinetic_energy, last.kinetic_energy);
  both("magnetic_energy", first.magnetic_energy, last.magnetic_energy);
  both("energy", first.kinetic_energy + first.magnetic_energy,
       last.kinetic_energy + last.magnetic_energy);
  both("cross_helicity", first.cross_helicity, last.cross_helicity);
  both("residual", first.residual, last.residual);
  both("equilibrium_residual", first.equilibrium_residual, last.equilibrium_residual);
  j["invariant_drift_max"] = tally.drift_max;
  j["energy_rises"] = watch_energy ? app::Json(tally.rises.count()) : app::Json();
  j["iterations_total"] = tally.iterations_total;
  j["iterations_max"] = tally.iterations_max;
  j["runtime_s"] = runtime_s;
  j["failure"] = result.ok() ? app::Json() : app::Json(result.failure);
  return j;
}

/// The run of `o`, `s` (a new one, or with `resume` the checkpoint's, whose folder `lock`
/// holds); returns the exit status. A new run's folder is claimed here once the run is known to
/// start: bad input leaves no folder behind.
int relax(const Options& o, const Settings& s, Checkpoint* resume,
          std::optional<app::RunFolderLock>& lock) {
  const auto start = std::chrono::steady_clock::now();
  const Eigen::Index n = s.W0.rows();
  const State mu0 = zeitlinMhdState(s.W0, s.Theta0);
  const auto system = makeZeitlinMhd(n, s.alpha);
  std::unique_ptr<OneStepMethod<DualNumberSUN>> method;
  std::optional<Relaxation<DualNumberSUN>> relaxing;
  try {
    method = makeMethod<DualNumberSUN>(o.method, system);
    relaxing.emplace(*method, *system, mu0, s.h, s.relax);
  } catch (const InvalidArgument& e) {
    throw app::UsageError(e.what());
  }
  Relaxation<DualNumberSUN>& run = *relaxing;
  Tally tally;
  if (resume != nullptr) {
    app::resumeRelaxation(resume->relaxation, s.relax, o.resume, kCheckpointFile,
                          [&](BinaryRecordReader& in) {
                            run.load(in);
                            return run.state();
                          });
    tally = resume->tally;
    app::removeTemporaries(s.out, runFiles());
  } else {
    lock.emplace(app::claimNewRunFolder("--out", o.out, s.out, runFiles(), o.overwrite,
                                        "--overwrite", "--resume"));
  }
  // ---- from here on, files are written: failures are exit status 1 ----
  const RelaxState& at = run.state();
  if (resume != nullptr) {
    spdlog::info("resuming {} at step {}, t = {}", s.out.string(), at.k, at.t);
  }
  spdlog::info("N = {}, alpha = {}, {} init, Theta0 {} ({}), {} with h = {}{}", n, s.alpha, s.init,
               s.theta_init, s.Theta0.norm() > 0 ? "nonzero" : "zero: Zeitlin's fluid", o.method,
               s.h,
               s.relax.control.adaptive ? fmt::format(" adaptive to t = {}", s.relax.t_end)
                                        : fmt::format(", at most {} steps", s.relax.max_steps));
  app::warnAboutSlowBlasKernels();

  HistoryFiles files(o, s, *system, resume != nullptr ? &resume->files : nullptr);
  const bool watch_energy =
      app::EnergyRises::applies(findMethod(o.method)->keeps_casimirs, s.alpha);
  const auto row = [&](long k, double t, const State& mu) {
    files.write(k, t, at.h, mu);
    if (k == 0) tally.first = files.last();
    tally.drift_max = std::max(tally.drift_max, files.last().invariant_drift);
  };
  EveryKth<State, decltype(row)> history(o.every, row);
  const auto observe = [&] {
    if (at.k > 0 && method->solvesEquations()) {
      tally.iterations_total += method->lastStepIterations();
      tally.iterations_max = std::max(tally.iterations_max, method->lastStepIterations());
    }
    if (watch_energy) tally.rises.observe(at.k, at.t, at.energy);
    history(at.k, at.t, run.current());
  };
  // A checkpoint of the current state: the files that grow are on disk up to `lengths`.
  auto last_checkpoint = std::chrono::steady_clock::now();
  long checkpointed_at = -1;
  const auto checkpoint = [&](const FileLengths& lengths) {
    BinaryRecordWriter record = beginCheckpoint(o, s, tally, lengths);
    run.save(record);
    writeCheckpoint(s.out, record);
    last_checkpoint = std::chrono::steady_clock::now();
    checkpointed_at = at.k;
  };
  if (resume == nullptr) {
    observe();
  } else if (at.k % o.every != 0) {
    // The checkpoint's state is the last row, held back (its length excludes that row).
    history(at.k, at.t, run.current());
  }
  app::Progress progress(o.log.quiet);
  const std::string label = o.method + " N=" + std::to_string(n);
  app::StopSignals signals;
  int signal = 0;
  while (run.advance()) {
    observe();
    if ((signal = signals.received()) != 0) {
      run.interrupt();
      break;
    }
    const bool due = o.checkpoint_every > 0 ? at.k % o.checkpoint_every == 0
                                            : std::chrono::steady_clock::now() - last_checkpoint >=
                                                  std::chrono::duration<double>(kCheckpointSeconds);
    if (due) checkpoint(files.sync());
    progress.update(label, at.k, s.relax.max_steps, [&] {
      return fmt::format("t {:.6g}  E {:.6g}  h {:.3g}", at.t, at.energy, at.h);
    });
  }
  progress.clear();
  // The checkpoint of the final state records the files without the held-back last row, which a
  // run resumed from it writes again (or not, if it goes past it).
  const FileLengths lengths = files.sync();
  history.finish();
  files.commit();
  if (checkpointed_at != at.k) checkpoint(lengths);
  const RelaxResult<DualNumberSUN>& result = run.result();
  const double runtime_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (watch_energy) tally.rises.warnIfAny(o.method);
  const MhdFrameNumbers& last = files.last();
  // A failed run writes no final fields: W_final.csv and theta_final.csv would claim a time the
  // run did not reach.
  if (result.ok()) {
    app::writeMatrixCsv(s.out / "W_final.csv", result.final.eps);
    app::writeMatrixCsv(s.out / "theta_final.csv", result.final.real);
  }
  app::writeJsonFile(s.out / "summary.json",
                     runSummary(o, s, result, tally, last, watch_energy, runtime_s));
  if (!result.ok()) {
    spdlog::error("{}", result.failure);
    spdlog::error("history.csv and fluid.hdf5 hold the {} steps before the failure; wrote {}", at.k,
                  s.out.string());
    return app::kExitFailed;
  }
  if (result.stop == RelaxStop::kInterrupted) {
    spdlog::warn(
        "stopped by {} after step {} (t = {}): wrote the outputs and a checkpoint to {}; "
        "continue with: mhd-relax --resume {}",
        app::StopSignals::name(signal), at.k, at.t, s.out.string(), s.out.string());
    return app::StopSignals::exitStatus(signal);
  }
  const MhdFrameNumbers& first = tally.first;
  spdlog::info(
      "{} at step {}, t = {} ({} rejected): E {} -> {}, E_mag {} -> {}, equilibrium residual "
      "{:.3g} -> {:.3g}, r {:.3g}, invariant drift <= {:.2e}, {:.3g} s; wrote {}",
      relaxStopName(result.stop), at.k, at.t, result.steps_rejected,
      first.kinetic_energy + first.magnetic_energy, last.kinetic_energy + last.magnetic_energy,
      first.magnetic_energy, last.magnetic_energy, first.equilibrium_residual,
      last.equilibrium_residual, last.residual, tally.drift_max, runtime_s, s.out.string());
  if (o.plot) {
    const std::string failure = app::runPlotScript(DDB_MHD_PLOT_SCRIPT, s.out);
    if (!failure.empty()) return app::recordFiguresFailure(s.out / "summary.json", failure);
  }
  return app::kExitOk;
}

int runMhd(int argc, char** argv) {
  CLI::App cli{
      "Relax magnetohydrodynamics on the sphere (Zeitlin's model on SU(N) x| su(N)*) "
      "with double-bracket dissipation",
      kApp};
  Options o;
  addOptions(cli, o);
  if (const auto status = app::parseCommandLine(cli, argc, argv)) return *status;
  app::setupLogging(o.log);
  std::optional<app::RunFolderLock> lock;
  if (!o.resume.empty()) {
    // The lock first: the checkpoint and the files are read as their one writer left them.
    lock.emplace(app::lockResumeFolder(o.resume, kCheckpointFile));
    rejectFlagsBesideResume(cli, o);
    Checkpoint c = readCheckpoint(o.resume);
    checkResumeFolder(o.resume, c);
    readStepCap(cli, o, c.settings, true);
    return relax(resumedOptions(o, c.options), c.settings, &c, lock);
  }
  const Settings s = settings(cli, o);
  return relax(o, s, nullptr, lock);
}

}  // namespace

int main(int argc, char** argv) { return ddb::app::runMain(ddb::mhd::kApp, runMhd, argc, argv); }
