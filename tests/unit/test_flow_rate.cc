// flowRate (integrators/drivers/flow_rate.h) against the same norm of a Jacobian taken by central
// differences of the double vector field, which involves no Jets: the rigid body and the
// heavy top at their defaults and at other points, and infinity where f is not finite.
#include <ddb/integrators/drivers/flow_rate.h>
#include <ddb/systems/paper_scenarios.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace flow_rate_tests {

/// ‖∂f/∂μ‖∞ at mu0 by central differences with step 1e-6·max(1, |μ_j|): truncation error
/// O(1e-12) relative for these polynomial fields, round-off O(1e-10).
template <class G>
double differencedRate(const ddb::LiePoissonSystem<G>& system,
                       const typename G::template Dual<double>& mu0) {
  Eigen::Matrix<double, G::kDim, G::kDim> jacobian;
  for (int j = 0; j < G::kDim; ++j) {
    const double step = 1e-6 * std::max(1.0, std::abs(mu0(j)));
    typename G::template Dual<double> plus = mu0, minus = mu0;
    plus(j) += step;
    minus(j) -= step;
    jacobian.col(j) = (system.vectorField(plus) - system.vectorField(minus)) / (2 * step);
  }
  return jacobian.cwiseAbs().rowwise().sum().maxCoeff();
}

TEST(FlowRate, RigidBodyMatchesCentralDifferences) {
  for (const auto& scenario : ddb::rigidBodyScenarios()) {
    const auto system = scenario.system();
    for (const Eigen::Vector3d& mu :
         {Eigen::Vector3d(scenario.mu0()), Eigen::Vector3d(0.3, -1.2, 2.5)}) {
      const double rate = ddb::flowRate(*system, mu);
      EXPECT_GT(rate, 0.0);
      EXPECT_NEAR(rate, differencedRate(*system, mu), 1e-7 * rate) << scenario.name;
    }
  }
}

TEST(FlowRate, HeavyTopMatchesCentralDifferences) {
  ddb::HeavyTopSetup setup;
  setup.mgl = 2.0;
  setup.alpha = 0.8;
  const auto system = setup.system();
  ddb::Vector6d other;
  other << 0.4, -0.2, 1.1, 0.3, -0.5, 0.8;
  for (const ddb::Vector6d& mu : {setup.mu0, other}) {
    const double rate = ddb::flowRate(*system, mu);
    EXPECT_GT(rate, 0.0);
    EXPECT_NEAR(rate, differencedRate(*system, mu), 1e-7 * rate);
  }
}

TEST(FlowRate, NotFiniteIsInfinity) {
  const auto& scenario = ddb::rigidBodyScenarios().front();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(ddb::flowRate(*scenario.system(), Eigen::Vector3d(0.0, nan, 1.0)),
            std::numeric_limits<double>::infinity());
  EXPECT_EQ(ddb::flowRate(*scenario.system(), Eigen::Vector3d(0.0, 1e200, 1.0)),
            std::numeric_limits<double>::infinity());
}

}  // namespace flow_rate_tests
