// ddb-compare: compares integrators on the paper's rigid-body scenarios (Section 5;
// docs/conventions.md §3) and on the heavy top and Kirchhoff body, with the command line
// and files of docs/file-formats.md. Exit status (apps/common/exit_status.h): 2 for bad
// input, checked in full before anything is written; 1 if a method failed (its valid
// prefix is still written and it is marked FAILED) or a file could not be written.
#include <ddb/integrators/method_table.h>
#include <ddb/integrators/run.h>
#include <ddb/systems/paper_scenarios.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "common/atomic_file.h"
#include "common/cli.h"
#include "common/csv_row.h"
#include "common/energy_rises.h"
#include "common/exit_status.h"
#include "common/format.h"
#include "common/json.h"
#include "common/logging.h"
#include "common/plot.h"
#include "common/progress.h"

namespace {

using namespace ddb;
namespace fs = std::filesystem;

constexpr const char* kApp = "ddb-compare";
constexpr long kMaxSteps = 1000000000L;
// Messages print doubles with fmt's shortest round-trip form ("0.3"); files use 17
// significant digits (app::number, docs/file-formats.md).
// A run shorter than this is timed again (--repeat) for a stable median; a longer one
// is timed once, as it ran.
constexpr double kRepeatBelowSeconds = 1.0;
constexpr int kMaxRepeat = 1000;

const std::vector<std::pair<std::string, std::string>>& systemDescriptions() {
  static const std::vector<std::pair<std::string, std::string>> systems{
      {"rigid-body", "free rigid body on so(3)*, K = alpha I (paper, Section 5)"},
      {"heavy-top", "heavy top on se(3)*, Hamiltonian-form DDB, K = alpha diag(metric)"},
      {"kirchhoff", "rigid body in ideal fluid on se(3)*, K = alpha diag(metric)"}};
  return systems;
}

std::vector<std::string> scenarioNames() {
  std::vector<std::string> names;
  for (const auto& s : rigidBodyScenarios()) names.push_back(s.name);
  return names;
}

/// Short form of a default for --help: "1,1.3,0.5".
template <class Derived>
std::string shortList(const Eigen::DenseBase<Derived>& v) {
  std::string s;
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    s += (i ? "," : "") + app::number(v.derived()(i), std::chars_format::general, 6);
  }
  return s;
}
std::string shortList(double v) { return shortList(Eigen::Matrix<double, 1, 1>(v)); }

// ---- the command line (docs/file-formats.md) ----
struct Options {
  std::string system = "rigid-body", scenario = "A", methods, out = "results", sweep;
  std::string h = "0.1", t_end, alpha, mgl, inertia, omega0, mu0, chi, metric, mass;
  bool plot = false;
  int repeat = 5;
  long every = 1;
  app::LogFlags log;
};

std::string helpFooter() {
  const RigidBodyScenario& a = rigidBodyScenarios().front();
  const HeavyTopSetup top;
  const KirchhoffSetup kirchhoff;
  return "\nSystems (--system):\n" + app::describeChoices(systemDescriptions()) +
         "\nScenarios (--scenario, rigid body only; alpha " + shortList(a.alpha) + ", omega0 " +
         shortList(a.omega0) + ", M0 = inertia * omega0):\n" +
         [] {
           std::vector<std::pair<std::string, std::string>> lines;
           for (const auto& s : rigidBodyScenarios()) lines.push_back({s.name, s.description});
           return app::describeChoices(lines);
         }() +
         "\nMethods (--method; default: every method that applies to the system):\n" +
         app::describeChoices(methodDescriptions()) + "\nDefaults of the other systems (t-end " +
         shortList(top.t_end) + "):\n  heavy-top  inertia " + shortList(top.inertia) + ", mgl " +
         shortList(top.mgl) + ", chi " + shortList(top.chi) + ", mu0 " + shortList(top.mu0) +
         ", metric " + shortList(top.metric) + ", alpha " + shortList(top.alpha) +
         "\n  kirchhoff  inertia " + shortList(kirchhoff.inertia) + ", mass " +
         shortList(kirchhoff.mass) + ", mu0 " + shortList(kirchhoff.mu0) + ", metric " +
         shortList(kirchhoff.metric) + ", alpha " + shortList(kirchhoff.alpha) +
         "\n\nA parameter that differs from the scenario's is recorded in summary.json, whose "
         "scenario is then \"custom\".\nExit status: 0 ok, 1 a method failed or a file could not "
         "be written, 2 bad input (nothing written).\n";
}

