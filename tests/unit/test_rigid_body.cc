// The rigid body against the component equations of the paper's Examples 3.1/3.5 and
// the energy/Casimir rates of Proposition 3.3, by central differences along the flow.
#include <ceres/jet.h>
#include <ddb/core/legendre_hamiltonian.h>
#include <ddb/systems/heavy_top.h>
#include <ddb/systems/kirchhoff.h>
#include <ddb/systems/manakov_body.h>
#include <ddb/systems/paper_scenarios.h>
#include <ddb/systems/rigid_body.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <gmock/gmock.h>

#include "test_support.h"

namespace ddb::test {
namespace rigid_body_tests {

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

// makeLiePoissonSystem keeps the concrete types of H and k♯ (TypedLiePoissonSystem), so that its
// double vector field calls them without virtual dispatch when they are final. A type that is not
// final must still reach the override of the object it is given: here a subclass that doubles
// ∂H/∂μ, so that the field is 2 M × Ω + 2α M × (M × Ω), not the base class's.
// (The metric is passed as a pointer to non-const: makeLiePoissonSystem takes either.)
class DiagonalQuadraticHamiltonian : public Hamiltonian<SO3> {
 public:
  explicit DiagonalQuadraticHamiltonian(const Eigen::Vector3d& inverse) : inverse_(inverse) {}
  double value(const Eigen::Vector3d& m) const override {
    return 0.5 * m.dot(inverse_.cwiseProduct(m));
  }
  Eigen::Vector3d gradient(const Eigen::Vector3d& m) const override {
    return inverse_.cwiseProduct(m);
  }
  Eigen::Vector3d hessianTimes(const Eigen::Vector3d&, const Eigen::Vector3d& v) const override {
    return inverse_.cwiseProduct(v);
  }

