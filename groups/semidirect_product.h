// SemidirectProduct<G, Representation>: G ⋉ Rᵐ for a fixed-size real matrix group G acting on
// Rᵐ by a representation ρ (groups/representation.h): by default G's own n×n matrices (SE(2) =
// SO(2) ⋉ R², SE(3) = SO(3) ⋉ R³), else one the user gives or the adjoint or coadjoint action;
// composed from G's functions and ρ (docs/guide/defining-a-system.md, "A group made of groups";
// the formulas are derived in docs/reference/conventions.md §1, "Semidirect products").
//
// Elements (g, r) are the (n+1)×(n+1) matrices [[g, r], [0, 1]] (G's own matrices), else the
// (p+m+1)×(p+m+1) matrices [[g, 0, 0], [0, ρ(g), r], [0, 0, 1]] (g p×p); ξ = (ω, v) ∈ 𝔤 × Rᵐ and
// μ = (π, γ) ∈ 𝔤* × Rᵐ are stacked vectors, paired by <π, ω>_G + γ·v. With Ω = ρ'(ω) and the
// diamond v ⋄ γ ∈ 𝔤* defined by <v ⋄ γ, η> = γ·ρ'(η) v (= dualVee_G(γ vᵀ) for G's matrices):
//   [(ω₁, v₁), (ω₂, v₂)] = ([ω₁, ω₂], Ω₁v₂ − Ω₂v₁),   ad*_(ω,v)(π, γ) = (ad*_ω π − v ⋄ γ, Ωᵀγ),
//   Ad*_(g,r)(π, γ) = (Ad*_g(π − r ⋄ γ), ρ(g)ᵀγ).
// The Cayley retraction is cay(ω, v) = (cay_G(ω), A⁻¹v) with A⁻¹ = (I + ρ(cay_G ω))/2, so that
// cay(−ξ) = cay(ξ)⁻¹ for every ρ; its tangents follow from the group law:
// dcay^{-1}_(ω,v)(η, u) = (dcay^{-1}_ω η, A(u + Hv/2)), H = ρ'(η), and the dual
// (dcay^{-1}_(ω,v))*(π, γ) = ((dcay^{-1}_ω)*π + v ⋄ Aᵀγ / 2, Aᵀγ). For G's own matrices
// A = I − Ω/2 and these are the block forms of the paper's eqs. (4.15), (4.16); for another ρ,
// A = 2(I + ρ(cay_G ω))⁻¹, which exists while ρ(cay_G ω) has no eigenvalue −1. exp(ω, v) =
// (exp_G(ω), φ(Ω)v) with φ(Ω) = Σ_k Ω^k/(k+1)!, from SemidirectProductTraits<G, Representation>
// where it has a closed form (SO(3): φ(ω̂) = dexp_ω), else summed to round-off; dexp and dexp^{-1}
// are LieGroupBase's series. What composition cannot deduce, the group's name and its Casimirs,
// SemidirectProductTraits<G, Representation> states (groups/se2.h and groups/se3.h for SO(2) and
// SO(3)).
#pragma once

#include <ddb/core/detail/has_retraction_jacobian.h>
#include <ddb/core/detail/is_complete.h>
#include <ddb/core/lie_group.h>
#include <ddb/groups/representation.h>

#include <Eigen/Core>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <type_traits>
#include <utility>

