// DirectProduct<G1, G2>: G1 × G2 for fixed-size groups, every function the factors' own on its
// block (docs/reference/conventions.md §1, "Direct products"): ξ = (ξ₁, ξ₂) and μ = (μ₁, μ₂) are
// stacked vectors, ⟨μ, ξ⟩ = ⟨μ₁, ξ₁⟩ + ⟨μ₂, ξ₂⟩, elements the block-diagonal matrices
// diag(g₁, g₂), and the bracket, ad*, Ad*, exp, log, the retractions, their tangents and Legendre
// Jacobians act block by block, each through its factor's closed form. The Casimirs are both
// factors', stacked. A product of three, DirectProduct<G1, G2, G3>, is the product of G1 and
// DirectProduct<G2, G3>.
#pragma once

#include <ddb/core/detail/has_retraction_jacobian.h>
#include <ddb/core/lie_group.h>

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cstddef>
#include <type_traits>

namespace ddb {

namespace detail {
constexpr std::size_t nameLength(const char* s) {
  std::size_t n = 0;
  while (s[n] != '\0') ++n;
  return n;
}
/// "G1xG2", at compile time.
template <class G1, class G2>
struct DirectProductName {
  static constexpr std::size_t kFirst = nameLength(G1::kName), kSecond = nameLength(G2::kName);
  static constexpr std::array<char, kFirst + kSecond + 2> kValue = [] {
    std::array<char, kFirst + kSecond + 2> name{};
    for (std::size_t i = 0; i < kFirst; ++i) name[i] = G1::kName[i];
    name[kFirst] = 'x';
    for (std::size_t i = 0; i < kSecond; ++i) name[kFirst + 1 + i] = G2::kName[i];
    return name;
  }();
};

template <class G, class = void>
struct HasDirectAdRadius : std::false_type {};
template <class G>
struct HasDirectAdRadius<G, std::void_t<decltype(G::adRadius(
                                std::declval<const typename G::template Algebra<double>&>()))>>
    : std::true_type {};
}  // namespace detail

/// G₁ × G₂ × … for two or more fixed-size groups. Three or more are the two-factor product of the
/// first and the product of the rest, DirectProduct<G1, DirectProduct<G2, G3, …>>, whose functions
/// the type inherits: its name is "G1xG2xG3", its states the factors' stacked in order.
template <class G1, class G2, class... Rest>
struct DirectProduct;

/// @cond
// Doxygen takes the base of a recursive specialisation for a cycle: it documents the two-factor
// product only.
template <class G1, class G2, class G3, class... Rest>
struct DirectProduct<G1, G2, G3, Rest...> : DirectProduct<G1, DirectProduct<G2, G3, Rest...>> {};
/// @endcond

/// G₁ × G₂.
template <class G1, class G2>
struct DirectProduct<G1, G2> : LieGroupBase<DirectProduct<G1, G2>> {
  static_assert(G1::kDim != Eigen::Dynamic && G2::kDim != Eigen::Dynamic,
                "DirectProduct<G1, G2> composes fixed-size groups (static kDim and matrices)");
  using First = G1;
  using Second = G2;
  static constexpr int kFirstDim = G1::kDim;
  static constexpr int kSecondDim = G2::kDim;
  static constexpr int kFirstCasimirs = G1::kNumCasimirs;
  static constexpr int kFirstSize = G1::template Matrix<double>::RowsAtCompileTime;
  static constexpr int kSecondSize = G2::template Matrix<double>::RowsAtCompileTime;

  static constexpr const char* kName = detail::DirectProductName<G1, G2>::kValue.data();
  static constexpr int kDim = kFirstDim + kSecondDim;
  static constexpr int kNumCasimirs = G1::kNumCasimirs + G2::kNumCasimirs;

  template <class T>
  using Algebra = Eigen::Matrix<T, kDim, 1>;
  template <class T>
  using Dual = Eigen::Matrix<T, kDim, 1>;
  template <class T>
  using Matrix = Eigen::Matrix<T, kFirstSize + kSecondSize, kFirstSize + kSecondSize>;
  template <class T>
  using Casimirs = Eigen::Matrix<T, kNumCasimirs, 1>;

  // Each factor's algebra and dual are the same vector type, so a block serves as either.
  template <class T>
  using FirstVector = typename G1::template Algebra<T>;
  template <class T>
  using SecondVector = typename G2::template Algebra<T>;
  template <class T>
  using FirstMatrix = typename G1::template Matrix<T>;
  template <class T>
  using SecondMatrix = typename G2::template Matrix<T>;
  static_assert(std::is_same_v<FirstVector<double>, typename G1::template Dual<double>> &&
                    std::is_same_v<SecondVector<double>, typename G2::template Dual<double>>,
                "DirectProduct: each factor's Algebra and Dual must be the same vector type");