 protected:
  Eigen::Vector3d inverse_;
};
class DoubledQuadraticHamiltonian final : public DiagonalQuadraticHamiltonian {
 public:
  using DiagonalQuadraticHamiltonian::DiagonalQuadraticHamiltonian;
  double value(const Eigen::Vector3d& m) const override { return m.dot(inverse_.cwiseProduct(m)); }
  Eigen::Vector3d gradient(const Eigen::Vector3d& m) const override {
    return 2.0 * inverse_.cwiseProduct(m);
  }
  Eigen::Vector3d hessianTimes(const Eigen::Vector3d&, const Eigen::Vector3d& v) const override {
    return 2.0 * inverse_.cwiseProduct(v);
  }
};

TEST(TypedLiePoissonSystem, CallsTheOverridesOfATypeThatIsNotFinal) {
  const double alpha = 0.5;
  const std::shared_ptr<const DiagonalQuadraticHamiltonian> doubled =
      std::make_shared<const DoubledQuadraticHamiltonian>(kInertia.cwiseInverse());
  const auto system =
      makeLiePoissonSystem("doubled", doubled, std::make_shared<ScaledIdentityMetric<SO3>>(alpha));
  Sampler s(13);
  for (int i = 0; i < 5; ++i) {
    const Eigen::Vector3d M = s.vector<Eigen::Vector3d>();
    const Eigen::Vector3d W = 2.0 * M.cwiseQuotient(kInertia);
    EXPECT_LT((system->vectorField(M) - (M.cross(W) + alpha * M.cross(M.cross(W)))).norm(), 1e-14);
  }
}

// The typed double field (makeRigidBody) and the generic one (a system built from the base
// classes, and the Jet path of either) are one function: equal values to a few ulps (equal
// bits without floating-point contraction), and the Jets' derivative matches central
// differences of the typed field.
TEST(TypedLiePoissonSystem, AgreesWithTheGenericFieldAndItsJetDerivative) {
  const double alpha = 0.5;
  const auto typed = makeRigidBody(kInertia, alpha);
  const LiePoissonSystem<SO3> generic("rigid-body",
                                      std::make_shared<const RigidBodyHamiltonian>(kInertia),
                                      std::make_shared<const ScaledIdentityMetric<SO3>>(alpha));
  using Jet = ceres::Jet<double, 3>;
  Sampler s(17);
  for (int i = 0; i < 5; ++i) {
    const Eigen::Vector3d M = s.vector<Eigen::Vector3d>();
    const double ulps = 4 * std::numeric_limits<double>::epsilon() * generic.vectorField(M).norm();
    EXPECT_LE((typed->vectorField(M) - generic.vectorField(M)).norm(), ulps);
    Eigen::Matrix<Jet, 3, 1> jet_M;
    for (int j = 0; j < 3; ++j) jet_M(j) = Jet(M(j), j);
    const Eigen::Matrix<Jet, 3, 1> jet_field = typed->vectorField(jet_M);
    const double d = 1e-6;
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector3d e = Eigen::Vector3d::Unit(j);
      const Eigen::Vector3d central = (typed->vectorField(Eigen::Vector3d(M + d * e)) -
                                       typed->vectorField(Eigen::Vector3d(M - d * e))) /
                                      (2 * d);
      for (int r = 0; r < 3; ++r) {
        EXPECT_NEAR(jet_field(r).a, typed->vectorField(M)(r), ulps);
        EXPECT_NEAR(jet_field(r).v(j), central(r), 1e-8 * (1 + std::abs(central(r))));
      }
    }
  }
}

// The library's factories keep their parts' types, so that explicit steps take the typed path.
template <class G, class H, class K>
bool isTyped(const std::shared_ptr<const LiePoissonSystem<G>>& system) {
  return dynamic_cast<const TypedLiePoissonSystem<G, H, K>*>(system.get()) != nullptr;
}
TEST(TypedLiePoissonSystem, TheLibrarysSystemsAreTyped) {
  const Eigen::Matrix<double, 6, 1> metric = Eigen::Matrix<double, 6, 1>::Ones();
  EXPECT_TRUE((
      isTyped<SO3, RigidBodyHamiltonian, ScaledIdentityMetric<SO3>>(makeRigidBody(kInertia, 0.5))));
  EXPECT_TRUE((isTyped<SE3, HeavyTopHamiltonian, DiagonalMetric<SE3>>(
      makeHeavyTop(kInertia, 1.0, Eigen::Vector3d::UnitZ(), 0.5, metric))));
  EXPECT_TRUE((isTyped<SE3, KirchhoffHamiltonian, DiagonalMetric<SE3>>(
      makeKirchhoffBody(kInertia, kInertia, 0.5, metric))));
  EXPECT_TRUE((isTyped<SON, ManakovHamiltonian, ScaledIdentityMetric<SON>>(
      makeManakovBody(Eigen::VectorXd::LinSpaced(4, 1.0, 2.0), 0.5))));
  EXPECT_TRUE(
      (isTyped<SUN, ZeitlinHamiltonian, ScaledIdentityMetric<SUN>>(makeZeitlinFluid(4, 0.5))));
  EXPECT_TRUE((isTyped<SO3, LegendreHamiltonian<SO3>, DissipationMetric<SO3>>(
      makeSystemFromLagrangian<SO3>("from-l", std::make_shared<const RigidBodyLagrangian>(kInertia),
                                    std::make_shared<const ScaledIdentityMetric<SO3>>(0.5)))));
}

TEST(TypedLiePoissonSystem, RejectsANullHamiltonianOrMetricNamingIt) {
  const auto metric = std::make_shared<const ScaledIdentityMetric<SO3>>(0.5);
  const auto hamiltonian = std::make_shared<const RigidBodyHamiltonian>(kInertia);
  EXPECT_THAT(
      [&] { makeLiePoissonSystem("x", std::shared_ptr<const RigidBodyHamiltonian>(), metric); },
      ::testing::ThrowsMessage<InvalidArgument>(::testing::HasSubstr("hamiltonian")));
  EXPECT_THAT(
      [&] {
        makeLiePoissonSystem("x", hamiltonian, std::shared_ptr<const ScaledIdentityMetric<SO3>>());
      },
      ::testing::ThrowsMessage<InvalidArgument>(::testing::HasSubstr("metric")));
}

}  // namespace rigid_body_tests
}  // namespace ddb::test