namespace ddb {

/// What SemidirectProduct<G, Representation> takes from its user: specialise it for G (and the
/// representation, where it is not G's own matrices) with
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
/// and, optionally, the action and the diamond as vector operations (all four or none), so that
/// ad*, the diamond and, for G's own matrices, the Cayley step and its Jacobian form no m×m matrix
/// (SO(3)'s in groups/se3.h):
/// @code
///   template <class T> static Vector<T> cayAction(omega, v);                // ρ(cay_G ω) v
///   template <class T> static Vector<T> cayActionTransposed(omega, gamma);  // ρ(cay_G ω)ᵀ γ
///   template <class T> static Vector<T> algebraActionTransposed(omega, gamma);  // ρ'(ω)ᵀ γ
///   template <class T> static FactorDual<T> diamond(v, gamma);              // v ⋄ γ
/// @endcode
/// and, optionally, the spectral radius of ρ'(ω), for the injectivity guard (adRadius below; a
/// double, as G::adRadius):
/// @code
///   static double algebraActionRadius(omega);  // max |λ| over the eigenvalues λ of ρ'(ω)
/// @endcode
template <class G, class Representation = DefiningRepresentation<G>>
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

template <class Traits, class W, class V, class = void>
struct HasVectorForms : std::false_type {};
template <class Traits, class W, class V>
struct HasVectorForms<
    Traits, W, V,
    std::void_t<decltype(Traits::cayAction(std::declval<const W&>(), std::declval<const V&>())),
                decltype(Traits::cayActionTransposed(std::declval<const W&>(),
                                                     std::declval<const V&>())),
                decltype(Traits::algebraActionTransposed(std::declval<const W&>(),
                                                         std::declval<const V&>())),
                decltype(Traits::diamond(std::declval<const V&>(), std::declval<const V&>()))>>
    : std::true_type {};

template <class Traits, class W, class = void>
struct HasAlgebraActionRadius : std::false_type {};
template <class Traits, class W>
struct HasAlgebraActionRadius<
    Traits, W, std::void_t<decltype(Traits::algebraActionRadius(std::declval<const W&>()))>>
    : std::true_type {};

template <class G, class = void>
struct HasCayAdDual : std::false_type {};
template <class G>
struct HasCayAdDual<G, std::void_t<decltype(G::cayAdDual(
                           std::declval<const typename G::template Algebra<double>&>(),
                           std::declval<const typename G::template Dual<double>&>()))>>
    : std::true_type {};

/// Whether the matrix type M (a representation's ρ(g) or ρ'(ω)) is m×m at compile time.
template <class M>
constexpr bool isSquareOfSize(int m) {
  using Plain = std::decay_t<M>;
  return Plain::RowsAtCompileTime == m && Plain::ColsAtCompileTime == m;
}

template <class G, class = void>
struct HasGroupAdRadius : std::false_type {};
template <class G>
struct HasGroupAdRadius<G, std::void_t<decltype(G::adRadius(
                               std::declval<const typename G::template Algebra<double>&>()))>>
    : std::true_type {};
}  // namespace detail

