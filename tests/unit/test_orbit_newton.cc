// The Newton search on the orbit (OrbitNewton through Relaxation; docs/guide/steady-states.md,
// "Newton on the orbit"), against closed forms: the rigid body's steady states of least and
// largest energy on the sphere |M| = |M₀| are ±|M₀| along the axes of largest and smallest
// inertia; the fluid's and the Manakov body's residuals recomputed from their matrices, their
// spectra by Eigen's eigensolver; Newton's superlinear convergence (a wrong Hessian product
// converges linearly); every accepted state's energy moved the flow's way.
#include <ddb/core/legendre_hamiltonian.h>
#include <ddb/integrators/drivers/relax.h>
#include <ddb/systems/manakov_body.h>
#include <ddb/systems/paper_scenarios.h>
#include <ddb/systems/rigid_body.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace ddb::test {
namespace orbit_newton_tests {

constexpr double kEps = std::numeric_limits<double>::epsilon();

RelaxOptions newtonUntil(double tolerance, long max_steps = 10000) {
  RelaxOptions options;
  options.newton = true;
  options.tolerance = tolerance;
  options.max_steps = max_steps;
  return options;
}

/// Every accepted state's residual and energy; the largest energy move against `direction`
/// (−1: the energy must fall) beyond rounding, relative.
template <class G>
struct Record {
  double direction;
  std::vector<double> residuals, energies;
  double against = 0.0;

  void operator()(const RelaxState& state, const typename G::template Dual<double>&) {
    if (!energies.empty()) {
      const double change = direction * (state.energy - energies.back());
      against = std::max(against, -change / std::abs(state.energy));
    }
    residuals.push_back(state.residual);
    energies.push_back(state.energy);
  }