void addOptions(CLI::App& cli, Options& o) {
  const RigidBodyScenario& a = rigidBodyScenarios().front();
  cli.add_option("--system", o.system, "rigid-body | heavy-top | kirchhoff (listed below)")
      ->capture_default_str();
  cli.add_option("--scenario", o.scenario, "A | B | C, rigid body only (listed below)")
      ->capture_default_str();
  cli.add_option("--method", o.methods,
                 "comma-separated methods (default: every one that applies)");
  cli.add_option("--h", o.h, "step size")->capture_default_str();
  cli.add_option("--t-end", o.t_end,
                 "final time (default: the scenario's, A 30, B and C 250; other systems " +
                     shortList(HeavyTopSetup().t_end) +
                     "); rounded to a whole number of steps, with a warning");
  cli.add_option("--every", o.every, "write every K-th state and the last one to <method>.csv")
      ->capture_default_str();
  cli.add_option("--out", o.out, "output folder")->capture_default_str();
  cli.add_flag("--plot", o.plot, "render PNG figures with matplotlib");
  cli.add_option("--sweep-h", o.sweep, "HMIN:HMAX:COUNT log-spaced step sizes -> error_vs_h.csv");
  cli.add_option("--repeat", o.repeat,
                 "timed runs per method for the median runtime, for runs shorter than 1 s")
      ->capture_default_str();
  cli.add_option("--inertia", o.inertia,
                 "principal moments a,b,c (default: scenario A/B " + shortList(a.inertia) + ", C " +
                     shortList(rigidBodyScenarios().back().inertia) + ", other systems " +
                     shortList(HeavyTopSetup().inertia) + ")");
  cli.add_option(
      "--alpha", o.alpha,
      "dissipation scale, K = alpha I or alpha diag(metric) (default " + shortList(a.alpha) + ")");
  cli.add_option(
      "--omega0", o.omega0,
      "rigid body: initial angular velocity x,y,z (default " + shortList(a.omega0) + ")");
  cli.add_option("--mgl", o.mgl,
                 "heavy top: m g l (default " + shortList(HeavyTopSetup().mgl) + ")");
  cli.add_option(
      "--chi", o.chi,
      "heavy top: centre-of-mass direction x,y,z (default " + shortList(HeavyTopSetup().chi) + ")");
  cli.add_option("--mu0", o.mu0, "heavy top, Kirchhoff: initial momentum, 6 numbers (below)");
  cli.add_option("--metric", o.metric,
                 "heavy top, Kirchhoff: k1,...,k6, K = alpha diag(k) (default " +
                     shortList(HeavyTopSetup().metric) + ")");
  cli.add_option(
      "--mass", o.mass,
      "Kirchhoff: added masses m1,m2,m3 (default " + shortList(KirchhoffSetup().mass) + ")");
  app::addLogFlags(cli, o.log);
  app::addVersionFlag(cli, kApp);
  cli.footer(helpFooter());
}

struct Sweep {
  double h_min = 0, h_max = 0;
  int count = 0;
  std::vector<double> steps() const {
    std::vector<double> hs;
    for (int i = 0; i < count; ++i) {
      const double s = count == 1 ? 0.0 : double(i) / (count - 1);
      hs.push_back(h_max * std::pow(h_min / h_max, s));  // log-spaced, largest first
    }
    return hs;
  }
};

