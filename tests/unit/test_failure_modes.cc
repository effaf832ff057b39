// Extreme but valid inputs end promptly in a typed error naming what went wrong
// (docs/reference/guarantees.md): a loop out of its budget, a state or residual that overflowed,
// an exponential-map step past the injectivity limit π. Never an untyped exception, an
// InvalidArgument from inside a step, or a run without bound.
#include <ddb/core/errors.h>
#include <ddb/groups/se3.h>
#include <ddb/integrators/drivers/run.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/integrators/methods/reference.h>
#include <ddb/integrators/solvers/injectivity_guard.h>
#include <ddb/systems/paper_scenarios.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <string>

namespace ddb::test {
namespace failure_modes_tests {

using ::testing::HasSubstr;
const RigidBodyScenario& kA = rigidBodyScenario("A");

// REVIEW §3: `--alpha 1e308` ran for minutes. The field's time scale is 1e-308: the
// adaptive reference must stop at once, not shrink its step forever.
TEST(ReferenceBudget, StiffFieldEndsInABudgetErrorAtOnce) {
  for (const double alpha : {1e308, -1e308, 1e200}) {
    auto body = makeRigidBody(kA.inertia, alpha);
    ReferenceSolver<SO3> reference(body);
    try {
      reference.step(kA.mu0(), 0.0, 30.0);
      FAIL() << "alpha = " << alpha << ": no error";
    } catch (const BudgetExhausted& e) {
      EXPECT_THAT(e.what(), HasSubstr("reference solver"));
      EXPECT_THAT(e.what(), HasSubstr("h = 30"));
      EXPECT_EQ(e.h(), 30.0);
    }
  }
}

TEST(ReferenceBudget, SubstepBudgetIsEnforcedAndNamed) {
  // Scenario A to t = 30 takes far more than 10 sub-steps at tolerance 1e-13 (and fits
  // in the default budget: the ddb-compare tests run it).
  ReferenceSolver<SO3> reference(kA.system(), 1e-13, 10);
  try {
    integrate(reference, kA.mu0(), 0.0, 30.0, 1, [](long, double, const Eigen::Vector3d&) {});
    FAIL() << "no error";
  } catch (const BudgetExhausted& e) {
    EXPECT_THAT(e.what(), HasSubstr("10 sub-steps"));
    EXPECT_THAT(e.what(), HasSubstr("step 0 (t = 0, h = 30)"));
    EXPECT_EQ(e.step(), 0);
  }
  // The budget is per trajectory: 300 steps of 0.1 take at least 300 sub-steps, so a
  // budget of 50 runs out after some good steps, at the same one on every run.
  ReferenceSolver<SO3> per_trajectory(kA.system(), 1e-13, 50);
  long failed = -1;
  for (int run = 0; run < 2; ++run) {
    try {
      integrate(per_trajectory, kA.mu0(), 0.0, 0.1, 300,
                [](long, double, const Eigen::Vector3d&) {});
      FAIL() << "no error";
    } catch (const BudgetExhausted& e) {
      EXPECT_THAT(e.what(), HasSubstr("50 sub-steps in this trajectory"));
      EXPECT_GT(e.step(), 0);
      if (run == 1) {
        EXPECT_EQ(e.step(), failed);
      }
      failed = e.step();
    }
  }
  ReferenceSolver<SO3> unlimited(kA.system());
  EXPECT_NO_THROW(unlimited.step(kA.mu0(), 0.0, 30.0));
  EXPECT_THROW(ReferenceSolver<SO3>(kA.system(), 1e-13, 0), InvalidArgument);
}

// REVIEW §3: the series threw InvalidArgument, the bad-input status, after files were
// written. |ω| = 7 > 2π is beyond its radius of convergence: a solve failure.
TEST(SeriesBudget, DexpSeriesBeyondItsRadiusIsASolveFailure) {
  Vector6d x, mu;
  x << 0.0, 0.0, 7.0, 0.1, 0.2, 0.3;
  mu << 1.0, 2.0, 3.0, 4.0, 5.0, 6.0;
  try {
    SE3::dexpInvDual(x, mu);
    FAIL() << "no error";
  } catch (const BudgetExhausted& e) {
    EXPECT_THAT(e.what(), HasSubstr("dexp series"));
    EXPECT_THAT(e.what(), HasSubstr("2π"));
  }
  x(2) = 4.0;  // well inside the radius: summed to round-off within the 120 terms
  EXPECT_TRUE(SE3::dexpInvDual(x, mu).allFinite());
}

// Overflow inside an implicit solve is named as such, not as a missed tolerance.
TEST(NonFinite, OverflowingTargetIsANonFiniteResidual) {
  auto body = makeRigidBody(kA.inertia, 1e308);
  auto method = makeMethod<SO3>("sddb-cay", body);
  try {
    integrate(*method, kA.mu0(), 0.0, 0.1, 3, [](long, double, const Eigen::Vector3d&) {});
    FAIL() << "no error";
  } catch (const NonFiniteState& e) {
    EXPECT_THAT(e.what(), HasSubstr("residual non-finite"));
    EXPECT_THAT(e.what(), HasSubstr("step 0 (t = 0, h = 0.1"));
    EXPECT_THAT(e.what(), ::testing::Not(HasSubstr("tolerance")));
  }
}

TEST(NonFinite, MatrixFreeSolveOverflowIsANonFiniteIterate) {
  // α = 1e308 alone no longer overflows: the dissipative factors are applied as increments,
  // and cay(2b) of a huge b is finite. A huge state makes a h ξ p overflow in the first sweep.
  auto fluid = makeZeitlinFluid(4, 1e308);
  auto method = makeMethod<SUN>("sddb-cay", fluid);
  const Eigen::MatrixXcd W0 = 1e200 * randomVorticity(4, 7);
  try {
    integrate(*method, W0, 0.0, 0.1, 3, [](long, double, const Eigen::MatrixXcd&) {});
    FAIL() << "no error";
  } catch (const NonFiniteState& e) {
    EXPECT_THAT(e.what(), HasSubstr("iterate non-finite"));
    EXPECT_EQ(e.step(), 0);
  }
}

// The exponential retraction refuses |hξ| ≥ π and names the largest admissible h,
// π/|ξ(M_k)| with ξ(M_0) = 𝕀⁻¹M_0 = Ω_0 (REVIEW §4: `--scenario B --h 5` climbed to
// the maximum-energy state).
TEST(Injectivity, ExpMethodsRefuseStepsPastPiAndNameTheLargestH) {
  const double largest = M_PI / kA.omega0.norm();
  for (const std::string name :
       {"ddb-exp", "ddb-exp-exact", "sddb-paper-exp", "sddb-exp", "ddb4-exp", "ddb6-exp"}) {
    auto method = makeMethod<SO3>(name, kA.system());
    try {
      integrate(*method, kA.mu0(), 0.0, 5.0, 50, [](long, double, const Eigen::Vector3d&) {});
      FAIL() << name << ": no error";
    } catch (const InjectivityLimit& e) {
      EXPECT_EQ(e.step(), 0) << name;
      EXPECT_DOUBLE_EQ(e.limit(), M_PI);
      EXPECT_NEAR(e.largestH(), largest, 1e-14) << name;
      EXPECT_THAT(e.what(), HasSubstr("injectivity limit 3.14159")) << name;
    }
  }
  // Cayley has no such limit: the same step is taken.
  auto cayley = makeMethod<SO3>("ddb-cay", kA.system());
  EXPECT_TRUE(cayley->step(kA.mu0(), 0.0, 5.0).allFinite());
}

TEST(Injectivity, TheLimitIsSharpAtTheInitialState) {
  const double largest = M_PI / kA.omega0.norm();
  // Below it the first step of every exp method is taken (1% below: the solved |hξ|
  // differs from h|Ω_0| by O(h²|α|), still below π here); at 1.001× it is refused.
  for (const std::string name : {"ddb-exp", "ddb-exp-exact"}) {
    auto method = makeMethod<SO3>(name, kA.system());
    EXPECT_NO_THROW(method->step(kA.mu0(), 0.0, 0.9 * largest)) << name;
    method->reset();
    EXPECT_THROW(method->step(kA.mu0(), 0.0, 1.001 * largest), InjectivityLimit) << name;
  }
}

TEST(Injectivity, ASolutionOnAFarBranchIsRefused) {
  // The check after the solve: a solution ξ with |hξ| ≥ π, whatever the state predicted.
  auto body = kA.system();
  const Eigen::Vector3d far(0.0, 0.0, 4.0);
  EXPECT_THROW(InjectivityGuard<Exponential<SO3>>::afterSolve(*body, kA.mu0(), far, 0.0, 1.0),
               InjectivityLimit);
  EXPECT_NO_THROW(
      InjectivityGuard<Exponential<SO3>>::afterSolve(*body, kA.mu0(), far / 2.0, 0.0, 1.0));
  EXPECT_NO_THROW(InjectivityGuard<Cayley<SO3>>::afterSolve(*body, kA.mu0(), far, 0.0, 1.0));
}

TEST(Injectivity, Se3UsesTheRotationPart) {
  // Heavy top: ξ = (𝕀⁻¹π, χ mgl): the limit is on |𝕀⁻¹π| only, however large the
  // translation part.
  HeavyTopSetup top;
  top.mgl = 100.0;  // |v| = 100
  auto system = top.system();
  const double speed = top.mu0.head<3>().cwiseQuotient(top.inertia).norm();
  auto method = makeMethod<SE3>("ddb-exp-exact", system);
  EXPECT_NO_THROW(method->step(top.mu0, 0.0, 0.01));  // h|v| = 1 > 0, h|ω| small
  method->reset();
  try {
    method->step(top.mu0, 0.0, 1.01 * M_PI / speed);
    FAIL() << "no error";
  } catch (const InjectivityLimit& e) {
    EXPECT_NEAR(e.largestH(), M_PI / speed, 1e-12);
  }
}

}  // namespace failure_modes_tests
}  // namespace ddb::test
