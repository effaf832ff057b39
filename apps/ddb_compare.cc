// ddb-compare: compares integrators on the paper's rigid-body scenarios (Section 5;
// DESIGN.md §3 and the command-line contract of §5). Writes <method>.csv (one row
// per step) and summary.json into --out. Bad input: one line naming the flag and
// value on stderr, exit status 2, nothing written.
#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <sstream>

#include "integrators/method_registry.h"
#include "output_files.h"
#include "systems/rigid_body.h"

namespace {

using namespace ddb;
using Vector3 = Eigen::Vector3d;

struct Scenario {
  Vector3 inertia;
  double t_end;
};

// DESIGN.md §3 (paper, Section 5): α = 0.5, Ω0 = (0, 0.05, 1) in all three.
const std::map<std::string, Scenario> kScenarios{
    {"A", {Vector3(1.0, 1.3, 0.5), 30.0}},
    {"B", {Vector3(1.0, 1.3, 0.5), 250.0}},
    {"C", {Vector3(1.0, 1.0, 0.5), 250.0}},
};

[[noreturn]] void usageError(const std::string& flag, const std::string& value,
                             const std::string& why) {
  throw CLI::ValidationError(flag + " = " + value + ": " + why);
}

std::vector<std::string> split(const std::string& list) {
  std::vector<std::string> items;
  std::stringstream ss(list);
  for (std::string item; std::getline(ss, item, ',');) items.push_back(item);
  return items;
}

Vector3 parseVector3(const std::string& flag, const std::string& text) {
  const auto items = split(text);
  if (items.size() != 3) usageError(flag, text, "expected 3 comma-separated numbers");
  Vector3 v;
  for (int i = 0; i < 3; ++i) {
    try {
      size_t used = 0;
      v(i) = std::stod(items[i], &used);
      if (used != items[i].size()) throw std::invalid_argument(items[i]);
    } catch (const std::exception&) {
      usageError(flag, text, "'" + items[i] + "' is not a number");
    }
    if (!std::isfinite(v(i))) usageError(flag, text, "entries must be finite");
  }
  return v;
}

struct MethodResult {
  std::string name;
  std::vector<double> times;
  std::vector<Vector3> states;
  double runtime_s = 0.0;
  std::string failure;
};

MethodResult run(const std::string& name, std::shared_ptr<const LiePoissonSystem<SO3>> body,
                 const Vector3& m0, double h, long steps) {
  MethodResult result;
  result.name = name;
  auto method = makeMethod<SO3>(name, body);
  result.times.reserve(steps + 1);
  result.states.reserve(steps + 1);
  const auto start = std::chrono::steady_clock::now();
  try {
    integrate(*method, m0, 0.0, h, steps, [&](long, double t, const Vector3& mu) {
      result.times.push_back(t);
      result.states.push_back(mu);
    });
  } catch (const SolveFailure& failure) {
    result.failure = failure.what();
    spdlog::error("{}: {}", name, failure.what());
  }
  result.runtime_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

std::string csv(const MethodResult& r, const LiePoissonSystem<SO3>& body) {
  std::string s = "t,m1,m2,m3,energy,casimir\n";
  for (size_t k = 0; k < r.states.size(); ++k) {
    const Vector3& m = r.states[k];
    s += app::number(r.times[k]) + "," + app::number(m(0)) + "," + app::number(m(1)) + "," +
         app::number(m(2)) + "," + app::number(body.energy(m)) + "," +
         app::number(body.casimirs(m)(0)) + "\n";
  }
  return s;
}

int runCompare(int argc, char** argv) {
  CLI::App app{"Compare integrators for double-bracket dissipation (paper, Section 5)"};
  std::string system = "rigid-body", scenario_name = "A", method_list, out = "results";
  std::string inertia_text, omega0_text;
  double h = 0.1, t_end = 0.0, alpha = 0.5;
  bool verbose = false, quiet = false;
  app.add_option("--system", system, "rigid-body");
  app.add_option("--scenario", scenario_name, "A, B or C (paper, Section 5)");
  app.add_option("--method", method_list, "comma-separated methods (default: all)");
  app.add_option("--h", h, "step size");
  auto* t_end_option = app.add_option("--t-end", t_end, "final time (default: the scenario's)");
  app.add_option("--out", out, "output folder");
  app.add_option("--inertia", inertia_text, "principal moments a,b,c (override the scenario)");
  auto* alpha_option = app.add_option("--alpha", alpha, "dissipation α (K = αI)");
  app.add_option("--omega0", omega0_text, "initial angular velocity x,y,z");
  app.add_flag("--verbose", verbose, "debug logging");
  app.add_flag("--quiet", quiet, "errors only");
  app.parse(argc, argv);
  spdlog::set_level(quiet ? spdlog::level::err
                          : (verbose ? spdlog::level::debug : spdlog::level::info));

  // ---- validate everything before writing anything ----
  if (system != "rigid-body") usageError("--system", system, "supported: rigid-body");
  const auto scenario = kScenarios.find(scenario_name);
  if (scenario == kScenarios.end()) usageError("--scenario", scenario_name, "expected A, B or C");
  if (!std::isfinite(h) || h <= 0) usageError("--h", app::number(h), "must be finite and > 0");
  if (t_end_option->count() == 0) t_end = scenario->second.t_end;
  if (!std::isfinite(t_end) || t_end <= 0)
    usageError("--t-end", app::number(t_end), "must be finite and > 0");
  const double step_count = std::round(t_end / h);
  if (step_count > 1e9)
    usageError("--h", app::number(h), "more than 1e9 steps to --t-end " + app::number(t_end));
  const long steps = std::max(1L, static_cast<long>(step_count));
  const Vector3 inertia =
      inertia_text.empty() ? scenario->second.inertia : parseVector3("--inertia", inertia_text);
  if ((inertia.array() <= 0).any()) usageError("--inertia", inertia_text, "entries must be > 0");
  if (alpha_option->count() && !std::isfinite(alpha))
    usageError("--alpha", app::number(alpha), "must be finite");
  const Vector3 omega0 =
      omega0_text.empty() ? Vector3(0.0, 0.05, 1.0) : parseVector3("--omega0", omega0_text);
  std::vector<std::string> methods = method_list.empty() ? methodNames() : split(method_list);
  for (const auto& m : methods) {
    if (std::find(methodNames().begin(), methodNames().end(), m) == methodNames().end())
      usageError("--method", m, "unknown method");
  }
  const std::filesystem::path out_dir(out);
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec || !std::filesystem::is_directory(out_dir))
    usageError("--out", out, "cannot create the folder");
  {
    const auto probe = out_dir / ".ddb-compare-write-test";
    std::ofstream test(probe);
    if (!test) usageError("--out", out, "folder is not writable");
    test.close();
    std::filesystem::remove(probe, ec);
  }

  const auto body = makeRigidBody(inertia, alpha);
  const Vector3 m0 = inertia.cwiseProduct(omega0);
  spdlog::info("rigid body, scenario {}: inertia ({}, {}, {}), alpha {}, h {}, {} steps",
               scenario_name, inertia(0), inertia(1), inertia(2), alpha, h, steps);

  const MethodResult reference = run("reference", body, m0, h, steps);
  app::JsonObject method_json;
  bool any_failed = !reference.failure.empty();
  for (const auto& name : methods) {
    const MethodResult r = name == "reference" ? reference : run(name, body, m0, h, steps);
    any_failed |= !r.failure.empty();
    const Vector3& last = r.states.back();
    const double c0 = body->casimirs(m0)(0);
    double drift = 0.0;
    for (const auto& m : r.states) drift = std::max(drift, std::abs(body->casimirs(m)(0) - c0) / c0);
    const bool complete = r.failure.empty() && reference.failure.empty();
    const double err_final = complete ? (last - reference.states.back()).norm() : NAN;
    app::JsonObject entry;
    entry.add("final", app::JsonObject::array({last(0), last(1), last(2)}))
        .add("err_final", err_final)
        .add("casimir_drift", drift)
        .add("energy_final", body->energy(last))
        .add("runtime_s", r.runtime_s)
        .add("steps", static_cast<double>(r.states.size() - 1));
    if (!r.failure.empty()) entry.addString("failure", r.failure);
    method_json.add(name, entry.str(4));
    app::writeFileAtomically(out_dir / (name + ".csv"), csv(r, *body));
    spdlog::info("{:14s} err_final {:.3e}  casimir drift {:.3e}  runtime {:.4f} s", name,
                 err_final, drift, r.runtime_s);
  }
  app::JsonObject summary;
  summary.addString("system", system)
      .addString("scenario", scenario_name)
      .add("h", h)
      .add("t_end", steps * h)
      .add("methods", method_json.str(2));
  app::writeFileAtomically(out_dir / "summary.json", summary.str() + "\n");
  spdlog::info("wrote {}", out_dir.string());
  return any_failed ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return runCompare(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) {  // --help
      std::cout << e.what();
      return 0;
    }
    std::cerr << "ddb-compare: " << e.what() << "\n";
    return 2;
  } catch (const ddb::InvalidArgument& e) {
    std::cerr << "ddb-compare: " << e.what() << "\n";
    return 2;
  }
}
