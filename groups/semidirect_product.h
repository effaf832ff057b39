// SemidirectProduct<G>: G ⋉ Rⁿ for a fixed-size real matrix group G acting on Rⁿ by its own
// n×n matrices (SE(2) = SO(2) ⋉ R², SE(3) = SO(3) ⋉ R³), composed from G's functions
// (docs/guide/defining-a-system.md, "A group made of groups"; the formulas are derived in
// docs/reference/conventions.md §1, "Semidirect products").
//
// Elements (g, r) are the (n+1)×(n+1) matrices [[g, r], [0, 1]]; ξ = (ω, v) ∈ 𝔤 × Rⁿ and
// μ = (π, γ) ∈ 𝔤* × Rⁿ are stacked vectors, paired by <π, ω>_G + γ·v. With Ω = hat_G(ω) and
// the diamond v ⋄ γ ∈ 𝔤* defined by <v ⋄ γ, η> = γ·hat_G(η) v (= dualVee_G(γ vᵀ)):
//   [(ω₁, v₁), (ω₂, v₂)] = ([ω₁, ω₂], Ω₁v₂ − Ω₂v₁),   ad*_(ω,v)(π, γ) = (ad*_ω π − v ⋄ γ, Ωᵀγ),
//   Ad*_(g,r)(π, γ) = (Ad*_g(π − r ⋄ γ), gᵀγ).
// The Cayley map and its tangents are the block forms of the paper's eqs. (4.15), (4.16) with
// A = I − Ω/2:  cay(ω, v) = (cay_G(ω), A⁻¹v),  dcay^{-1}_(ω,v)(η, u) = (dcay^{-1}_ω η, A(u +
// Hv/2)), H = hat_G(η), and its dual (dcay^{-1}_(ω,v))*(π, γ) = ((dcay^{-1}_ω)*π + v ⋄ Aᵀγ / 2,
// Aᵀγ). exp(ω, v) = (exp_G(ω), φ(Ω)v) with φ(Ω) = Σ_k Ω^k/(k+1)!, from SemidirectProductTraits<G>
// where it has a closed form (SO(3): φ(ω̂) = dexp_ω), else summed to round-off; dexp and dexp^{-1}
// are LieGroupBase's series. What composition cannot deduce, the group's name and its Casimirs,
// SemidirectProductTraits<G> states (groups/se2.h and groups/se3.h for SO(2) and SO(3)).
#pragma once

#include <ddb/core/detail/has_retraction_jacobian.h>
#include <ddb/core/detail/is_complete.h>
#include <ddb/core/lie_group.h>

#include <Eigen/Core>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <type_traits>
#include <utility>

namespace ddb {

/// What SemidirectProduct<G> takes from its user: specialise it for G with
/// @code
///   static constexpr const char* kName;             // the product's name
///   static constexpr int kNumCasimirs;
///   template <class T> static Eigen::Matrix<T, kNumCasimirs, 1> casimirs(pi, gamma);
/// @endcode
/// and, optionally, closed forms of φ(Ω)v = Σ_k Ω^k v/(k+1)! and of its inverse:
/// @code
///   template <class T> static Vector<T> expIntegral(omega, v);
///   template <class T> static Vector<T> expIntegralInverse(omega, r);
/// @endcode
template <class G>
struct SemidirectProductTraits;

namespace detail {
template <class Traits, class W, class V, class = void>
struct HasExpIntegral : std::false_type {};
template <class Traits, class W, class V>
struct HasExpIntegral<
    Traits, W, V,
    std::void_t<decltype(Traits::expIntegral(std::declval<const W&>(), std::declval<const V&>())),
                decltype(Traits::expIntegralInverse(
                    std::declval<const W&>(), std::declval<const V&>()))>> : std::true_type {};

template <class G, class = void>
struct HasCayAdDual : std::false_type {};
template <class G>
struct HasCayAdDual<G, std::void_t<decltype(G::cayAdDual(
                           std::declval<const typename G::template Algebra<double>&>(),
                           std::declval<const typename G::template Dual<double>&>()))>>
    : std::true_type {};

template <class G, class = void>
struct HasGroupAdRadius : std::false_type {};
template <class G>
struct HasGroupAdRadius<G, std::void_t<decltype(G::adRadius(
                               std::declval<const typename G::template Algebra<double>&>()))>>
    : std::true_type {};
}  // namespace detail

template <class G>
struct SemidirectProduct : LieGroupBase<SemidirectProduct<G>> {
  using Factor = G;
  using Traits = SemidirectProductTraits<G>;
  static_assert(detail::kIsComplete<Traits>,
                "SemidirectProduct<G> needs SemidirectProductTraits<G>: specialise it with kName, "
                "kNumCasimirs and casimirs(pi, gamma) (groups/se2.h has SO(2)'s)");
  static_assert(G::kDim != Eigen::Dynamic,
                "SemidirectProduct<G> composes a fixed-size group G (static kDim and matrices)");
  static_assert(G::template Matrix<double>::RowsAtCompileTime ==
                        G::template Matrix<double>::ColsAtCompileTime &&
                    std::is_same_v<typename G::template Matrix<double>::Scalar, double>,
                "SemidirectProduct<G>: G must act on R^n by real n x n matrices");
  /// n: G acts on Rⁿ by its n×n matrices.
  static constexpr int kVectorDim = G::template Matrix<double>::RowsAtCompileTime;
  static constexpr int kFactorDim = G::kDim;