template <class G, class Representation = DefiningRepresentation<G>>
struct SemidirectProduct : LieGroupBase<SemidirectProduct<G, Representation>> {
  using Factor = G;
  /// ρ, G's action on the vector part.
  using Action = Representation;
  using Traits = SemidirectProductTraits<G, Representation>;
  static_assert(detail::kIsComplete<Traits>,
                "SemidirectProduct<G, Representation> needs SemidirectProductTraits<G, "
                "Representation>: specialise it with kName, kNumCasimirs and casimirs(pi, gamma) "
                "(groups/se2.h has SO(2)'s)");
  static_assert(G::kDim != Eigen::Dynamic,
                "SemidirectProduct<G> composes a fixed-size group G (static kDim and matrices)");
  static_assert(G::template Matrix<double>::RowsAtCompileTime ==
                        G::template Matrix<double>::ColsAtCompileTime &&
                    std::is_same_v<typename G::template Matrix<double>::Scalar, double>,
                "SemidirectProduct<G>: G's elements must be real square matrices");
  /// Whether G acts by its own matrices (then the elements are [[g, r], [0, 1]]).
  static constexpr bool kOwnMatrices = std::is_same_v<Representation, DefiningRepresentation<G>>;
  /// m: G acts on Rᵐ (n, the size of G's matrices, for its own).
  static constexpr int kVectorDim = Representation::kDim;
  static constexpr int kFactorDim = G::kDim;
  /// Whether cay is the matrix Cayley map of hat (LieGroupBase::cay): for G's own matrices; for
  /// another ρ, ρ(cay_G ω) is not the Cayley map of ρ'(ω), and the block one leaves the group.
  static constexpr bool kCayleyOfBlocks = kOwnMatrices;

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
  static_assert(detail::isSquareOfSize<decltype(Representation::template ofGroup<double>(
                        std::declval<const FactorMatrix<double>&>()))>(kVectorDim) &&
                    detail::isSquareOfSize<decltype(Representation::template ofAlgebra<double>(
                        std::declval<const FactorAlgebra<double>&>()))>(kVectorDim),
                "SemidirectProduct<G, Representation>: Representation::ofGroup<T>(g) (g one of "
                "G's matrices) and Representation::ofAlgebra<T>(w) (w in G's algebra) must return "
                "kDim x kDim matrices (groups/representation.h)");
  /// p, the size of G's matrices.
  static constexpr int kFactorMatrixDim = G::template Matrix<double>::RowsAtCompileTime;
  /// The row and column where ρ(g) and r begin in an element's matrix.
  static constexpr int kVectorOffset = kOwnMatrices ? 0 : kFactorMatrixDim;
  static constexpr int kMatrixDim = kVectorOffset + kVectorDim + 1;
  template <class T>
  using Matrix = Eigen::Matrix<T, kMatrixDim, kMatrixDim>;
  template <class T>
  using Casimirs = Eigen::Matrix<T, kNumCasimirs, 1>;
  /// The vector part's type, Rᵐ.
  template <class T>
  using Vector = Eigen::Matrix<T, kVectorDim, 1>;
  /// ρ(g) and ρ'(ω), m×m.
  template <class T>
  using ActionMatrix = Eigen::Matrix<T, kVectorDim, kVectorDim>;
  /// Whether the traits give the action and the diamond as vector operations (above).
  static constexpr bool kVectorForms =
      detail::HasVectorForms<Traits, FactorAlgebra<double>, Vector<double>>::value;

  template <class T>
  static Matrix<T> hat(const Algebra<T>& x) {
    Matrix<T> X = Matrix<T>::Zero();
    X.template topLeftCorner<kFactorMatrixDim, kFactorMatrixDim>() = G::hat(factor(x));
    if constexpr (!kOwnMatrices) {
      X.template block<kVectorDim, kVectorDim>(kVectorOffset, kVectorOffset) =
          Representation::template ofAlgebra<T>(factor(x));
    }
    X.template block<kVectorDim, 1>(kVectorOffset, kMatrixDim - 1) = vector(x);
    return X;
  }
  template <class T>
  static Algebra<T> vee(const Matrix<T>& X) {
    return join(G::vee(factorOf(X)), translationOf(X));
  }
  /// <μ, ξ> = Re tr(dualHat(μ)ᵀ hat(ξ)) with dualHat(μ) = [[dualHat_G(π), γ], [0, 0]] (for
  /// another ρ, γ in r's column and zero where ρ'(ω) is).
  template <class T>
  static Matrix<T> dualHat(const Dual<T>& mu) {
    Matrix<T> M = Matrix<T>::Zero();
    M.template topLeftCorner<kFactorMatrixDim, kFactorMatrixDim>() = G::dualHat(factor(mu));
    M.template block<kVectorDim, 1>(kVectorOffset, kMatrixDim - 1) = vector(mu);
    return M;
  }
  /// The μ with <μ, ξ> = Re tr(Yᵀ hat(ξ)) for every ξ (hat's transpose under the trace pairing):
  /// for another ρ, π also pairs with the block where hat has ρ'(ω).
  template <class T>
  static Dual<T> dualVee(const Matrix<T>& Y) {
    if constexpr (kOwnMatrices) {
      return join(G::dualVee(factorOf(Y)), translationOf(Y));
    } else {
      const ActionMatrix<T> Y_action =
          Y.template block<kVectorDim, kVectorDim>(kVectorOffset, kVectorOffset);
      FactorDual<T> c;
      for (int j = 0; j < kFactorDim; ++j) {
        c(j) = Y_action.cwiseProduct(actionOfAlgebra<T>(unit<T>(j))).sum();
      }
      return join(FactorDual<T>(G::dualVee(factorOf(Y)) + pairingSolve(c)), translationOf(Y));
    }
  }

