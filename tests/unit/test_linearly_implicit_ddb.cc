// LinearlyImplicitDdb (integrators/methods/linearly_implicit_ddb.h, docs/guide/steady-states.md, "A
// dissipative factor that lowers the energy at any h"): the DDB step whose dissipative
// factor is one line-searched Newton step of the minimizing movement. Independent of the
// code: the energy from the closed forms (E = Re tr(WP)/(2N) with P = Δ⁻¹W by the fluid's
// Poisson solve; ½ M·𝕀⁻¹M), the spectrum by Eigen's eigensolver (G::casimirs), the limit
// point ±|M₀| e₂ of Scenario B, and the explicit DDB step, a different formula for the same
// flow, to which it must agree to O(h²) per step (the global order is fitted against the
// reference solver with every row of the method table, test_matrix_orders.cc and
// test_integrators.cc).
#include <ddb/integrators/methods/method_table.h>
#include <ddb/systems/heavy_top.h>
#include <ddb/systems/paper_scenarios.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "order_fit.h"

namespace ddb::test {
namespace linearly_implicit_ddb_tests {

constexpr double kEps = std::numeric_limits<double>::epsilon();

/// E = Re tr(W P)/(2N), P = Δ⁻¹W: the fluid's energy from its definition.
double fluidEnergy(const ZeitlinHamiltonian& hamiltonian, const Eigen::MatrixXcd& W) {
  const Eigen::MatrixXcd P = hamiltonian.streamMatrix(W);
  return (W * P).trace().real() / (2.0 * W.rows());
}

double spectrumDrift(const Eigen::MatrixXcd& W, const Eigen::VectorXd& spectrum0) {
  return (SUN::casimirs(W) - spectrum0).norm() / spectrum0.norm();
}

// The dissipative factor lowers the energy for every h: from the conservative part's state,
// E falls for α > 0 (rises for α < 0) at h|α| from 0.005 to 2500 (h itself is bounded by the
// conservative part's Legendre solve), where the explicit factor at α = 50 and h = 0.1
// raises it (the check can fail); the spectrum is kept to rounding.
TEST(LinearlyImplicitDdb, DissipativeFactorMovesTheEnergyTheFlowsWayAtAnyStepSize) {
  const Eigen::Index n = 8;
  const Eigen::MatrixXcd W0 = randomVorticity(n, 3);
  const Eigen::VectorXd spectrum0 = SUN::casimirs(W0);
  for (const double alpha : {0.5, 50.0, -0.5, 5000.0, -5000.0}) {
    const auto system = makeZeitlinFluid(n, alpha);
    const auto& hamiltonian = dynamic_cast<const ZeitlinHamiltonian&>(system->hamiltonian());
    for (const double h : {0.01, 0.1, 0.5}) {
      auto method = makeMethod<SUN>("ddb-cay-implicit", system);
      auto conservative = makeMethod<SUN>("ddb-cay", system->withoutDissipation());
      Eigen::MatrixXcd W = W0;
      double moved = 0.0;  // the dissipative factor's energy change, summed, σ-signed
      for (int k = 0; k < 10; ++k) {
        const Eigen::MatrixXcd conserved = conservative->step(W, k * h, h);
        method->advance(W, k * h, h);
        const double before = fluidEnergy(hamiltonian, conserved);
        const double after = fluidEnergy(hamiltonian, W);
        const double sigma = alpha > 0 ? 1.0 : -1.0;
        EXPECT_LE(sigma * (after - before), 8 * kEps * std::abs(before))
            << "alpha " << alpha << " h " << h << " step " << k;
        moved += sigma * (after - before);
        EXPECT_LE(spectrumDrift(W, spectrum0), 1e-13) << "alpha " << alpha << " h " << h;
      }
      EXPECT_LT(moved, -1e-6 * fluidEnergy(hamiltonian, W0)) << "alpha " << alpha << " h " << h;
    }
  }
  // The explicit factor at α = 50, h = 0.1: the energy rises at some step.
  const auto stiff = makeZeitlinFluid(n, 50.0);
  const auto& hamiltonian = dynamic_cast<const ZeitlinHamiltonian&>(stiff->hamiltonian());
  auto ddb = makeMethod<SUN>("ddb-cay", stiff);
  Eigen::MatrixXcd W = W0;
  int rises = 0;
  for (int k = 0; k < 10; ++k) {
    const double before = fluidEnergy(hamiltonian, W);
    ddb->advance(W, 0.1 * k, 0.1);
    if (fluidEnergy(hamiltonian, W) > before) ++rises;
  }
  EXPECT_GT(rises, 0);
}

// Both factors approximate the same flow to first order: one step from the same state
// differs by O(h²) (the fitted slope of the difference against h is 2), on the fluid and on
// the rigid body (the fixed-size path).
TEST(LinearlyImplicitDdb, AgreesWithTheExplicitDdbStepToSecondOrder) {
  const std::vector<double> steps{0.08, 0.04, 0.02, 0.01, 0.005};
  {
    const auto system = makeZeitlinFluid(6, 0.5);
    const Eigen::MatrixXcd W0 = randomVorticity(6, 5);
    std::vector<double> difference;
    for (const double h : steps) {
      const Eigen::MatrixXcd a = makeMethod<SUN>("ddb-cay-implicit", system)->step(W0, 0.0, h);
      const Eigen::MatrixXcd b = makeMethod<SUN>("ddb-cay", system)->step(W0, 0.0, h);
      difference.push_back((a - b).norm() / W0.norm());
    }
    const OrderFit fit = fitOrder(steps, difference);
    EXPECT_NEAR(fit.slope, 2.0, 0.1) << "fluid";
  }
  {
    const RigidBodyScenario& s = rigidBodyScenario("A");
    const auto system = s.system();
    std::vector<double> difference;
    for (const double h : steps) {
      const Eigen::Vector3d a = makeMethod<SO3>("ddb-exp-implicit", system)->step(s.mu0(), 0, h);
      const Eigen::Vector3d b = makeMethod<SO3>("ddb-exp-exact", system)->step(s.mu0(), 0, h);
      difference.push_back((a - b).norm() / s.mu0().norm());
    }
    const OrderFit fit = fitOrder(steps, difference);
    EXPECT_NEAR(fit.slope, 2.0, 0.1) << "rigid body";
  }
}

// With α = 0 there is no dissipative factor: the step is DDB's, to the bit (the method skips
// the factor; this checks that the conservative part is DDB's own step, not a copy).
TEST(LinearlyImplicitDdb, IsTheDdbStepWithoutDissipation) {
  const auto system = makeZeitlinFluid(5, 0.0);
  Eigen::MatrixXcd a = randomVorticity(5, 7), b = a;
  auto implicit = makeMethod<SUN>("ddb-cay-implicit", system);
  auto explicit_ = makeMethod<SUN>("ddb-cay", system);
  for (int k = 0; k < 5; ++k) {
    implicit->advance(a, 0.1 * k, 0.1);
    explicit_->advance(b, 0.1 * k, 0.1);
  }
  EXPECT_EQ(a, b);
}

// Steps far beyond the explicit factor's bound still relax the rigid body of Scenario B, with
// α = 50 instead of 0.5, to its limit point ±|M₀| e₂ (closed form), the energy falling at every
// step and |M| kept; the explicit DDB step at that h does not get there.
TEST(LinearlyImplicitDdb, LargeStepsRelaxScenarioBToItsLimitPoint) {
  const RigidBodyScenario& s = rigidBodyScenario("B");
  const auto system = makeRigidBody(s.inertia, 50.0);
  for (const char* name : {"ddb-cay-implicit", "ddb-exp-implicit"}) {
    auto method = makeMethod<SO3>(name, system);
    Eigen::Vector3d M = s.mu0();
    const double h = 0.5;  // h α = 25
    double energy = 0.5 * M.dot(M.cwiseQuotient(s.inertia));
    for (int k = 0; k < 100; ++k) {
      method->advance(M, k * h, h);
      const double next = 0.5 * M.dot(M.cwiseQuotient(s.inertia));
      EXPECT_LE(next, energy + 8 * kEps * energy) << name << " step " << k;
      energy = next;
      EXPECT_NEAR(M.norm(), s.mu0().norm(), 1e-13 * s.mu0().norm()) << name;
    }
    const Eigen::Vector3d limit = std::copysign(s.mu0().norm(), M(1)) * Eigen::Vector3d::UnitY();
    EXPECT_LE((M - limit).norm(), 1e-10 * s.mu0().norm()) << name;
  }
  auto ddb = makeMethod<SO3>("ddb-cay", system);
  Eigen::Vector3d M = s.mu0();
  for (int k = 0; k < 100; ++k) ddb->advance(M, k * 0.5, 0.5);
  EXPECT_GT((M - std::copysign(s.mu0().norm(), M(1)) * Eigen::Vector3d::UnitY()).norm(),
            1e-3 * s.mu0().norm());
}

// Only k♯ = α·I has the scalar τ = h|α|: the heavy top's diagonal metric is refused by name.
TEST(LinearlyImplicitDdb, NeedsTheScalarMetric) {
  const auto top = makeHeavyTop(Eigen::Vector3d(1, 2, 3), 1.0, Eigen::Vector3d(0, 0, 1), 0.5,
                                Eigen::Matrix<double, 6, 1>::Ones());
  EXPECT_FALSE(methodApplies<SE3>("ddb-cay-implicit", *top));
  try {
    makeMethod<SE3>("ddb-cay-implicit", top);
    FAIL() << "no exception";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("ddb-cay-implicit"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("metric"), std::string::npos) << e.what();
  }
}

}  // namespace linearly_implicit_ddb_tests
}  // namespace ddb::test
