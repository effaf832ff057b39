#include "ddb_compare/comparison.h"

#include <ddb/core/group_traits.h>
#include <ddb/integrators/drivers/relax.h>
#include <ddb/integrators/drivers/run.h>
#include <ddb/integrators/drivers/steady_state_probe.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/integrators/methods/reference.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <type_traits>

#include "common/atomic_file.h"
#include "common/energy_rises.h"
#include "common/exit_status.h"
#include "common/logging.h"
#include "common/plot.h"
#include "common/progress.h"
#include "common/run_folder.h"
#include "common/spectrum_drift.h"
#include "ddb_compare/output_files.h"
#include "ddb_compare/report.h"

namespace ddb::compare {

namespace {

// A run shorter than this is timed again (--repeat) for a stable median; a longer one
// is timed once, as it ran.
constexpr double kRepeatBelowSeconds = 1.0;

std::string failedLabel(long step) { return "FAILED at step " + std::to_string(step); }

/// The method's order at α (MethodInfo: with α = 0 the order without dissipation).
int orderAt(const std::string& name, double alpha) {
  const MethodInfo* method = findMethod(name);
  return alpha == 0.0 ? method->order_without_dissipation : method->order;
}

/// --adaptive's checks that need the problem (docs/reference/bad-inputs.md): the step control
/// judges steps by the energy's change, which dissipation must drive.
template <class G>
void requireDissipation(const Options& o, const Settings& s, const Problem<G>& problem) {
  if (problem.alpha == 0) {
    app::usageError("--adaptive", o.alpha, "needs --alpha != 0 (the energy must move)");
  }
  // relax() refuses this too, but only after the files are created.
  SteadyStateProbe<G> probe(*problem.system);
  probe.evaluate(problem.mu0);
  if (probe.energyRate() == 0 && probe.residual() > s.relax.tolerance) {
    app::usageError("--adaptive", o.metric,
                    "needs dissipation: dH/dt = 0 at mu0 where the flow moves (--metric?)");
  }
}

}  // namespace

/// casimir_drift as docs/reference/command-lines-and-files.md defines it, over every state shown to
/// observe(): on fixed-size groups Casimir by Casimir (CasimirDrift, runMethod's own). Outside the
/// unnamed namespace: runComparison's lambdas, of external linkage, capture it (GCC's
/// -Wsubobject-linkage).
template <class G, bool = isDynamicGroup<G>>
class DriftWatch {
 public:
  using Dual = typename G::template Dual<double>;

  DriftWatch(const LiePoissonSystem<G>& system, const Dual& mu0) : casimirs_(system, mu0) {}
  void observe(const Dual& mu) { casimirs_.observe(mu); }
  double value() const { return casimirs_.value(); }

 private:
  CasimirDrift<G> casimirs_;
};

/// On matrix groups, the spectrum's relative change (app::SpectrumDrift), which runMethod
/// does not give: it compares the eigenvalues one by one.
template <class G>
class DriftWatch<G, true> {
 public:
  using Dual = typename G::template Dual<double>;

  DriftWatch(const LiePoissonSystem<G>&, const Dual& mu0) : spectrum_(mu0) {}
  void observe(const Dual& mu) {
    current_ = spectrum_(mu);
    max_ = std::max(max_, current_);
  }
  /// The drift of the state last observed.
  const double& current() const { return current_; }
  double value() const { return max_; }

