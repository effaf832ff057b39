// ddb-compare: compares integrators on the paper's rigid-body scenarios (Section 5;
// docs/conventions.md §3) and on the heavy top and Kirchhoff body, with the command line and
// files of docs/file-formats.md. Bad input: one line naming the flag and value on stderr,
// exit status 2, nothing written. Every file is written under a temporary name and
// renamed. Exit status 1 if an integrator failed (its valid prefix is still written).
#include <ddb/integrators/method_registry.h>
#include <ddb/systems/heavy_top.h>
#include <ddb/systems/kirchhoff.h>
#include <ddb/systems/rigid_body.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>
#include <sstream>

#include "output_files.h"

namespace {

using namespace ddb;
namespace fs = std::filesystem;

[[noreturn]] void usageError(const std::string& flag, const std::string& value,
                             const std::string& why) {
  throw CLI::ValidationError(flag + " = " + value + ": " + why);
}

std::vector<std::string> split(const std::string& list, char separator = ',') {
  std::vector<std::string> items;
  std::stringstream ss(list);
  for (std::string item; std::getline(ss, item, separator);) items.push_back(item);
  return items;
}

double parseNumber(const std::string& flag, const std::string& text, const std::string& item) {
  try {
    size_t used = 0;
    const double v = std::stod(item, &used);
    if (used == item.size() && std::isfinite(v)) return v;
  } catch (const std::exception&) {
  }
  usageError(flag, text, "'" + item + "' is not a finite number");
}

template <int N>
Eigen::Matrix<double, N, 1> parseVector(const std::string& flag, const std::string& text,
                                        const Eigen::Matrix<double, N, 1>& fallback) {
  if (text.empty()) return fallback;
  const auto items = split(text);
  if (items.size() != N) {
    usageError(flag, text, "expected " + std::to_string(N) + " comma-separated numbers");
  }
  Eigen::Matrix<double, N, 1> v;
  for (int i = 0; i < N; ++i) v(i) = parseNumber(flag, text, items[i]);
  return v;
}

// ---- the command line (docs/file-formats.md) ----
struct Options {
  std::string system = "rigid-body", scenario = "A", methods, out = "results", sweep;
  std::string inertia, omega0, mu0, chi, metric, mass;
  double h = 0.1, t_end = 0.0, alpha = 0.5, mgl = 1.0;
  bool t_end_given = false, plot = false, verbose = false, quiet = false;
  int repeat = 5;
};

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

long stepCount(double t_end, double h, const std::string& flag) {
  const double n = std::round(t_end / h);
  if (n > 1e9)
    usageError(flag, app::number(h), "more than 1e9 steps to t-end " + app::number(t_end));
  return std::max(1L, static_cast<long>(n));
}

// ---- one system's problem: the system, μ0, the scenario and its parameters ----
template <class G>
struct Problem {
  std::shared_ptr<const LiePoissonSystem<G>> system;
  typename G::template Dual<double> mu0;
  std::string scenario;
  app::JsonObject parameters;
};

template <class G>
struct Run {
  std::vector<double> times;
  std::vector<typename G::template Dual<double>> states;
  double runtime_s = 0.0;
  std::string failure;
};

template <class G>
Run<G> runMethod(const std::string& name, const Problem<G>& problem, double h, long steps,
                 bool keep_states) {
  Run<G> run;
  auto method = makeMethod<G>(name, problem.system);
  if (keep_states) {
    run.times.reserve(steps + 1);
    run.states.reserve(steps + 1);
  }
  typename G::template Dual<double> last = problem.mu0;
  const auto start = std::chrono::steady_clock::now();
  try {
    integrate(*method, problem.mu0, 0.0, h, steps,
              [&](long k, double t, const typename G::template Dual<double>& mu) {
                if (keep_states || k == steps) {
                  run.times.push_back(t);
                  run.states.push_back(mu);
                }
                last = mu;
              });
  } catch (const SolveFailure& failure) {
    run.failure = failure.what();
    if (!keep_states) run.states.push_back(last);
  }
  run.runtime_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

template <class G>
double casimirDrift(const Problem<G>& problem,
                    const std::vector<typename G::template Dual<double>>& states) {
  const auto c0 = problem.system->casimirs(problem.mu0);
  double drift = 0.0;
  for (const auto& mu : states) {
    const auto c = problem.system->casimirs(mu);
    for (Eigen::Index i = 0; i < c.size(); ++i) {
      const double scale = std::abs(c0(i)) > 0 ? std::abs(c0(i)) : 1.0;
      drift = std::max(drift, std::abs(c(i) - c0(i)) / scale);
    }
  }
  return drift;
}

template <class G>
std::string trajectoryCsv(const Problem<G>& problem, const Run<G>& run) {
  std::string s = "t";
  for (int i = 1; i <= G::kDim; ++i) s += ",m" + std::to_string(i);
  s += ",energy";
  if (G::kNumCasimirs == 1) {
    s += ",casimir";
  } else {
    for (int i = 1; i <= G::kNumCasimirs; ++i) s += ",casimir" + std::to_string(i);
  }
  s += "\n";
  for (size_t k = 0; k < run.states.size(); ++k) {
    const auto& mu = run.states[k];
    s += app::number(run.times[k]);
    for (int i = 0; i < G::kDim; ++i) s += "," + app::number(mu(i));
    s += "," + app::number(problem.system->energy(mu));
    const auto c = problem.system->casimirs(mu);
    for (int i = 0; i < G::kNumCasimirs; ++i) s += "," + app::number(c(i));
    s += "\n";
  }
  return s;
}

class Progress {
 public:
  explicit Progress(bool quiet) : enabled_(!quiet && isatty(STDERR_FILENO)) {}
  void show(const std::string& line) const {
    if (enabled_) std::fprintf(stderr, "\r\033[K%s", line.c_str());
  }
  ~Progress() {
    if (enabled_) std::fprintf(stderr, "\r\033[K");
  }

 private:
  bool enabled_;
};

template <class G>
int compare(const Options& options, const Problem<G>& problem, std::vector<std::string> methods,
            long steps, const Sweep& sweep, const fs::path& out) {
  // Default: every method that applies; an explicit method that does not is bad input.
  for (const auto& name : methods) {
    if (!options.methods.empty() && !methodApplies(name, *problem.system))
      usageError("--method", name, "does not apply to " + problem.system->name());
  }
  methods.erase(std::remove_if(
                    methods.begin(), methods.end(),
                    [&](const std::string& name) { return !methodApplies(name, *problem.system); }),
                methods.end());
  const double h = options.h;
  const Progress progress(options.quiet);
  spdlog::info("{}{}: h {}, {} steps, methods {}", problem.system->name(),
               problem.scenario.empty() ? "" : ", scenario " + problem.scenario, h, steps,
               options.methods.empty() ? "all" : options.methods);

  const Run<G> reference = runMethod<G>("reference", problem, h, steps, true);
  bool any_failed = !reference.failure.empty();
  app::JsonObject method_json, runtime_table;
  std::string table = "| method | runtime (s), median of " + std::to_string(options.repeat) +
                      " | err_final | casimir_drift |\n|---|---|---|---|\n";
  for (const auto& name : methods) {
    progress.show("running " + name);
    Run<G> run = name == "reference" ? reference : runMethod<G>(name, problem, h, steps, true);
    // The runtime is the median of `repeat` in-process runs (the first included).
    std::vector<double> runtimes{run.runtime_s};
    for (int r = 1; r < options.repeat; ++r) {
      progress.show("timing " + name + " (" + std::to_string(r + 1) + "/" +
                    std::to_string(options.repeat) + ")");
      runtimes.push_back(runMethod<G>(name, problem, h, steps, false).runtime_s);
    }
    std::sort(runtimes.begin(), runtimes.end());
    const double median = runtimes[runtimes.size() / 2];
    if (!run.failure.empty()) spdlog::error("{}: {}", name, run.failure);
    any_failed |= !run.failure.empty();
    const auto& last = run.states.back();
    const bool complete = run.failure.empty() && reference.failure.empty();
    const double err_final = complete ? (last - reference.states.back()).norm() : NAN;
    const double drift = casimirDrift(problem, run.states);
    app::JsonObject entry;
    entry
        .add("final",
             app::JsonObject::array(std::vector<double>(last.data(), last.data() + G::kDim)))
        .add("err_final", err_final)
        .add("casimir_drift", drift)
        .add("energy_final", problem.system->energy(last))
        .add("runtime_s", median)
        .add("steps", static_cast<double>(run.states.size() - 1));
    if (!run.failure.empty()) entry.addString("failure", run.failure);
    method_json.add(name, entry.str(4));
    runtime_table.add(name, median);
    char row[256];
    std::snprintf(row, sizeof row, "| %s | %.4g | %.3e | %.3e |\n", name.c_str(), median, err_final,
                  drift);
    table += row;
    app::writeFileAtomically(out / (name + ".csv"), trajectoryCsv(problem, run));
    spdlog::info("{:14s} err_final {:.3e}  casimir drift {:.3e}  runtime {:.3g} s", name, err_final,
                 drift, median);
  }

  if (sweep.count > 0) {
    std::string rows = "method,h,err_final,casimir_drift,runtime_s\n";
    const auto hs = sweep.steps();
    for (size_t i = 0; i < hs.size(); ++i) {
      const long n = stepCount(options.t_end, hs[i], "--sweep-h");
      // The reference at the same final time n·h, in one adaptive sweep.
      const Run<G> exact = runMethod<G>("reference", problem, n * hs[i], 1, false);
      for (const auto& name : methods) {
        if (name == "reference") continue;
        progress.show("sweep " + std::to_string(i + 1) + "/" + std::to_string(hs.size()) +
                      "  h = " + app::number(hs[i]) + "  " + name);
        const Run<G> run = runMethod<G>(name, problem, hs[i], n, true);
        const double err = run.failure.empty() && exact.failure.empty()
                               ? (run.states.back() - exact.states.back()).norm()
                               : NAN;
        if (!run.failure.empty()) spdlog::warn("sweep {} h={}: {}", name, hs[i], run.failure);
        rows += name + "," + app::number(hs[i]) + "," + app::csvNumber(err) + "," +
                app::csvNumber(casimirDrift(problem, run.states)) + "," +
                app::number(run.runtime_s) + "\n";
      }
    }
    app::writeFileAtomically(out / "error_vs_h.csv", rows);
  }

  app::JsonObject summary;
  summary.addString("system", problem.system->name())
      .addString("scenario", problem.scenario.empty() ? "none" : problem.scenario)
      .add("h", h)
      .add("t_end", steps * h)
      .add("parameters", problem.parameters.str(2))
      .add("methods", method_json.str(2))
      .add("runtime_table", runtime_table.str(2));
  app::writeFileAtomically(out / "summary.json", summary.str() + "\n");
  app::writeFileAtomically(out / "runtime_table.md", table);
  spdlog::info("wrote {}", out.string());
  return any_failed ? 1 : 0;
}

int plot(const fs::path& out) {
  const std::string command = "'" + std::string(DDB_PYTHON3) + "' '" +
                              std::string(DDB_PLOT_SCRIPT) + "' '" + out.string() + "'";
  spdlog::info("plotting: {}", command);
  const int status = std::system(command.c_str());
  if (status != 0) spdlog::error("plotting failed (python3 with matplotlib is needed)");
  return status == 0 ? 0 : 1;
}

int runCompare(int argc, char** argv) {
  CLI::App cli{"Compare integrators for double-bracket dissipation (paper, Section 5)"};
  Options o;
  cli.add_option("--system", o.system, "rigid-body | heavy-top | kirchhoff");
  cli.add_option("--scenario", o.scenario, "A | B | C (rigid body; paper, Section 5)");
  cli.add_option("--method", o.methods, "comma-separated methods (default: all)");
  cli.add_option("--h", o.h, "step size");
  auto* t_end = cli.add_option("--t-end", o.t_end, "final time (default: the scenario's, or 30)");
  cli.add_option("--out", o.out, "output folder");
  cli.add_flag("--plot", o.plot, "render PNG figures with matplotlib");
  cli.add_option("--sweep-h", o.sweep, "HMIN:HMAX:COUNT log-spaced step sizes");
  cli.add_option("--repeat", o.repeat, "in-process runs per method for the median runtime");
  cli.add_option("--inertia", o.inertia, "principal moments a,b,c");
  cli.add_option("--alpha", o.alpha, "dissipation scale α (K = α·I or α·diag(metric))");
  cli.add_option("--omega0", o.omega0, "rigid body: initial angular velocity x,y,z");
  cli.add_option("--mgl", o.mgl, "heavy top: m·g·ℓ");
  cli.add_option("--chi", o.chi, "heavy top: centre-of-mass direction x,y,z");
  cli.add_option("--mu0", o.mu0, "heavy top / Kirchhoff: initial momentum (6 numbers)");
  cli.add_option("--metric", o.metric, "heavy top / Kirchhoff: k1,...,k6 (K = α·diag(k))");
  cli.add_option("--mass", o.mass, "Kirchhoff: added masses m1,m2,m3");
  cli.add_flag("--verbose", o.verbose, "debug logging");
  cli.add_flag("--quiet", o.quiet, "errors only");
  try {
    cli.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return cli.exit(e);
  }
  o.t_end_given = t_end->count() > 0;
  spdlog::set_level(o.quiet ? spdlog::level::err
                            : (o.verbose ? spdlog::level::debug : spdlog::level::info));

  // ---- validate everything before writing anything ----
  static const std::map<std::string, std::pair<Eigen::Vector3d, double>> scenarios{
      {"A", {Eigen::Vector3d(1.0, 1.3, 0.5), 30.0}},
      {"B", {Eigen::Vector3d(1.0, 1.3, 0.5), 250.0}},
      {"C", {Eigen::Vector3d(1.0, 1.0, 0.5), 250.0}}};
  const bool rigid = o.system == "rigid-body";
  if (!rigid && o.system != "heavy-top" && o.system != "kirchhoff")
    usageError("--system", o.system, "expected rigid-body, heavy-top or kirchhoff");
  const auto scenario = scenarios.find(o.scenario);
  if (scenario == scenarios.end()) usageError("--scenario", o.scenario, "expected A, B or C");
  if (!std::isfinite(o.h) || o.h <= 0)
    usageError("--h", app::number(o.h), "must be finite and > 0");
  if (!o.t_end_given) o.t_end = rigid ? scenario->second.second : 30.0;
  if (!std::isfinite(o.t_end) || o.t_end <= 0)
    usageError("--t-end", app::number(o.t_end), "must be finite and > 0");
  const long steps = stepCount(o.t_end, o.h, "--h");
  if (!std::isfinite(o.alpha)) usageError("--alpha", app::number(o.alpha), "must be finite");
  if (!std::isfinite(o.mgl)) usageError("--mgl", app::number(o.mgl), "must be finite");
  if (o.repeat < 1) usageError("--repeat", std::to_string(o.repeat), "must be >= 1");
  const Eigen::Vector3d inertia = parseVector<3>(
      "--inertia", o.inertia, rigid ? scenario->second.first : Eigen::Vector3d(1.0, 1.3, 0.5));
  if ((inertia.array() <= 0).any()) usageError("--inertia", o.inertia, "entries must be > 0");
  using Vector6 = Eigen::Matrix<double, 6, 1>;
  const Vector6 metric = parseVector<6>("--metric", o.metric, Vector6::Ones());
  if ((metric.array() < 0).any()) usageError("--metric", o.metric, "entries must be >= 0");
  const Eigen::Vector3d mass = parseVector<3>("--mass", o.mass, Eigen::Vector3d(1.0, 2.0, 3.0));
  if ((mass.array() <= 0).any()) usageError("--mass", o.mass, "entries must be > 0");
  const Eigen::Vector3d omega0 = parseVector<3>("--omega0", o.omega0, Eigen::Vector3d(0, 0.05, 1));
  const Eigen::Vector3d chi = parseVector<3>("--chi", o.chi, Eigen::Vector3d(0, 0, 1));
  const Vector6 top_mu0 =
      (Vector6() << 0.0, 0.065, 0.5, 0.0, std::sin(0.3), std::cos(0.3)).finished();
  const Vector6 kirchhoff_mu0 = (Vector6() << 0.0, 0.065, 0.5, 1.0, 0.0, 0.2).finished();
  const Vector6 mu0 =
      parseVector<6>("--mu0", o.mu0, o.system == "heavy-top" ? top_mu0 : kirchhoff_mu0);
  Sweep sweep;
  if (!o.sweep.empty()) {
    const auto parts = split(o.sweep, ':');
    if (parts.size() != 3) usageError("--sweep-h", o.sweep, "expected HMIN:HMAX:COUNT");
    sweep.h_min = parseNumber("--sweep-h", o.sweep, parts[0]);
    sweep.h_max = parseNumber("--sweep-h", o.sweep, parts[1]);
    const double count = parseNumber("--sweep-h", o.sweep, parts[2]);
    if (!(sweep.h_min > 0) || !(sweep.h_max >= sweep.h_min) || count < 1 || count > 1000 ||
        count != std::floor(count))
      usageError("--sweep-h", o.sweep, "need 0 < HMIN <= HMAX and an integer COUNT in [1, 1000]");
    sweep.count = static_cast<int>(count);
    stepCount(o.t_end, sweep.h_min, "--sweep-h");
  }
  const std::vector<std::string> methods = o.methods.empty() ? methodNames() : split(o.methods);
  if (methods.empty()) usageError("--method", o.methods, "no method given");
  for (const auto& m : methods) {
    if (std::find(methodNames().begin(), methodNames().end(), m) == methodNames().end())
      usageError("--method", m, "unknown method");
  }
  const fs::path out(o.out);
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec || !fs::is_directory(out)) usageError("--out", o.out, "cannot create the folder");
  {
    const auto probe = out / ".ddb-compare-write-test";
    std::ofstream test(probe);
    if (!test) usageError("--out", o.out, "folder is not writable");
    test.close();
    fs::remove(probe, ec);
  }

  int status = 0;
  if (rigid) {
    Problem<SO3> p{makeRigidBody(inertia, o.alpha), inertia.cwiseProduct(omega0), o.scenario, {}};
    p.parameters.add("inertia", app::JsonObject::array({inertia(0), inertia(1), inertia(2)}))
        .add("alpha", o.alpha)
        .add("omega0", app::JsonObject::array({omega0(0), omega0(1), omega0(2)}));
    status = compare(o, p, methods, steps, sweep, out);
  } else {
    const auto vec = [](const auto& v) {
      return app::JsonObject::array(std::vector<double>(v.data(), v.data() + v.size()));
    };
    Problem<SE3> p{nullptr, mu0, "", {}};
    p.parameters.add("inertia", vec(inertia)).add("alpha", o.alpha).add("metric", vec(metric));
    p.parameters.add("mu0", vec(mu0));
    if (o.system == "heavy-top") {
      p.system = makeHeavyTop(inertia, o.mgl, chi, o.alpha, metric);
      p.parameters.add("mgl", o.mgl).add("chi", vec(chi));
    } else {
      p.system = makeKirchhoffBody(inertia, mass, o.alpha, metric);
      p.parameters.add("mass", vec(mass));
    }
    status = compare(o, p, methods, steps, sweep, out);
  }
  if (o.plot) status = std::max(status, plot(out));
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return runCompare(argc, argv);
  } catch (const CLI::ParseError& e) {
    std::cerr << "ddb-compare: " << e.what() << "\n";
    return 2;
  } catch (const ddb::InvalidArgument& e) {
    std::cerr << "ddb-compare: " << e.what() << "\n";
    return 2;
  }
}
