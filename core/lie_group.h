// LieGroupBase: the abstract interface every group implements (CRTP; the API is
// Sophus-like static functions, the split into a required and a deduced part is manif's).
//
// Minimum API: a group `G : LieGroupBase<G>` provides, as scalar-generic static members
// (checked one by one, with a message each, by core/group_traits.h):
//   kDim, kNumCasimirs (Eigen::Dynamic for matrix groups whose N is chosen at run time)
//   Algebra<T>, Dual<T>, Matrix<T> (group elements too), Casimirs<T>
//   hat(x) -> Matrix     matrix representation of the algebra element x
//   vee(X) -> Algebra    inverse of hat on the algebra
//   dualHat(mu)          Riesz representer: <mu, x> = Re tr(dualHat(mu)^H hat(x))
//   dualVee(Y)           the dual element y with <y, x> = Re tr(Y^H hat(x)) for all x
//                        (for any matrix Y: the orthogonal projection is built in)
//   exp(x), log(g), casimirs(mu)
// Deduced API: everything composed below is written once from those; a group may shadow any of
// them with a closed form (SO3 does), and the generic test suite checks each
// group's versions against the defining identities of docs/reference/conventions.md §1:
//   <ad*_x mu, y> = <mu, [x, y]>,  <Ad*_g mu, y> = <mu, Ad_g y>,  Ad*_{gh} = Ad*_h Ad*_g.
//
// The algebra and dual element types are parameters: fixed-size Eigen vectors for
// SO(3) and SE(3) (pairing = dot product), N×N matrices for SO(N) and SU(N)
// (hat = vee = identity, pairing Re tr(A^H B)); no n×n operator is ever formed here.
#pragma once

#include <ddb/core/detail/bernoulli.h>
#include <ddb/core/detail/linear_map_matrix.h>
#include <ddb/core/detail/scalar.h>
#include <ddb/core/errors.h>

#include <Eigen/Core>
#include <Eigen/LU>
#include <complex>
#include <type_traits>
#include <utility>

namespace ddb {

template <class Derived>
struct LieGroupBase {
  // Signatures are generic in the argument type (A: algebra, D: dual, M: matrix):
  // Derived is incomplete here, and T would not be deducible through its aliases.
  /// The identity of a fixed-size group (matrix groups: identityLike(g)).
  template <class T>
  static auto identity() {
    using M = typename Derived::template Matrix<T>;
    static_assert(M::RowsAtCompileTime != Eigen::Dynamic,
                  "identity<T>() needs a fixed size: use identityLike(g) for matrix groups");
    return M(M::Identity());
  }
  /// x ← its part in the algebra. The coordinates of a fixed-size group are the algebra:
  /// nothing to project (matrix groups shadow it: SkewHermitianGroup).
  template <class A>
  static void projectToAlgebra(A&) {}
  /// The identity of the size of m (any group).
  template <class M>
  static M identityLike(const M& m) {
    return M::Identity(m.rows(), m.cols());
  }
  template <class M>
  static M compose(const M& g, const M& h) {
    return g * h;
  }
  template <class M>
  static M inverse(const M& g) {
    return g.inverse();
  }

  /// <mu, x> = Re tr(dualHat(mu)^H hat(x)) = Re Σ conj(M_ij) X_ij: O(N²), no product.
  template <class D, class A>
  static auto pairing(const D& mu, const A& x) {
    return realPart(Derived::dualHat(mu).conjugate().cwiseProduct(Derived::hat(x)).sum());
  }

  /// [x, y] = XY - YX.
  template <class A>
  static A bracket(const A& x, const A& y) {
    const auto X = Derived::hat(x);
    const auto Y = Derived::hat(y);
    return Derived::vee(matrix<A>(X * Y - Y * X));
  }

  /// ad*_x mu, from <mu, XY - YX> = Re tr((X^H M - M X^H)^H Y) with M = dualHat(mu).
  template <class A, class D>
  static D adDual(const A& x, const D& mu) {
    const auto XH = matrix<A>(Derived::hat(x).adjoint());
    const auto M = Derived::dualHat(mu);
    return Derived::dualVee(matrix<A>(XH * M - M * XH));
  }

