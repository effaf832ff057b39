// The analytic Jacobian of the small Legendre equation (integrators/solvers/legendre_equation.h)
// and its parts, each against central differences and against Jets through the
// scalar-generic formula it differentiates:
//   ∂_x[(dτ^{-1}_x)* mu] of the basic groups' retractions (retraction_jacobian_suite.h; the
//   products' in test_group_products.cc), the SO(3) and SE(3) closed forms
//   against LieGroupBase's Jet versions; the assembled ∂r/∂u in both forms, for DDB's
//   fixed target and the symmetric method's half-force target, on the rigid body, the
//   heavy top, the Kirchhoff body and a user system given by its Lagrangian alone.
#include <ddb/core/autodiff.h>
#include <ddb/core/legendre_hamiltonian.h>
#include <ddb/core/retraction_jacobians.h>
#include <ddb/integrators/methods/symmetric_ddb.h>
#include <ddb/integrators/solvers/legendre_equation.h>
#include <ddb/systems/paper_scenarios.h>

#include "retraction_jacobian_suite.h"
#include "test_support.h"

namespace ddb::test {
namespace legendre_jacobian_tests {

// The suite of every basic group's retractions; the products' are test_group_products.cc's.
using BasicRetractions = ::testing::Types<Cayley<SO2>, Exponential<SO2>, Cayley<SO3>,
                                          Exponential<SO3>, TruncatedExponential<SO3>, Cayley<SE2>,
                                          Exponential<SE2>, TruncatedExponential<SE2>, Cayley<SE3>,
                                          Exponential<SE3>, TruncatedExponential<SE3>>;
// The prefix is the suite's name, which ctest's names keep (gtest_discover_tests).
INSTANTIATE_TYPED_TEST_SUITE_P(RetractionJacobianTest, RetractionJacobianTest, BasicRetractions);

// The closed forms against Jets through the formula they differentiate
// (core/retraction_jacobians.h).
TEST(RetractionJacobian, ClosedFormsMatchJets) {
  Sampler s;
  for (double size : {1e-4, 0.09, 0.11, 0.5, 1.0, 2.0, 3.0}) {
    const Eigen::Vector3d x = size * s.vector<Eigen::Vector3d>().normalized();
    const Eigen::Vector3d mu = s.vector<Eigen::Vector3d>();
    EXPECT_LT((SO3::dcayInvDualJacobian(x, mu) - dcayInvDualJacobianByJets<SO3>(x, mu)).norm(),
              1e-14 * (1 + x.squaredNorm()) * mu.norm());
    // c(θ) of dexp^{-1} loses ~1e-16/θ² to cancellation in either evaluation.
    EXPECT_LT((SO3::dexpInvDualJacobian(x, mu) - dexpInvDualJacobianByJets<SO3>(x, mu)).norm(),
              1e-12 * (1 + x.squaredNorm()) * mu.norm())
        << "|x| = " << size;
    using V6 = Eigen::Matrix<double, 6, 1>;
    const V6 x6 = size * s.vector<V6>().normalized(), mu6 = s.vector<V6>();
    EXPECT_LT((SE3::dcayInvDualJacobian(x6, mu6) - dcayInvDualJacobianByJets<SE3>(x6, mu6)).norm(),
              1e-14 * (1 + x6.squaredNorm()) * mu6.norm());
    // The products' block forms (groups/semidirect_product.h), composed from their factor's.
    using SE3Composed = SemidirectProduct<SO3>;
    EXPECT_LT((SE3Composed::dcayInvDualJacobian(x6, mu6) -
               dcayInvDualJacobianByJets<SE3Composed>(x6, mu6))
                  .norm(),
              1e-14 * (1 + x6.squaredNorm()) * mu6.norm());
    const Eigen::Vector3d x3 = size * s.vector<Eigen::Vector3d>().normalized();
    EXPECT_LT((SE2::dcayInvDualJacobian(x3, mu) - dcayInvDualJacobianByJets<SE2>(x3, mu)).norm(),
              1e-14 * (1 + x3.squaredNorm()) * mu.norm());
  }
}

// Where a group writes no closed form (SE3's exponential), dexpInvDualJacobian<G> falls back to
// Jets: against central differences of SE3::dexpInvDual (step 1e-6, error O(1e-10)).
TEST(RetractionJacobian, TheFallbackByJetsMatchesCentralDifferences) {
  Sampler s;
  using V6 = Eigen::Matrix<double, 6, 1>;
  for (double size : {0.1, 1.0, 2.5}) {
    const V6 x = size * s.vector<V6>().normalized(), mu = s.vector<V6>();
    const Eigen::Matrix<double, 6, 6> jets = dexpInvDualJacobian<SE3>(x, mu);
    Eigen::Matrix<double, 6, 6> differences;
    const double step = 1e-6;
    for (int j = 0; j < 6; ++j) {
      const V6 e = V6::Unit(j) * step;
      differences.col(j) =
          (SE3::dexpInvDual(V6(x + e), mu) - SE3::dexpInvDual(V6(x - e), mu)) / (2 * step);
    }
    EXPECT_LT((jets - differences).norm(), 1e-8 * (1 + x.squaredNorm()) * mu.norm())
        << "|x| = " << size;
  }
}

// l(Ω) = ½Ω·𝕀Ω + β/4 |Ω|⁴: a user system written as l alone (H by the Legendre transform).
class QuarticLagrangian : public AutoDiffLagrangian<QuarticLagrangian, SO3> {
 public:
  template <class T>
  T evaluate(const Eigen::Matrix<T, 3, 1>& w) const {
    const T square = w(0) * w(0) + w(1) * w(1) + w(2) * w(2);  // nested Jets: no squaredNorm
    return constant<T>(0.5) * (constant<T>(1.0) * w(0) * w(0) + constant<T>(1.3) * w(1) * w(1) +
                               constant<T>(0.5) * w(2) * w(2)) +
           constant<T>(0.25 * 0.3) * square * square;
  }
};

// The assembled Jacobian at random unknowns against the residual differentiated by Jets
// and by central differences.
template <class R, class Target>
void expectJacobianMatches(const LiePoissonSystem<typename R::Group>& system, const Target& target,
                           LegendreForm form, double h, const std::string& what) {
  using G = typename R::Group;
  constexpr int n = G::kDim;
  using V = Eigen::Matrix<double, n, 1>;
  const R retraction;
  const LegendreEquation<R, Target> equation{system, retraction, target, h, form};
  const auto residual = [&](const auto& u) {
    Eigen::Matrix<typename std::decay_t<decltype(u)>::Scalar, n, 1> r;
    equation.residual(u.data(), r.data());
    return r;
  };
  Sampler s;
  for (int i = 0; i < 5; ++i) {
    const V u = s.vector<V>();
    V r;
    Eigen::Matrix<double, n, n> analytic;
    equation(u.data(), r.data(), analytic.data());
    const V expected_r = residual(u);
    EXPECT_LT((r - expected_r).norm(), 1e-15 * (1 + u.norm())) << what;
    const auto jets = jacobianByJets<n>(residual, u);
    const auto numeric = centralDifferences<n>(residual, u);
    const double scale = 1 + analytic.norm();
    EXPECT_LT((analytic - jets).norm(), 1e-13 * scale) << what << " against Jets";
    EXPECT_LT((analytic - numeric).norm(), 1e-7 * scale) << what << " against differences";
  }
}

template <class R>
void expectBothTargets(std::shared_ptr<const LiePoissonSystem<typename R::Group>> system,
                       const typename R::Group::template Dual<double>& mu,
                       const std::string& name) {
  const R retraction;
  const FixedMomentum<typename R::Group> fixed{mu};
  const HalfForceTarget<R> half{*system, retraction, mu, 0.3};
  std::vector<LegendreForm> forms{LegendreForm::kHamiltonian};
  if (system->lagrangian() != nullptr) forms.push_back(LegendreForm::kLagrangian);
  for (const LegendreForm form : forms) {
    const std::string what = name + "/" + R::kName +
                             (form == LegendreForm::kLagrangian ? "/lagrangian" : "/hamiltonian");
    expectJacobianMatches<R>(*system, fixed, form, 0.3, what + "/ddb");
    expectJacobianMatches<R>(*system, half, form, 0.3, what + "/sddb");
  }
}

TEST(LegendreJacobian, MatchesJetsAndDifferences) {
  const auto& a = rigidBodyScenario("A");
  const auto body = a.system();
  expectBothTargets<Cayley<SO3>>(body, a.mu0(), "rigid-body");
  expectBothTargets<Exponential<SO3>>(body, a.mu0(), "rigid-body");
  expectBothTargets<TruncatedExponential<SO3>>(body, a.mu0(), "rigid-body");
  const HeavyTopSetup top;
  expectBothTargets<Cayley<SE3>>(top.system(), top.mu0, "heavy-top");
  expectBothTargets<Exponential<SE3>>(top.system(), top.mu0, "heavy-top");
  const KirchhoffSetup kirchhoff;
  expectBothTargets<Cayley<SE3>>(kirchhoff.system(), kirchhoff.mu0, "kirchhoff");
  const auto user =
      makeSystemFromLagrangian<SO3>("quartic", std::make_shared<const QuarticLagrangian>(),
                                    std::make_shared<const ScaledIdentityMetric<SO3>>(0.5));
  expectBothTargets<Cayley<SO3>>(user, a.mu0(), "quartic");
}

}  // namespace legendre_jacobian_tests
}  // namespace ddb::test
