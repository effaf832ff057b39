// Generic group suite (one typed test list over every group): exp against Eigen's
// matrix exponential, log∘exp = id, and the defining identities of docs/conventions.md §1.
#include <unsupported/Eigen/MatrixFunctions>

#include "test_support.h"

namespace ddb::test {
namespace {

template <class G>
class GroupTest : public ::testing::Test {
 protected:
  using A = typename G::template Algebra<double>;
  using D = typename G::template Dual<double>;
  using M = typename G::template Matrix<double>;
  Sampler sampler;
  std::vector<A> points() { return samplePoints<G>(sampler, /*near_pi=*/true); }
  M randomElement() { return G::exp(sampler.vector<A>()); }
};

TYPED_TEST_SUITE(GroupTest, AllGroups::Groups);

TYPED_TEST(GroupTest, ExpMatchesEigenMatrixExponential) {
  using G = TypeParam;
  for (const auto& x : this->points()) {
    const typename TestFixture::M expected = G::hat(x).exp();
    EXPECT_LT((G::exp(x) - expected).norm(), kTight) << "x = " << x.transpose();
  }
}

TYPED_TEST(GroupTest, LogInvertsExp) {
  using G = TypeParam;
  for (const auto& x : this->points()) {
    const double tolerance = x.norm() > 3.0 ? 1e-9 : kTight;  // log is ill-conditioned at π
    EXPECT_LT((G::log(G::exp(x)) - x).norm(), tolerance) << "x = " << x.transpose();
  }
}

TYPED_TEST(GroupTest, BracketIsMatrixCommutatorAndSatisfiesJacobi) {
  using G = TypeParam;
  using A = typename TestFixture::A;
  for (int i = 0; i < 5; ++i) {
    const A x = this->sampler.template vector<A>(), y = this->sampler.template vector<A>(),
            z = this->sampler.template vector<A>();
    const auto X = G::hat(x), Y = G::hat(y);
    EXPECT_LT((G::hat(G::bracket(x, y)) - (X * Y - Y * X)).norm(), kTight);
    const A jacobi = G::bracket(x, G::bracket(y, z)) + G::bracket(y, G::bracket(z, x)) +
                     G::bracket(z, G::bracket(x, y));
    EXPECT_LT(jacobi.norm(), kTight);
  }
}

TYPED_TEST(GroupTest, PairingIsTracePairingOfRepresentatives) {
  using G = TypeParam;
  using A = typename TestFixture::A;
  using D = typename TestFixture::D;
  for (int i = 0; i < 5; ++i) {
    const A x = this->sampler.template vector<A>();
    const D mu = this->sampler.template vector<D>();
    const double trace = (G::dualHat(mu).adjoint() * G::hat(x)).trace();
    EXPECT_NEAR(G::pairing(mu, x), trace, kTight);
    EXPECT_LT((G::dualVee(G::dualHat(mu)) - mu).norm(), kTight);
  }
}

TYPED_TEST(GroupTest, CoadjointActionsAreDualsOfAdjointActions) {
  using G = TypeParam;
  using A = typename TestFixture::A;
  using D = typename TestFixture::D;
  for (int i = 0; i < 5; ++i) {
    const A x = this->sampler.template vector<A>(), y = this->sampler.template vector<A>();
    const D mu = this->sampler.template vector<D>();
    const auto g = this->randomElement(), h = this->randomElement();
    // <ad*_x mu, y> = <mu, [x, y]>
    EXPECT_NEAR(G::pairing(G::adDual(x, mu), y), G::pairing(mu, G::bracket(x, y)), kTight);
    // <Ad*_g mu, y> = <mu, Ad_g y>, with Ad_g y checked against g Y g^{-1}.
    EXPECT_NEAR(G::pairing(G::AdDual(g, mu), y), G::pairing(mu, G::Ad(g, y)), kTight);
    const auto gYgInv = (g * G::hat(y) * g.inverse()).eval();
    EXPECT_LT((G::hat(G::Ad(g, y)) - gYgInv).norm(), kTight);
    // Ad*_{gh} = Ad*_h Ad*_g
    const D lhs = G::AdDual(G::compose(g, h), mu);
    EXPECT_LT((lhs - G::AdDual(h, G::AdDual(g, mu))).norm(), kTight);
  }
}

TYPED_TEST(GroupTest, CasimirsAreConstantOnCoadjointOrbits) {
  using G = TypeParam;
  using D = typename TestFixture::D;
  for (int i = 0; i < 5; ++i) {
    const D mu = this->sampler.template vector<D>();
    const auto g = this->randomElement();
    EXPECT_LT((G::casimirs(G::AdDual(g, mu)) - G::casimirs(mu)).norm(), kTight);
  }
}

TYPED_TEST(GroupTest, ClosedFormsAgreeWithGenericBase) {
  using G = TypeParam;
  using Base = LieGroupBase<G>;
  using A = typename TestFixture::A;
  using D = typename TestFixture::D;
  for (const auto& x : this->points()) {
    const A y = this->sampler.template vector<A>();
    const D mu = this->sampler.template vector<D>();
    const auto g = this->randomElement();
    EXPECT_LT((G::bracket(x, y) - Base::bracket(x, y)).norm(), kTight);
    EXPECT_LT((G::adDual(x, mu) - Base::adDual(x, mu)).norm(), kTight);
    EXPECT_LT((G::Ad(g, y) - Base::Ad(g, y)).norm(), kTight);
    EXPECT_LT((G::AdDual(g, mu) - Base::AdDual(g, mu)).norm(), kTight);
    EXPECT_LT((G::inverse(g) - g.inverse()).norm(), kTight);
    EXPECT_LT((G::cay(x) - Base::cay(x)).norm(), kTight);
    EXPECT_LT((G::dcay(x, y) - Base::dcay(x, y)).norm(), kTight);
    EXPECT_LT((G::dcayInv(x, y) - Base::dcayInv(x, y)).norm(), kTight);
    EXPECT_LT((G::dcayInvDual(x, mu) - Base::dcayInvDual(x, mu)).norm(), kTight);
    if (x.norm() < 3.0) {  // the series converge for |x| < 2π; near π they need ~100 terms
      EXPECT_LT((G::dexp(x, y) - Base::dexp(x, y)).norm(), 1e-12);
      EXPECT_LT((G::dexpInv(x, y) - Base::dexpInv(x, y)).norm(), 1e-12);
      EXPECT_LT((G::dexpInvDual(x, mu) - Base::dexpInvDual(x, mu)).norm(), 1e-12);
    }
  }
}

TEST(SO3, LogNearPiRecoversAxisUpToSign) {
  // At exactly θ = π the axis sign is ambiguous; exp(log R) must still be R.
  const Eigen::Vector3d axis = Eigen::Vector3d(1, -2, 0.5).normalized();
  const Eigen::Matrix3d R = SO3::exp(Eigen::Vector3d(M_PI * axis));
  const Eigen::Vector3d x = SO3::log(R);
  EXPECT_NEAR(x.norm(), M_PI, 1e-12);
  EXPECT_LT((SO3::exp(x) - R).norm(), 1e-12);
}

}  // namespace
}  // namespace ddb::test