  template <class T>
  static T pairing(const Dual<T>& mu, const Algebra<T>& x) {
    return G::pairing(factor(mu), factor(x)) + vector(mu).dot(vector(x));
  }
  template <class T>
  static Algebra<T> bracket(const Algebra<T>& a, const Algebra<T>& b) {
    return join(G::bracket(factor(a), factor(b)),
                Vector<T>(actionOfAlgebra<T>(factor(a)) * vector(b) -
                          actionOfAlgebra<T>(factor(b)) * vector(a)));
  }
  /// v ⋄ γ ∈ 𝔤*: <v ⋄ γ, η> = γ·ρ'(η)v, i.e. dualVee_G(γ vᵀ) for G's own matrices; for another
  /// ρ the π with <π, e_j>_G = γ·ρ'(e_j)v on G's coordinate vectors e_j (G's pairing matrix
  /// solved, the identity where G pairs by the dot product).
  template <class T>
  static FactorDual<T> diamond(const Vector<T>& v, const Vector<T>& gamma) {
    if constexpr (kVectorForms) {
      return Traits::diamond(v, gamma);
    } else if constexpr (kOwnMatrices) {
      return G::dualVee(FactorMatrix<T>(gamma * v.transpose()));
    } else {
      FactorDual<T> c;
      for (int j = 0; j < kFactorDim; ++j) {
        c(j) = gamma.dot(Vector<T>(actionOfAlgebra<T>(unit<T>(j)) * v));
      }
      return pairingSolve(c);
    }
  }
  /// ad*_(ω,v)(π, γ) = (ad*_ω π − v ⋄ γ, Ωᵀγ). ω and γ taken out once and the halves written in
  /// place, inlined as SE3's: under Lobatto IIIC's Jets each 3-block copy is an out-of-line
  /// constructor (docs/results/benchmarks.md, "SE(3) composed: ad-star without the Jets' block
  /// copies").
  template <class T>
  EIGEN_ALWAYS_INLINE static Dual<T> adDual(const Algebra<T>& x, const Dual<T>& mu) {
    const FactorAlgebra<T> w = factor(x);
    const Vector<T> gamma = vector(mu);
    Dual<T> out;
    out.template head<kFactorDim>() =
        G::adDual(w, FactorDual<T>(factor(mu))) - diamond<T>(vector(x), gamma);
    out.template tail<kVectorDim>() = algebraActionTransposed<T>(w, gamma);
    return out;
  }
  /// Ad*_(g,r)(π, γ) = (Ad*_g(π − r ⋄ γ), ρ(g)ᵀγ).
  template <class T>
  static Dual<T> AdDual(const Matrix<T>& g, const Dual<T>& mu) {
    const FactorMatrix<T> R = factorOf(g);
    const Vector<T> r = translationOf(g);
    const Vector<T> gamma = vector(mu);
    return join(G::AdDual(R, FactorDual<T>(factor(mu) - diamond<T>(r, gamma))),
                Vector<T>(actionOf<T>(R).transpose() * gamma));
  }
  /// (g, r)⁻¹ = (g⁻¹, −ρ(g⁻¹)r).
  template <class T>
  static Matrix<T> inverse(const Matrix<T>& g) {
    const FactorMatrix<T> inverse_rotation = G::inverse(factorOf(g));
    return element<T>(inverse_rotation,
                      Vector<T>(-actionOf<T>(inverse_rotation) * translationOf(g)));
  }
  /// The element (g, r).
  template <class T>
  static Matrix<T> element(const FactorMatrix<T>& g, const Vector<T>& r) {
    Matrix<T> out = Matrix<T>::Identity();
    out.template topLeftCorner<kFactorMatrixDim, kFactorMatrixDim>() = g;
    if constexpr (!kOwnMatrices) {
      out.template block<kVectorDim, kVectorDim>(kVectorOffset, kVectorOffset) = actionOf<T>(g);
    }
    out.template block<kVectorDim, 1>(kVectorOffset, kMatrixDim - 1) = r;
    return out;
  }
  /// g of an element (g, r).
  template <class T>
  static FactorMatrix<T> factorOf(const Matrix<T>& g) {
    return g.template topLeftCorner<kFactorMatrixDim, kFactorMatrixDim>();
  }
  /// r of an element (g, r).
  template <class T>
  static Vector<T> translationOf(const Matrix<T>& g) {
    return g.template block<kVectorDim, 1>(kVectorOffset, kMatrixDim - 1);
  }