  /// ξ₁ (or μ₁) of a stacked vector.
  template <class T>
  static FirstVector<T> first(const Algebra<T>& x) {
    return x.template head<kFirstDim>();
  }
  /// ξ₂ (or μ₂).
  template <class T>
  static SecondVector<T> second(const Algebra<T>& x) {
    return x.template tail<kSecondDim>();
  }
  /// (ξ₁, ξ₂) stacked.
  template <class T>
  static Algebra<T> join(const FirstVector<T>& a, const SecondVector<T>& b) {
    Algebra<T> x;
    x.template head<kFirstDim>() = a;
    x.template tail<kSecondDim>() = b;
    return x;
  }
  /// g₁ and g₂ of diag(g₁, g₂).
  template <class T>
  static FirstMatrix<T> firstBlock(const Matrix<T>& g) {
    return g.template topLeftCorner<kFirstSize, kFirstSize>();
  }
  template <class T>
  static SecondMatrix<T> secondBlock(const Matrix<T>& g) {
    return g.template bottomRightCorner<kSecondSize, kSecondSize>();
  }
  /// diag(g₁, g₂).
  template <class T>
  static Matrix<T> blockDiagonal(const FirstMatrix<T>& a, const SecondMatrix<T>& b) {
    Matrix<T> g = Matrix<T>::Zero();
    g.template topLeftCorner<kFirstSize, kFirstSize>() = a;
    g.template bottomRightCorner<kSecondSize, kSecondSize>() = b;
    return g;
  }

  template <class T>
  static Matrix<T> hat(const Algebra<T>& x) {
    return blockDiagonal<T>(G1::hat(first(x)), G2::hat(second(x)));
  }
  template <class T>
  static Algebra<T> vee(const Matrix<T>& X) {
    return join<T>(G1::vee(firstBlock(X)), G2::vee(secondBlock(X)));
  }
  template <class T>
  static Matrix<T> dualHat(const Dual<T>& mu) {
    return blockDiagonal<T>(G1::dualHat(first(mu)), G2::dualHat(second(mu)));
  }
  /// The off-diagonal blocks pair with nothing: projected away.
  template <class T>
  static Dual<T> dualVee(const Matrix<T>& Y) {
    return join<T>(G1::dualVee(firstBlock(Y)), G2::dualVee(secondBlock(Y)));
  }

  template <class T>
  static T pairing(const Dual<T>& mu, const Algebra<T>& x) {
    return G1::pairing(first(mu), first(x)) + G2::pairing(second(mu), second(x));
  }
  template <class T>
  static Algebra<T> bracket(const Algebra<T>& a, const Algebra<T>& b) {
    return join<T>(G1::bracket(first(a), first(b)), G2::bracket(second(a), second(b)));
  }
  template <class T>
  static Dual<T> adDual(const Algebra<T>& x, const Dual<T>& mu) {
    return join<T>(G1::adDual(first(x), first(mu)), G2::adDual(second(x), second(mu)));
  }
  template <class T>
  static Algebra<T> Ad(const Matrix<T>& g, const Algebra<T>& x) {
    return join<T>(G1::Ad(firstBlock(g), first(x)), G2::Ad(secondBlock(g), second(x)));
  }
  template <class T>
  static Dual<T> AdDual(const Matrix<T>& g, const Dual<T>& mu) {
    return join<T>(G1::AdDual(firstBlock(g), first(mu)), G2::AdDual(secondBlock(g), second(mu)));
  }
  template <class T>
  static Matrix<T> compose(const Matrix<T>& g, const Matrix<T>& h) {
    return blockDiagonal<T>(G1::compose(firstBlock(g), firstBlock(h)),
                            G2::compose(secondBlock(g), secondBlock(h)));
  }
  template <class T>
  static Matrix<T> inverse(const Matrix<T>& g) {
    return blockDiagonal<T>(G1::inverse(firstBlock(g)), G2::inverse(secondBlock(g)));
  }
  /// Both factors' Casimirs, stacked.
  template <class T>
  static Casimirs<T> casimirs(const Dual<T>& mu) {
    Casimirs<T> c;
    c.template head<kFirstCasimirs>() = G1::casimirs(first(mu));
    c.template tail<G2::kNumCasimirs>() = G2::casimirs(second(mu));
    return c;
  }

