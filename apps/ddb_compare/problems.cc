#include "ddb_compare/problems.h"

#include <ddb/systems/paper_scenarios.h>

namespace ddb::compare {

namespace {

std::vector<std::string> scenarioNames() {
  std::vector<std::string> names;
  for (const auto& s : rigidBodyScenarios()) names.push_back(s.name);
  return names;
}

void requirePositiveEntries(const std::string& flag, const std::string& text,
                            const Eigen::VectorXd& v) {
  if ((v.array() <= 0).any()) app::usageError(flag, text, "entries must be > 0");
}

/// The flags of the matrix systems, refused on the others.
void rejectMatrixSystemsFlags(const CLI::App& cli, const std::string& context) {
  for (const char* flag : {"--n", "--j", "--mu0-file", "--seed", "--init", "--init-file"}) {
    app::rejectIfGiven(cli, flag, context);
  }
}

}  // namespace

Problem<SO3> rigidBodyProblem(const CLI::App& cli, const Options& o) {
  for (const char* flag : {"--mgl", "--chi", "--mu0", "--metric", "--mass"}) {
    app::rejectIfGiven(cli, flag, "--system rigid-body");
  }
  rejectMatrixSystemsFlags(cli, "--system rigid-body");
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
  rejectMatrixSystemsFlags(cli, context);
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

}  // namespace ddb::compare