/// round(t_end / h), at least 1; more than kMaxSteps is bad input naming `flag` = `text`.
long stepCount(double t_end, double h, const std::string& flag, const std::string& text) {
  const double n = std::round(t_end / h);
  if (n > static_cast<double>(kMaxSteps)) {
    app::usageError(flag, text, fmt::format("more than 1e9 steps of h = {} to t-end {}", h, t_end));
  }
  return std::max(1L, static_cast<long>(n));
}

/// What every system shares, validated.
struct Settings {
  double h = 0.0, t_end = 0.0;
  long steps = 0;
  Sweep sweep;
  std::vector<std::string> methods;
  fs::path out;
};

// ---- one system's problem: the system, μ0, the scenario label and its parameters ----
template <class G>
struct Problem {
  std::shared_ptr<const LiePoissonSystem<G>> system;
  typename G::template Dual<double> mu0;
  std::string scenario;       // "A", "B", "C", "custom" or "none"
  std::string scenario_base;  // the scenario "custom" started from
  double t_end = 0.0;         // the default horizon
  double alpha = 0.0;         // the dissipation scale, for energy_rises
  app::Json parameters = app::Json::object();
};

double optionalNumber(const std::string& flag, const std::string& text, double fallback) {
  return text.empty() ? fallback : app::parseNumber(flag, text, text);
}
template <int N>
Eigen::Matrix<double, N, 1> optionalVector(const std::string& flag, const std::string& text,
                                           const Eigen::Matrix<double, N, 1>& fallback) {
  return text.empty() ? fallback : app::parseVector<N>(flag, text);
}

void requirePositiveEntries(const std::string& flag, const std::string& text,
                            const Eigen::VectorXd& v) {
  if ((v.array() <= 0).any()) app::usageError(flag, text, "entries must be > 0");
}

Problem<SO3> rigidBodyProblem(const CLI::App& cli, const Options& o) {
  for (const char* flag : {"--mgl", "--chi", "--mu0", "--metric", "--mass"}) {
    app::rejectIfGiven(cli, flag, "--system rigid-body");
  }
  app::requireChoice("--scenario", o.scenario, scenarioNames());
  const RigidBodyScenario& base = rigidBodyScenario(o.scenario);
  RigidBodyScenario used = base;
  used.inertia = optionalVector<3>("--inertia", o.inertia, base.inertia);
  requirePositiveEntries("--inertia", o.inertia, used.inertia);
  used.alpha = optionalNumber("--alpha", o.alpha, base.alpha);
  used.omega0 = optionalVector<3>("--omega0", o.omega0, base.omega0);
  const bool custom = !used.sameParameters(base);
  Problem<SO3> p{
      used.system(), used.mu0(), custom ? "custom" : base.name, custom ? base.name : "", base.t_end,
      used.alpha,    {}};
  p.parameters["inertia"] = app::jsonArray(used.inertia);
  p.parameters["alpha"] = used.alpha;
  p.parameters["omega0"] = app::jsonArray(used.omega0);
  p.parameters["mu0"] = app::jsonArray(used.mu0());
  return p;
}

