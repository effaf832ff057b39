// Generic retraction suite over every (group, retraction) pair: τ(0) = e,
// τ(x)τ(-x) = e, τ^{-1}∘τ = id, dτ against central differences of τ,
// dτ∘dτ^{-1} = I, the dual against the pairing, and the paper's identity
// (dτ^{-1}_{-x})* = Ad*_{τ(x)} (dτ^{-1}_x)* (Section 4.1).
#include <type_traits>
#include <unsupported/Eigen/MatrixFunctions>

#include "order_fit.h"
#include "test_support.h"

namespace ddb::test {
namespace retractions_tests {

template <class TG>
class RetractionTest : public ::testing::Test {
 protected:
  using G = typename TG::Group;
  using R = typename TG::Retraction;
  using A = typename G::template Algebra<double>;
  using D = typename G::template Dual<double>;
  R retraction;
  Sampler sampler;
  Samples<TG> samples{sampler};
  std::vector<A> points() {
    // Cayley is singular nowhere on compact groups but the near-π points matter only for exp.
    auto p = samples.points(/*near_pi=*/true);
    for (int i = 0; i < 2; ++i) p.push_back(1.5 * samples.algebra());
    return p;
  }
  A algebra() { return samples.algebra(); }
  D dual() { return samples.dual(); }
  template <class... Xs>
  static double scale(const Xs&... xs) {
    return Samples<TG>::scale(xs...);
  }
};

// Every group with the Cayley and with the exponential retraction.
template <class... Ts>
struct Concat;
template <class... As, class... Bs>
struct Concat<::testing::Types<As...>, ::testing::Types<Bs...>> {
  using type = ::testing::Types<As..., Bs...>;
};
using AllRetractions = Concat<AllGroups::With<Cayley>, AllGroups::With<Exponential>>::type;
TYPED_TEST_SUITE(RetractionTest, AllRetractions);

TYPED_TEST(RetractionTest, IdentityAndInverseProperty) {
  this->samples.forEachSize([&] {
    using G = typename TestFixture::G;
    using A = typename TestFixture::A;
    const auto& r = this->retraction;
    const A zero = this->algebra() * 0.0;
    EXPECT_LT((r.tau(zero) - G::identityLike(r.tau(zero))).norm(), kTight);
    for (const auto& x : this->points()) {
      const A minus = -x;
      const auto product = G::compose(r.tau(x), r.tau(minus));
      EXPECT_LT((product - G::identityLike(product)).norm(), 1e-12 * this->scale(x))
          << "x = " << x.transpose();
    }
  });
}

TYPED_TEST(RetractionTest, TauInverseInvertsTau) {
  this->samples.forEachSize([&] {
    for (const auto& x : this->points()) {
      const double tolerance = (x.norm() > 3.0 ? 1e-8 : 1e-12) * this->scale(x);
      EXPECT_LT((this->retraction.tauInverse(this->retraction.tau(x)) - x).norm(),
                tolerance * (1 + x.norm()))
          << "x = " << x.transpose();
    }
  });
}

TYPED_TEST(RetractionTest, TangentMatchesCentralDifferences) {
  this->samples.forEachSize([&] {
    using G = typename TestFixture::G;
    using A = typename TestFixture::A;
    const auto& r = this->retraction;
    const double eps = 1e-6;
    for (const auto& x : this->points()) {
      const A y = this->algebra();
      const A xp = x + eps * y, xm = x - eps * y;
      const auto difference = ((r.tau(xp) - r.tau(xm)) / (2 * eps)).eval();
      // T_xτ(y) = dτ_x(y) τ(x)
      const auto expected = (G::hat(r.dTau(x, y)) * r.tau(x)).eval();
      EXPECT_LT((difference - expected).norm(), 1e-8 * (1 + x.squaredNorm()) * this->scale(y))
          << "x = " << x.transpose();
    }
  });
}

TYPED_TEST(RetractionTest, TangentInverseAndDual) {
  this->samples.forEachSize([&] {
    using G = typename TestFixture::G;
    using A = typename TestFixture::A;
    using D = typename TestFixture::D;
    const auto& r = this->retraction;
    for (const auto& x : this->points()) {
      // The exponential's dτ⁻¹ is a series with poles at ad-radius 2π; matrix groups reach
      // that at spectral radius π, where it cannot be summed to round-off.
      if (std::is_same_v<typename TestFixture::R, Exponential<G>> &&
          Samples<TypeParam>::adRadius(x) > 4.0) {
        continue;
      }
      const A y = this->algebra();
      const D mu = this->dual();
      const double scale = (1 + x.squaredNorm()) * this->scale(y, mu);
      EXPECT_LT((r.dTau(x, r.dTauInverse(x, y)) - y).norm(), 1e-12 * scale);
      EXPECT_LT((r.dTauInverse(x, r.dTau(x, y)) - y).norm(), 1e-12 * scale);
      EXPECT_NEAR(G::pairing(r.dTauInverseDual(x, mu), y), G::pairing(mu, r.dTauInverse(x, y)),
                  1e-12 * scale);
      const A minus = -x;
      const D lhs = r.dTauInverseDual(minus, mu);
      const D rhs = G::AdDual(r.tau(x), r.dTauInverseDual(x, mu));
      EXPECT_LT((lhs - rhs).norm(), 1e-12 * scale) << "x = " << x.transpose();
    }
  });
}

TEST(Cayley, SO3DualMatchesPaperClosedForm) {
  // (dcay^{-1}_x)* = I + x̂/2 + x xᵀ/4 (paper, Section 4.1).
  Sampler s;
  Cayley<SO3> cay;
  for (int i = 0; i < 5; ++i) {
    const Eigen::Vector3d x = 2 * s.vector<Eigen::Vector3d>(), mu = s.vector<Eigen::Vector3d>();
    const Eigen::Matrix3d closed =
        Eigen::Matrix3d::Identity() + SO3::hat(x) / 2 + x * x.transpose() / 4;
    EXPECT_LT((cay.dTauInverseDual(x, mu) - closed * mu).norm(), 1e-14);
  }
}

// Truncated dexp^{-1}: the error against the closed form scales like |x|^q, q the
// index of the first omitted non-zero Bernoulli term (B_j = 0 for odd j > 1), so
// q = order + 1 when order + 1 is even and order + 2 otherwise. Fitted log-log slope.
TEST(TruncatedExponential, ErrorShrinksLikeFirstOmittedPower) {
  Sampler s;
  const Eigen::Vector3d direction = s.vector<Eigen::Vector3d>().normalized();
  const Eigen::Vector3d mu = s.vector<Eigen::Vector3d>();
  for (int order = 1; order <= 6; ++order) {
    TruncatedExponential<SO3> truncated(order);
    Exponential<SO3> exact;
    const std::vector<double> radii{1.0, 0.7, 0.5, 0.35, 0.25, 0.18, 0.125, 0.09};
    std::vector<double> errors;
    for (double r : radii) {
      const Eigen::Vector3d x = r * direction;
      errors.push_back((truncated.dTauInverseDual(x, mu) - exact.dTauInverseDual(x, mu)).norm());
    }
    const OrderFit fit = fitOrder(radii, errors);  // round-off plateau (< 1e-13) dropped
    ASSERT_GE(fit.points, 4) << "order " << order;
    const int expected = (order + 1) % 2 == 0 ? order + 1 : order + 2;
    EXPECT_NEAR(fit.slope, expected, 0.1) << "order " << order;
  }
}

}  // namespace retractions_tests
}  // namespace ddb::test
