// The method table (integrators/methods/method_table.h) against what its methods do: a row builds
// and runs on every group of the families it names, a row said to keep the Casimirs keeps
// them to round-off there and a fixed-step row said not to drifts off the orbit,
// compositions compose a symmetric method, and the descriptions say what the fields say.
// The orders the table claims are fitted in test_integrators.cc and test_symmetric.cc.
#include <ddb/integrators/drivers/run.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/systems/manakov_body.h>
#include <ddb/systems/paper_scenarios.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <gmock/gmock.h>

#include <set>

#include "test_support.h"

namespace ddb::test {
namespace method_table_tests {

TEST(MethodTable, NamesAreUniqueAndDescriptionsAreOneLine) {
  std::set<std::string_view> names;
  for (const MethodInfo& m : kMethods) {
    EXPECT_TRUE(names.insert(m.name).second) << m.name << " twice";
    EXPECT_FALSE(m.description.empty()) << m.name;
    EXPECT_EQ(m.description.find('\n'), std::string_view::npos) << m.name;
    EXPECT_NE(m.groups, 0u) << m.name << " runs on no group";
  }
}

// The one-line descriptions repeat some fields for --help; they must not contradict them.
TEST(MethodTable, DescriptionsAgreeWithTheFields) {
  for (const MethodInfo& m : kMethods) {
    const std::string text(m.description);
    const bool says_not_kept = text.find("does not keep Casimirs") != std::string::npos;
    EXPECT_EQ(says_not_kept, !m.keeps_casimirs && m.kind != MethodKind::kReference) << m.name;
    EXPECT_EQ(text.find("Lagrangian only") != std::string::npos, m.needs_lagrangian) << m.name;
    for (std::size_t at = text.find("order "); at != std::string::npos;
         at = text.find("order ", at + 1)) {
      const int said = text[at + 6] - '0';
      EXPECT_TRUE(said == m.order || said == m.order_without_dissipation)
          << m.name << ": '" << text << "'";
    }
  }
}

TEST(MethodTable, CompositionsComposeASymmetricMethodOnTheSameGroups) {
  for (const MethodInfo& m : kMethods) {
    if (m.kind != MethodKind::kComposition) continue;
    const MethodInfo* base = findMethod(m.base);
    ASSERT_NE(base, nullptr) << m.name;
    // Raising the order by a symmetric composition needs Φ_{−h} = Φ_h⁻¹ (conventions.md §2).
    EXPECT_EQ(base->kind, MethodKind::kSymmetricDdb) << m.name;
    EXPECT_EQ(base->groups & m.groups, m.groups) << m.name;
    EXPECT_EQ(base->keeps_casimirs, m.keeps_casimirs) << m.name;
  }
}

/// ‖C(μ_K) − C(μ₀)‖/‖C(μ₀)‖ after `steps` steps of h.
template <class G>
double casimirDrift(OneStepMethod<G>& method, const LiePoissonSystem<G>& system,
                    const typename G::template Dual<double>& mu0, double h, long steps) {
  const RunResult<G> run = runMethod(method, system, mu0, h, steps);
  EXPECT_TRUE(run.ok()) << method.name() << ": " << run.failure;
  const auto c0 = system.casimirs(mu0);
  return (system.casimirs(run.final) - c0).norm() / c0.norm();
}

/// Every row builds on G iff the table names G's family, and its Casimir claim holds.
template <class G>
void checkRows(std::shared_ptr<const LiePoissonSystem<G>> system,
               const typename G::template Dual<double>& mu0, double h) {
  for (const MethodInfo& m : kMethods) {
    if (!methodApplies(m, *system)) {
      EXPECT_THROW(makeMethod<G>(m, system), InvalidArgument) << m.name << " on " << G::kName;
      continue;
    }
    auto method = makeMethod<G>(m, system);
    ASSERT_NE(method, nullptr) << m.name;
    if (m.kind == MethodKind::kReference) continue;  // adaptive: near the orbit by accuracy
    const double drift = casimirDrift(*method, *system, mu0, h, 40);
    if (m.keeps_casimirs) {
      EXPECT_LT(drift, 1e-13) << m.name << " on " << G::kName;
    } else {
      EXPECT_GT(drift, 1e-10) << m.name << " on " << G::kName << " keeps the Casimirs";
    }
  }
}

TEST(MethodTable, RowsMatchWhatTheMethodsDoOnSO3) {
  const RigidBodyScenario& a = rigidBodyScenario("A");
  checkRows<SO3>(a.system(), a.mu0(), 0.2);
}

TEST(MethodTable, RowsMatchWhatTheMethodsDoOnSE3WithoutALagrangian) {
  const HeavyTopSetup top;
  ASSERT_EQ(top.system()->lagrangian(), nullptr);
  checkRows<SE3>(top.system(), top.mu0, 0.2);
  EXPECT_FALSE(methodApplies("sddb-paper-cay", *top.system()));
}

TEST(MethodTable, RowsMatchWhatTheMethodsDoOnSUN) {
  checkRows<SUN>(makeZeitlinFluid(6, 0.5), randomVorticity(6, 3), 0.05);
}

TEST(MethodTable, RowsMatchWhatTheMethodsDoOnSON) {
  const Eigen::VectorXd J = Eigen::VectorXd::LinSpaced(4, 1.0, 2.5);
  Sampler sampler(8);
  const Eigen::Matrix4d a = sampler.vector<Eigen::Matrix4d>();
  const Eigen::MatrixXd M0 = a - a.transpose();
  // h = 0.3: at 0.2 Lobatto IIIC is accurate enough that its drift falls between the two
  // bounds (docs/design/architecture.md, "Lobatto IIIC on matrix groups").
  checkRows<SON>(makeManakovBody(J, 0.5), M0, 0.3);
}

TEST(MethodTable, NamesNotInTheTableAreRefusedByName) {
  const RigidBodyScenario& a = rigidBodyScenario("A");
  EXPECT_THAT([&] { makeMethod<SO3>("ddb-cayley", a.system()); },
              ::testing::ThrowsMessage<InvalidArgument>(::testing::HasSubstr("ddb-cayley")));
  // A fixed-size-only name on a matrix group: the message names it and lists the valid ones.
  EXPECT_THAT([&] { makeMethod<SUN>("sddb-paper-cay", makeZeitlinFluid(4, 0.5)); },
              ::testing::ThrowsMessage<InvalidArgument>(::testing::AllOf(
                  ::testing::HasSubstr("sddb-paper-cay"),
                  ::testing::HasSubstr("methods for matrix groups: ddb-cay, ddb-exp, "),
                  ::testing::HasSubstr(", rk4, "), ::testing::EndsWith("reference"))));
  EXPECT_FALSE(methodApplies("ddb-cayley", *a.system()));
}

TEST(MethodTable, AnUnknownNameOnAFixedSizeGroupListsEveryMethodForIt) {
  // Not "unknown method" alone: the valid names, so that a typo is mended from the message.
  const RigidBodyScenario& a = rigidBodyScenario("A");
  std::string message;
  try {
    makeMethod<SO3>("ddb-cayley", a.system());
  } catch (const InvalidArgument& e) {
    message = e.what();
  }
  EXPECT_THAT(message, ::testing::StartsWith("method = ddb-cayley is invalid: "));
  for (const MethodInfo& m : kMethods) {
    if ((m.groups & kFixedSizeGroups) != 0) {
      EXPECT_THAT(message, ::testing::HasSubstr(std::string(m.name))) << message;
    }
  }
}

/// The Legendre solver's own count of its last solve (fixed-point sweeps plus Newton steps) if
/// `method` is of the DDB family with retraction R, else `found`.
template <class R, class G>
long legendreSolveIterations(const OneStepMethod<G>& method, long found) {
  const auto* legendre = dynamic_cast<const LegendreMethod<R>*>(&method);
  if (legendre == nullptr) return found;
  const LegendreStats& stats = legendre->legendreSolver().stats();
  return stats.fixed_point + stats.newton;
}
/// That count for any retraction of the table; -1 if `method` is not of the DDB family.
template <class G>
long legendreSolveIterations(const OneStepMethod<G>& method) {
  long found = legendreSolveIterations<Cayley<G>>(method, -1);
  found = legendreSolveIterations<Exponential<G>>(method, found);
  return legendreSolveIterations<TruncatedExponential<G>>(method, found);
}

/// Every row's lastStepIterations() after each of a few steps, against the counts its solvers
/// keep themselves: the Legendre solve's (one per DDB step; the restart's too for the paper's
/// two-step recurrence; plus the dissipative factor's one Newton step for ddb-*-implicit),
/// the base method's solves summed over a composition's substeps (taken by a separate
/// instance of the base), the matrix-free stage solver's sweeps and Newton steps; explicit
/// rows solve nothing. What fluid-relax's iterations_mean and iterations_max add up.
template <class G>
void checkIterationCounts(std::shared_ptr<const LiePoissonSystem<G>> system,
                          const typename G::template Dual<double>& mu0, double h) {
  using Dual = typename G::template Dual<double>;
  for (const MethodInfo& m : kMethods) {
    if (!methodApplies(m, *system)) continue;
    auto method = makeMethod<G>(m, system);
    const bool composed = m.kind == MethodKind::kComposition;
    auto base = composed ? makeMethod<G>(m.base, system) : nullptr;
    const bool solves = m.kind != MethodKind::kExplicitRk4 && m.kind != MethodKind::kReference;
    EXPECT_EQ(method->solvesEquations(), solves) << m.name << " on " << G::kName;
    Dual mu = mu0, substepped = mu0;
    for (int k = 0; k < 3; ++k) {
      const double t = k * h;
      method->advance(mu, t, h);
      const long reported = method->lastStepIterations();
      const long legendre = legendreSolveIterations(*method);
      const std::string where =
          std::string(m.name) + " on " + G::kName + ", step " + std::to_string(k);
      switch (m.kind) {
        case MethodKind::kExplicitRk4:
        case MethodKind::kReference:
          EXPECT_EQ(reported, 0) << where;
          break;
        case MethodKind::kDdb:
        case MethodKind::kSymmetricDdb:
          EXPECT_EQ(reported, legendre) << where;
          break;
        case MethodKind::kPaperSymmetricDdb:
          // The first step starts the recurrence with a solve of its own.
          if (k == 0) {
            EXPECT_GT(reported, legendre) << where;
          } else {
            EXPECT_EQ(reported, legendre) << where;
          }
          break;
        case MethodKind::kLinearlyImplicitDdb:
          EXPECT_EQ(reported, legendre + 1) << where;  // α = 0.5, not at rest
          break;
        case MethodKind::kComposition: {
          long substeps = 0;
          double s = t;
          for (double gamma : detail::schemeOf(m.scheme).coefficients) {
            base->advance(substepped, s, gamma * h);
            substeps += legendreSolveIterations(*base);
            s += gamma * h;
          }
          EXPECT_EQ(substepped, mu) << where << ": the separate base took other steps";
          EXPECT_EQ(reported, substeps) << where;
          break;
        }
        case MethodKind::kLobattoIIIC:
          if constexpr (isDynamicGroup<G>) {
            const auto& rk = dynamic_cast<const MatrixFreeImplicitRungeKutta<G, 3>&>(*method);
            EXPECT_EQ(reported, rk.fixedPointSweeps() + rk.newtonSteps()) << where;
          }
          break;
      }
      if (solves) {
        EXPECT_GE(reported, 1) << where << ": a solve takes an iteration at least";
      }
    }
  }
}

TEST(MethodTable, StepIterationsAreTheSolversOwnCountsOnSO3) {
  const RigidBodyScenario& a = rigidBodyScenario("A");
  checkIterationCounts<SO3>(a.system(), a.mu0(), 0.2);
}

TEST(MethodTable, StepIterationsAreTheSolversOwnCountsOnSUN) {
  checkIterationCounts<SUN>(makeZeitlinFluid(6, 0.5), randomVorticity(6, 3), 0.05);
}

}  // namespace method_table_tests
}  // namespace ddb::test