Problem<SE3> se3Problem(const CLI::App& cli, const Options& o) {
  const std::string context = "--system " + o.system;
  for (const char* flag : {"--scenario", "--omega0"}) app::rejectIfGiven(cli, flag, context);
  const bool top = o.system == "heavy-top";
  for (const char* flag :
       top ? std::vector<const char*>{"--mass"} : std::vector<const char*>{"--mgl", "--chi"}) {
    app::rejectIfGiven(cli, flag, context);
  }
  Problem<SE3> p;
  // The parameters both systems share, parsed over `setup`'s defaults and recorded.
  const auto shared = [&](auto setup) {
    const auto defaults = setup;
    setup.inertia = optionalVector<3>("--inertia", o.inertia, defaults.inertia);
    requirePositiveEntries("--inertia", o.inertia, setup.inertia);
    setup.alpha = optionalNumber("--alpha", o.alpha, defaults.alpha);
    setup.mu0 = optionalVector<6>("--mu0", o.mu0, defaults.mu0);
    setup.metric = optionalVector<6>("--metric", o.metric, defaults.metric);
    if ((setup.metric.array() < 0).any()) {
      app::usageError("--metric", o.metric, "entries must be >= 0");
    }
    p.mu0 = setup.mu0;
    p.t_end = setup.t_end;
    p.alpha = setup.alpha;
    p.parameters["inertia"] = app::jsonArray(setup.inertia);
    p.parameters["alpha"] = setup.alpha;
    p.parameters["metric"] = app::jsonArray(setup.metric);
    p.parameters["mu0"] = app::jsonArray(setup.mu0);
    return setup;
  };
  bool custom = false;
  if (top) {
    HeavyTopSetup s = shared(HeavyTopSetup());
    s.mgl = optionalNumber("--mgl", o.mgl, s.mgl);
    s.chi = optionalVector<3>("--chi", o.chi, s.chi);
    custom = !s.sameParameters(HeavyTopSetup());
    p.system = s.system();
    p.parameters["mgl"] = s.mgl;
    p.parameters["chi"] = app::jsonArray(s.chi);
  } else {
    KirchhoffSetup s = shared(KirchhoffSetup());
    s.mass = optionalVector<3>("--mass", o.mass, s.mass);
    requirePositiveEntries("--mass", o.mass, s.mass);
    custom = !s.sameParameters(KirchhoffSetup());
    p.system = s.system();
    p.parameters["mass"] = app::jsonArray(s.mass);
  }
  // These systems have no paper scenario: "none" with the defaults, else "custom".
  p.scenario = custom ? "custom" : "none";
  return p;
}

/// ‖∂f/∂μ‖∞ at μ₀ of the flow μ̇ = f(μ) (core/lie_poisson_system.h), through Jets; inf
/// if H(μ₀), f(μ₀) or a derivative is not finite. Its inverse is the flow's fastest time
/// scale there, which the explicit adaptive reference must resolve.
template <class G>
double flowRate(const LiePoissonSystem<G>& system, const typename G::template Dual<double>& mu0) {
  using Jet = ceres::Jet<double, G::kDim>;
  typename G::template Dual<Jet> mu;
  for (int i = 0; i < G::kDim; ++i) mu(i) = Jet(mu0(i), i);
  if (!std::isfinite(system.energy(mu0))) return INFINITY;
  const auto f = system.vectorField(mu);
  double rate = 0.0;
  for (int i = 0; i < G::kDim; ++i) {
    const double row = f(i).v.cwiseAbs().sum();
    if (!std::isfinite(f(i).a) || !std::isfinite(row)) return INFINITY;
    rate = std::max(rate, row);
  }
  return rate;
}

/// Why the reference cannot follow the flow from μ₀ to t_end in at most kMaxSteps of
/// its time scale 1/rate, or "" if it can. An overflowing or extremely stiff problem
/// (α = 1e308, 𝕀 = 1e-300, μ₀ = 1e200) would otherwise run for hours or fail at step 0.
template <class G>
std::string unresolvable(const Problem<G>& p, double t_end) {
  const double rate = flowRate(*p.system, p.mu0);
  if (rate * t_end <= static_cast<double>(kMaxSteps)) return "";
  return fmt::format(
      "the flow's rate |df/dmu|_inf = {:.3g} at mu0 exceeds 1e9/t-end = {:.3g}: no integrator "
      "resolves it in 1e9 steps",
      rate, static_cast<double>(kMaxSteps) / t_end);
}

