// fluid-relax: relaxes Zeitlin's SU(N) fluid on the sphere (docs/conventions.md §2) with
// double-bracket dissipation towards a steady flow, with the command line and files of
// docs/file-formats.md ("fluid-relax"). Exit status (apps/common/exit_status.h): 2 for
// bad input, checked in full before anything is written; 1 if a step failed (history.csv
// keeps every state before it) or a file could not be written.
#include <ddb/integrators/method_table.h>
#include <ddb/integrators/relax.h>
#include <ddb/integrators/run.h>
#include <ddb/integrators/steady_state_probe.h>
#include <ddb/systems/spherical_harmonic_basis.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <spdlog/spdlog.h>

#include <algorithm>
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
#include "fluid_relax/fluid_h5.h"
#include "fluid_relax/input.h"
#include "fluid_relax/options.h"
#include "fluid_relax/outputs.h"

namespace {

using namespace ddb;
using namespace ddb::fluid;

int relax(const Options& o, const Settings& s) {
  const Eigen::Index n = s.W0.rows();
  const auto system = makeZeitlinFluid(n, s.alpha);
  const auto& hamiltonian = dynamic_cast<const ZeitlinHamiltonian&>(system->hamiltonian());
  const ZeitlinDiagnostics diagnostics(hamiltonian);
  const auto method = makeMethod<SUN>(o.method, system);
  // The DDB methods' Legendre solver reports its iterations; rk4 has none.
  const auto* legendre = dynamic_cast<const LegendreMethod<Cayley<SUN>>*>(method.get());
  app::prepareOutputFolder("--out", o.out, s.out);
  // ---- from here on, files are written: failures are exit status 1 ----

  spdlog::info("N = {}, alpha = {}, {} init{}, {}: {} steps of h = {}{} to t = {}", n, s.alpha,
               s.init, s.init == "file" ? " " + o.init_file : "", o.method, s.steps, s.h,
               s.default_h ? " (default)" : "", static_cast<double>(s.steps) * s.h);
  const app::SpectrumDrift<SUN> spectrumDrift(s.W0);
  double drift = 0.0, drift_max = 0.0;
  long iterations_total = 0, iterations_max = 0;

  HistoryCsv history_csv(s.out / "history.csv");
  const SphericalHarmonicBasis basis(hamiltonian.laplacian());
  std::optional<FluidH5> h5;  // --h5: every history row's state, too
  if (o.h5 || o.animate) {
    h5 = FluidH5::create(s.out / kFluidH5, h5Attributes(o, s, hamiltonian.hbar()));
  }
  // A row points at the run's current state; the one EveryKth holds back for finish() is
  // the last, which they still point to then.
  // r of each written row (relax() evaluates it only for --until-steady or --adaptive).
  SteadyStateProbe<SUN> rowProbe(*system);
  auto historyRow = [&](long k, double t, const std::pair<const RelaxState*, const Matrix*>& at) {
    const Matrix& W = *at.second;
    rowProbe.evaluate(W);
    const double energy = diagnostics.energy(W), enstrophy = diagnostics.enstrophy(W),
                 commutator = diagnostics.commutatorNorm(W);
    history_csv.write(t, energy, enstrophy, commutator, drift, at.first->h, rowProbe.residual());
    if (h5) h5->append({k, t, W, basis.coefficients(W), energy, enstrophy, commutator, drift});
  };
  EveryKth<std::pair<const RelaxState*, const Matrix*>, decltype(historyRow)> history(o.every,
                                                                                      historyRow);

  const bool watch_energy =
      app::EnergyRises::applies(findMethod(o.method)->keeps_casimirs, s.alpha);
  app::EnergyRises rises;
  app::Progress progress(o.log.quiet);
  const std::string label = o.method + " N=" + std::to_string(n);
  const RelaxResult<SUN> run =
      ddb::relax(*method, *system, s.W0, s.h, s.relax, [&](const RelaxState& at, const Matrix& W) {
        if (at.k > 0 && legendre != nullptr) {
          const auto& stats = legendre->legendreSolver().stats();
          const long iterations = stats.fixed_point + stats.newton;
          iterations_total += iterations;
          iterations_max = std::max(iterations_max, iterations);
        }
        if (watch_energy) rises.observe(at.k, at.t, at.energy);
        drift = spectrumDrift(W);
        drift_max = std::max(drift_max, drift);
        history(at.k, at.t, {&at, &W});
        progress.update(label, at.k, s.relax.max_steps, [&] {
          return fmt::format("E {:.6g}  |[P,W]| {:.3g}  h {:.3g}", at.energy,
                             diagnostics.commutatorNorm(W), at.h);
        });
      });
  history.finish();
  history_csv.commit();
  if (h5) h5->flush();
  progress.clear();
  rises.warnIfAny(o.method);

  const double commutator_final = diagnostics.commutatorNorm(run.final);
  const double residual_final = steadyStateResidual(*system, run.final);
  app::Json summary;
  summary["version"] = app::projectVersion();
  summary["status"] = run.ok() ? "ok" : "FAILED";
  summary["n"] = n;
  summary["alpha"] = s.alpha;
  summary["h"] = s.h;
  summary["h_source"] = s.default_h ? "default" : "--h";
  summary["steps"] = run.last.k;
  summary["steps_requested"] = s.steps;
  summary["t_end"] = run.last.t;
  summary["stop"] = relaxStopName(run.stop);
  summary["steady"] = run.steady();
  summary["until_steady"] = s.relax.tolerance > 0 ? app::Json(s.relax.tolerance) : app::Json();
  summary["residual_final"] = residual_final;
  summary["adaptive"] = s.relax.control.adaptive;
  summary["adaptive_tol"] =
      s.relax.control.adaptive ? app::Json(s.relax.control.tolerance) : app::Json();
  summary["steps_rejected"] = run.steps_rejected;
  summary["h_final"] = run.last.h;
  summary["every"] = o.every;
  summary["method"] = o.method;
  summary["init"] = s.init;
  summary["seed"] = s.init == "file" ? app::Json() : app::Json(o.seed);
  summary["init_file"] = s.init == "file" ? app::Json(o.init_file) : app::Json();
  summary["energy_initial"] = diagnostics.energy(s.W0);
  summary["energy_final"] = diagnostics.energy(run.final);
  summary["enstrophy_initial"] = diagnostics.enstrophy(s.W0);
  summary["enstrophy"] = diagnostics.enstrophy(run.final);
  summary["spectrum_drift_max"] = drift_max;
  summary["commutator_initial"] = diagnostics.commutatorNorm(s.W0);
  summary["commutator_final"] = commutator_final;
  summary["runtime_s"] = run.runtime_s;
  summary["iterations_mean"] =
      run.last.k > 0 ? static_cast<double>(iterations_total) / run.last.k : 0.0;
  summary["iterations_max"] = iterations_max;
  if (watch_energy) summary["energy_rises"] = rises.count();
  if (!run.ok()) {
    // A failed run writes no final state: W_final.csv and omega_final.csv would claim a
    // time the run did not reach (docs/file-formats.md).
    summary["failed_step"] = run.failed_step;
    summary["failure"] = run.failure;
    app::writeJsonFile(s.out / "summary.json", summary);
    spdlog::error("{}", run.failure);
    spdlog::error("history.csv holds the {} steps before the failure; wrote {}", run.last.k,
                  s.out.string());
    return app::kExitFailed;
  }
  writeMatrixCsv(s.out / "W_final.csv", run.final);
  writeOmegaCsv(s.out / "omega_initial.csv", basis, s.W0);
  writeOmegaCsv(s.out / "omega_final.csv", basis, run.final);
  app::writeJsonFile(s.out / "summary.json", summary);
  spdlog::info(
      "{} at step {}, t = {} ({} rejected): E {} -> {}, |[P,W]| {} -> {}, r {:.3g}, spectrum "
      "drift <= {:.2e}, {:.3g} s; wrote {}",
      relaxStopName(run.stop), run.last.k, run.last.t, run.steps_rejected, diagnostics.energy(s.W0),
      diagnostics.energy(run.final), diagnostics.commutatorNorm(s.W0), commutator_final,
      residual_final, drift_max, run.runtime_s, s.out.string());
  return app::kExitOk;
}

int runRelax(int argc, char** argv) {
  CLI::App cli{"Relax Zeitlin's SU(N) fluid on the sphere with double-bracket dissipation", kApp};
  Options o;
  addOptions(cli, o);
  if (const auto status = app::parseCommandLine(cli, argc, argv)) return *status;
  app::setupLogging(o.log);
  const Settings s = settings(cli, o);
  const int status = relax(o, s);
  if (status != app::kExitOk) {
    if (o.plot || o.animate) spdlog::error("no figures: the run failed");
    return status;
  }
  int figures = app::kExitOk;
  if (o.animate) {
    figures = app::runPlotScript(DDB_ANIMATE_SCRIPT,
                                 {(s.out / kFluidH5).string(), (s.out / "fluid.mp4").string()});
  }
  if (o.plot) figures = std::max(figures, app::runPlotScript(DDB_PLOT_SCRIPT, s.out));
  return figures;
}

}  // namespace

int main(int argc, char** argv) {
  return ddb::app::runMain(ddb::fluid::kApp, runRelax, argc, argv);
}
