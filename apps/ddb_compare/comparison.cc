#include "ddb_compare/comparison.h"

#include <ddb/core/group_traits.h>
#include <ddb/integrators/method_table.h>
#include <ddb/integrators/reference.h>
#include <ddb/integrators/run.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <type_traits>

#include "common/atomic_file.h"
#include "common/energy_rises.h"
#include "common/exit_status.h"
#include "common/progress.h"
#include "common/spectrum_drift.h"
#include "ddb_compare/report.h"

namespace ddb::compare {

namespace {

// A run shorter than this is timed again (--repeat) for a stable median; a longer one
// is timed once, as it ran.
constexpr double kRepeatBelowSeconds = 1.0;

template <class G>
std::string failedLabel(const RunResult<G>& run) {
  return "FAILED at step " + std::to_string(run.failed_step);
}

/// The method's order at α (MethodInfo: with α = 0 the order without dissipation).
int orderAt(const std::string& name, double alpha) {
  const MethodInfo* method = findMethod(name);
  return alpha == 0.0 ? method->order_without_dissipation : method->order;
}

/// casimir_drift as docs/file-formats.md defines it, over every state shown to
/// observe(). On fixed-size groups it is runMethod's own (Casimir by Casimir).
template <class G, bool = isDynamicGroup<G>>
class DriftWatch {
 public:
  using Dual = typename G::template Dual<double>;

  explicit DriftWatch(const Dual&) {}
  void observe(const Dual&) {}
  double of(const RunResult<G>& run) const { return run.casimir_drift; }
};

/// On matrix groups, the spectrum's relative change (app::SpectrumDrift), which runMethod
/// does not give: it compares the eigenvalues one by one.
template <class G>
class DriftWatch<G, true> {
 public:
  using Dual = typename G::template Dual<double>;

  explicit DriftWatch(const Dual& mu0) : spectrum_(mu0) {}
  void observe(const Dual& mu) {
    current_ = spectrum_(mu);
    max_ = std::max(max_, current_);
  }
  /// The drift of the state last observed.
  const double& current() const { return current_; }
  double of(const RunResult<G>&) const { return max_; }