  /// G's types. Its algebra and dual are both kFactorDim-vectors, so that a stacked vector's
  /// factor part serves as either (factor()).
  template <class T>
  using FactorAlgebra = typename G::template Algebra<T>;
  template <class T>
  using FactorDual = typename G::template Dual<T>;
  template <class T>
  using FactorMatrix = typename G::template Matrix<T>;
  static_assert(std::is_same_v<FactorAlgebra<double>, FactorDual<double>>,
                "SemidirectProduct<G>: G's Algebra and Dual must be the same vector type");

  static constexpr const char* kName = Traits::kName;
  static constexpr int kDim = kFactorDim + kVectorDim;
  static constexpr int kNumCasimirs = Traits::kNumCasimirs;

  template <class T>
  using Algebra = Eigen::Matrix<T, kDim, 1>;
  template <class T>
  using Dual = Eigen::Matrix<T, kDim, 1>;
  template <class T>
  using Matrix = Eigen::Matrix<T, kVectorDim + 1, kVectorDim + 1>;
  template <class T>
  using Casimirs = Eigen::Matrix<T, kNumCasimirs, 1>;
  /// The vector part's type, Rⁿ.
  template <class T>
  using Vector = Eigen::Matrix<T, kVectorDim, 1>;

  template <class T>
  static Matrix<T> hat(const Algebra<T>& x) {
    Matrix<T> X = Matrix<T>::Zero();
    X.template topLeftCorner<kVectorDim, kVectorDim>() = G::hat(factor(x));
    X.template topRightCorner<kVectorDim, 1>() = vector(x);
    return X;
  }
  template <class T>
  static Algebra<T> vee(const Matrix<T>& X) {
    return join(G::vee(FactorMatrix<T>(X.template topLeftCorner<kVectorDim, kVectorDim>())),
                Vector<T>(X.template topRightCorner<kVectorDim, 1>()));
  }
  /// <μ, ξ> = Re tr(dualHat(μ)ᵀ hat(ξ)) with dualHat(μ) = [[dualHat_G(π), γ], [0, 0]].
  template <class T>
  static Matrix<T> dualHat(const Dual<T>& mu) {
    Matrix<T> M = Matrix<T>::Zero();
    M.template topLeftCorner<kVectorDim, kVectorDim>() = G::dualHat(factor(mu));
    M.template topRightCorner<kVectorDim, 1>() = vector(mu);
    return M;
  }
  template <class T>
  static Dual<T> dualVee(const Matrix<T>& Y) {
    return join(G::dualVee(FactorMatrix<T>(Y.template topLeftCorner<kVectorDim, kVectorDim>())),
                Vector<T>(Y.template topRightCorner<kVectorDim, 1>()));
  }

