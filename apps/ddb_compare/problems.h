// ddb-compare's problems (docs/reference/command-lines-and-files.md, "ddb-compare"): the rigid body
// of a paper scenario (docs/reference/conventions.md §3) or the heavy top, Kirchhoff body or planar
// Kirchhoff body, with the parameters given on the command line, and the check that the reference
// can resolve the flow (docs/reference/bad-inputs.md, "Decisions").
#pragma once

#include <ddb/core/group_traits.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/groups/se2.h>
#include <ddb/groups/se3.h>
#include <ddb/groups/so3.h>
#include <ddb/integrators/drivers/flow_rate.h>
#include <spdlog/spdlog.h>

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "common/cli.h"
#include "common/exit_status.h"
#include "common/json.h"
#include "ddb_compare/matrix_flow_rate.h"
#include "ddb_compare/options.h"
#include "ddb_compare/system_table.h"

namespace ddb::compare {

/// One system's problem: the system, μ0, the scenario label and its parameters.
template <class G>
struct Problem {
  std::shared_ptr<const LiePoissonSystem<G>> system;
  typename G::template Dual<double> mu0;
  std::string scenario;                        // "A", "B", "C", "custom" or "none"
  std::string scenario_base;                   // the scenario "custom" started from
  double t_end = 0.0;                          // the default horizon
  double alpha = 0.0;                          // the dissipation scale, for energy_rises
  app::Json parameters = app::Json::object();  // summary.json's "parameters"
};

// The problems of the system table (system_table.h), which has refused the flags a system
// does not take before it calls them.

/// The rigid body of --scenario with --inertia, --alpha, --omega0 over its values.
Problem<SO3> rigidBodyProblem(const CLI::App& cli, const Options& o);

/// The heavy top with the given parameters over the defaults (HeavyTopSetup).
Problem<SE3> heavyTopProblem(const CLI::App& cli, const Options& o);

/// The Kirchhoff body with the given parameters over the defaults (KirchhoffSetup).
Problem<SE3> kirchhoffProblem(const CLI::App& cli, const Options& o);

/// Kirchhoff's planar body with the given parameters over the defaults (PlanarKirchhoffSetup).
Problem<SE2> planarKirchhoffProblem(const CLI::App& cli, const Options& o);

/// Why the reference cannot follow the flow from μ₀ to t_end in at most kMaxSteps of
/// its time scale 1/rate, or "" if it can. An overflowing or extremely stiff problem
/// (α = 1e308, 𝕀 = 1e-300, μ₀ = 1e200) would otherwise run for hours or fail at step 0.
/// The rate is flowRate()'s on fixed-size groups, matrixFlowRate()'s bound on matrix
/// groups.
template <class G>
std::string unresolvable(const Problem<G>& p, double t_end) {
  double rate = 0.0;
  if constexpr (isDynamicGroup<G>) {
    rate = matrixFlowRate(*p.system, p.mu0, p.alpha);
  } else {
    rate = flowRate(*p.system, p.mu0);
  }
  if (rate * t_end <= static_cast<double>(kMaxSteps)) return "";
  const char* what = isDynamicGroup<G> ? "4|dH/dmu|_2 (1 + 3|alpha||mu0|_2)" : "|df/dmu|_inf";
  return fmt::format(
      "the flow's rate {} = {:.3g} at mu0 exceeds 1e9/t-end = {:.3g}: no integrator "
      "resolves it in 1e9 steps",
      what, rate, static_cast<double>(kMaxSteps) / t_end);
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
  // --alpha, the system flags whose absence means a default (the system table's order), and
  // --t-end. A flag the system does not take was refused before.
  std::vector<std::pair<std::string, std::string Options::*>> flags{{"--alpha", &Options::alpha}};
  for (const SystemFlag& flag : kSystemFlags) {
    if (flag.text != nullptr) flags.emplace_back(std::string(flag.name), flag.text);
  }
  flags.emplace_back("--t-end", &Options::t_end);
  const std::pair<std::string, std::string Options::*>* blamed = nullptr;
  for (const auto& flag : flags) {
    if ((o.*flag.second).empty()) continue;
    Options reverted = o;
    (reverted.*flag.second).clear();
    // Without the flag the rest may not fit (--j's count is --mu0-file's N): not this one.
    std::optional<Problem<G>> fixed;
    try {
      fixed = make(reverted);
    } catch (const app::UsageError&) {
    }
    if (fixed && unresolvable(*fixed, horizon(reverted, fixed->t_end)).empty()) {
      blamed = &flag;
      break;
    }
    if (blamed == nullptr) blamed = &flag;
  }
  if (blamed == nullptr) throw std::logic_error("the default problem is unresolvable: " + why);
  app::usageError(blamed->first, o.*blamed->second, why);
}

}  // namespace ddb::compare