  /// Ad_g x = g X g^{-1}.
  template <class M, class A>
  static A Ad(const M& g, const A& x) {
    return Derived::vee(M(g * Derived::hat(x) * Derived::inverse(g)));
  }

  /// Ad*_g mu, from <mu, g Y g^{-1}> = Re tr((g^H M g^{-H})^H Y).
  template <class M, class D>
  static D AdDual(const M& g, const D& mu) {
    const M gInvH = Derived::inverse(g).adjoint();
    return Derived::dualVee(M(g.adjoint() * Derived::dualHat(mu) * gInvH));
  }

  /// Cayley map cay(x) = (I - X/2)^{-1}(I + X/2) (paper, Section 4.1 b)).
  template <class A>
  static auto cay(const A& x) {
    const auto half = matrix<A>(Derived::hat(x) * typename A::Scalar(0.5));
    const auto I = identityLike(half);
    return matrix<A>((I - half).partialPivLu().solve(I + half));
  }

  /// Ad*_{cay(a) cay(b)} mu, the DDB update (paper, eq. (4.12)) with τ = cay; SO3 shadows it
  /// with an unbiased vector form (docs/results/casimir-drift.md).
  template <class A, class D>
  static D cayTransport(const A& a, const A& b, const D& mu) {
    return Derived::AdDual(Derived::compose(Derived::cay(a), Derived::cay(b)), mu);
  }

  /// cay^{-1}(g) = 2 (g - I)(g + I)^{-1} (g and its generator commute).
  template <class M>
  static auto cayInverse(const M& g) {
    const M I = identityLike(g);
    const M X = (g + I).transpose().partialPivLu().solve((g - I).transpose()).transpose();
    return Derived::vee(M(X * typename M::Scalar(2)));
  }

  /// dcay_x y = (I - X/2)^{-1} Y (I + X/2)^{-1} (paper, eq. (4.15)).
  template <class A>
  static A dcay(const A& x, const A& y) {
    const auto half = matrix<A>(Derived::hat(x) * typename A::Scalar(0.5));
    const auto I = identityLike(half);
    const auto left = matrix<A>((I - half).partialPivLu().solve(Derived::hat(y)));
    const auto both = matrix<A>((I + half).transpose().partialPivLu().solve(left.transpose()));
    return Derived::vee(matrix<A>(both.transpose()));
  }

  /// dcay^{-1}_x y = (I - X/2) Y (I + X/2) (paper, eq. (4.16)).
  template <class A>
  static A dcayInv(const A& x, const A& y) {
    const auto half = matrix<A>(Derived::hat(x) * typename A::Scalar(0.5));
    const auto I = identityLike(half);
    return Derived::vee(matrix<A>((I - half) * Derived::hat(y) * (I + half)));
  }

  /// (dcay^{-1}_x)* mu = dualVee((I - X/2)^H M (I + X/2)^H), M = dualHat(mu).
  template <class A, class D>
  static D dcayInvDual(const A& x, const D& mu) {
    const auto half = matrix<A>(Derived::hat(x) * typename A::Scalar(0.5));
    const auto I = identityLike(half);
    return Derived::dualVee(
        matrix<A>((I - half).adjoint() * Derived::dualHat(mu) * (I + half).adjoint()));
  }

  /// Right-trivialised tangent of exp: dexp_x y = Σ_j ad_x^j y / (j+1)!  (paper, eq. (4.13)).
  template <class A>
  static A dexp(const A& x, const A& y) {
    return sumSeries<A>(
        y, [&](const A& z) { return Derived::bracket(x, z); },
        [](int j) {
          double f = 1.0;
          for (int i = 2; i <= j + 1; ++i) f *= i;
          return 1.0 / f;
        },
        kMaxBernoulliIndex);
  }

  /// dexp^{-1}_x y = Σ_j B_j/j! ad_x^j y (paper, eq. (4.14)), summed to round-off.
  template <class A>
  static A dexpInv(const A& x, const A& y) {
    return sumSeries<A>(
        y, [&](const A& z) { return Derived::bracket(x, z); }, bernoulliOverFactorial,
        kMaxBernoulliIndex);
  }