 private:
  app::SpectrumDrift<G> spectrum_;
  double current_ = 0.0, max_ = 0.0;
};

template <class G>
int runComparison(const Options& o, const Settings& s, const Problem<G>& problem) {
  // Default: every method that applies; an explicit method that does not is bad input.
  // With --adaptive: every one that applies and keeps the Casimirs (the step control's
  // premise, docs/guide/steady-states.md); an explicit one that does not is bad input.
  std::vector<std::string> names;
  for (const auto& name : s.methods) {
    if (!methodApplies(name, *problem.system)) {
      if (!o.methods.empty()) app::usageError("--method", name, "does not apply to " + o.system);
      continue;
    }
    if (s.relax.control.adaptive && !findMethod(name)->keeps_casimirs) {
      if (!o.methods.empty()) {
        app::usageError("--adaptive", name,
                        "needs a method that keeps the Casimirs (the DDB family), not this "
                        "--method");
      }
      continue;
    }
    names.push_back(name);
  }
  if (s.relax.control.adaptive) requireDissipation(o, s, problem);
  std::vector<std::unique_ptr<OneStepMethod<G>>> methods;
  for (const auto& name : names) methods.push_back(makeMethod<G>(name, problem.system));
  const app::RunFolderLock lock =
      app::claimNewRunFolder("--out", o.out, s.out, outputFiles(), o.overwrite, "--overwrite", "");
  // ---- from here on, files are written: failures are exit status 1 ----

  // With --adaptive the cap is the time itself; else the steps of h, which end at t_reached.
  const bool adaptive = s.relax.control.adaptive;
  const double t_reached = adaptive ? s.t_end : static_cast<double>(s.steps) * s.h;
  if (std::abs(t_reached - s.t_end) > 1e-9 * s.t_end) {
    spdlog::warn("--t-end {} is not a multiple of --h {}: {} steps end at t = {}", s.t_end, s.h,
                 s.steps, t_reached);
  }
  const LiePoissonSystem<G>& system = *problem.system;
  using Dual = typename G::template Dual<double>;
  app::Progress progress(o.log.quiet);
  spdlog::info("{}{}: h {}{}, {} to t = {}{}, methods {}", system.name(),
               problem.scenario == "none" ? "" : ", scenario " + problem.scenario, s.h,
               adaptive ? " (first step, adaptive)" : "",
               adaptive ? "capped" : std::to_string(s.steps) + " steps", t_reached,
               s.relax.tolerance > 0 ? fmt::format(", until r <= {}", s.relax.tolerance) : "",
               o.methods.empty() ? "all" : o.methods);
  // Only the matrix groups' steps are BLAS products; the small groups' never reach the BLAS.
  if constexpr (isDynamicGroup<G>) app::warnAboutSlowBlasKernels();

  // err_final's reference: the adaptive solver in one sweep to each run's final time
  // (t_reached but for runs that --until-steady or --adaptive ended elsewhere).
  ReferenceSolver<G> reference_solver(problem.system);
  std::map<double, RunResult<G>> references;
  bool any_failed = false;
  const auto referenceAt = [&](double t) -> const RunResult<G>& {
    auto found = references.find(t);
    if (found != references.end()) return found->second;
    progress.show(fmt::format("reference solution to t = {}", t));
    RunResult<G> reference;
    if (t > 0) {
      reference = runMethod(reference_solver, system, problem.mu0, t, 1);
    } else {
      reference.final = problem.mu0;  // a run stopped at step 0: μ₀ itself
    }
    progress.clear();
    if (!reference.ok()) {
      any_failed = true;
      spdlog::error("reference (for err_final) at t = {} FAILED: {}", t, reference.failure);
    }
    return references.emplace(t, std::move(reference)).first->second;
  };
  if (!s.relaxing()) referenceAt(t_reached);

  Report report(o.repeat);
  for (size_t m = 0; m < names.size(); ++m) {
    const std::string& name = names[m];
    app::AtomicFile csv_file(s.out / (name + ".csv"));
    DriftWatch<G> drift(system, problem.mu0);
    RelaxState at;  // of the state the sink saw last, for the rows' h
    using Csv = std::conditional_t<isDynamicGroup<G>, MatrixTrajectoryCsv<G>, TrajectoryCsv<G>>;
    Csv csv = [&] {
      if constexpr (isDynamicGroup<G>) {
        return Csv(csv_file, system, drift.current(), at);
      } else {
        return Csv(csv_file, system, at);
      }
    }();
    // Every state passes the energy and drift checks; only every K-th reaches the file.
    EveryKth<Dual, Csv> rows(o.every, csv);
    const bool watch_energy =
        app::EnergyRises::applies(findMethod(name)->keeps_casimirs, problem.alpha);
    app::EnergyRises rises;
    const RelaxResult<G> run = relax(*methods[m], system, problem.mu0, s.h, s.relax,
                                     [&](const RelaxState& state, const Dual& mu) {
                                       at = state;
                                       if (watch_energy)
                                         rises.observe(state.k, state.t, state.energy);
                                       drift.observe(mu);
                                       rows(state.k, state.t, mu);
                                       progress.update(name, state.k, s.relax.max_steps, [&] {
                                         return fmt::format("t {:.4g}  h {:.3g}", at.t, at.h);
                                       });
                                     });
    rows.finish();
    csv_file.commit();
    rises.warnIfAny(name);

    // A short run is timed again without output, for a median that is not noise; a fixed-step
    // run as runMethod() runs it (no energy or residual per step).
    double runtime = run.runtime_s;
    int timed_runs = 1;
    if (run.ok() && run.runtime_s < kRepeatBelowSeconds && o.repeat > 1) {
      std::vector<double> runtimes;
      for (int r = 0; r < o.repeat; ++r) {
        progress.show("timing " + name + " (" + std::to_string(r + 1) + "/" +
                      std::to_string(o.repeat) + ")");
        runtimes.push_back(
            s.relaxing() ? relax(*methods[m], system, problem.mu0, s.h, s.relax).runtime_s
                         : runMethod(*methods[m], system, problem.mu0, s.h, s.steps).runtime_s);
      }
      std::sort(runtimes.begin(), runtimes.end());
      runtime = runtimes[runtimes.size() / 2];
      timed_runs = o.repeat;
    }
    progress.clear();

    MethodResult result;
    result.name = name;
    result.final = stateJson(run.final);
    result.order = orderAt(name, problem.alpha);
    result.energy_final = system.energy(run.final);
    result.steps = run.last.k;
    result.t_final = run.last.t;
    if (watch_energy) result.energy_rises = rises.count();
    result.ok = run.ok();
    result.stop = relaxStopName(run.stop);
    result.steady = run.steady();
    result.residual_final = steadyStateResidual(system, run.final);
    result.steps_rejected = run.steps_rejected;
    result.h_final = run.last.h;
    if (run.ok()) {
      const RunResult<G>& reference = referenceAt(run.last.t);
      result.err_final = reference.ok() ? (run.final - reference.final).norm() : NAN;
      result.casimir_drift = drift.value();
      result.runtime_s = runtime;
      result.timed_runs = timed_runs;
      spdlog::info(
          "{:14s} {} at step {}, t = {:.6g}{}: r {:.3e}  err_final {:.3e}  casimir drift "
          "{:.3e}  runtime {:.3g} s",
          name, result.stop, result.steps, result.t_final,
          adaptive ? fmt::format(" ({} rejected)", run.steps_rejected) : "", result.residual_final,
          result.err_final, result.casimir_drift, runtime);
    } else {
      any_failed = true;
      result.failed_step = run.failed_step;
      result.failed_label = failedLabel(run.failed_step);
      result.failure = run.failure;
      spdlog::error("{:14s} {}: {}", name, result.failed_label, run.failure);
    }
    report.add(result);
  }

  if (s.sweep.count > 0) {
    SweepCsv sweep;
    const auto hs = s.sweep.steps();
    for (size_t i = 0; i < hs.size(); ++i) {
      const long n = stepCount(s.t_end, hs[i], "--sweep-h", o.sweep);
      // The reference at the same final time n·h, in one adaptive sweep.
      progress.show("sweep " + std::to_string(i + 1) + "/" + std::to_string(hs.size()) +
                    fmt::format("  h = {}  reference", hs[i]));
      const RunResult<G> exact = runMethod(reference_solver, system, problem.mu0, n * hs[i], 1);
      for (size_t m = 0; m < names.size(); ++m) {
        if (names[m] == "reference") continue;
        const std::string label = "sweep " + std::to_string(i + 1) + "/" +
                                  std::to_string(hs.size()) + fmt::format("  h = {}  ", hs[i]) +
                                  names[m];
        RunOptions options;
        options.progress = [&](long done, long total) { progress.update(label, done, total); };
        DriftWatch<G> drift(system, problem.mu0);
        const RunResult<G> run =
            runMethod(*methods[m], system, problem.mu0, hs[i], n, options,
                      [&](long, double, const auto& mu) { drift.observe(mu); });
        const bool ok = run.ok() && exact.ok();
        if (!run.ok()) {
          progress.clear();
          spdlog::warn("sweep {} h={} {}: {}", names[m], hs[i], failedLabel(run.failed_step),
                       run.failure);
        }
        sweep.add(names[m], hs[i], ok ? (run.final - exact.final).norm() : NAN,
                  run.ok() ? drift.value() : NAN, run.ok() ? run.runtime_s : NAN);
      }
    }
    progress.clear();
    sweep.write(s.out);
  }

  app::Json summary;  // the head of summary.json; the report adds the methods
  summary["system"] = o.system;
  summary["scenario"] = problem.scenario;
  if (!problem.scenario_base.empty()) summary["scenario_base"] = problem.scenario_base;
  summary["version"] = app::projectVersion();
  summary["h"] = s.h;
  summary["t_end"] = t_reached;
  summary["t_end_requested"] = s.t_end;
  summary["steps"] = s.steps;
  summary["every"] = o.every;
  summary["until_steady"] = s.relax.tolerance > 0 ? app::Json(s.relax.tolerance) : app::Json();
  summary["adaptive"] = adaptive;
  summary["adaptive_tol"] = adaptive ? app::Json(s.relax.control.tolerance) : app::Json();
  summary["parameters"] = problem.parameters;
  report.write(s.out, summary);
  spdlog::info("wrote {}", s.out.string());
  if (o.plot) {
    const std::string failure = app::runPlotScript(DDB_PLOT_SCRIPT, s.out);
    if (!failure.empty()) return app::recordFiguresFailure(s.out / "summary.json", failure);
  }
  return any_failed ? app::kExitFailed : app::kExitOk;
}

template int runComparison<SO3>(const Options&, const Settings&, const Problem<SO3>&);
template int runComparison<SE2>(const Options&, const Settings&, const Problem<SE2>&);
template int runComparison<SE3>(const Options&, const Settings&, const Problem<SE3>&);
template int runComparison<SON>(const Options&, const Settings&, const Problem<SON>&);
template int runComparison<SUN>(const Options&, const Settings&, const Problem<SUN>&);

}  // namespace ddb::compare
