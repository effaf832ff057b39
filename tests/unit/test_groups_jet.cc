// The fixed-size groups on ceres::Jet as on double (Sophus's habit): every implicit solve
// differentiates SO3 and SE3 through Jets, so the group identities of docs/reference/conventions.md
// §1 are checked on both scalars, the Jet's derivative parts included (an identity between
// functions holds for their derivatives too). Then the derivatives the solves use, taken by
// Jets, against central differences of the double formulas, at points on both sides of the
// small-angle branches (θ² = 1e-6 in dexp^{-1}).
#include <ceres/jet.h>

#include "test_support.h"

namespace ddb::test {
namespace groups_jet_tests {

constexpr int kSeeds = 4;  // infinitesimal directions of the Jet samples
using Jet = ceres::Jet<double, kSeeds>;

template <class G, class T>
struct ScalarCase {
  using Group = G;
  using Scalar = T;
};

/// The largest |value| or |derivative| in a scalar, vector or matrix.
inline double largest(double x) { return std::abs(x); }
inline double largest(const Jet& x) { return std::max(std::abs(x.a), x.v.cwiseAbs().maxCoeff()); }
template <class Derived>
double largest(const Eigen::MatrixBase<Derived>& m) {
  double most = 0.0;
  for (Eigen::Index i = 0; i < m.size(); ++i) most = std::max(most, largest(m.derived()(i)));
  return most;
}

template <class TC>
class GroupOnScalarTest : public ::testing::Test {
 protected:
  using G = typename TC::Group;
  using T = typename TC::Scalar;
  using A = typename G::template Algebra<T>;
  using D = typename G::template Dual<T>;

  /// Entries in [-scale, scale]; on Jets, infinitesimal parts in [-1, 1].
  template <class V>
  V sample(double scale = 1.0) {
    V v;
    for (Eigen::Index i = 0; i < v.size(); ++i) {
      if constexpr (std::is_same_v<T, Jet>) {
        v(i) = Jet(scale * s_.uniform());
        for (int k = 0; k < kSeeds; ++k) v(i).v(k) = s_.uniform();
      } else {
        v(i) = scale * s_.uniform();
      }
    }
    return v;
  }
  /// |value part| = scale exactly (below π: log's domain).
  A algebra(double scale = 1.0) {
    const A x = sample<A>();
    double norm2 = 0.0;
    for (Eigen::Index i = 0; i < x.size(); ++i) norm2 += std::pow(valueOf(x(i)), 2);
    return x * T(scale / std::sqrt(norm2));
  }
  static double valueOf(double x) { return x; }
  static double valueOf(const Jet& x) { return x.a; }
  D dual() { return sample<D>(); }
  auto element() { return G::exp(algebra()); }

