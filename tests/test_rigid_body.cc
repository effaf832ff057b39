// The rigid body against the component equations of the paper's Examples 3.1/3.5 and
// the energy/Casimir rates of Proposition 3.3, by central differences along the flow.
#include <ddb/systems/paper_scenarios.h>
#include <ddb/systems/rigid_body.h>
#include <gmock/gmock.h>

#include "test_support.h"

namespace ddb::test {
namespace {

const Eigen::Vector3d kInertia = rigidBodyScenario("A").inertia;

// Components of d(𝕀Ω)/dt = 𝕀Ω × (Ω + φ(Ω)) (paper, Example 3.1 corrected;
// eq. (3.6)) with the paper's φ components, written out by hand.
Eigen::Vector3d componentEquations(const Eigen::Vector3d& W, double alpha) {
  const double I1 = kInertia(0), I2 = kInertia(1), I3 = kInertia(2);
  const Eigen::Vector3d phi(alpha * (I2 - I3) * W(1) * W(2), alpha * (I3 - I1) * W(2) * W(0),
                            alpha * (I1 - I2) * W(0) * W(1));
  return Eigen::Vector3d(I2 * W(1) * (W(2) + phi(2)) - I3 * W(2) * (W(1) + phi(1)),
                         I3 * W(2) * (W(0) + phi(0)) - I1 * W(0) * (W(2) + phi(2)),
                         I1 * W(0) * (W(1) + phi(1)) - I2 * W(1) * (W(0) + phi(0)));
}

// The paper's printed component equations for φ = α𝕀Ω×Ω (Example 3.5).
Eigen::Vector3d paperPrintedComponents(const Eigen::Vector3d& W, double alpha) {
  const double I1 = kInertia(0), I2 = kInertia(1), I3 = kInertia(2);
  return Eigen::Vector3d((I2 - I3) * W(1) * W(2) + alpha * (I3 - I1) * W(0) * W(2) * W(2) -
                             alpha * (I1 - I2) * W(0) * W(1) * W(1),
                         (I3 - I1) * W(2) * W(0) + alpha * (I1 - I2) * W(1) * W(0) * W(0) -
                             alpha * (I2 - I3) * W(1) * W(2) * W(2),
                         (I1 - I2) * W(0) * W(1) + alpha * (I2 - I3) * W(2) * W(1) * W(1) -
                             alpha * (I3 - I1) * W(2) * W(0) * W(0));
}

TEST(RigidBody, VectorFieldMatchesComponentEquations) {
  const double alpha = 0.5;
  const auto body = makeRigidBody(kInertia, alpha);
  Sampler s;
  for (int i = 0; i < 10; ++i) {
    const Eigen::Vector3d M = s.vector<Eigen::Vector3d>();
    const Eigen::Vector3d W = M.cwiseQuotient(kInertia);
    EXPECT_LT((body->vectorField(M) - componentEquations(W, alpha)).norm(), 1e-14);
    // ... and eq. (3.6): Ṁ = M × Ω + α M × (M × Ω).
    EXPECT_LT((body->vectorField(M) - (M.cross(W) + alpha * M.cross(M.cross(W)))).norm(), 1e-14);
    const Eigen::Vector3d phi(alpha * (kInertia(1) - kInertia(2)) * W(1) * W(2),
                              alpha * (kInertia(2) - kInertia(0)) * W(2) * W(0),
                              alpha * (kInertia(0) - kInertia(1)) * W(0) * W(1));
    EXPECT_LT((body->dissipation(body->velocity(M), M) - phi).norm(), 1e-14);
  }
}

// Documents a misprint: the paper's printed components for α ≠ 0 conserve energy
// exactly (Σ Ω_i I_iΩ̇_i ≡ 0), contradicting Proposition 3.3 and eq. (3.6);
// they differ from the vector field by more than round-off.
TEST(RigidBody, PaperPrintedComponentsAreAMisprint) {
  const double alpha = 0.5;
  const auto body = makeRigidBody(kInertia, alpha);
  Sampler s(5);
  for (int i = 0; i < 5; ++i) {
    const Eigen::Vector3d M = s.vector<Eigen::Vector3d>();
    const Eigen::Vector3d W = M.cwiseQuotient(kInertia);
    EXPECT_NEAR(W.dot(paperPrintedComponents(W, alpha)), 0.0, 1e-14);
    EXPECT_GT((body->vectorField(M) - paperPrintedComponents(W, alpha)).norm(), 1e-3);
  }
}

TEST(RigidBody, EnergyDecaysAtDoubleBracketRateAndCasimirIsConstant) {
  for (double alpha : {0.5, 0.0, -0.3}) {
    const auto body = makeRigidBody(kInertia, alpha);
    Sampler s(7);
    for (int i = 0; i < 10; ++i) {
      const Eigen::Vector3d M = s.vector<Eigen::Vector3d>();
      const Eigen::Vector3d f = body->vectorField(M);
      const double d = 1e-5;
      const Eigen::Vector3d plus = M + d * f, minus = M - d * f;
      const double dE = (body->energy(plus) - body->energy(minus)) / (2 * d);
      const double dC = (body->casimirs(plus)(0) - body->casimirs(minus)(0)) / (2 * d);
      const Eigen::Vector3d W = M.cwiseQuotient(kInertia);
      EXPECT_NEAR(dE, -alpha * M.cross(W).squaredNorm(), 1e-9) << "alpha " << alpha;
      EXPECT_NEAR(dC, 0.0, 1e-9);
    }
  }
}

TEST(RigidBody, LagrangianAndHamiltonianAreLegendreDual) {
  const auto body = makeRigidBody(kInertia, 0.5);
  Sampler s(3);
  for (int i = 0; i < 5; ++i) {
    const Eigen::Vector3d M = s.vector<Eigen::Vector3d>();
    const Eigen::Vector3d W = body->velocity(M);
    EXPECT_LT((body->lagrangian()->gradient(W) - M).norm(), 1e-15);
    // H(μ) = <μ, ξ> - l(ξ)
    EXPECT_NEAR(body->energy(M), M.dot(W) - body->lagrangian()->value(W), 1e-15);
  }
}

TEST(RigidBody, AnalyticDerivativesMatchAutodiff) {
  const RigidBodyLagrangian l(kInertia);
  const RigidBodyHamiltonian H(kInertia);
  using LBase = AutoDiffLagrangian<RigidBodyLagrangian, SO3>;
  using HBase = AutoDiffHamiltonian<RigidBodyHamiltonian, SO3>;
  Sampler s(11);
  for (int i = 0; i < 5; ++i) {
    const Eigen::Vector3d x = s.vector<Eigen::Vector3d>(), v = s.vector<Eigen::Vector3d>();
    EXPECT_LT((l.gradient(x) - l.LBase::gradient(x)).norm(), 1e-15);
    EXPECT_LT((l.hessianTimes(x, v) - l.LBase::hessianTimes(x, v)).norm(), 1e-15);
    EXPECT_LT((H.gradient(x) - H.HBase::gradient(x)).norm(), 1e-15);
    EXPECT_LT((H.hessianTimes(x, v) - H.HBase::hessianTimes(x, v)).norm(), 1e-15);
    Eigen::Matrix3d l_columns, H_columns;  // the whole Hessians, column by column by Jets
    for (int j = 0; j < 3; ++j) {
      l_columns.col(j) = l.LBase::hessianTimes(x, Eigen::Vector3d::Unit(j));
      H_columns.col(j) = H.HBase::hessianTimes(x, Eigen::Vector3d::Unit(j));
    }
    EXPECT_LT((l.hessian(x) - l_columns).norm(), 1e-15);
    EXPECT_LT((H.hessian(x) - H_columns).norm(), 1e-15);
  }
}

TEST(RigidBody, RejectsBadParametersNamingThem) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THAT([] { makeRigidBody(Eigen::Vector3d(1, -1, 2), 0.5); },
              ::testing::ThrowsMessage<InvalidArgument>(::testing::HasSubstr("inertia")));
  EXPECT_THAT([] { makeRigidBody(Eigen::Vector3d(1, 0, 2), 0.5); },
              ::testing::ThrowsMessage<InvalidArgument>(::testing::HasSubstr("inertia")));
  EXPECT_THAT([&] { makeRigidBody(Eigen::Vector3d(1, nan, 2), 0.5); },
              ::testing::ThrowsMessage<InvalidArgument>(::testing::HasSubstr("inertia")));
  EXPECT_THAT([&] { makeRigidBody(Eigen::Vector3d(1, 1, 2), nan); },
              ::testing::ThrowsMessage<InvalidArgument>(::testing::HasSubstr("alpha")));
  EXPECT_THAT([] { makeRigidBody(Eigen::Vector3d(1, 1, 2), INFINITY); },
              ::testing::ThrowsMessage<InvalidArgument>(::testing::HasSubstr("alpha")));
}

}  // namespace
}  // namespace ddb::test