  template <class T>
  static T pairing(const Dual<T>& mu, const Algebra<T>& x) {
    return G::pairing(factor(mu), factor(x)) + vector(mu).dot(vector(x));
  }
  template <class T>
  static Algebra<T> bracket(const Algebra<T>& a, const Algebra<T>& b) {
    return join(G::bracket(factor(a), factor(b)),
                Vector<T>(G::hat(factor(a)) * vector(b) - G::hat(factor(b)) * vector(a)));
  }
  /// v ⋄ γ ∈ 𝔤*: <v ⋄ γ, η> = γ·hat_G(η)v, i.e. dualVee_G(γ vᵀ).
  template <class T>
  static FactorDual<T> diamond(const Vector<T>& v, const Vector<T>& gamma) {
    return G::dualVee(FactorMatrix<T>(gamma * v.transpose()));
  }
  /// ad*_(ω,v)(π, γ) = (ad*_ω π − v ⋄ γ, Ωᵀγ).
  template <class T>
  static Dual<T> adDual(const Algebra<T>& x, const Dual<T>& mu) {
    const Vector<T> gamma = vector(mu);
    return join(FactorDual<T>(G::adDual(factor(x), factor(mu)) - diamond<T>(vector(x), gamma)),
                Vector<T>(G::hat(factor(x)).transpose() * gamma));
  }
  /// Ad*_(g,r)(π, γ) = (Ad*_g(π − r ⋄ γ), gᵀγ).
  template <class T>
  static Dual<T> AdDual(const Matrix<T>& g, const Dual<T>& mu) {
    const FactorMatrix<T> R = g.template topLeftCorner<kVectorDim, kVectorDim>();
    const Vector<T> r = g.template topRightCorner<kVectorDim, 1>();
    const Vector<T> gamma = vector(mu);
    return join(G::AdDual(R, FactorDual<T>(factor(mu) - diamond<T>(r, gamma))),
                Vector<T>(R.transpose() * gamma));
  }
  template <class T>
  static Matrix<T> inverse(const Matrix<T>& g) {
    const FactorMatrix<T> inverse_rotation =
        G::inverse(FactorMatrix<T>(g.template topLeftCorner<kVectorDim, kVectorDim>()));
    Matrix<T> out = Matrix<T>::Identity();
    out.template topLeftCorner<kVectorDim, kVectorDim>() = inverse_rotation;
    out.template topRightCorner<kVectorDim, 1>() =
        -inverse_rotation * g.template topRightCorner<kVectorDim, 1>();
    return out;
  }

  template <class T>
  static Casimirs<T> casimirs(const Dual<T>& mu) {
    return Traits::casimirs(factor(mu), vector(mu));
  }

