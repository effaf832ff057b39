// mhd-relax: relaxes Zeitlin's magnetic fluid on the sphere (magnetohydrodynamics on SU(N) ⋉
// su(N)*, systems/zeitlin_mhd.h) by the double bracket towards a magnetic equilibrium, with the
// command line and files of docs/reference/command-lines-and-files.md ("mhd-relax"). The run is the
// library's Relaxation of the method of --method; every method of the DDB family keeps tr Θᵏ and
// tr(WΘᵏ) for every k while α > 0 lowers E_kin + E_mag. Exit status (apps/common/exit_status.h):
// 2 for bad input, checked in full before anything is written; 1 if a step failed (history.csv
// and fluid.hdf5 keep every row before it) or a file could not be written; 130/143 if
// SIGINT/SIGTERM stopped it (after its step, with its outputs). mhd-relax writes no checkpoint:
// a killed run leaves history.csv.partial and fluid.hdf5.partial, and starts again.
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
#include "common/run_folder.h"
#include "common/stop_signals.h"
#include "mhd_relax/history.h"
#include "mhd_relax/options.h"

namespace {

using namespace ddb;
using namespace ddb::mhd;

/// The files of a run (a replaced run's, and the temporaries of a killed one).
const app::RunFiles& runFiles() {
  static const app::RunFiles files{
      {"history.csv", app::JournalFile::partialOf("history.csv").string(), "fluid.hdf5",
       "fluid.hdf5.partial", "summary.json", "W_final.csv", "theta_final.csv", "mhd.png",
       "mhd.png.tmp.png"}};
  return files;
}

/// What summary.json says of the run; `first` and `last` are the first and last rows' numbers.
app::Json runSummary(const Options& o, const Settings& s, const RelaxResult<DualNumberSUN>& result,
                     const MhdFrameNumbers& first, const MhdFrameNumbers& last,
                     const app::EnergyRises& rises, bool watch_energy, double drift_max,
                     long iterations_total, long iterations_max, double runtime_s) {
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
  j["invariant_drift_max"] = drift_max;
  j["energy_rises"] = watch_energy ? app::Json(rises.count()) : app::Json();
  j["iterations_total"] = iterations_total;
  j["iterations_max"] = iterations_max;
  j["runtime_s"] = runtime_s;
  j["failure"] = result.ok() ? app::Json() : app::Json(result.failure);
  return j;
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
  const auto start = std::chrono::steady_clock::now();
  const Settings s = settings(cli, o);
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
  const app::RunFolderLock lock =
      app::claimNewRunFolder("--out", o.out, s.out, runFiles(), o.overwrite, "--overwrite", "");
  // ---- from here on, files are written: failures are exit status 1 ----
  spdlog::info("N = {}, alpha = {}, {} init, Theta0 {} ({}), {} with h = {}{}", n, s.alpha, s.init,
               s.theta_init, s.Theta0.norm() > 0 ? "nonzero" : "zero: Zeitlin's fluid", o.method,
               s.h,
               s.relax.control.adaptive ? fmt::format(" adaptive to t = {}", s.relax.t_end)
                                        : fmt::format(", at most {} steps", s.relax.max_steps));
  app::warnAboutSlowBlasKernels();

  HistoryFiles files(o, s, *system);
  const RelaxState& at = run.state();
  const bool watch_energy =
      app::EnergyRises::applies(findMethod(o.method)->keeps_casimirs, s.alpha);
  app::EnergyRises rises;
  std::optional<MhdFrameNumbers> first;
  double drift_max = 0.0;
  long iterations_total = 0, iterations_max = 0;
  const auto row = [&](long k, double t, const State& mu) {
    files.write(k, t, at.h, mu);
    if (!first) first = files.last();
    drift_max = std::max(drift_max, files.last().invariant_drift);
  };
  EveryKth<State, decltype(row)> history(o.every, row);
  const auto observe = [&] {
    if (at.k > 0 && method->solvesEquations()) {
      iterations_total += method->lastStepIterations();
      iterations_max = std::max(iterations_max, method->lastStepIterations());
    }
    if (watch_energy) rises.observe(at.k, at.t, at.energy);
    history(at.k, at.t, run.current());
  };
  observe();
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
    progress.update(label, at.k, s.relax.max_steps, [&] {
      return fmt::format("t {:.6g}  E {:.6g}  h {:.3g}", at.t, at.energy, at.h);
    });
  }
  progress.clear();
  history.finish();
  files.commit();
  const RelaxResult<DualNumberSUN>& result = run.result();
  const double runtime_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (watch_energy) rises.warnIfAny(o.method);
  const MhdFrameNumbers& last = files.last();
  // A failed run writes no final fields: W_final.csv and theta_final.csv would claim a time the
  // run did not reach.
  if (result.ok()) {
    app::writeMatrixCsv(s.out / "W_final.csv", result.final.eps);
    app::writeMatrixCsv(s.out / "theta_final.csv", result.final.real);
  }
  app::writeJsonFile(s.out / "summary.json",
                     runSummary(o, s, result, *first, last, rises, watch_energy, drift_max,
                                iterations_total, iterations_max, runtime_s));
  if (!result.ok()) {
    spdlog::error("{}", result.failure);
    spdlog::error("history.csv and fluid.hdf5 hold the {} steps before the failure; wrote {}", at.k,
                  s.out.string());
    return app::kExitFailed;
  }
  if (result.stop == RelaxStop::kInterrupted) {
    spdlog::warn("stopped by {} after step {} (t = {}): wrote the outputs to {}",
                 app::StopSignals::name(signal), at.k, at.t, s.out.string());
    return app::StopSignals::exitStatus(signal);
  }
  spdlog::info(
      "{} at step {}, t = {} ({} rejected): E {} -> {}, E_mag {} -> {}, equilibrium residual "
      "{:.3g} "
      "-> {:.3g}, r {:.3g}, invariant drift <= {:.2e}, {:.3g} s; wrote {}",
      relaxStopName(result.stop), at.k, at.t, result.steps_rejected,
      first->kinetic_energy + first->magnetic_energy, last.kinetic_energy + last.magnetic_energy,
      first->magnetic_energy, last.magnetic_energy, first->equilibrium_residual,
      last.equilibrium_residual, last.residual, drift_max, runtime_s, s.out.string());
  if (o.plot) {
    const std::string failure = app::runPlotScript(DDB_MHD_PLOT_SCRIPT, s.out);
    if (!failure.empty()) return app::recordFiguresFailure(s.out / "summary.json", failure);
  }
  return app::kExitOk;
}

}  // namespace

int main(int argc, char** argv) { return ddb::app::runMain(ddb::mhd::kApp, runMhd, argc, argv); }
