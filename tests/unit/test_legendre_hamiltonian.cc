// LegendreHamiltonian: a system defined by its Lagrangian alone, against the rigid
// body's hand-written Hamiltonian and, for a non-quadratic l, against the defining
// identities ∂l/∂ξ(∂H/∂μ(μ)) = μ and central differences of H and ∂H/∂μ.
#include <ddb/core/autodiff.h>
#include <ddb/core/legendre_hamiltonian.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/systems/paper_scenarios.h>
#include <ddb/systems/rigid_body.h>
#include <gmock/gmock.h>

#include "test_support.h"

namespace ddb::test {
namespace legendre_hamiltonian_tests {

const Eigen::Vector3d kInertia = rigidBodyScenario("A").inertia;

// A convex, non-quadratic Lagrangian: l(ξ) = ½ ξ·𝕀ξ + ¼ |ξ|⁴ + log cosh(ξ₁).
class QuarticLagrangian : public AutoDiffLagrangian<QuarticLagrangian, SO3> {
 public:
  template <class T>
  T evaluate(const Eigen::Matrix<T, 3, 1>& x) const {
    T quadratic = constant<T>(0.0), norm2 = constant<T>(0.0);
    for (int i = 0; i < 3; ++i) {
      quadratic += constant<T>(kInertia(i)) * x(i) * x(i);
      norm2 += x(i) * x(i);
    }
    using std::cosh;
    using std::log;
    return constant<T>(0.5) * quadratic + constant<T>(0.25) * norm2 * norm2 + log(cosh(x(0)));
  }
};

TEST(LegendreHamiltonian, ReproducesTheRigidBodyHamiltonian) {
  const auto from_l = makeSystemFromLagrangian<SO3>(
      "rigid-body-from-l", std::make_shared<const RigidBodyLagrangian>(kInertia),
      std::make_shared<const ScaledIdentityMetric<SO3>>(0.5));
  const auto body = makeRigidBody(kInertia, 0.5);
  Sampler s(41);
  for (int i = 0; i < 5; ++i) {
    const Eigen::Vector3d mu = s.vector<Eigen::Vector3d>(), nu = s.vector<Eigen::Vector3d>();
    EXPECT_NEAR(from_l->energy(mu), body->energy(mu), 1e-15);
    EXPECT_LT((from_l->velocity(mu) - body->velocity(mu)).norm(), 1e-14);
    EXPECT_LT(
        (from_l->hamiltonian().hessianTimes(mu, nu) - body->hamiltonian().hessianTimes(mu, nu))
            .norm(),
        1e-14);
    EXPECT_LT((from_l->vectorField(mu) - body->vectorField(mu)).norm(), 1e-14);
  }
  // And the integrators run on it unchanged: same DDB trajectory.
  const Eigen::Vector3d m0 = rigidBodyScenario("A").mu0();
  Eigen::Vector3d a, b;
  auto ddb_a = makeMethod<SO3>("ddb-cay", from_l);
  auto ddb_b = makeMethod<SO3>("ddb-cay", body);
  integrate(*ddb_a, m0, 0.0, 0.1, 100, [&](long, double, const Eigen::Vector3d& m) { a = m; });
  integrate(*ddb_b, m0, 0.0, 0.1, 100, [&](long, double, const Eigen::Vector3d& m) { b = m; });
  EXPECT_LT((a - b).norm(), 1e-13);
}

TEST(LegendreHamiltonian, NonQuadraticLagrangian) {
  const auto l = std::make_shared<const QuarticLagrangian>();
  const LegendreHamiltonian<SO3> H(l);
  Sampler s(42);
  for (int i = 0; i < 5; ++i) {
    const Eigen::Vector3d mu = s.vector<Eigen::Vector3d>(), nu = s.vector<Eigen::Vector3d>();
    const Eigen::Vector3d xi = H.gradient(mu);
    EXPECT_LT((l->gradient(xi) - mu).norm(), 1e-14);             // ∂l/∂ξ(ξ(μ)) = μ
    EXPECT_NEAR(H.value(mu), mu.dot(xi) - l->value(xi), 1e-15);  // Legendre
    const double d = 1e-6;
    EXPECT_NEAR((H.value(mu + d * nu) - H.value(mu - d * nu)) / (2 * d), xi.dot(nu), 1e-9);
    const Eigen::Vector3d dxi = (H.gradient(mu + d * nu) - H.gradient(mu - d * nu)) / (2 * d);
    EXPECT_LT((H.hessianTimes(mu, nu) - dxi).norm(), 1e-8);
  }
}

}  // namespace legendre_hamiltonian_tests
}  // namespace ddb::test
