// Generic group suite (one typed test list over every group): exp against Eigen's
// matrix exponential, log∘exp = id, and the defining identities of docs/reference/conventions.md
// §1.
#include <unsupported/Eigen/MatrixFunctions>

#include "test_support.h"

namespace ddb::test {
namespace groups_tests {

template <class TG>
class GroupTest : public ::testing::Test {
 protected:
  using G = typename TG::Group;
  using A = typename G::template Algebra<double>;
  using D = typename G::template Dual<double>;
  using M = typename G::template Matrix<double>;
  Sampler sampler;
  Samples<TG> samples{sampler};
  std::vector<A> points() { return samples.points(/*near_pi=*/true); }
  A algebra() { return samples.algebra(); }
  D dual() { return samples.dual(); }
  M randomElement() { return samples.element(); }
  template <class... Xs>
  static double tol(const Xs&... xs) {
    return kTight * Samples<TG>::scale(xs...);
  }
};

TYPED_TEST_SUITE(GroupTest, AllGroups::Groups);

// LieGroupBase's composed formulas (docs/reference/conventions.md §1: the bracket, ad*, Ad, Ad* and
// the Cayley family, paper eqs. (4.15)-(4.16)) written out again from hat, vee, dualHat and
// dualVee alone, on matrices of dynamic size: the groups' functions are checked against this
// test's own matrix algebra, and Eigen's products, inverse and LU are instantiated once for every
// group rather than once for each fixed size, as for the exponential above
// (docs/results/compile-costs.md, "The group suite's references at the dynamic size").
template <class G>
struct MatrixFormulas {
  using A = typename G::template Algebra<double>;
  using D = typename G::template Dual<double>;
  using Fixed = std::decay_t<decltype(G::hat(std::declval<const A&>()))>;
  using Scalar = typename Fixed::Scalar;
  using Dynamic = Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic>;

  static Dynamic hat(const A& x) { return G::hat(x); }
  static Dynamic dualHat(const D& mu) { return G::dualHat(mu); }
  static A vee(const Dynamic& X) { return G::vee(Fixed(X)); }
  static D dualVee(const Dynamic& M) { return G::dualVee(Fixed(M)); }
  static Dynamic identity(const Dynamic& X) { return Dynamic::Identity(X.rows(), X.cols()); }

