// The small Legendre solver's two paths (integrators/solvers/legendre.h,
// docs/reference/conventions.md §4): fixed-point sweeps to the tolerance while they contract fast,
// Levenberg–Marquardt's Newton when they do not. Each path is checked against the paper's closed
// form of (dcay⁻¹_x)* on SO(3), written out here, and the two against each other on the states of
// real trajectories.
#include <ddb/core/legendre_hamiltonian.h>
#include <ddb/integrators/methods/composition.h>
#include <ddb/integrators/methods/ddb.h>
#include <ddb/integrators/methods/symmetric_ddb.h>
#include <ddb/systems/paper_scenarios.h>
#include <ddb/systems/rigid_body.h>
#include <gtest/gtest.h>

#include <algorithm>

namespace ddb::test {
namespace legendre_solver_tests {

const RigidBodyScenario& kA = rigidBodyScenario("A");
constexpr double kTolerance = 1e-14;  // SolverOptions' default relative tolerance

// ‖(I + X/2 + x xᵀ/4) 𝕀ξ − M‖ with x = hξ (paper, Section 4.1): the Lagrangian-form residual
// of DDB's Legendre equation on the rigid body, from the matrix the paper prints.
double closedFormResidual(const Eigen::Vector3d& xi, const Eigen::Vector3d& M, double h) {
  const Eigen::Vector3d x = h * xi;
  Eigen::Matrix3d X;
  X << 0, -x(2), x(1), x(2), 0, -x(0), -x(1), x(0), 0;
  const Eigen::Matrix3d dual = Eigen::Matrix3d::Identity() + X / 2 + x * x.transpose() / 4;
  return (dual * kA.inertia.cwiseProduct(xi) - M).norm();
}

// The states M_k of a DDB Cayley trajectory from M_0 (the momenta every solve starts from).
std::vector<Eigen::Vector3d> ddbStates(double alpha, double h, long steps) {
  Ddb<Cayley<SO3>> ddb(makeRigidBody(kA.inertia, alpha));
  std::vector<Eigen::Vector3d> states;
  integrate(ddb, kA.mu0(), 0.0, h, steps,
            [&](long, double, const Eigen::Vector3d& mu) { states.push_back(mu); });
  return states;
}

SolverOptions withSweeps(int sweeps) {
  SolverOptions options;
  options.max_sweeps = sweeps;
  return options;
}

// Solves every M_k of a trajectory with the default solver (sweeps first) and with Newton
// alone (max_sweeps = 0), each with its own warm starts, and checks both solutions against
// the closed form and against each other. Returns the fraction of the default solver's
// solves that needed no Newton step.
double compareThePaths(double alpha, double h, long steps) {
  const auto body = makeRigidBody(kA.inertia, alpha);
  const Cayley<SO3> cayley;
  DiscreteLegendreSolver<Cayley<SO3>> swept(*body, cayley, LegendreForm::kLagrangian, {});
  DiscreteLegendreSolver<Cayley<SO3>> newton(*body, cayley, LegendreForm::kLagrangian,
                                             withSweeps(0));
  long without_newton = 0;
  const auto states = ddbStates(alpha, h, steps);
  for (size_t k = 0; k + 1 < states.size(); ++k) {
    const Eigen::Vector3d& M = states[k];
    const double tolerance = kTolerance * M.norm();
    Eigen::Vector3d p_swept, p_newton;
    const Eigen::Vector3d xi_swept = swept.solve(M, k * h, h, p_swept);
    const Eigen::Vector3d xi_newton = newton.solve(M, k * h, h, p_newton);
    SCOPED_TRACE("alpha " + std::to_string(alpha) + ", h " + std::to_string(h) + ", step " +
                 std::to_string(k));
    EXPECT_LE(closedFormResidual(xi_swept, M, h), tolerance);
    EXPECT_LE(closedFormResidual(xi_newton, M, h), tolerance);
    // p is ∂l/∂ξ(ξ) = 𝕀ξ on both paths (the sweeps' p, with ξ = 𝕀⁻¹p, to rounding).
    EXPECT_LE((p_swept - kA.inertia.cwiseProduct(xi_swept)).norm(), 1e-15 * M.norm());
    // Two solutions within the tolerance differ by up to cond(∂r/∂ξ) × 2 tolerances.
    EXPECT_LE((xi_swept - xi_newton).norm(), 4 * kTolerance * xi_newton.norm());
    EXPECT_EQ(newton.stats().fixed_point, 0);
    EXPECT_GE(newton.stats().newton, 1);
    if (swept.stats().newton == 0) {
      ++without_newton;
      // The returned iterate is one contraction past the one whose ‖r‖ was measured: its
      // own residual, by the closed form, is no larger (up to rounding of r's terms).
      EXPECT_LE(closedFormResidual(xi_swept, M, h),
                std::max(swept.stats().residual, 1e-15 * M.norm()));
    }
  }
  return static_cast<double>(without_newton) / static_cast<double>(states.size() - 1);
}

TEST(LegendreSolver, FastSweepsReachTheToleranceWithoutNewtonOnScenarioA) {
  // Rate 0.02–0.03 at h = 0.1 (docs/design/architecture.md): the sweeps converge on their own.
  EXPECT_GE(compareThePaths(0.5, 0.1, 300), 0.99);
  EXPECT_GE(compareThePaths(0.0, 0.1, 300), 0.99);
}

TEST(LegendreSolver, ThePredictorLeavesAboutThreeSweepsAStepOnScenarioA) {
  // The polynomial predictor at its full order misses by 1.5e-11 relative (median; 9.4e-11 at
  // most) at h = 0.1, and each sweep contracts by 0.03 or less: three to four sweeps reach
  // 1e-14 (6.2 with the quadratic extrapolation of 0.2.0; docs/results/benchmarks.md).
  const auto body = makeRigidBody(kA.inertia, 0.5);
  const Cayley<SO3> cayley;
  DiscreteLegendreSolver<Cayley<SO3>> solver(*body, cayley, LegendreForm::kLagrangian, {});
  const auto states = ddbStates(0.5, 0.1, 300);
  long sweeps = 0, newton = 0;
  for (size_t k = 0; k + 1 < states.size(); ++k) {
    Eigen::Vector3d p;
    const Eigen::Vector3d xi = solver.solve(states[k], k * 0.1, 0.1, p);
    ASSERT_LE(closedFormResidual(xi, states[k], 0.1), kTolerance * states[k].norm()) << k;
    sweeps += solver.stats().fixed_point;
    newton += solver.stats().newton;
  }
  EXPECT_EQ(newton, 0);
  EXPECT_LE(static_cast<double>(sweeps) / static_cast<double>(states.size() - 1), 4.0);
}

TEST(LegendreSolver, SlowSweepsHandOverToNewtonAndBothPathsAgree) {
  // The rate grows with h: at h = 1 it is above kFastContraction, and at h = 3 the sweeps
  // hardly contract; Newton finishes (nearly) every solve.
  EXPECT_LE(compareThePaths(0.5, 1.0, 30), 0.05);
  EXPECT_LE(compareThePaths(0.5, 3.0, 10), 0.05);
}

TEST(LegendreSolver, ANewStepSizeOrResetStartsAfresh) {
  // A fresh solve starts from M_k itself (no extrapolated correction) with the rate unknown,
  // so its first sweep cannot end the sweeps: it takes at least two. reset() makes the next
  // solve exactly that fresh one again; a new h forgets as much (corrections and rates scale
  // with h) and still solves to the tolerance.
  const auto body = makeRigidBody(kA.inertia, 0.5);
  const Cayley<SO3> cayley;
  DiscreteLegendreSolver<Cayley<SO3>> solver(*body, cayley, LegendreForm::kLagrangian, {});
  const auto states = ddbStates(0.5, 0.1, 5);
  Eigen::Vector3d p;
  solver.solve(states[0], 0.0, 0.1, p);
  const int fresh = solver.stats().fixed_point;
  EXPECT_GE(fresh, 2);
  for (int k = 1; k < 5; ++k) solver.solve(states[k], k * 0.1, 0.1, p);
  solver.reset();
  solver.solve(states[0], 0.0, 0.1, p);
  EXPECT_EQ(solver.stats().fixed_point, fresh);
  solver.solve(states[0], 0.0, 0.05, p);
  EXPECT_GE(solver.stats().fixed_point, 2);
  EXPECT_LE(closedFormResidual(solver.solve(states[0], 0.0, 0.05, p), states[0], 0.05),
            kTolerance * states[0].norm());
}

TEST(LegendreSolver, ACompositionsStagesEachExtrapolateTheirOwnCorrections) {
  // The triple jump solves at γ₁h, γ₂h, γ₁h: three interleaved sequences of corrections, each
  // smooth, which the solver keeps apart by (h, the previous h). Its sub-steps then take about
  // what a step of the symmetric DDB alone does (3.3 iterations); with one history forgotten
  // at every change of h, as until 0.2.0, they took 26.7 a step.
  const auto body = makeRigidBody(kA.inertia, 0.5);
  SymmetricDdb<Cayley<SO3>> alone(body);
  Composition<SO3> composed("ddb4-cay", std::make_unique<SymmetricDdb<Cayley<SO3>>>(body),
                            tripleJump());
  const auto iterationsPerStep = [&](OneStepMethod<SO3>& method) {
    Eigen::Vector3d mu = kA.mu0();
    long iterations = 0;
    for (int k = 0; k < 300; ++k) {
      method.advance(mu, k * 0.1, 0.1);
      iterations += method.lastStepIterations();
    }
    return static_cast<double>(iterations) / 300.0;
  };
  const double one = iterationsPerStep(alone);
  EXPECT_LE(one, 4.0);
  EXPECT_LE(iterationsPerStep(composed), 3.0 * one + 1.5);
}

TEST(LegendreSolver, ASlotUnusedForEightSolvesStartsAfresh) {
  // Solves alternating between h = 0.1 and 0.05 (the keys (0.1, 0.05) and (0.05, 0.1)), then
  // `away` solves at h = 0.2 and one at 0.05, then one at 0.1 again: within eight solves of its
  // last use the slot (0.1, 0.05) still extrapolates (fewer sweeps than a fresh solve); after
  // more it is stale and the solve is exactly a fresh one, as after reset().
  const auto body = makeRigidBody(kA.inertia, 0.5);
  const Cayley<SO3> cayley;
  const auto states = ddbStates(0.5, 0.1, 12);
  const auto sweepsBack = [&](int away) {
    DiscreteLegendreSolver<Cayley<SO3>> solver(*body, cayley, LegendreForm::kLagrangian, {});
    Eigen::Vector3d p;
    for (int k = 0; k < 10; ++k) solver.solve(states[k], k * 0.1, k % 2 == 0 ? 0.1 : 0.05, p);
    for (int k = 0; k < away; ++k) solver.solve(states[10], 1.0, 0.2, p);
    solver.solve(states[10], 1.0, 0.05, p);
    solver.solve(states[10], 1.0, 0.1, p);
    return solver.stats().fixed_point;
  };
  DiscreteLegendreSolver<Cayley<SO3>> fresh(*body, cayley, LegendreForm::kLagrangian, {});
  Eigen::Vector3d p;
  fresh.solve(states[10], 1.0, 0.1, p);
  EXPECT_LT(sweepsBack(3), fresh.stats().fixed_point);  // last used 6 solves before
  EXPECT_EQ(sweepsBack(6), fresh.stats().fixed_point);  // 9 solves before
}

TEST(LegendreSolver, NoSweepsMeansNewtonFromTheExtrapolatedGuess) {
  const auto body = makeRigidBody(kA.inertia, 0.5);
  const Cayley<SO3> cayley;
  DiscreteLegendreSolver<Cayley<SO3>> solver(*body, cayley, LegendreForm::kHamiltonian,
                                             withSweeps(-3));
  Eigen::Vector3d p;
  const Eigen::Vector3d xi = solver.solve(kA.mu0(), 0.0, 0.1, p);
  EXPECT_EQ(solver.stats().fixed_point, 0);
  EXPECT_GE(solver.stats().newton, 1);
  EXPECT_LE(closedFormResidual(xi, kA.mu0(), 0.1), kTolerance * kA.mu0().norm());
}

TEST(LegendreSolver, NoSweepsWhenTheVelocityIsItselfASolve) {
  // The body from l alone: ξ = ∂H/∂μ(p) is an inverse Legendre solve, so a sweep would cost
  // one; Newton works in ξ with l's derivatives directly.
  const auto body = makeSystemFromLagrangian<SO3>(
      "body from l", std::make_shared<const RigidBodyLagrangian>(kA.inertia),
      std::make_shared<const ScaledIdentityMetric<SO3>>(0.5));
  ASSERT_TRUE(body->hamiltonian().gradientIsASolve());
  EXPECT_FALSE(makeRigidBody(kA.inertia, 0.5)->hamiltonian().gradientIsASolve());
  const Cayley<SO3> cayley;
  DiscreteLegendreSolver<Cayley<SO3>> solver(*body, cayley, LegendreForm::kLagrangian, {});
  const auto states = ddbStates(0.5, 0.1, 20);
  for (size_t k = 0; k + 1 < states.size(); ++k) {
    Eigen::Vector3d p;
    const Eigen::Vector3d xi = solver.solve(states[k], k * 0.1, 0.1, p);
    EXPECT_EQ(solver.stats().fixed_point, 0);
    EXPECT_GE(solver.stats().newton, 1);
    EXPECT_LE(closedFormResidual(xi, states[k], 0.1), kTolerance * states[k].norm());
  }
}

}  // namespace legendre_solver_tests
}  // namespace ddb::test