  /// cay(ω, v) = [[cay_G(ω), A⁻¹v], [0, 1]], A = I − Ω/2, A⁻¹ = (cay_G(ω) + I)/2.
  template <class T>
  static Matrix<T> cay(const Algebra<T>& x) {
    const FactorMatrix<T> rotation = G::cay(factor(x));
    Matrix<T> g = Matrix<T>::Identity();
    g.template topLeftCorner<kVectorDim, kVectorDim>() = rotation;
    g.template topRightCorner<kVectorDim, 1>() = halfStepInverseOf<T>(rotation) * vector(x);
    return g;
  }
  /// cay^{-1}(g, r) = (cay_G^{-1}(g), A r), with A from ω = cay_G^{-1}(g).
  template <class M>
  static auto cayInverse(const M& g) {
    using T = typename M::Scalar;
    const FactorAlgebra<T> w =
        G::cayInverse(FactorMatrix<T>(g.template topLeftCorner<kVectorDim, kVectorDim>()));
    const Vector<T> r = g.template topRightCorner<kVectorDim, 1>();
    return join(w, Vector<T>(r - G::hat(w) * r * T(0.5)));
  }
  /// dcay_(ω,v)(η, u) = (dcay_ω η, A⁻¹u − K v/2), K = hat_G(dcay_ω η).
  template <class T>
  static Algebra<T> dcay(const Algebra<T>& x, const Algebra<T>& y) {
    const FactorAlgebra<T> k = G::dcay(factor(x), factor(y));
    return join(
        k, Vector<T>(halfStepInverse<T>(factor(x)) * vector(y) - G::hat(k) * vector(x) * T(0.5)));
  }
  /// dcay^{-1}_(ω,v)(η, u) = (dcay^{-1}_ω η, A(u + H v/2)), H = hat_G(η).
  template <class T>
  static Algebra<T> dcayInv(const Algebra<T>& x, const Algebra<T>& y) {
    return join(G::dcayInv(factor(x), factor(y)),
                Vector<T>(halfStep(x) * (vector(y) + G::hat(factor(y)) * vector(x) * T(0.5))));
  }
  /// (dcay^{-1}_(ω,v))*(π, γ) = ((dcay^{-1}_ω)*π + v ⋄ γ'/2, γ'), γ' = Aᵀγ: the transpose of
  /// dcayInv.
  template <class T>
  static Dual<T> dcayInvDual(const Algebra<T>& x, const Dual<T>& mu) {
    const Vector<T> gamma = halfStep(x).transpose() * vector(mu);
    return join(FactorDual<T>(G::dcayInvDual(factor(x), factor(mu)) +
                              diamond<T>(vector(x), gamma) * T(0.5)),
                gamma);
  }
  /// Ad*_{cay(x)} μ: (Ad*_{cay ω}(π − r ⋄ γ), cay(ω)ᵀγ) with r = A⁻¹v. G's own transport moves
  /// π (SO3's unbiased vector form, docs/results/casimir-drift.md), and cay(ω)ᵀγ is applied as
  /// γ + A⁻ᵀΩᵀγ (cay(ω) = (I + Ω/2)A⁻¹, and I + Ω/2 − A = Ω), so that the only rounding of
  /// order ulp(γ) is the final sum, as in SO3::cayAdDual.
  template <class T>
  static Dual<T> cayAdDual(const Algebra<T>& x, const Dual<T>& mu) {
    const FactorAlgebra<T> w = factor(x);
    const Vector<T> gamma = vector(mu);
    const FactorMatrix<T> Omega = G::hat(w);
    // A⁻¹ once, for r and for the γ part.
    const FactorMatrix<T> A_inverse = halfStepInverse<T>(w);
    const Vector<T> r = A_inverse * vector(x);
    return join(factorCayAdDual<T>(w, FactorDual<T>(factor(mu) - diamond<T>(r, gamma))),
                Vector<T>(gamma + A_inverse.transpose() * Vector<T>(Omega.transpose() * gamma)));
  }
  /// Ad*_{cay(a) cay(b)} μ = Ad*_{cay(b)} Ad*_{cay(a)} μ, the DDB update (paper, eq. (4.12)).
  template <class T>
  static Dual<T> cayTransport(const Algebra<T>& a, const Algebra<T>& b, const Dual<T>& mu) {
    return cayAdDual<T>(b, cayAdDual<T>(a, mu));
  }
  /// The matrix of (dcay^{-1}_x)*: [[D_G, Δ_v Aᵀ/2], [0, Aᵀ]], D_G G's matrix and Δ_v the matrix
  /// of γ ↦ v ⋄ γ.
  static Eigen::Matrix<double, kDim, kDim> dcayInvDualMatrix(const Algebra<double>& x) {
    const Vector<double> v = vector(x);
    const FactorMatrix<double> At = halfStep(x).transpose();
    Eigen::Matrix<double, kDim, kDim> D = Eigen::Matrix<double, kDim, kDim>::Zero();
    D.template topLeftCorner<kFactorDim, kFactorDim>() = G::dcayInvDualMatrix(factor(x));
    D.template topRightCorner<kFactorDim, kVectorDim>() = diamondMatrix(v) * At * 0.5;
    D.template bottomRightCorner<kVectorDim, kVectorDim>() = At;
    return D;
  }
  /// ∂/∂x [(dcay^{-1}_x)* μ]. In ω: G's Jacobian plus ½ v ⋄ ∂_ω(Aᵀγ), ∂_ω(Aᵀγ) being the map
  /// η ↦ −hat_G(η)ᵀγ/2; in v: ½ Δ_{Aᵀγ} with the roles of the diamond's arguments swapped.
  /// Written where G writes its own Jacobian (SO2, SO3); else the retraction differentiates the
  /// product's dcayInvDual by Jets (core/retraction_jacobians.h).
  template <class Factor = G,
            std::enable_if_t<detail::HasDcayInvDualJacobian<Factor, FactorAlgebra<double>,
                                                            FactorDual<double>>::value,
                             int> = 0>
  static Eigen::Matrix<double, kDim, kDim> dcayInvDualJacobian(const Algebra<double>& x,
                                                               const Dual<double>& mu) {
    const Vector<double> v = vector(x), gamma = vector(mu);
    const Vector<double> gamma_prime = halfStep(x).transpose() * gamma;
    // The linear map η ↦ −hat_G(η)ᵀγ/2, column by column.
    Eigen::Matrix<double, kVectorDim, kFactorDim> turn;
    for (int j = 0; j < kFactorDim; ++j) {
      turn.col(j) =
          G::hat(FactorAlgebra<double>(FactorAlgebra<double>::Unit(j))).transpose() * gamma * -0.5;
    }
    Eigen::Matrix<double, kDim, kDim> J = Eigen::Matrix<double, kDim, kDim>::Zero();
    J.template topLeftCorner<kFactorDim, kFactorDim>() =
        G::dcayInvDualJacobian(factor(x), factor(mu)) + diamondMatrix(v) * turn * 0.5;
    for (int j = 0; j < kVectorDim; ++j) {
      J.template block<kFactorDim, 1>(0, kFactorDim + j) =
          diamond<double>(Vector<double>(Vector<double>::Unit(j)), gamma_prime) * 0.5;
    }
    J.template bottomLeftCorner<kVectorDim, kFactorDim>() = turn;
    return J;
  }

