#include "mhd_relax/options.h"

#include <ddb/groups/dual_number_sun.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <ddb/systems/zeitlin_mhd.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "common/cli.h"
#include "common/exit_status.h"
#include "common/initial_vorticity.h"

namespace ddb::mhd {

namespace {

// A first dissipative step h|α|(‖P₀‖ + ‖B₀‖)(‖W₀‖ + ‖Θ₀‖)/ħ beyond this would overflow the
// Legendre solve's numbers: refused as bad input (as fluid-relax refuses its own), with a margin.
constexpr double kMaxDissipativeStep = 1e150;

/// Warns (valid input only: bad input gives its one line and nothing else) where --t-end is not
/// a whole number of steps.
void warnIfTimeIsNotReached(const CLI::App& cli, const Options& o, const Settings& s) {
  if (cli.count("--t-end") == 0 || s.relax.control.adaptive) return;
  const double t_end = app::parseNumber("--t-end", o.t_end, o.t_end);
  const double reached = static_cast<double>(s.relax.max_steps) * s.h;
  if (std::abs(reached - t_end) > 1e-9 * t_end) {
    spdlog::warn("--t-end {} is not a multiple of --h {}: {} steps end at t = {}", t_end, s.h,
                 s.relax.max_steps, reached);
  }
}

/// Θ₀ from --theta-file (then the generator's flags must not be given), or the low modes.
void readTheta(const CLI::App& cli, const Options& o, Settings& s) {
  const Eigen::Index n = s.W0.rows();
  if (!o.theta_file.empty()) {
    for (const char* flag : {"--theta-scale", "--theta-lmax", "--theta-seed"}) {
      app::rejectIfGiven(cli, flag, "--theta-file");
    }
    s.Theta0 = app::readSuNMatrixFile("--theta-file", o.theta_file, "Theta", {kMaxN, ""});
    if (s.Theta0.rows() != n) {
      app::usageError("--theta-file", o.theta_file,
                      fmt::format("has N = {}; W0's N is {}", s.Theta0.rows(), n));
    }
    s.theta_init = "file";
    return;
  }
  const double scale = app::parseNumber("--theta-scale", o.theta_scale, o.theta_scale);
  if (!(scale >= 0 && scale <= 1e6)) {
    app::usageError("--theta-scale", o.theta_scale, "must be in [0, 1e6]");
  }
  if (o.theta_lmax < 1 || o.theta_lmax > n - 1) {
    app::usageError("--theta-lmax", std::to_string(o.theta_lmax),
                    fmt::format("must be in [1, N - 1 = {}]", n - 1));
  }
  const Eigen::MatrixXcd shape = lowModeVorticity(n, o.theta_lmax, o.theta_seed);
  s.Theta0 = shape * (scale * s.W0.norm() / shape.norm());
  s.theta_init = "low-modes";
}

/// Refuses a first step whose dissipative part would overflow, naming --alpha if the default
/// α would fit, else --h, else the fields.
void requireRepresentableStep(const CLI::App& cli, const Options& o, const Settings& s) {
  const Eigen::Index n = s.W0.rows();
  const ZeitlinMhdHamiltonian hamiltonian(HoppeYauLaplacian(n), n);
  Eigen::MatrixXcd P(n, n), B(n, n);
  hamiltonian.poisson().solve(s.W0, P);
  hamiltonian.poisson().apply(s.Theta0, B);
  const double scale =
      (P.norm() + B.norm()) * (s.W0.norm() + s.Theta0.norm()) / hamiltonian.hbar() * s.h;
  const auto fits = [&](double alpha) { return std::abs(alpha) * scale <= kMaxDissipativeStep; };
  if (fits(s.alpha)) return;
  const std::string why = fmt::format(
      "the dissipative step h|alpha|(|P0| + |B0|)(|W0| + |Theta0|)/hbar = {:.3g} exceeds {:g} "
      "and would overflow",
      std::abs(s.alpha) * scale, kMaxDissipativeStep);
  if (fits(app::parseNumber("--alpha", Options().alpha, Options().alpha))) {
    app::usageError("--alpha", o.alpha, why);
  }
  if (cli.count("--h") > 0) app::usageError("--h", o.h, why);
  app::usageError(o.theta_file.empty() ? "--theta-scale" : "--theta-file",
                  o.theta_file.empty() ? o.theta_scale : o.theta_file, why);
}

}  // namespace

void readStepCap(const CLI::App& cli, const Options& o, Settings& s, bool keep_if_none) {
  const bool by_time = cli.count("--t-end") > 0, by_steps = cli.count("--steps") > 0;
  if (by_time && by_steps) {
    throw app::UsageError("--steps, --t-end: give at most one of them (both given)");
  }
  if (keep_if_none && !by_time && !by_steps) return;
  s.relax.t_end = std::numeric_limits<double>::infinity();
  if (!by_time) {
    const long steps = by_steps ? o.steps : 1000;
    if (steps < 1 || steps > kMaxSteps) {
      app::usageError("--steps", std::to_string(o.steps), "must be in [1, 1e9]");
    }
    s.relax.max_steps = steps;
    return;
  }
  const double t_end = app::parseNumber("--t-end", o.t_end, o.t_end);
  if (!(t_end > 0 && std::isfinite(t_end))) {
    app::usageError("--t-end", o.t_end, "must be finite and > 0");
  }
  if (s.relax.control.adaptive) {
    // --h is only the first step, which the step control grows: the cap is the time.
    s.relax.max_steps = kMaxSteps;
    s.relax.t_end = t_end;
    return;
  }
  const double count = std::round(t_end / s.h);
  if (!(count <= static_cast<double>(kMaxSteps))) {
    app::usageError("--t-end", o.t_end,
                    fmt::format("more than 1e9 steps of h = {} (or give --adaptive, whose --h is "
                                "only the first step)",
                                s.h));
  }
  s.relax.max_steps = std::max(1L, static_cast<long>(count));
}

void rejectFlagsBesideResume(const CLI::App& cli, const Options& o) {
  for (const CLI::Option* option : cli.get_options()) {
    const std::string name = option->get_name();
    if (option->count() == 0 || name.rfind("--", 0) != 0) continue;
    if (name == "--out" && std::filesystem::path(o.out).lexically_normal() ==
                               std::filesystem::path(o.resume).lexically_normal()) {
      continue;
    }
    if (name != "--resume" && name != "--steps" && name != "--t-end" &&
        name != "--checkpoint-every" && name != "--plot" && name != "--quiet" &&
        name != "--verbose") {
      app::usageError(name, option->as<std::string>(),
                      "does not apply to --resume: the checkpoint's run is continued as it was "
                      "defined (give --steps or --t-end for a new cap)");
    }
  }
  if (cli.count("--checkpoint-every") > 0 && o.checkpoint_every < 1) {
    app::usageError("--checkpoint-every", std::to_string(o.checkpoint_every), "must be >= 1");
  }
}

Options resumedOptions(const Options& given, const Options& recorded) {
  Options o = recorded;
  o.steps = given.steps;
  o.t_end = given.t_end;
  o.checkpoint_every = given.checkpoint_every;
  o.plot = given.plot;
  o.log = given.log;
  o.resume = given.resume;
  return o;
}

std::vector<std::pair<std::string, std::string>> mhdMethods() {
  const auto system = makeZeitlinMhd(2, 1.0);
  std::vector<std::pair<std::string, std::string>> methods;
  for (const MethodInfo& m : kMethods) {
    if (methodApplies(m, *system)) methods.emplace_back(m.name, m.description);
  }
  return methods;
}

void addOptions(CLI::App& cli, Options& o) {
  cli.add_option("--n", o.n, "resolution N, 2 <= N <= " + std::to_string(kMaxN))
      ->capture_default_str()
      ->check(app::fitsIn<long>());
  cli.add_option("--alpha", o.alpha,
                 "double-bracket coefficient: > 0 lowers E_kin + E_mag to a magnetic "
                 "equilibrium, 0 is ideal MHD")
      ->capture_default_str();
  cli.add_option("--h", o.h, "time step (with --adaptive: the first one)")->capture_default_str();
  cli.add_option("--steps", o.steps,
                 "number of steps (default 1000; at most one of --steps and "
                 "--t-end)")
      ->check(app::fitsIn<long>());
  cli.add_option("--t-end", o.t_end,
                 "end time: round(T/h) steps, or with --adaptive the time the steps stop at");
  app::addRelaxFlags(cli, o.relax,
                     "stop once r = |ad*_dH mu|/(|dH||mu|) <= TOL, r zero exactly at the "
                     "magnetic equilibria [P, Theta] = 0, [P, W] + [B, Theta] = 0",
                     "the DDB methods; --t-end then caps the time");
  cli.add_option("--method", o.method, "integrator (listed below)")->capture_default_str();
  cli.add_option("--init", o.init, "initial vorticity W0, as fluid-relax's (listed below)")
      ->capture_default_str();
  app::addSeedOption(cli, o.seed, "--init's seed");
  cli.add_option("--init-file", o.init_file,
                 "W0 from a CSV of N rows x 2N columns (row j: Re W[j, :] then Im W[j, :])");
  cli.add_option("--theta-scale", o.theta_scale,
                 "|Theta0|_F / |W0|_F of the generated magnetic potential (0: no field, "
                 "Zeitlin's fluid)")
      ->capture_default_str();
  cli.add_option("--theta-lmax", o.theta_lmax,
                 "the generated Theta0's degrees 1..L, omega_lm normal of deviation 1/l")
      ->capture_default_str()
      ->check(app::fitsIn<long>());
  app::addSeedOption(cli, o.theta_seed, "the generated Theta0's seed", "--theta-seed");
  cli.add_option("--theta-file", o.theta_file, "Theta0 from a CSV in --init-file's layout");
  cli.add_option("--every", o.every, "write every K-th state and the last one")
      ->capture_default_str()
      ->check(app::fitsIn<long>());
  cli.add_option("--checkpoint-every", o.checkpoint_every,
                 "write OUT/checkpoint.ddb every K steps (default: every 5 minutes) and at the end")
      ->check(app::fitsIn<long>());
  cli.add_option("--resume", o.resume,
                 "continue the run in DIR from its checkpoint.ddb, to the bit (with --steps or "
                 "--t-end for a new cap)");
  app::addRunFolderFlags(cli, o.out, o.overwrite);
  cli.add_flag("--plot", o.plot, "render mhd.png (python3 with matplotlib)");
  app::addLogFlags(cli, o.log);
  app::addVersionFlag(cli, kApp);
  cli.footer("\nInitial vorticities (--init):\n" + app::describeChoices(app::initDescriptions()) +
             "\nMethods (--method):\n" + app::describeChoices(mhdMethods()) +
             "\nFiles in --out: history.csv, fluid.hdf5 (W and Theta per row), summary.json, "
             "checkpoint.ddb, W_final.csv, theta_final.csv, mhd.png with --plot\n"
             "(docs/reference/command-lines-and-files.md, \"mhd-relax\").\nExit status: 0 ok, 1 a "
             "step failed or a file could not be written, 2 bad input (nothing written), 130/143 "
             "stopped by SIGINT/SIGTERM (outputs and a checkpoint written; --resume continues).\n");
}

Settings settings(const CLI::App& cli, const Options& o) {
  Settings s;
  const std::vector<std::string> methods = app::namesOf(mhdMethods());
  if (findMethod(o.method) != nullptr &&
      std::find(methods.begin(), methods.end(), o.method) == methods.end()) {
    std::string list;
    for (const std::string& name : methods) list += (list.empty() ? "" : ", ") + name;
    app::usageError("--method", o.method,
                    "does not run on SU(N) x| su(N)* (it is for other groups); valid: " + list);
  }
  app::requireChoice("--method", o.method, methods);
  s.alpha = app::parseNumber("--alpha", o.alpha, o.alpha);
  s.h = app::parseNumber("--h", o.h, o.h);
  if (!(s.h > 0)) app::usageError("--h", o.h, "must be > 0");
  app::readRelaxFlags(o.relax, s.relax);
  readStepCap(cli, o, s, false);
  if (o.every < 1) app::usageError("--every", std::to_string(o.every), "must be >= 1");
  if (cli.count("--checkpoint-every") > 0 && o.checkpoint_every < 1) {
    app::usageError("--checkpoint-every", std::to_string(o.checkpoint_every), "must be >= 1");
  }
  if (o.relax.adaptive && !findMethod(o.method)->keeps_casimirs) {
    app::usageError("--adaptive", o.method,
                    "needs a method that keeps the Casimirs (the DDB family), not this --method");
  }
  if (o.relax.adaptive && s.alpha == 0) {
    app::usageError("--adaptive", o.alpha, "needs --alpha != 0 (the energy must move)");
  }
  app::InitialVorticity initial =
      app::initialVorticity(cli, {o.n, o.seed, o.init, o.init_file}, {kMaxN, ""});
  s.W0 = std::move(initial.W);
  s.init = initial.init;
  readTheta(cli, o, s);
  requireRepresentableStep(cli, o, s);
  warnIfTimeIsNotReached(cli, o, s);
  s.out = o.out;
  return s;
}

}  // namespace ddb::mhd