  Sampler s_{77};
};

using Cases = ::testing::Types<ScalarCase<SO3, double>, ScalarCase<SO3, Jet>,
                               ScalarCase<SE3, double>, ScalarCase<SE3, Jet>>;
TYPED_TEST_SUITE(GroupOnScalarTest, Cases);

TYPED_TEST(GroupOnScalarTest, BracketSatisfiesJacobiAndPairingIsDual) {
  using G = typename TestFixture::G;
  for (int i = 0; i < 5; ++i) {
    const auto x = this->algebra(), y = this->algebra(), z = this->algebra();
    const auto mu = this->dual();
    const auto jacobi = (G::bracket(x, G::bracket(y, z)) + G::bracket(y, G::bracket(z, x)) +
                         G::bracket(z, G::bracket(x, y)))
                            .eval();
    EXPECT_LT(largest(jacobi), kTight);
    EXPECT_LT(largest(G::pairing(G::adDual(x, mu), y) - G::pairing(mu, G::bracket(x, y))), kTight);
  }
}

TYPED_TEST(GroupOnScalarTest, CoadjointActionIsDualOfAdjointAndAHomomorphism) {
  using G = typename TestFixture::G;
  for (int i = 0; i < 5; ++i) {
    const auto g = this->element(), h = this->element();
    const auto y = this->algebra();
    const auto mu = this->dual();
    EXPECT_LT(largest(G::pairing(G::AdDual(g, mu), y) - G::pairing(mu, G::Ad(g, y))), kTight);
    const auto conjugated = (g * G::hat(y) * G::inverse(g)).eval();
    EXPECT_LT(largest((G::hat(G::Ad(g, y)) - conjugated).eval()), kTight);
    EXPECT_LT(largest((G::AdDual(G::compose(g, h), mu) - G::AdDual(h, G::AdDual(g, mu))).eval()),
              kTight);
    EXPECT_LT(largest((G::casimirs(G::AdDual(g, mu)) - G::casimirs(mu)).eval()), kTight);
  }
}

TYPED_TEST(GroupOnScalarTest, ExpAndCayAreRetractionsAndLogInvertsExp) {
  using G = typename TestFixture::G;
  using A = typename TestFixture::A;
  for (double scale : {1e-4, 1.0, 2.5}) {
    const A x = this->algebra(scale);
    const A minus_x = -x;
    const auto identity = G::compose(G::exp(x), G::exp(minus_x));
    const auto cay_identity = G::compose(G::cay(x), G::cay(minus_x));
    using M = std::decay_t<decltype(identity)>;
    EXPECT_LT(largest((identity - M::Identity()).eval()), kTight) << scale;
    EXPECT_LT(largest((cay_identity - M::Identity()).eval()), kTight) << scale;
    EXPECT_LT(largest((G::log(G::exp(x)) - x).eval()), 1e-12) << scale;
  }
}

TYPED_TEST(GroupOnScalarTest, ClosedFormsAgreeWithGenericBase) {
  using G = typename TestFixture::G;
  using Base = LieGroupBase<G>;
  for (double scale : {5e-4, 2e-3, 1.0, 2.5}) {  // both sides of the θ² = 1e-6 branch
    const auto x = this->algebra(scale), y = this->algebra();
    const auto mu = this->dual();
    EXPECT_LT(largest((G::cay(x) - Base::cay(x)).eval()), kTight) << scale;
    EXPECT_LT(largest((G::dcayInvDual(x, mu) - Base::dcayInvDual(x, mu)).eval()), kTight) << scale;
    EXPECT_LT(largest((G::cayTransport(x, y, mu) - Base::cayTransport(x, y, mu)).eval()), kTight)
        << scale;
    if (!std::is_same_v<typename TestFixture::T, Jet> || scale > 0.05) {
      // On Jets, below θ = 0.05 see DexpJetDerivativeLosesDigitsAboveItsTaylorThreshold.
      EXPECT_LT(largest((G::dexp(x, y) - Base::dexp(x, y)).eval()), 1e-12) << scale;
    }
    EXPECT_LT(largest((G::dexpInvDual(x, mu) - Base::dexpInvDual(x, mu)).eval()), 1e-12) << scale;
  }
}

/// d/dx f(x) by Jets against central differences of f on doubles, column by column.
template <class G, class F>
void expectJetDerivativeMatchesCentralDifferences(const F& f,
                                                  const typename G::template Algebra<double>& x,
                                                  const char* what) {
  constexpr int n = G::kDim;
  using J = ceres::Jet<double, n>;
  typename G::template Algebra<J> lifted;
  for (int i = 0; i < n; ++i) lifted(i) = J(x(i), i);
  const auto jet = f(lifted);
  const double step = 1e-6;
  for (int i = 0; i < n; ++i) {
    typename G::template Algebra<double> plus = x, minus = x;
    plus(i) += step;
    minus(i) -= step;
    const auto difference = ((f(plus) - f(minus)) / (2 * step)).eval();
    for (Eigen::Index k = 0; k < difference.size(); ++k) {
      EXPECT_NEAR(jet(k).v(i), difference(k), 1e-8 * std::max(1.0, std::abs(difference(k))))
          << what << ": d/dx_" << i << " of entry " << k << " at |x| = " << x.norm();
    }
  }
}

template <class G>
void checkSolveDerivatives() {
  Sampler s(5);
  const auto mu = s.vector<typename G::template Dual<double>>();
  const auto y = s.vector<typename G::template Algebra<double>>();
  const auto direction = s.vector<typename G::template Algebra<double>>().normalized();
  for (double r : {5e-4, 2e-3, 0.7, 2.5}) {
    const typename G::template Algebra<double> x = r * direction;
    const auto dual = [&](const auto& z) {
      using T = typename std::decay_t<decltype(z)>::Scalar;
      return typename G::template Dual<T>(mu.template cast<T>());
    };
    const auto algebra = [&](const auto& z) {
      using T = typename std::decay_t<decltype(z)>::Scalar;
      return typename G::template Algebra<T>(y.template cast<T>());
    };
    expectJetDerivativeMatchesCentralDifferences<G>(
        [&](const auto& z) { return G::dcayInvDual(z, dual(z)); }, x, "dcayInvDual");
    expectJetDerivativeMatchesCentralDifferences<G>(
        [&](const auto& z) { return G::dexpInvDual(z, dual(z)); }, x, "dexpInvDual");
    expectJetDerivativeMatchesCentralDifferences<G>(
        [&](const auto& z) { return G::cayTransport(z, algebra(z), dual(z)); }, x, "cayTransport");
    expectJetDerivativeMatchesCentralDifferences<G>(
        [&](const auto& z) { return G::AdDual(G::exp(z), dual(z)); }, x, "AdDual(exp)");
  }
}

// A known defect, kept visible: SO3::dexp switches to its Taylor series only below
// θ² = 1e-8, and just above it (θ − sin θ)/θ³ cancels; the values stay good to round-off
// (the factor multiplies θ²), their Jet derivatives do not (docs/design/architecture.md, "Jets").
// The closed form and its branch decide every exp trajectory on SE(3) bit for bit, so the
// threshold moves with a release that may change trajectories; only Newton Jacobians
// (sddb-exp on SE(3)) see the error, not results. Against the generic series on Jets
// (accurate there), where the loss is large enough not to depend on libm's rounding:
TEST(GroupJets, DexpJetDerivativeLosesDigitsAboveItsTaylorThreshold) {
  using Base = LieGroupBase<SO3>;
  for (double theta : {1.5e-4, 5e-4}) {
    Eigen::Matrix<Jet, 3, 1> x, y;
    for (int i = 0; i < 3; ++i) {
      x(i) = Jet(theta * (i + 1) / std::sqrt(14.0), i);
      y(i) = Jet(0.3 * i - 0.4);
    }
    const double error = largest((SO3::dexp(x, y) - Base::dexp(x, y)).eval());
    EXPECT_GT(error, 1e-11) << theta << ": fixed? then drop this test and the exclusion above";
    EXPECT_LT(error, 1e-8) << theta;
  }
}

TEST(GroupJets, SO3DerivativesMatchCentralDifferences) { checkSolveDerivatives<SO3>(); }
TEST(GroupJets, SE3DerivativesMatchCentralDifferences) { checkSolveDerivatives<SE3>(); }

}  // namespace groups_jet_tests
}  // namespace ddb::test