/// Bad input if the problem cannot be resolved (unresolvable()), naming the first given
/// flag whose default alone makes it resolvable, else the first given one: the flag
/// whose value made the flow too fast or overflow.
template <class G, class MakeProblem>
void requireResolvable(const Options& o, const Problem<G>& problem, const MakeProblem& make) {
  const auto horizon = [](const Options& options, double fallback) {
    return optionalNumber("--t-end", options.t_end, fallback);
  };
  const std::string why = unresolvable(problem, horizon(o, problem.t_end));
  if (why.empty()) return;
  const std::vector<std::pair<const char*, std::string Options::*>> flags{
      {"--alpha", &Options::alpha},   {"--inertia", &Options::inertia},
      {"--omega0", &Options::omega0}, {"--mu0", &Options::mu0},
      {"--mgl", &Options::mgl},       {"--chi", &Options::chi},
      {"--metric", &Options::metric}, {"--mass", &Options::mass},
      {"--t-end", &Options::t_end}};
  const std::pair<const char*, std::string Options::*>* blamed = nullptr;
  for (const auto& flag : flags) {
    if ((o.*flag.second).empty()) continue;
    Options reverted = o;
    (reverted.*flag.second).clear();
    const auto fixed = make(reverted);
    if (unresolvable(fixed, horizon(reverted, fixed.t_end)).empty()) {
      blamed = &flag;
      break;
    }
    if (blamed == nullptr) blamed = &flag;
  }
  if (blamed == nullptr) throw std::logic_error("the default problem is unresolvable: " + why);
  app::usageError(blamed->first, o.*blamed->second, why);
}

/// h, t-end, steps, sweep and method names; `default_t_end` is the system's or scenario's.
Settings commonSettings(const Options& o, double default_t_end) {
  Settings s;
  s.h = app::parseNumber("--h", o.h, o.h);
  if (!(s.h > 0)) app::usageError("--h", o.h, "must be > 0");
  s.t_end = optionalNumber("--t-end", o.t_end, default_t_end);
  if (!(s.t_end > 0)) app::usageError("--t-end", o.t_end, "must be > 0");
  // The message names both; the flag is --t-end if given (every default t-end takes at
  // most 2500 steps of the default h), else --h.
  s.steps = o.t_end.empty() ? stepCount(s.t_end, s.h, "--h", o.h)
                            : stepCount(s.t_end, s.h, "--t-end", o.t_end);
  // Each timed run is shorter than 1 s: 1000 of them per method bound the timing to
  // minutes, where 1e9 would take years.
  if (o.repeat < 1 || o.repeat > kMaxRepeat) {
    app::usageError("--repeat", std::to_string(o.repeat), "must be in [1, 1000]");
  }
  if (o.every < 1) app::usageError("--every", std::to_string(o.every), "must be >= 1");
  if (!o.sweep.empty()) {
    const auto parts = app::split(o.sweep, ':');
    if (parts.size() != 3) app::usageError("--sweep-h", o.sweep, "expected HMIN:HMAX:COUNT");
    s.sweep.h_min = app::parseNumber("--sweep-h", o.sweep, parts[0]);
    s.sweep.h_max = app::parseNumber("--sweep-h", o.sweep, parts[1]);
    const double count = app::parseNumber("--sweep-h", o.sweep, parts[2]);
    if (!(s.sweep.h_min > 0) || !(s.sweep.h_max >= s.sweep.h_min) || count < 1 || count > 1000 ||
        count != std::floor(count)) {
      app::usageError("--sweep-h", o.sweep,
                      "need 0 < HMIN <= HMAX and an integer COUNT in [1, 1000]");
    }
    s.sweep.count = static_cast<int>(count);
    stepCount(s.t_end, s.sweep.h_min, "--sweep-h", o.sweep);
  }
  s.methods = o.methods.empty() ? methodNames() : app::splitItems("--method", o.methods);
  for (auto m = s.methods.begin(); m != s.methods.end(); ++m) {
    app::requireChoice("--method", *m, methodNames());
    // Twice the same method would write its file twice and its summary entry twice.
    if (std::find(s.methods.begin(), m, *m) != m) {
      app::usageError("--method", o.methods, *m + " is given twice");
    }
  }
  s.out = o.out;
  return s;
}

/// <method>.csv rows as they are computed (docs/file-formats.md): t, μ, energy,
/// Casimirs.
template <class G>
class TrajectoryCsv {
 public:
  using Dual = typename G::template Dual<double>;