  /// (dexp^{-1}_x)* mu = Σ_j B_j/j! (ad*_x)^j mu, summed to round-off.
  template <class A, class D>
  static D dexpInvDual(const A& x, const D& mu) {
    return sumSeries<D>(
        mu, [&](const D& m) { return Derived::adDual(x, m); }, bernoulliOverFactorial,
        kMaxBernoulliIndex);
  }

  /// The series of dexp^{-1}_x truncated after the ad_x^order term (the paper's runs: order 2).
  template <class A>
  static A dexpInvSeries(const A& x, const A& y, int order) {
    return sumSeries<A>(
        y, [&](const A& z) { return Derived::bracket(x, z); }, bernoulliOverFactorial, order,
        /*to_round_off=*/false);
  }

  /// Dual of dexpInvSeries: Σ_{j<=order} B_j/j! (ad*_x)^j mu.
  template <class A, class D>
  static D dexpInvDualSeries(const A& x, const D& mu, int order) {
    return sumSeries<D>(
        mu, [&](const D& m) { return Derived::adDual(x, m); }, bernoulliOverFactorial, order,
        /*to_round_off=*/false);
  }

  /// The matrix of mu ↦ (dcay^{-1}_x)* mu (fixed-size groups), column by column.
  template <class A>
  static auto dcayInvDualMatrix(const A& x) {
    return linearMapMatrix<A::RowsAtCompileTime>(
        [&](const auto& mu) { return Derived::dcayInvDual(x, mu); });
  }

  /// The matrix of mu ↦ (dexp^{-1}_x)* mu (fixed-size groups), column by column.
  template <class A>
  static auto dexpInvDualMatrix(const A& x) {
    return linearMapMatrix<A::RowsAtCompileTime>(
        [&](const auto& mu) { return Derived::dexpInvDual(x, mu); });
  }

 protected:
  /// The group's matrix type for algebra type A (the type hat returns, so that complex
  /// matrix algebras keep their scalar), materialised from an expression.
  template <class A, class Expression>
  static auto matrix(const Expression& e) {
    using M = std::decay_t<decltype(Derived::hat(std::declval<const A&>()))>;
    return M(e);
  }

 private:
  // Σ_{j=0}^{max_order} c(j) A^j v. With to_round_off, stops once two consecutive
  // terms are below round-off relative to the sum (odd Bernoulli terms vanish);
  // throws BudgetExhausted if that does not happen by max_order (|x| beyond the radius 2π).
  template <class V, class Operator, class Coefficient>
  static V sumSeries(const V& v, const Operator& apply, const Coefficient& c, int max_order,
                     bool to_round_off = true) {
    V power = v;
    V sum = v * typename V::Scalar(c(0));
    int small_terms = 0;
    for (int j = 1; j <= max_order; ++j) {
      power = apply(power);
      const double cj = c(j);
      if (cj != 0.0) sum += power * typename V::Scalar(cj);
      if (!to_round_off) continue;
      const double term = std::abs(cj) * scalarNorm(power);
      small_terms = (term <= 1e-17 * scalarNorm(sum)) ? small_terms + 1 : 0;
      if (small_terms >= 2 || scalarNorm(power) == 0.0) return sum;
    }
    if (to_round_off) {
      // A step size too large for this state, not bad input: a solve failure that ends
      // the run and keeps its prefix (docs/reference/guarantees.md).
      throw BudgetExhausted("dexp series",
                            std::to_string(max_order) +
                                " terms did not reach round-off (|x| is beyond "
                                "the radius of convergence 2π)",
                            -1, NAN, NAN);
    }
    return sum;
  }

  template <class V>
  static double scalarNorm(const V& v) {
    double s = 0.0;
    for (Eigen::Index i = 0; i < v.size(); ++i) {
      const double a = std::abs(scalarPart(v.data()[i]));
      s += a * a;
    }
    return std::sqrt(s);
  }
};

}  // namespace ddb