  /// exp(ω, v) = [[exp_G(ω), φ(Ω)v], [0, 1]].
  template <class T>
  static Matrix<T> exp(const Algebra<T>& x) {
    Matrix<T> g = Matrix<T>::Identity();
    g.template topLeftCorner<kVectorDim, kVectorDim>() = G::exp(factor(x));
    g.template topRightCorner<kVectorDim, 1>() = expIntegral<T>(factor(x), vector(x));
    return g;
  }
  /// log(g, r) = (ω, φ(Ω)⁻¹r), ω = log_G(g).
  template <class T>
  static Algebra<T> log(const Matrix<T>& g) {
    const FactorAlgebra<T> w =
        G::log(FactorMatrix<T>(g.template topLeftCorner<kVectorDim, kVectorDim>()));
    const Vector<T> r = g.template topRightCorner<kVectorDim, 1>();
    if constexpr (detail::HasExpIntegral<Traits, FactorAlgebra<T>, Vector<T>>::value) {
      return join(w, Vector<T>(Traits::expIntegralInverse(w, r)));
    } else {
      return join(w, Vector<T>(expIntegralMatrix<T>(w).inverse() * r));
    }
  }

  /// The spectral radius of ad_(ω,v), block triangular with ad_ω and Ω on its diagonal: the
  /// larger of G's and Ω's. Ω is taken as skew (G acts by rotations), whose spectral radius is
  /// ‖Ω‖_F/√2 for n ≤ 3 and at most that above (the injectivity guard then refuses early).
  template <class Factor = G, std::enable_if_t<detail::HasGroupAdRadius<Factor>::value, int> = 0>
  static double adRadius(const Algebra<double>& x) {
    const FactorAlgebra<double> w = factor(x);
    return std::max(G::adRadius(w), G::hat(w).norm() / std::sqrt(2.0));
  }

