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

}  // namespace

Problem<SO3> rigidBodyProblem(const CLI::App&, const Options& o) {
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

namespace {

/// The parameters the SE(3) systems share, parsed over `setup`'s defaults into p and
/// recorded; returns the setup with them.
template <class Setup>
Setup se3Parameters(const Options& o, Setup setup, Problem<SE3>& p) {
  const Setup defaults = setup;
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
}

/// These systems have no paper scenario: "none" with the defaults, else "custom".
const char* noScenario(bool custom) { return custom ? "custom" : "none"; }

}  // namespace

Problem<SE3> heavyTopProblem(const CLI::App&, const Options& o) {
  Problem<SE3> p;
  HeavyTopSetup s = se3Parameters(o, HeavyTopSetup(), p);
  s.mgl = optionalNumber("--mgl", o.mgl, s.mgl);
  s.chi = optionalVector<3>("--chi", o.chi, s.chi);
  p.system = s.system();
  p.parameters["mgl"] = s.mgl;
  p.parameters["chi"] = app::jsonArray(s.chi);
  p.scenario = noScenario(!s.sameParameters(HeavyTopSetup()));
  return p;
}

Problem<SE3> kirchhoffProblem(const CLI::App&, const Options& o) {
  Problem<SE3> p;
  KirchhoffSetup s = se3Parameters(o, KirchhoffSetup(), p);
  s.mass = optionalVector<3>("--mass", o.mass, s.mass);
  requirePositiveEntries("--mass", o.mass, s.mass);
  p.system = s.system();
  p.parameters["mass"] = app::jsonArray(s.mass);
  p.scenario = noScenario(!s.sameParameters(KirchhoffSetup()));
  return p;
}

Problem<SE2> planarKirchhoffProblem(const CLI::App&, const Options& o) {
  const PlanarKirchhoffSetup defaults;
  PlanarKirchhoffSetup s = defaults;
  if (o.inertia.find(',') != std::string::npos) {
    app::usageError("--inertia", o.inertia, "expected 1 number (the body's one moment of inertia)");
  }
  s.inertia = optionalNumber("--inertia", o.inertia, defaults.inertia);
  if (!(s.inertia > 0)) app::usageError("--inertia", o.inertia, "must be > 0");
  s.mass = optionalVector<2>("--mass", o.mass, defaults.mass);
  requirePositiveEntries("--mass", o.mass, s.mass);
  s.alpha = optionalNumber("--alpha", o.alpha, defaults.alpha);
  s.mu0 = optionalVector<3>("--mu0", o.mu0, defaults.mu0);
  s.metric = optionalVector<3>("--metric", o.metric, defaults.metric);
  if ((s.metric.array() < 0).any()) app::usageError("--metric", o.metric, "entries must be >= 0");
  Problem<SE2> p{s.system(), s.mu0, noScenario(!s.sameParameters(defaults)), "", s.t_end,
                 s.alpha,    {}};
  p.parameters["inertia"] = s.inertia;
  p.parameters["mass"] = app::jsonArray(s.mass);
  p.parameters["alpha"] = s.alpha;
  p.parameters["metric"] = app::jsonArray(s.metric);
  p.parameters["mu0"] = app::jsonArray(s.mu0);
  return p;
}

}  // namespace ddb::compare