  template <class T>
  static Matrix<T> exp(const Algebra<T>& x) {
    return blockDiagonal<T>(G1::exp(first(x)), G2::exp(second(x)));
  }
  template <class T>
  static Algebra<T> log(const Matrix<T>& g) {
    return join<T>(G1::log(firstBlock(g)), G2::log(secondBlock(g)));
  }
  template <class T>
  static Algebra<T> dexp(const Algebra<T>& x, const Algebra<T>& y) {
    return join<T>(G1::dexp(first(x), first(y)), G2::dexp(second(x), second(y)));
  }
  template <class T>
  static Algebra<T> dexpInv(const Algebra<T>& x, const Algebra<T>& y) {
    return join<T>(G1::dexpInv(first(x), first(y)), G2::dexpInv(second(x), second(y)));
  }
  template <class T>
  static Dual<T> dexpInvDual(const Algebra<T>& x, const Dual<T>& mu) {
    return join<T>(G1::dexpInvDual(first(x), first(mu)), G2::dexpInvDual(second(x), second(mu)));
  }
  static Eigen::Matrix<double, kDim, kDim> dexpInvDualMatrix(const Algebra<double>& x) {
    return blockMatrix(G1::dexpInvDualMatrix(first(x)), G2::dexpInvDualMatrix(second(x)));
  }
  /// Where both factors write theirs; else the retraction differentiates by Jets.
  template <
      class A = G1, class B = G2,
      std::enable_if_t<
          detail::HasDexpInvDualJacobian<A, FirstVector<double>, FirstVector<double>>::value &&
              detail::HasDexpInvDualJacobian<B, SecondVector<double>, SecondVector<double>>::value,
          int> = 0>
  static Eigen::Matrix<double, kDim, kDim> dexpInvDualJacobian(const Algebra<double>& x,
                                                               const Dual<double>& mu) {
    return blockMatrix(G1::dexpInvDualJacobian(first(x), first(mu)),
                       G2::dexpInvDualJacobian(second(x), second(mu)));
  }

  template <class T>
  static Matrix<T> cay(const Algebra<T>& x) {
    return blockDiagonal<T>(G1::cay(first(x)), G2::cay(second(x)));
  }
  template <class M>
  static auto cayInverse(const M& g) {
    using T = typename M::Scalar;
    return join<T>(G1::cayInverse(firstBlock<T>(g)), G2::cayInverse(secondBlock<T>(g)));
  }
  template <class T>
  static Algebra<T> dcay(const Algebra<T>& x, const Algebra<T>& y) {
    return join<T>(G1::dcay(first(x), first(y)), G2::dcay(second(x), second(y)));
  }
  template <class T>
  static Algebra<T> dcayInv(const Algebra<T>& x, const Algebra<T>& y) {
    return join<T>(G1::dcayInv(first(x), first(y)), G2::dcayInv(second(x), second(y)));
  }
  template <class T>
  static Dual<T> dcayInvDual(const Algebra<T>& x, const Dual<T>& mu) {
    return join<T>(G1::dcayInvDual(first(x), first(mu)), G2::dcayInvDual(second(x), second(mu)));
  }
  /// Ad*_{cay(a) cay(b)} μ by each factor's own transport.
  template <class T>
  static Dual<T> cayTransport(const Algebra<T>& a, const Algebra<T>& b, const Dual<T>& mu) {
    return join<T>(G1::cayTransport(first(a), first(b), first(mu)),
                   G2::cayTransport(second(a), second(b), second(mu)));
  }
  static Eigen::Matrix<double, kDim, kDim> dcayInvDualMatrix(const Algebra<double>& x) {
    return blockMatrix(G1::dcayInvDualMatrix(first(x)), G2::dcayInvDualMatrix(second(x)));
  }
  template <
      class A = G1, class B = G2,
      std::enable_if_t<
          detail::HasDcayInvDualJacobian<A, FirstVector<double>, FirstVector<double>>::value &&
              detail::HasDcayInvDualJacobian<B, SecondVector<double>, SecondVector<double>>::value,
          int> = 0>
  static Eigen::Matrix<double, kDim, kDim> dcayInvDualJacobian(const Algebra<double>& x,
                                                               const Dual<double>& mu) {
    return blockMatrix(G1::dcayInvDualJacobian(first(x), first(mu)),
                       G2::dcayInvDualJacobian(second(x), second(mu)));
  }

  /// ad is block diagonal: the larger of the factors' spectral radii.
  template <
      class A = G1, class B = G2,
      std::enable_if_t<detail::HasDirectAdRadius<A>::value && detail::HasDirectAdRadius<B>::value,
                       int> = 0>
  static double adRadius(const Algebra<double>& x) {
    return std::max(G1::adRadius(first(x)), G2::adRadius(second(x)));
  }

 private:
  template <class M1, class M2>
  static Eigen::Matrix<double, kDim, kDim> blockMatrix(const M1& a, const M2& b) {
    Eigen::Matrix<double, kDim, kDim> m = Eigen::Matrix<double, kDim, kDim>::Zero();
    m.template topLeftCorner<kFirstDim, kFirstDim>() = a;
    m.template bottomRightCorner<kSecondDim, kSecondDim>() = b;
    return m;
  }
};

}  // namespace ddb