  /// (ω, v) stacked.
  template <class T>
  static Algebra<T> join(const FactorAlgebra<T>& w, const Vector<T>& v) {
    Algebra<T> x;
    x.template head<kFactorDim>() = w;
    x.template tail<kVectorDim>() = v;
    return x;
  }
  /// The factor's part ω (or π) of a stacked vector.
  template <class T>
  static FactorAlgebra<T> factor(const Algebra<T>& x) {
    return x.template head<kFactorDim>();
  }
  /// The vector part v (or γ).
  template <class T>
  static Vector<T> vector(const Algebra<T>& x) {
    return x.template tail<kVectorDim>();
  }

 private:
  /// Ad*_{cay_G(w)} π by G's one-factor closed form where it has one (SO3), else by G's Ad* of
  /// G's Cayley map: not G's transport of two factors, the second of which would be the identity.
  template <class T>
  static FactorDual<T> factorCayAdDual(const FactorAlgebra<T>& w, const FactorDual<T>& pi) {
    if constexpr (detail::HasCayAdDual<G>::value) {
      return G::cayAdDual(w, pi);
    } else {
      return G::AdDual(FactorMatrix<T>(G::cay(w)), pi);
    }
  }
  /// A = I − Ω/2.
  template <class T>
  static FactorMatrix<T> halfStep(const Algebra<T>& x) {
    return FactorMatrix<T>::Identity() - G::hat(factor(x)) * T(0.5);
  }
  /// A⁻¹ = (cay_G(ω) + I)/2, as cay_G(ω) = A⁻¹(I + Ω/2) = A⁻¹(2I − A): no inverse where G's
  /// Cayley map is a closed form (SO2, SO3; else G's one solve).
  template <class T>
  static FactorMatrix<T> halfStepInverse(const FactorAlgebra<T>& w) {
    return halfStepInverseOf<T>(G::cay(w));
  }
  /// The same given cay_G(ω).
  template <class T>
  static FactorMatrix<T> halfStepInverseOf(const FactorMatrix<T>& rotation) {
    return (rotation + FactorMatrix<T>::Identity()) * T(0.5);
  }
  /// The matrix of γ ↦ v ⋄ γ.
  static Eigen::Matrix<double, kFactorDim, kVectorDim> diamondMatrix(const Vector<double>& v) {
    Eigen::Matrix<double, kFactorDim, kVectorDim> m;
    for (int j = 0; j < kVectorDim; ++j) {
      m.col(j) = diamond<double>(v, Vector<double>(Vector<double>::Unit(j)));
    }
    return m;
  }

  /// φ(Ω)v = Σ_k Ω^k v/(k+1)!: the traits' closed form, else the series to round-off.
  template <class T>
  static Vector<T> expIntegral(const FactorAlgebra<T>& w, const Vector<T>& v) {
    if constexpr (detail::HasExpIntegral<Traits, FactorAlgebra<T>, Vector<T>>::value) {
      return Traits::expIntegral(w, v);
    } else {
      return expIntegralMatrix<T>(w) * v;
    }
  }
  /// φ(Ω) = Σ_k Ω^k/(k+1)!, summed until two terms in a row are below round-off of the sum
  /// (within exp's injectivity domain, |Ω| < π, in at most 30 terms; 60 allowed).
  template <class T>
  static FactorMatrix<T> expIntegralMatrix(const FactorAlgebra<T>& w) {
    const FactorMatrix<T> Omega = G::hat(w);
    FactorMatrix<T> term = FactorMatrix<T>::Identity();
    FactorMatrix<T> sum = term;
    int small_terms = 0;
    for (int k = 1; k <= 60 && small_terms < 2; ++k) {
      term = (Omega * term) * T(1.0 / (k + 1));
      sum += term;
      small_terms = magnitude(term) <= 1e-17 * magnitude(sum) ? small_terms + 1 : 0;
    }
    return sum;
  }
  template <class M>
  static double magnitude(const M& m) {
    double s = 0.0;
    for (Eigen::Index i = 0; i < m.size(); ++i) {
      const double a = scalarPart(m.data()[i]);
      s += a * a;
    }
    return std::sqrt(s);
  }
};

}  // namespace ddb