 private:
  app::SpectrumDrift<G> spectrum_;
  double current_ = 0.0, max_ = 0.0;
};

}  // namespace

template <class G>
int runComparison(const Options& o, const Settings& s, const Problem<G>& problem) {
  // Default: every method that applies; an explicit method that does not is bad input.
  std::vector<std::string> names;
  for (const auto& name : s.methods) {
    if (methodApplies(name, *problem.system)) {
      names.push_back(name);
    } else if (!o.methods.empty()) {
      app::usageError("--method", name, "does not apply to " + o.system);
    }
  }
  std::vector<std::unique_ptr<OneStepMethod<G>>> methods;
  for (const auto& name : names) methods.push_back(makeMethod<G>(name, problem.system));
  app::prepareOutputFolder("--out", o.out, s.out);
  // ---- from here on, files are written: failures are exit status 1 ----

  const double t_reached = static_cast<double>(s.steps) * s.h;
  if (std::abs(t_reached - s.t_end) > 1e-9 * s.t_end) {
    spdlog::warn("--t-end {} is not a multiple of --h {}: {} steps end at t = {}", s.t_end, s.h,
                 s.steps, t_reached);
  }
  const LiePoissonSystem<G>& system = *problem.system;
  app::Progress progress(o.log.quiet);
  spdlog::info("{}{}: h {}, {} steps to t = {}, methods {}", system.name(),
               problem.scenario == "none" ? "" : ", scenario " + problem.scenario, s.h, s.steps,
               t_reached, o.methods.empty() ? "all" : o.methods);

  // err_final's reference: the adaptive solver in one sweep to t_reached.
  progress.show(fmt::format("reference solution to t = {}", t_reached));
  ReferenceSolver<G> reference_solver(problem.system);
  const RunResult<G> reference = runMethod(reference_solver, system, problem.mu0, t_reached, 1);
  progress.clear();
  bool any_failed = !reference.ok();
  if (!reference.ok()) spdlog::error("reference (for err_final) FAILED: {}", reference.failure);

  Report report(o.repeat);
  for (size_t m = 0; m < names.size(); ++m) {
    const std::string& name = names[m];
    RunOptions options;
    options.progress = [&](long done, long total) { progress.update(name, done, total); };
    app::AtomicFile csv_file(s.out / (name + ".csv"));
    DriftWatch<G> drift(problem.mu0);
    using Csv = std::conditional_t<isDynamicGroup<G>, MatrixTrajectoryCsv<G>, TrajectoryCsv<G>>;
    Csv csv = [&] {
      if constexpr (isDynamicGroup<G>) {
        return Csv(csv_file, system, drift.current());
      } else {
        return Csv(csv_file, system);
      }
    }();
    // Every state passes the energy and drift checks; only every K-th reaches the file.
    EveryKth<typename G::template Dual<double>, Csv> rows(o.every, csv);
    const bool watch_energy =
        app::EnergyRises::applies(findMethod(name)->keeps_casimirs, problem.alpha);
    app::EnergyRises rises;
    const RunResult<G> run = runMethod(*methods[m], system, problem.mu0, s.h, s.steps, options,
                                       [&](long k, double t, const auto& mu) {
                                         if (watch_energy) rises.observe(k, t, system.energy(mu));
                                         drift.observe(mu);
                                         rows(k, t, mu);
                                       });
    rows.finish();
    csv_file.commit();
    rises.warnIfAny(name);

    // A short run is timed again without output, for a median that is not noise.
    double runtime = run.runtime_s;
    int timed_runs = 1;
    if (run.ok() && run.runtime_s < kRepeatBelowSeconds && o.repeat > 1) {
      std::vector<double> runtimes;
      for (int r = 0; r < o.repeat; ++r) {
        progress.show("timing " + name + " (" + std::to_string(r + 1) + "/" +
                      std::to_string(o.repeat) + ")");
        runtimes.push_back(runMethod(*methods[m], system, problem.mu0, s.h, s.steps).runtime_s);
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
    result.steps = run.steps;
    result.t_final = run.t_final;
    if (watch_energy) result.energy_rises = rises.count();
    result.ok = run.ok();
    if (run.ok()) {
      result.err_final = reference.ok() ? (run.final - reference.final).norm() : NAN;
      result.casimir_drift = drift.of(run);
      result.runtime_s = runtime;
      result.timed_runs = timed_runs;
      spdlog::info("{:14s} err_final {:.3e}  casimir drift {:.3e}  runtime {:.3g} s", name,
                   result.err_final, result.casimir_drift, runtime);
    } else {
      any_failed = true;
      result.failed_step = run.failed_step;
      result.failed_label = failedLabel(run);
      result.failure = run.failure;
      spdlog::error("{:14s} {}: {}", name, failedLabel(run), run.failure);
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
        DriftWatch<G> drift(problem.mu0);
        const RunResult<G> run =
            runMethod(*methods[m], system, problem.mu0, hs[i], n, options,
                      [&](long, double, const auto& mu) { drift.observe(mu); });
        const bool ok = run.ok() && exact.ok();
        if (!run.ok()) {
          progress.clear();
          spdlog::warn("sweep {} h={} {}: {}", names[m], hs[i], failedLabel(run), run.failure);
        }
        sweep.add(names[m], hs[i], ok ? (run.final - exact.final).norm() : NAN,
                  run.ok() ? drift.of(run) : NAN, run.ok() ? run.runtime_s : NAN);
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
  summary["parameters"] = problem.parameters;
  report.write(s.out, summary);
  spdlog::info("wrote {}", s.out.string());
  return any_failed ? app::kExitFailed : app::kExitOk;
}

template int runComparison<SO3>(const Options&, const Settings&, const Problem<SO3>&);
template int runComparison<SE3>(const Options&, const Settings&, const Problem<SE3>&);
template int runComparison<SON>(const Options&, const Settings&, const Problem<SON>&);
template int runComparison<SUN>(const Options&, const Settings&, const Problem<SUN>&);

}  // namespace ddb::compare