  template <class T>
  static Casimirs<T> casimirs(const Dual<T>& mu) {
    return Traits::casimirs(factor(mu), vector(mu));
  }

  /// cay(ω, v) = (cay_G(ω), A⁻¹v), A⁻¹ = (ρ(cay_G ω) + I)/2 (= (I − Ω/2)⁻¹ for G's own
  /// matrices).
  template <class T>
  static Matrix<T> cay(const Algebra<T>& x) {
    const FactorMatrix<T> rotation = G::cay(factor(x));
    return element<T>(rotation, Vector<T>(halfStepInverseOf<T>(actionOf<T>(rotation)) * vector(x)));
  }
  /// cay^{-1}(g, r) = (cay_G^{-1}(g), A r), with A from ω = cay_G^{-1}(g): r − Ωr/2 for G's own
  /// matrices, else 2(I + ρ(g))⁻¹r.
  template <class M>
  static auto cayInverse(const M& g) {
    using T = typename M::Scalar;
    const Matrix<T> element_matrix = g;  // g may be an expression
    const FactorMatrix<T> rotation = factorOf(element_matrix);
    const FactorAlgebra<T> w = G::cayInverse(rotation);
    const Vector<T> r = translationOf(element_matrix);
    if constexpr (kOwnMatrices) {
      return join(w, Vector<T>(r - G::hat(w) * r * T(0.5)));
    } else {
      const ActionMatrix<T> sum = ActionMatrix<T>::Identity() + actionOf<T>(rotation);
      return join(w, Vector<T>(sum.partialPivLu().solve(r) * T(2)));
    }
  }
  /// dcay_(ω,v)(η, u) = (dcay_ω η, A⁻¹u − K v/2), K = ρ'(dcay_ω η).
  template <class T>
  static Algebra<T> dcay(const Algebra<T>& x, const Algebra<T>& y) {
    const FactorAlgebra<T> k = G::dcay(factor(x), factor(y));
    return join(k, Vector<T>(halfStepInverse<T>(factor(x)) * vector(y) -
                             actionOfAlgebra<T>(k) * vector(x) * T(0.5)));
  }
  /// dcay^{-1}_(ω,v)(η, u) = (dcay^{-1}_ω η, A(u + H v/2)), H = ρ'(η).
  template <class T>
  static Algebra<T> dcayInv(const Algebra<T>& x, const Algebra<T>& y) {
    return join(
        G::dcayInv(factor(x), factor(y)),
        Vector<T>(halfStep(x) * (vector(y) + actionOfAlgebra<T>(factor(y)) * vector(x) * T(0.5))));
  }
  /// (dcay^{-1}_(ω,v))*(π, γ) = ((dcay^{-1}_ω)*π + v ⋄ γ'/2, γ'), γ' = Aᵀγ: the transpose of
  /// dcayInv. It, cayAdDual and cayTransport are always inlined, as SE3's closed forms are: in
  /// a method table's unit GCC left them calls, and SE(3) composed's ddb-cay step took 1.2 times
  /// SE3's (docs/results/benchmarks.md, "A method table's unit and GCC's inlining").
  template <class T>
  EIGEN_ALWAYS_INLINE static Dual<T> dcayInvDual(const Algebra<T>& x, const Dual<T>& mu) {
    const Vector<T> gamma = halfStepTransposed<T>(x, vector(mu));
    return join(FactorDual<T>(G::dcayInvDual(factor(x), factor(mu)) +
                              diamond<T>(vector(x), gamma) * T(0.5)),
                gamma);
  }
  /// Ad*_{cay(x)} μ: (Ad*_{cay ω}(π − r ⋄ γ), ρ(cay ω)ᵀγ) with r = A⁻¹v. G's own transport
  /// moves π (SO3's unbiased vector form, docs/results/casimir-drift.md); for G's own matrices
  /// cay(ω)ᵀγ is applied as γ + A⁻ᵀΩᵀγ (cay(ω) = (I + Ω/2)A⁻¹, and I + Ω/2 − A = Ω), so that
  /// the only rounding of order ulp(γ) is the final sum, as in SO3::cayAdDual.
  template <class T>
  EIGEN_ALWAYS_INLINE static Dual<T> cayAdDual(const Algebra<T>& x, const Dual<T>& mu) {
    const FactorAlgebra<T> w = factor(x);
    const Vector<T> gamma = vector(mu);
    if constexpr (kOwnMatrices && kVectorForms) {  // r = A⁻¹v = (cay(ω)v + v)/2
      const Vector<T> r = (Traits::cayAction(w, vector(x)) + vector(x)) * T(0.5);
      return join(factorCayAdDual<T>(w, FactorDual<T>(factor(mu) - diamond<T>(r, gamma))),
                  Vector<T>(Traits::cayActionTransposed(w, gamma)));
    } else if constexpr (kOwnMatrices) {
      const FactorMatrix<T> Omega = G::hat(w);
      // A⁻¹ once, for r and for the γ part.
      const FactorMatrix<T> A_inverse = halfStepInverse<T>(w);
      const Vector<T> r = A_inverse * vector(x);
      return join(factorCayAdDual<T>(w, FactorDual<T>(factor(mu) - diamond<T>(r, gamma))),
                  Vector<T>(gamma + A_inverse.transpose() * Vector<T>(Omega.transpose() * gamma)));
    } else {
      const ActionMatrix<T> action = actionOf<T>(FactorMatrix<T>(G::cay(w)));
      const Vector<T> r = halfStepInverseOf<T>(action) * vector(x);
      return join(factorCayAdDual<T>(w, FactorDual<T>(factor(mu) - diamond<T>(r, gamma))),
                  Vector<T>(action.transpose() * gamma));
    }
  }
  /// Ad*_{cay(a) cay(b)} μ = Ad*_{cay(b)} Ad*_{cay(a)} μ, the DDB update (paper, eq. (4.12)).
  template <class T>
  EIGEN_ALWAYS_INLINE static Dual<T> cayTransport(const Algebra<T>& a, const Algebra<T>& b,
                                                  const Dual<T>& mu) {
    return cayAdDual<T>(b, cayAdDual<T>(a, mu));
  }
  /// The matrix of (dcay^{-1}_x)*: [[D_G, Δ_v Aᵀ/2], [0, Aᵀ]], D_G G's matrix and Δ_v the matrix
  /// of γ ↦ v ⋄ γ.
  static Eigen::Matrix<double, kDim, kDim> dcayInvDualMatrix(const Algebra<double>& x) {
    const Vector<double> v = vector(x);
    const ActionMatrix<double> At = halfStep(x).transpose();
    Eigen::Matrix<double, kDim, kDim> D = Eigen::Matrix<double, kDim, kDim>::Zero();
    D.template topLeftCorner<kFactorDim, kFactorDim>() = G::dcayInvDualMatrix(factor(x));
    D.template topRightCorner<kFactorDim, kVectorDim>() = diamondMatrix(v) * At * 0.5;
    D.template bottomRightCorner<kVectorDim, kVectorDim>() = At;
    return D;
  }
  /// ∂/∂x [(dcay^{-1}_x)* μ]. In ω: G's Jacobian plus ½ v ⋄ ∂_ω(Aᵀγ), ∂_ω(Aᵀγ) being the map
  /// η ↦ −hat_G(η)ᵀγ/2; in v: ½ Δ_{Aᵀγ} with the roles of the diamond's arguments swapped.
  /// Written where G writes its own Jacobian (SO2, SO3) and acts by its own matrices; else the
  /// retraction differentiates the product's dcayInvDual by Jets (core/retraction_jacobians.h).
  template <
      class Factor = G,
      std::enable_if_t<kOwnMatrices && detail::HasDcayInvDualJacobian<Factor, FactorAlgebra<double>,
                                                                      FactorDual<double>>::value,
                       int> = 0>
  static Eigen::Matrix<double, kDim, kDim> dcayInvDualJacobian(const Algebra<double>& x,
                                                               const Dual<double>& mu) {
    const Vector<double> v = vector(x), gamma = vector(mu);
    const Vector<double> gamma_prime = halfStepTransposed<double>(x, gamma);
    // The linear map η ↦ −hat_G(η)ᵀγ/2, column by column.
    Eigen::Matrix<double, kVectorDim, kFactorDim> turn;
    for (int j = 0; j < kFactorDim; ++j) {
      turn.col(j) = algebraActionTransposed<double>(unit<double>(j), gamma) * -0.5;
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

  /// exp(ω, v) = (exp_G(ω), φ(Ω)v).
  template <class T>
  static Matrix<T> exp(const Algebra<T>& x) {
    return element<T>(FactorMatrix<T>(G::exp(factor(x))), expIntegral<T>(factor(x), vector(x)));
  }
  /// log(g, r) = (ω, φ(Ω)⁻¹r), ω = log_G(g).
  template <class T>
  static Algebra<T> log(const Matrix<T>& g) {
    const FactorAlgebra<T> w = G::log(factorOf(g));
    const Vector<T> r = translationOf(g);
    if constexpr (detail::HasExpIntegral<Traits, FactorAlgebra<T>, Vector<T>>::value) {
      return join(w, Vector<T>(Traits::expIntegralInverse(w, r)));
    } else {
      return join(w, Vector<T>(expIntegralMatrix<T>(w).inverse() * r));
    }
  }

  /// The spectral radius of ad_(ω,v), block triangular with ad_ω and Ω = ρ'(ω) on its diagonal:
  /// the larger of G's and Ω's. Ω's is the traits' `algebraActionRadius(ω)` where they give it
  /// (SO(3)'s |ω|); else, for G's own matrices Ω is skew (G acts by rotations), whose spectral
  /// radius is ‖Ω‖_F/√2 for n ≤ 3 and at most that above; for another ρ, ‖Ω‖_F, at least the
  /// spectral radius of any matrix (the injectivity guard then refuses early).
  template <class Factor = G, std::enable_if_t<detail::HasGroupAdRadius<Factor>::value, int> = 0>
  static double adRadius(const Algebra<double>& x) {
    const FactorAlgebra<double> w = factor(x);
    if constexpr (detail::HasAlgebraActionRadius<Traits, FactorAlgebra<double>>::value) {
      return std::max(G::adRadius(w), Traits::algebraActionRadius(w));
    } else if constexpr (kOwnMatrices) {
      return std::max(G::adRadius(w), G::hat(w).norm() / std::sqrt(2.0));
    } else {
      return std::max(G::adRadius(w), actionOfAlgebra<double>(w).norm());
    }
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
  EIGEN_ALWAYS_INLINE static FactorAlgebra<T> factor(const Algebra<T>& x) {
    return x.template head<kFactorDim>();
  }
  /// The vector part v (or γ).
  template <class T>
  EIGEN_ALWAYS_INLINE static Vector<T> vector(const Algebra<T>& x) {
    return x.template tail<kVectorDim>();
  }

 private:
  /// ρ(g).
  template <class T>
  static ActionMatrix<T> actionOf(const FactorMatrix<T>& g) {
    return Representation::template ofGroup<T>(g);
  }
  /// ρ'(ω).
  template <class T>
  static ActionMatrix<T> actionOfAlgebra(const FactorAlgebra<T>& w) {
    return Representation::template ofAlgebra<T>(w);
  }
  /// ρ'(ω)ᵀγ.
  template <class T>
  static Vector<T> algebraActionTransposed(const FactorAlgebra<T>& w, const Vector<T>& gamma) {
    if constexpr (kVectorForms) {
      return Traits::algebraActionTransposed(w, gamma);
    } else {
      return actionOfAlgebra<T>(w).transpose() * gamma;
    }
  }
  template <class T>
  static FactorAlgebra<T> unit(int j) {
    return FactorAlgebra<T>::Unit(j);
  }
  /// The π with <π, e_j>_G = c_j for G's coordinate vectors e_j: P⁻ᵀc, P_ij = <e_i, e_j>_G.
  template <class T>
  static FactorDual<T> pairingSolve(const FactorDual<T>& c) {
    using PairingMatrix = Eigen::Matrix<double, kFactorDim, kFactorDim>;
    static const PairingMatrix inverse_transpose = [] {
      PairingMatrix P;
      for (int i = 0; i < kFactorDim; ++i) {
        for (int j = 0; j < kFactorDim; ++j) {
          P(i, j) = G::pairing(FactorDual<double>(unit<double>(i)), unit<double>(j));
        }
      }
      return PairingMatrix(P.transpose().inverse());
    }();
    if (inverse_transpose.isIdentity(0.0)) return c;
    return inverse_transpose.template cast<T>() * c;
  }
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
  /// Aᵀγ: γ − Ωᵀγ/2 for G's own matrices (no matrix formed where the traits give Ωᵀγ).
  template <class T>
  static Vector<T> halfStepTransposed(const Algebra<T>& x, const Vector<T>& gamma) {
    if constexpr (kOwnMatrices && kVectorForms) {
      return gamma - Traits::algebraActionTransposed(factor(x), gamma) * T(0.5);
    } else {
      return halfStep(x).transpose() * gamma;
    }
  }
  /// A = I − Ω/2 for G's own matrices, else 2(I + ρ(cay_G ω))⁻¹.
  template <class T>
  static ActionMatrix<T> halfStep(const Algebra<T>& x) {
    if constexpr (kOwnMatrices) {
      return FactorMatrix<T>::Identity() - G::hat(factor(x)) * T(0.5);
    } else {
      return halfStepInverse<T>(factor(x)).inverse();
    }
  }
  /// A⁻¹ = (ρ(cay_G ω) + I)/2; for G's own matrices cay_G(ω) = A⁻¹(I + Ω/2) = A⁻¹(2I − A): no
  /// inverse where G's Cayley map is a closed form (SO2, SO3; else G's one solve).
  template <class T>
  static ActionMatrix<T> halfStepInverse(const FactorAlgebra<T>& w) {
    return halfStepInverseOf<T>(actionOf<T>(FactorMatrix<T>(G::cay(w))));
  }
  /// The same given ρ(cay_G ω).
  template <class T>
  static ActionMatrix<T> halfStepInverseOf(const ActionMatrix<T>& action) {
    return (action + ActionMatrix<T>::Identity()) * T(0.5);
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
  static ActionMatrix<T> expIntegralMatrix(const FactorAlgebra<T>& w) {
    const ActionMatrix<T> Omega = actionOfAlgebra<T>(w);
    ActionMatrix<T> term = ActionMatrix<T>::Identity();
    ActionMatrix<T> sum = term;
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