  static A bracket(const A& x, const A& y) {
    const Dynamic X = hat(x), Y = hat(y);
    return vee(X * Y - Y * X);
  }
  static D adDual(const A& x, const D& mu) {
    const Dynamic XH = hat(x).adjoint(), M = dualHat(mu);
    return dualVee(XH * M - M * XH);
  }
  static Dynamic inverse(const Dynamic& g) { return g.inverse(); }
  static A Ad(const Dynamic& g, const A& x) { return vee(g * hat(x) * inverse(g)); }
  static D AdDual(const Dynamic& g, const D& mu) {
    return dualVee(g.adjoint() * dualHat(mu) * inverse(g).adjoint());
  }
  static Dynamic cay(const A& x) {
    const Dynamic half = hat(x) * Scalar(0.5), I = identity(half);
    return (I - half).partialPivLu().solve(I + half);
  }
  static A dcay(const A& x, const A& y) {  // (I − X/2)⁻¹ Y (I + X/2)⁻¹
    const Dynamic half = hat(x) * Scalar(0.5), I = identity(half);
    return vee((I - half).partialPivLu().solve(hat(y)) * inverse(I + half));
  }
  static A dcayInv(const A& x, const A& y) {  // (I − X/2) Y (I + X/2)
    const Dynamic half = hat(x) * Scalar(0.5), I = identity(half);
    return vee((I - half) * hat(y) * (I + half));
  }
  static D dcayInvDual(const A& x, const D& mu) {
    const Dynamic half = hat(x) * Scalar(0.5), I = identity(half);
    return dualVee((I - half).adjoint() * dualHat(mu) * (I + half).adjoint());
  }
  static D cayTransport(const A& a, const A& b, const D& mu) { return AdDual(cay(a) * cay(b), mu); }
};

TYPED_TEST(GroupTest, ExpMatchesEigenMatrixExponential) {
  this->samples.forEachSize([&] {
    using G = typename TestFixture::G;
    for (const auto& x : this->points()) {
      // Eigen's exponential of the dynamic-size matrix: one instantiation of its Padé
      // approximants for every group, not one per fixed size (docs/results/compile-costs.md).
      using Scalar = typename TestFixture::M::Scalar;
      const Eigen::Matrix<Scalar, Eigen::Dynamic, Eigen::Dynamic> hat = G::hat(x);
      const typename TestFixture::M expected = hat.exp();
      EXPECT_LT((G::exp(x) - expected).norm(), this->tol(x)) << "x = " << x.transpose();
    }
  });
}

TYPED_TEST(GroupTest, LogInvertsExp) {
  this->samples.forEachSize([&] {
    using G = typename TestFixture::G;
    for (const auto& x : this->points()) {
      // log is ill-conditioned at π: the samples there, |θ| = π − 1e-6, give exp(x) two
      // eigenvalues 2 sin(1e-6) apart, and a rounding of a few ulps in exp(x) turns its
      // eigenvectors by ulps/gap, which moves log by up to 2π·ulps/gap ≈ 3e-9.
      const double tolerance = x.norm() > 3.0 ? 1e-8 : this->tol(x);
      EXPECT_LT((G::log(G::exp(x)) - x).norm(), tolerance) << "x = " << x.transpose();
    }
  });
}

TYPED_TEST(GroupTest, BracketIsMatrixCommutatorAndSatisfiesJacobi) {
  this->samples.forEachSize([&] {
    using G = typename TestFixture::G;
    using A = typename TestFixture::A;
    for (int i = 0; i < 5; ++i) {
      const A x = this->algebra(), y = this->algebra(), z = this->algebra();
      const auto X = G::hat(x), Y = G::hat(y);
      EXPECT_LT((G::hat(G::bracket(x, y)) - (X * Y - Y * X)).norm(), this->tol(x, y));
      const A jacobi = G::bracket(x, G::bracket(y, z)) + G::bracket(y, G::bracket(z, x)) +
                       G::bracket(z, G::bracket(x, y));
      EXPECT_LT(jacobi.norm(), this->tol(x, y, z));
    }
  });
}

TYPED_TEST(GroupTest, PairingIsTracePairingOfRepresentatives) {
  this->samples.forEachSize([&] {
    using G = typename TestFixture::G;
    using A = typename TestFixture::A;
    using D = typename TestFixture::D;
    for (int i = 0; i < 5; ++i) {
      const A x = this->algebra();
      const D mu = this->dual();
      const double trace = std::real((G::dualHat(mu).adjoint() * G::hat(x)).trace());
      EXPECT_NEAR(G::pairing(mu, x), trace, this->tol(mu, x));
      EXPECT_LT((G::dualVee(G::dualHat(mu)) - mu).norm(), this->tol(mu));
    }
  });
}

TYPED_TEST(GroupTest, CoadjointActionsAreDualsOfAdjointActions) {
  this->samples.forEachSize([&] {
    using G = typename TestFixture::G;
    using A = typename TestFixture::A;
    using D = typename TestFixture::D;
    for (int i = 0; i < 5; ++i) {
      const A x = this->algebra(), y = this->algebra();
      const D mu = this->dual();
      const auto g = this->randomElement(), h = this->randomElement();
      // <ad*_x mu, y> = <mu, [x, y]>
      EXPECT_NEAR(G::pairing(G::adDual(x, mu), y), G::pairing(mu, G::bracket(x, y)),
                  this->tol(x, y, mu));
      // <Ad*_g mu, y> = <mu, Ad_g y>, with Ad_g y checked against g Y g^{-1}.
      EXPECT_NEAR(G::pairing(G::AdDual(g, mu), y), G::pairing(mu, G::Ad(g, y)), this->tol(y, mu));
      using Formulas = MatrixFormulas<G>;
      const typename Formulas::Dynamic gYgInv = g * G::hat(y) * Formulas::inverse(g);
      EXPECT_LT((Formulas::hat(G::Ad(g, y)) - gYgInv).norm(), this->tol(y));
      // Ad*_{gh} = Ad*_h Ad*_g
      const D lhs = G::AdDual(G::compose(g, h), mu);
      EXPECT_LT((lhs - G::AdDual(h, G::AdDual(g, mu))).norm(), this->tol(mu));
    }
  });
}

// d/dt Ad*_{exp(tx)} mu at t = 0 is ad*_x mu (with <ad*_x mu, y> = <mu, [x, y]> and
// <Ad*_g mu, y> = <mu, Ad_g y>, docs/reference/conventions.md §1), by central differences.
TYPED_TEST(GroupTest, CoadjointActionDifferentiatesToAdDual) {
  this->samples.forEachSize([&] {
    using G = typename TestFixture::G;
    using A = typename TestFixture::A;
    using D = typename TestFixture::D;
    const double eps = 1e-5;
    for (int i = 0; i < 5; ++i) {
      const A x = this->algebra(), plus = eps * x, minus = -eps * x;
      const D mu = this->dual();
      const D difference = (G::AdDual(G::exp(plus), mu) - G::AdDual(G::exp(minus), mu)) / (2 * eps);
      EXPECT_LT((difference - G::adDual(x, mu)).norm(), 1e-8 * Samples<TypeParam>::scale(x, mu));
    }
  });
}

TYPED_TEST(GroupTest, CasimirsAreConstantOnCoadjointOrbits) {
  this->samples.forEachSize([&] {
    using G = typename TestFixture::G;
    using D = typename TestFixture::D;
    for (int i = 0; i < 5; ++i) {
      const D mu = this->dual();
      const auto g = this->randomElement();
      EXPECT_LT((G::casimirs(G::AdDual(g, mu)) - G::casimirs(mu)).norm(), this->tol(mu));
    }
  });
}

// Each group's bracket, ad*, Ad, Ad* and Cayley family, closed forms or LieGroupBase's at its
// fixed size, against MatrixFormulas; its dexp family against LieGroupBase's series.
TYPED_TEST(GroupTest, ClosedFormsAgreeWithTheMatrixFormulas) {
  this->samples.forEachSize([&] {
    using G = typename TestFixture::G;
    using Base = LieGroupBase<G>;
    using Formulas = MatrixFormulas<G>;
    using A = typename TestFixture::A;
    using D = typename TestFixture::D;
    for (const auto& x : this->points()) {
      const A y = this->algebra();
      const D mu = this->dual();
      const auto g = this->randomElement();
      const typename Formulas::Dynamic matrix_g = g;
      const double tol = this->tol(x, y, mu);
      EXPECT_LT((G::bracket(x, y) - Formulas::bracket(x, y)).norm(), tol);
      EXPECT_LT((G::adDual(x, mu) - Formulas::adDual(x, mu)).norm(), tol);
      EXPECT_LT((G::Ad(g, y) - Formulas::Ad(matrix_g, y)).norm(), tol);
      EXPECT_LT((G::AdDual(g, mu) - Formulas::AdDual(matrix_g, mu)).norm(), tol);
      EXPECT_LT((G::inverse(g) - Formulas::inverse(matrix_g)).norm(), tol);
      // Where G's Cayley map is not the block one, the retraction suite checks it by its
      // defining identities (test_retractions.cc).
      if constexpr (CayleyOfBlocks<G>::value) {
        EXPECT_LT((G::cay(x) - Formulas::cay(x)).norm(), tol);
        EXPECT_LT((G::dcay(x, y) - Formulas::dcay(x, y)).norm(), tol);
        EXPECT_LT((G::dcayInv(x, y) - Formulas::dcayInv(x, y)).norm(), tol);
        EXPECT_LT((G::dcayInvDual(x, mu) - Formulas::dcayInvDual(x, mu)).norm(), tol);
        EXPECT_LT((G::cayTransport(x, y, mu) - Formulas::cayTransport(x, y, mu)).norm(), tol);
      }
      if (x.norm() < 3.0) {  // the series converge for |x| < 2π; near π they need ~100 terms
        EXPECT_LT((G::dexp(x, y) - Base::dexp(x, y)).norm(), 1e-12);
        EXPECT_LT((G::dexpInv(x, y) - Base::dexpInv(x, y)).norm(), 1e-12);
        EXPECT_LT((G::dexpInvDual(x, mu) - Base::dexpInvDual(x, mu)).norm(), 1e-12);
      }
    }
  });
}

TEST(SO3, LogNearPiRecoversAxisUpToSign) {
  // At exactly θ = π the axis sign is ambiguous; exp(log R) must still be R.
  const Eigen::Vector3d axis = Eigen::Vector3d(1, -2, 0.5).normalized();
  const Eigen::Matrix3d R = SO3::exp(Eigen::Vector3d(M_PI * axis));
  const Eigen::Vector3d x = SO3::log(R);
  EXPECT_NEAR(x.norm(), M_PI, 1e-12);
  EXPECT_LT((SO3::exp(x) - R).norm(), 1e-12);
}

}  // namespace groups_tests
}  // namespace ddb::test