  TrajectoryCsv(app::AtomicFile& file, const LiePoissonSystem<G>& system)
      : file_(file), system_(system), row_(G::kDim + 2 + G::kNumCasimirs) {
    std::string header = "t";
    for (int i = 1; i <= G::kDim; ++i) header += ",m" + std::to_string(i);
    header += ",energy";
    if (G::kNumCasimirs == 1) {
      header += ",casimir";
    } else {
      for (int i = 1; i <= G::kNumCasimirs; ++i) header += ",casimir" + std::to_string(i);
    }
    file_.write(header + "\n");
  }

  void operator()(long, double t, const Dual& mu) {
    row_.put(t);
    for (int i = 0; i < G::kDim; ++i) row_.put(mu(i));
    row_.put(system_.energy(mu));
    const auto c = system_.casimirs(mu);
    for (int i = 0; i < G::kNumCasimirs; ++i) row_.put(c(i));
    row_.writeTo(file_);
  }

 private:
  app::AtomicFile& file_;
  const LiePoissonSystem<G>& system_;
  app::CsvRow row_;
};

struct MethodOutcome {
  std::string name;
  bool ok = true;
  double runtime_s = NAN;
  int timed_runs = 1;
};

template <class G>
std::string failedLabel(const RunResult<G>& run) {
  return "FAILED at step " + std::to_string(run.failed_step);
}