  /// The least r_k/r_{k−1} over the steps that started at r_{k−1} ≥ `floor`. Newton's
  /// convergence is superlinear: near the steady state a step shrinks r by orders of
  /// magnitude. A search with a wrong Hessian product would converge linearly, by a steady
  /// factor near 1 at these conditionings. Steps that start within a few orders of rounding
  /// are left out: there the reduction depends on the path rounding took (a CPU's BLAS kernel
  /// changes it), not on the method.
  double bestReductionFrom(double floor) const {
    double best = 1.0;
    for (std::size_t k = 1; k < residuals.size(); ++k) {
      if (residuals[k - 1] >= floor) best = std::min(best, residuals[k] / residuals[k - 1]);
    }
    return best;
  }
};

/// The rigid body's r = |M × Ω|/(|M| |Ω|), Ω = 𝕀⁻¹M.
double rigidBodyResidual(const Eigen::Vector3d& inertia, const Eigen::Vector3d& M) {
  const Eigen::Vector3d omega = M.cwiseQuotient(inertia);
  return M.cross(omega).norm() / (M.norm() * omega.norm());
}

/// The distance of M from ±|M₀| e_axis.
double distanceToAxis(const Eigen::Vector3d& M, double norm0, int axis) {
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  target(axis) = std::copysign(norm0, M(axis));
  return (M - target).norm();
}

TEST(OrbitNewton, RigidBodyReachesTheAxisOfLeastEnergyQuadratically) {
  // Scenario B starts near e₃, the energy's maximum on the sphere (smallest inertia); with
  // α > 0 the least energy is at ±|M₀| e₂ (largest inertia, 1.3).
  const RigidBodyScenario& s = rigidBodyScenario("B");
  const auto system = s.system();
  Record<SO3> record{-1.0, {}, {}};
  const RelaxResult<SO3> run =
      relaxByNewton(*system, s.mu0(), newtonUntil(1e-14), std::ref(record));
  ASSERT_TRUE(run.steady()) << relaxStopName(run.stop) << " " << run.failure;
  std::cout << "rigid body: " << run.last.k << " Newton steps (" << run.steps_rejected
            << " halvings), r = " << run.last.residual << "\n";
  EXPECT_LE(rigidBodyResidual(s.inertia, run.final), 1e-14);
  EXPECT_LE(distanceToAxis(run.final, s.mu0().norm(), 1), 1e-13);
  EXPECT_NEAR(run.final.norm(), s.mu0().norm(), 4 * kEps);
  EXPECT_LE(record.against, 8 * kEps);
  EXPECT_EQ(run.last.t, 0.0);
  EXPECT_LE(record.bestReductionFrom(1e-12), 1e-3);
}

TEST(OrbitNewton, NegativeAlphaReachesTheAxisOfLargestEnergy) {
  const RigidBodyScenario& s = rigidBodyScenario("B");
  const auto system = makeRigidBody(s.inertia, -0.5);
  // Off e₃ enough that the search moves: M₀ = 𝕀(0.3, 0.5, 0.2).
  const Eigen::Vector3d mu0 = s.inertia.cwiseProduct(Eigen::Vector3d(0.3, 0.5, 0.2));
  Record<SO3> record{+1.0, {}, {}};
  const RelaxResult<SO3> run = relaxByNewton(*system, mu0, newtonUntil(1e-13), std::ref(record));
  ASSERT_TRUE(run.steady()) << run.failure;
  EXPECT_LE(distanceToAxis(run.final, mu0.norm(), 2), 1e-12);
  EXPECT_LE(record.against, 8 * kEps);
}

TEST(OrbitNewton, ASystemDefinedByItsLagrangianAlone) {
  // The rigid body's Lagrangian through LegendreHamiltonian (its ∂H/∂μ solves l's
  // equation, its Hessian product is central differences): the same closed form.
  const RigidBodyScenario& s = rigidBodyScenario("B");
  const auto from_l = makeSystemFromLagrangian<SO3>(
      "rigid-body-from-l", std::make_shared<const RigidBodyLagrangian>(s.inertia),
      std::make_shared<const ScaledIdentityMetric<SO3>>(0.5));
  const RelaxResult<SO3> run = relaxByNewton(*from_l, s.mu0(), newtonUntil(1e-12),
                                             [](const RelaxState&, const Eigen::Vector3d&) {});
  ASSERT_TRUE(run.steady()) << run.failure;
  EXPECT_LE(rigidBodyResidual(s.inertia, run.final), 1e-12);
  EXPECT_LE(distanceToAxis(run.final, s.mu0().norm(), 1), 1e-11);
}

/// W's eigenvalues (of the Hermitian −iW), ascending, by Eigen.
Eigen::VectorXd spectrum(const Eigen::MatrixXcd& W) {
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd>(
             Eigen::MatrixXcd(std::complex<double>(0, -1) * W))
      .eigenvalues();
}

TEST(OrbitNewton, FluidReachesASteadyStateOnTheOrbitWithTheEnergyFalling) {
  constexpr Eigen::Index kN = 8;
  const auto system = makeZeitlinFluid(kN, 0.5);
  const auto& hamiltonian = dynamic_cast<const ZeitlinHamiltonian&>(system->hamiltonian());
  const Eigen::MatrixXcd W0 = randomVorticity(kN, 1);
  Record<SUN> record{-1.0, {}, {}};
  // The guide's tolerance for the fluid (docs/guide/steady-states.md). Below about 1e-11 the
  // search at N = 8 may stall at a point that depends on the BLAS kernel's rounding
  // (docs/results/steady-states.md, "The Newton search's floor at small N").
  constexpr double kTolerance = 1e-10;
  const RelaxResult<SUN> run =
      relaxByNewton(*system, W0, newtonUntil(kTolerance), std::ref(record));
  ASSERT_TRUE(run.steady()) << relaxStopName(run.stop) << " " << run.failure;
  const Eigen::MatrixXcd& W = run.final;
  const Eigen::MatrixXcd P = hamiltonian.streamMatrix(W);
  const double r = (P * W - W * P).norm() / (P.norm() * W.norm());
  std::cout << "fluid N = 8: " << run.last.k << " Newton steps (" << run.steps_rejected
            << " halvings), r = " << r << "\n";
  EXPECT_LE(r, kTolerance);
  EXPECT_NEAR(r, run.last.residual, 1e-3 * kTolerance);
  EXPECT_LE((spectrum(W) - spectrum(W0)).norm() / spectrum(W0).norm(), 1e-14);
  EXPECT_LE(record.against, 8 * kEps);
  EXPECT_LT(record.energies.back(), record.energies.front());
  EXPECT_LE(record.bestReductionFrom(1e-10), 1e-3);
}

TEST(OrbitNewton, OnlyTheSignOfAlphaMatters) {
  // The search minimises σH: α's size sets the flow's time scale, not the critical points.
  constexpr Eigen::Index kN = 6;
  const Eigen::MatrixXcd W0 = randomVorticity(kN, 2);
  std::vector<Eigen::MatrixXcd> finals;
  for (const double alpha : {0.5, 5.0, 50.0}) {
    const auto system = makeZeitlinFluid(kN, alpha);
    const RelaxResult<SUN> run = relaxByNewton(*system, W0, newtonUntil(1e-11),
                                               [](const RelaxState&, const Eigen::MatrixXcd&) {});
    ASSERT_TRUE(run.steady()) << run.failure;
    finals.push_back(run.final);
  }
  EXPECT_EQ(finals[0], finals[1]);
  EXPECT_EQ(finals[0], finals[2]);
}

TEST(OrbitNewton, ManakovBodyOnSONReachesASteadyState) {
  // SO(N): real skew-symmetric momenta, the same search (the preconditioner in C^N).
  constexpr Eigen::Index kN = 5;
  Eigen::VectorXd J(kN);
  J << 1.0, 1.4, 1.9, 2.5, 3.2;
  const auto system = makeManakovBody(J, 0.5);
  Eigen::MatrixXd M0 = Eigen::MatrixXd::Random(kN, kN);
  M0 = (M0 - M0.transpose()).eval();
  Record<SON> record{-1.0, {}, {}};
  const RelaxResult<SON> run = relaxByNewton(*system, M0, newtonUntil(1e-12), std::ref(record));
  ASSERT_TRUE(run.steady()) << relaxStopName(run.stop) << " " << run.failure;
  const Eigen::MatrixXd Omega = system->velocity(run.final);
  const Eigen::MatrixXd& M = run.final;
  EXPECT_LE((M * Omega - Omega * M).norm() / (M.norm() * Omega.norm()), 1e-12);
  EXPECT_LE((spectrum(M.cast<std::complex<double>>()) - spectrum(M0.cast<std::complex<double>>()))
                    .norm() /
                M0.norm(),
            1e-14);
  EXPECT_LE(record.against, 8 * kEps);
}

TEST(OrbitNewton, ASteadyStateTakesNoStep) {
  constexpr Eigen::Index kN = 8;
  const auto system = makeZeitlinFluid(kN, 0.5);
  for (const Eigen::MatrixXcd& W : {zonalVorticity(kN, 3), zeitlinX3(kN)}) {
    const RelaxResult<SUN> run = relaxByNewton(*system, W, newtonUntil(1e-12),
                                               [](const RelaxState&, const Eigen::MatrixXcd&) {});
    EXPECT_TRUE(run.steady());
    EXPECT_EQ(run.last.k, 0);
    EXPECT_EQ(run.final, W);
  }
}

TEST(OrbitNewton, AResumedSearchTakesTheSameSteps) {
  constexpr Eigen::Index kN = 6;
  const auto system = makeZeitlinFluid(kN, 0.5);
  const Eigen::MatrixXcd W0 = randomVorticity(kN, 4);
  const RelaxOptions options = newtonUntil(1e-12);
  Relaxation<SUN> whole(*system, W0, options);
  while (whole.advance()) {
  }
  ASSERT_TRUE(whole.result().steady()) << whole.result().failure;
  ASSERT_GT(whole.state().k, 10);

  Relaxation<SUN> first(*system, W0, options);
  for (int k = 0; k < 7; ++k) ASSERT_TRUE(first.advance());
  BinaryRecordWriter out;
  first.save(out);
  Relaxation<SUN> resumed(*system, W0, options);
  BinaryRecordReader in(out.bytes());
  resumed.load(in);
  while (resumed.advance()) {
  }
  EXPECT_EQ(resumed.state().k, whole.state().k);
  EXPECT_EQ(resumed.current(), whole.current());
}

TEST(OrbitNewton, BadArgumentsAreInvalidArguments) {
  const RigidBodyScenario& s = rigidBodyScenario("B");
  const auto system = s.system();
  RelaxOptions options = newtonUntil(1e-10);
  options.tolerance = 0.0;  // a search needs a target
  EXPECT_THROW(Relaxation<SO3>(*system, s.mu0(), options), InvalidArgument);
  options = newtonUntil(1e-10);
  options.t_end = 10.0;  // no time is simulated
  EXPECT_THROW(Relaxation<SO3>(*system, s.mu0(), options), InvalidArgument);
  options = newtonUntil(1e-10);
  options.control.adaptive = true;
  EXPECT_THROW(Relaxation<SO3>(*system, s.mu0(), options), InvalidArgument);
  // No dissipation: no direction to search in.
  const auto conservative = makeRigidBody(s.inertia, 0.0);
  EXPECT_THROW(Relaxation<SO3>(*conservative, s.mu0(), newtonUntil(1e-10)), InvalidArgument);
}

}  // namespace orbit_newton_tests
}  // namespace ddb::test
