#include "ddb_compare/options.h"

#include <ddb/integrators/methods/method_table.h>
#include <ddb/systems/paper_scenarios.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>

#include "common/format.h"
#include "common/initial_vorticity.h"
#include "ddb_compare/matrix_problems.h"
#include "ddb_compare/system_table.h"

namespace ddb::compare {

namespace {

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

/// A system flag's help: the systems that take it (the system table), then `text`.
std::string forSystems(std::string_view flag, const std::string& text) {
  return systemsTaking(flag) + ": " + text;
}

/// --system's help: the table's names.
std::string systemHelp() {
  std::string names;
  for (const SystemRow& row : systemTable()) {
    names += (names.empty() ? "" : " | ") + std::string(row.name);
  }
  return names + " (listed below)";
}

std::string helpFooter() {
  const RigidBodyScenario& a = rigidBodyScenarios().front();
  const HeavyTopSetup top;
  const KirchhoffSetup kirchhoff;
  const PlanarKirchhoffSetup planar;
  return "\nSystems (--system):\n" + app::describeChoices(systemDescriptions()) +
         "\nScenarios (--scenario, rigid body only; alpha " + shortList(a.alpha) + ", omega0 " +
         shortList(a.omega0) + ", M0 = inertia * omega0):\n" +
         [] {
           std::vector<std::pair<std::string, std::string>> lines;
           for (const auto& s : rigidBodyScenarios()) lines.push_back({s.name, s.description});
           return app::describeChoices(lines);
         }() +
         "\nMethods (--method; default: every method that applies to the system):\n" +
         app::describeChoices(methodDescriptions()) +
         "On manakov and zeitlin: " + methodList(kMatrixGroups) +
         "\n\nDefaults of the other systems (heavy-top, kirchhoff and planar-kirchhoff: t-end " +
         shortList(top.t_end) + "):\n  heavy-top  inertia " + shortList(top.inertia) + ", mgl " +
         shortList(top.mgl) + ", chi " + shortList(top.chi) + ", mu0 " + shortList(top.mu0) +
         ", metric " + shortList(top.metric) + ", alpha " + shortList(top.alpha) +
         "\n  kirchhoff  inertia " + shortList(kirchhoff.inertia) + ", mass " +
         shortList(kirchhoff.mass) + ", mu0 " + shortList(kirchhoff.mu0) + ", metric " +
         shortList(kirchhoff.metric) + ", alpha " + shortList(kirchhoff.alpha) +
         "\n  planar-kirchhoff  inertia " + shortList(planar.inertia) + ", mass " +
         shortList(planar.mass) + ", mu0 " + shortList(planar.mu0) + ", metric " +
         shortList(planar.metric) + ", alpha " + shortList(planar.alpha) + "\n  manakov    n " +
         std::to_string(kManakovDefaultN) +
         ", j_i = 1 + (i-1)/(n-1) (1 to 2), M0 the real part of the seeded random vorticity "
         "scaled to |M0|_F = sqrt(n), alpha " +
         shortList(kMatrixDefaultAlpha) + ", t-end " + shortList(kMatrixDefaultTEnd) +
         "\n  zeitlin    n " + std::to_string(kZeitlinDefaultN) + ", init random, alpha " +
         shortList(kMatrixDefaultAlpha) + ", t-end " + shortList(kMatrixDefaultTEnd) +
         "\n  manakov and zeitlin: 2 <= n <= " + std::to_string(kMaxMatrixN) +
         " (the reference's cost grows as n^3); seed 1\n"
         "\nInitial vorticities (--init, zeitlin; scaled to ||W||_F = sqrt(n), seeded by "
         "--seed):\n" +
         app::describeChoices(app::initDescriptions()) +
         "\nA parameter that differs from the scenario's is recorded in summary.json, whose "
         "scenario is then \"custom\".\nExit status: 0 ok, 1 a method failed or a file could not "
         "be written, 2 bad input (nothing written).\n";
}

}  // namespace

void addOptions(CLI::App& cli, Options& o) {
  const RigidBodyScenario& a = rigidBodyScenarios().front();
  cli.add_option("--system", o.system, systemHelp())->capture_default_str();
  cli.add_option("--scenario", o.scenario, forSystems("--scenario", "A | B | C (listed below)"))
      ->capture_default_str();
  cli.add_option("--method", o.methods,
                 "comma-separated methods (default: every one that applies)");
  cli.add_option("--h", o.h, "step size")->capture_default_str();
  cli.add_option("--t-end", o.t_end,
                 "final time (default: the scenario's, A 30, B and C 250; other systems " +
                     shortList(HeavyTopSetup().t_end) + ", manakov and zeitlin " +
                     shortList(kMatrixDefaultTEnd) +
                     "); rounded to a whole number of steps, with a warning");
  app::addRelaxFlags(cli, o.relax,
                     "stop each method at the first state with r = |ad*_xi mu|/(|xi| |mu|) <= "
                     "TOL, 0 < TOL < 1 (docs/guide/steady-states.md); --t-end is then the cap",
                     "choose h by the energy (docs/guide/steady-states.md): the methods that keep "
                     "the Casimirs, alpha != 0; --h is the first step, --t-end caps the time");
  cli.add_option("--every", o.every, "write every K-th state and the last one to <method>.csv")
      ->capture_default_str()
      ->check(app::fitsIn<decltype(o.every)>());
  app::addRunFolderFlags(cli, o.out, o.overwrite);
  cli.add_flag("--plot", o.plot, "render PNG figures with matplotlib");
  cli.add_option("--sweep-h", o.sweep, "HMIN:HMAX:COUNT log-spaced step sizes -> error_vs_h.csv");
  cli.add_option("--repeat", o.repeat,
                 "timed runs per method for the median runtime, for runs shorter than 1 s")
      ->capture_default_str()
      ->check(app::fitsIn<decltype(o.repeat)>());
  cli.add_option(
      "--inertia", o.inertia,
      forSystems("--inertia",
                 "principal moments a,b,c (default: scenario A/B " + shortList(a.inertia) + ", C " +
                     shortList(rigidBodyScenarios().back().inertia) + ", heavy-top and kirchhoff " +
                     shortList(HeavyTopSetup().inertia) +
                     "; planar-kirchhoff: one moment, default " +
                     shortList(PlanarKirchhoffSetup().inertia) + ")"));
  cli.add_option(
      "--alpha", o.alpha,
      "dissipation scale, K = alpha I or alpha diag(metric) (default " + shortList(a.alpha) + ")");
  cli.add_option("--omega0", o.omega0,
                 forSystems("--omega0", "initial angular velocity x,y,z (default " +
                                            shortList(a.omega0) + ")"));
  cli.add_option("--mgl", o.mgl,
                 forSystems("--mgl", "m g l (default " + shortList(HeavyTopSetup().mgl) + ")"));
  cli.add_option("--chi", o.chi,
                 forSystems("--chi", "centre-of-mass direction x,y,z (default " +
                                         shortList(HeavyTopSetup().chi) + ")"));
  cli.add_option("--mu0", o.mu0,
                 forSystems("--mu0", "initial momentum, 6 numbers (planar-kirchhoff: 3; below)"));
  cli.add_option("--metric", o.metric,
                 forSystems("--metric",
                            "k1,...,k6 (planar-kirchhoff: k1,k2,k3), K = alpha "
                            "diag(k) (default all 1)"));
  cli.add_option(
      "--mass", o.mass,
      forSystems("--mass", "added masses m1,m2,m3 (default " + shortList(KirchhoffSetup().mass) +
                               "; planar-kirchhoff: m1,m2, default " +
                               shortList(PlanarKirchhoffSetup().mass) + ")"));
  cli.add_option("--n", o.n,
                 forSystems("--n", "N of SO(N) or SU(N), 2 <= N <= " + std::to_string(kMaxMatrixN) +
                                       " (default manakov " + std::to_string(kManakovDefaultN) +
                                       ", zeitlin " + std::to_string(kZeitlinDefaultN) + ")"))
      ->check(app::fitsIn<decltype(o.n)>());
  cli.add_option("--j", o.j,
                 forSystems("--j",
                            "J1,...,JN > 0, inertia operator J Omega + Omega J (default "
                            "J_i = 1 + (i-1)/(N-1))"));
  cli.add_option("--mu0-file", o.mu0_file,
                 forSystems("--mu0-file",
                            "initial momentum M0 from a CSV of N rows x N columns, real "
                            "skew-symmetric (default: seeded by --seed)"));
  app::addSeedOption(cli, o.seed, forSystems("--seed", "seed of the initial state"));
  cli.add_option("--init", o.init, forSystems("--init", "initial vorticity (listed below)"))
      ->capture_default_str();
  cli.add_option("--init-file", o.init_file,
                 forSystems("--init-file",
                            "W0 from a CSV of N rows x 2N columns (row j: Re W[j,:] then "
                            "Im W[j,:]), fluid-relax's layout"));
  app::addLogFlags(cli, o.log);
  app::addVersionFlag(cli, kApp);
  cli.footer(helpFooter());
}

long stepCount(double t_end, double h, const std::string& flag, const std::string& text) {
  const double n = std::round(t_end / h);
  if (n > static_cast<double>(kMaxSteps)) {
    // --sweep-h's steps are fixed; --h and --t-end may be a first step and a time cap instead.
    const char* adaptive = flag == "--sweep-h" ? ""
                                               : " (or give --adaptive, whose --h is only "
                                                 "the first step)";
    app::usageError(flag, text,
                    fmt::format("more than 1e9 steps of h = {} to t-end {}{}", h, t_end, adaptive));
  }
  return std::max(1L, static_cast<long>(n));
}

double optionalNumber(const std::string& flag, const std::string& text, double fallback) {
  return text.empty() ? fallback : app::parseNumber(flag, text, text);
}

namespace {

/// --until-steady, --adaptive and --adaptive-tol into s.relax, with the caps, as
/// fluid-relax reads them (docs/reference/command-lines-and-files.md); the checks that need the
/// problem (the methods, alpha) are runComparison's.
void readRelaxOptions(const Options& o, Settings& s) {
  app::readRelaxFlags(o.relax, s.relax);
  // The sweep compares fixed steps at equal times; a relaxed run ends at its own time.
  if (s.sweep.count > 0 && s.relaxing()) {
    app::usageError("--sweep-h", o.sweep, "not with --until-steady or --adaptive");
  }
  // Without --adaptive every step has h and the step count is the cap; with it, the time.
  s.relax.max_steps = o.relax.adaptive ? kMaxSteps : s.steps;
  if (o.relax.adaptive) s.relax.t_end = s.t_end;
}

}  // namespace

Settings commonSettings(const Options& o, double default_t_end) {
  Settings s;
  s.h = app::parseNumber("--h", o.h, o.h);
  if (!(s.h > 0)) app::usageError("--h", o.h, "must be > 0");
  s.t_end = optionalNumber("--t-end", o.t_end, default_t_end);
  if (!(s.t_end > 0)) app::usageError("--t-end", o.t_end, "must be > 0");
  // The message names both; the flag is --t-end if given (every default t-end takes at
  // most 2500 steps of the default h), else --h. With --adaptive, --h is only the first step,
  // which the step control grows: any h > 0 can run, and the caps are the time and kMaxSteps.
  if (o.relax.adaptive) {
    s.steps = kMaxSteps;
  } else {
    s.steps = o.t_end.empty() ? stepCount(s.t_end, s.h, "--h", o.h)
                              : stepCount(s.t_end, s.h, "--t-end", o.t_end);
  }
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
  readRelaxOptions(o, s);
  s.out = o.out;
  return s;
}

}  // namespace ddb::compare