template <class G>
int compare(const Options& o, const Settings& s, const Problem<G>& problem) {
  // Default: every method that applies; an explicit method that does not is bad input.
  std::vector<std::string> names;
  for (const auto& name : s.methods) {
    if (methodApplies(name, *problem.system)) {
      names.push_back(name);
    } else if (!o.methods.empty()) {
      app::usageError("--method", name, "does not apply to " + problem.system->name());
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

  app::Json method_json = app::Json::object(), runtime_table = app::Json::object();
  std::string table = "| method | runtime (s), median of up to " + std::to_string(o.repeat) +
                      " runs | err_final | casimir_drift |\n|---|---|---|---|\n";
  for (size_t m = 0; m < names.size(); ++m) {
    const std::string& name = names[m];
    RunOptions options;
    options.progress = [&](long done, long total) { progress.update(name, done, total); };
    app::AtomicFile csv_file(s.out / (name + ".csv"));
    TrajectoryCsv<G> csv(csv_file, system);
    // Every state passes the energy check; only every K-th reaches the file.
    EveryKth<typename G::template Dual<double>, TrajectoryCsv<G>> rows(o.every, csv);
    const bool watch_energy =
        app::EnergyRises::applies(findMethod(name)->keeps_casimirs, problem.alpha);
    app::EnergyRises rises;
    const RunResult<G> run = runMethod(*methods[m], system, problem.mu0, s.h, s.steps, options,
                                       [&](long k, double t, const auto& mu) {
                                         if (watch_energy) rises.observe(k, t, system.energy(mu));
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

    app::Json& entry = method_json[name];
    entry["final"] = app::jsonArray(run.final);
    entry["energy_final"] = system.energy(run.final);
    entry["steps"] = run.steps;
    entry["t_final"] = run.t_final;
    if (watch_energy) entry["energy_rises"] = rises.count();
    if (run.ok()) {
      const double err_final = reference.ok() ? (run.final - reference.final).norm() : NAN;
      entry["status"] = "ok";
      entry["err_final"] = err_final;
      entry["casimir_drift"] = run.casimir_drift;
      entry["runtime_s"] = runtime;
      entry["timed_runs"] = timed_runs;
      runtime_table[name] = runtime;
      table += "| " + name + " | " + app::number(runtime, std::chars_format::general, 4) + " | " +
               app::number(err_final, std::chars_format::scientific, 3) + " | " +
               app::number(run.casimir_drift, std::chars_format::scientific, 3) + " |\n";
      spdlog::info("{:14s} err_final {:.3e}  casimir drift {:.3e}  runtime {:.3g} s", name,
                   err_final, run.casimir_drift, runtime);
    } else {
      // A failed run has no final error, drift or runtime to compare: say FAILED instead.
      any_failed = true;
      entry["status"] = "FAILED";
      entry["failed_step"] = run.failed_step;
      entry["err_final"] = NAN;
      entry["casimir_drift"] = NAN;
      entry["runtime_s"] = NAN;
      entry["failure"] = run.failure;
      runtime_table[name] = failedLabel(run);
      table += "| " + name + " | " + failedLabel(run) + " | - | - |\n";
      spdlog::error("{:14s} {}: {}", name, failedLabel(run), run.failure);
    }
  }

  if (s.sweep.count > 0) {
    std::string rows = "method,h,err_final,casimir_drift,runtime_s\n";
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
        const RunResult<G> run = runMethod(*methods[m], system, problem.mu0, hs[i], n, options);
        const bool ok = run.ok() && exact.ok();
        if (!run.ok()) {
          progress.clear();
          spdlog::warn("sweep {} h={} {}: {}", names[m], hs[i], failedLabel(run), run.failure);
        }
        rows += names[m] + "," + app::number(hs[i]) + "," +
                app::number(ok ? (run.final - exact.final).norm() : NAN) + "," +
                app::number(run.ok() ? run.casimir_drift : NAN) + "," +
                app::number(run.ok() ? run.runtime_s : NAN) + "\n";
      }
    }
    progress.clear();
    app::writeFileAtomically(s.out / "error_vs_h.csv", rows);
  }

  app::Json summary;
  summary["system"] = system.name();
  summary["scenario"] = problem.scenario;
  if (!problem.scenario_base.empty()) summary["scenario_base"] = problem.scenario_base;
  summary["version"] = app::projectVersion();
  summary["h"] = s.h;
  summary["t_end"] = t_reached;
  summary["t_end_requested"] = s.t_end;
  summary["steps"] = s.steps;
  summary["every"] = o.every;
  summary["parameters"] = problem.parameters;
  summary["methods"] = method_json;
  summary["runtime_table"] = runtime_table;
  app::writeJsonFile(s.out / "summary.json", summary);
  app::writeFileAtomically(s.out / "runtime_table.md", table);
  spdlog::info("wrote {}", s.out.string());
  return any_failed ? app::kExitFailed : app::kExitOk;
}

/// Library checks of the problem's data (InvalidArgument) are bad input too.
template <class F>
auto asUsageError(F&& make) {
  try {
    return make();
  } catch (const InvalidArgument& e) {
    throw app::UsageError(e.what());
  }
}

/// Every check of the input, in the order the messages name them, then the comparison.
template <class MakeProblem>
int checkAndCompare(const Options& o, const MakeProblem& make) {
  const auto problem = make(o);
  const Settings settings = commonSettings(o, problem.t_end);
  requireResolvable(o, problem, make);
  return compare(o, settings, problem);
}

int runCompare(int argc, char** argv) {
  CLI::App cli{"Compare integrators for double-bracket dissipation (paper, Section 5)", kApp};
  Options o;
  addOptions(cli, o);
  if (const auto status = app::parseCommandLine(cli, argc, argv)) return *status;
  app::setupLogging(o.log);

  app::requireChoice("--system", o.system, app::namesOf(systemDescriptions()));
  const auto rigidBody = [&](const Options& options) {
    return asUsageError([&] { return rigidBodyProblem(cli, options); });
  };
  const auto se3 = [&](const Options& options) {
    return asUsageError([&] { return se3Problem(cli, options); });
  };
  int status = o.system == "rigid-body" ? checkAndCompare(o, rigidBody) : checkAndCompare(o, se3);
  if (o.plot) status = std::max(status, app::runPlotScript(DDB_PLOT_SCRIPT, o.out));
  return status;
}

}  // namespace

int main(int argc, char** argv) { return ddb::app::runMain(kApp, runCompare, argc, argv); }
