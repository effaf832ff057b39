// SE(3) = SO(3) ⋉ R^3 in its 4×4 homogeneous representation; ξ = (ω, v), μ = (π, γ)
// with the dot pairing (docs/reference/conventions.md §1):
//   [ξ₁, ξ₂] = (ω₁×ω₂, ω₁×v₂ − ω₂×v₁),  ad*_ξ μ = (π×ω + γ×v, γ×ω),
//   Ad*_(R,r) μ = (Rᵀ(π + γ×r), Rᵀγ),   Casimirs |γ|² and π·γ.
// exp/log use SO(3)'s closed forms (V = dexp_ω of SO(3)); dexp and dexp^{-1} come
// from LieGroupBase's series summed to round-off. Cayley: closed forms derived from
// the 4×4 formulas (paper, eqs. (4.15), (4.16)); dcay from the 4×4 matrices.
//
// SemidirectProduct<SO3> is the same group composed from SO3's functions
// (groups/semidirect_product.h; its name and Casimirs at the end of this file). Its trajectories
// agree with SE3's for every method (tests/unit/test_group_products.cc), and its steps take from
// 0.5 to 1.06 times SE3's (docs/results/benchmarks.md, "A method table's unit and GCC's
// inlining"). SE3 stays as the hand-written specialisation: a name users' programs compile
// against, and the formulas written out that the composed ones are checked against.
#pragma once

#include <ddb/core/lie_group.h>
#include <ddb/groups/semidirect_product.h>
#include <ddb/groups/so3.h>

#include <Eigen/Core>

namespace ddb {

struct SE3 : LieGroupBase<SE3> {
  static constexpr const char* kName = "SE3";
  static constexpr int kDim = 6;
  static constexpr int kNumCasimirs = 2;

  template <class T>
  using Algebra = Eigen::Matrix<T, 6, 1>;
  template <class T>
  using Dual = Eigen::Matrix<T, 6, 1>;
  template <class T>
  using Matrix = Eigen::Matrix<T, 4, 4>;
  template <class T>
  using Casimirs = Eigen::Matrix<T, 2, 1>;

  template <class T>
  static Matrix<T> hat(const Algebra<T>& x) {
    Matrix<T> X = Matrix<T>::Zero();
    X.template topLeftCorner<3, 3>() = SO3::hat<T>(x.template head<3>());
    X.template topRightCorner<3, 1>() = x.template tail<3>();
    return X;
  }
  template <class T>
  static Algebra<T> vee(const Matrix<T>& X) {
    Algebra<T> x;
    x << SO3::vee<T>(X.template topLeftCorner<3, 3>()), X.template topRightCorner<3, 1>();
    return x;
  }
  /// <μ, ξ> = π·ω + γ·v = tr(dualHat(μ)ᵀ hat(ξ)) with dualHat(μ) = [[π̂/2, γ], [0, 0]].
  template <class T>
  static Matrix<T> dualHat(const Dual<T>& mu) {
    Matrix<T> M = Matrix<T>::Zero();
    M.template topLeftCorner<3, 3>() = SO3::dualHat<T>(mu.template head<3>());
    M.template topRightCorner<3, 1>() = mu.template tail<3>();
    return M;
  }
  template <class T>
  static Dual<T> dualVee(const Matrix<T>& Y) {
    Dual<T> mu;
    mu << SO3::dualVee<T>(Y.template topLeftCorner<3, 3>()), Y.template topRightCorner<3, 1>();
    return mu;
  }

  template <class T>
  static T pairing(const Dual<T>& mu, const Algebra<T>& x) {
    return mu.dot(x);
  }
  template <class T>
  static Algebra<T> bracket(const Algebra<T>& a, const Algebra<T>& b) {
    Algebra<T> c;
    c << a.template head<3>().cross(b.template head<3>()),
        a.template head<3>().cross(b.template tail<3>()) -
            b.template head<3>().cross(a.template tail<3>());
    return c;
  }
  /// ad*_ξ μ = (π×ω + γ×v, γ×ω).
  template <class T>
  EIGEN_ALWAYS_INLINE static Dual<T> adDual(const Algebra<T>& x, const Dual<T>& mu) {
    const auto w = x.template head<3>(), v = x.template tail<3>();
    const auto pi = mu.template head<3>(), gamma = mu.template tail<3>();
    Dual<T> out;  // halves assigned, not comma-initialised: see dcayInvDual
    out.template head<3>() = pi.cross(w) + gamma.cross(v);
    out.template tail<3>() = gamma.cross(w);
    return out;
  }
  /// Ad*_(R,r) μ = (Rᵀ(π + γ×r), Rᵀγ).
  template <class T>
  static Dual<T> AdDual(const Matrix<T>& g, const Dual<T>& mu) {
    const auto R = g.template topLeftCorner<3, 3>();
    const Eigen::Matrix<T, 3, 1> r = g.template topRightCorner<3, 1>();
    const Eigen::Matrix<T, 3, 1> gamma = mu.template tail<3>();
    Dual<T> out;
    out << R.transpose() * (mu.template head<3>() + gamma.cross(r)), R.transpose() * gamma;
    return out;
  }
  template <class T>
  static Matrix<T> inverse(const Matrix<T>& g) {
    Matrix<T> out = Matrix<T>::Identity();
    const Eigen::Matrix<T, 3, 3> Rt = g.template topLeftCorner<3, 3>().transpose();
    out.template topLeftCorner<3, 3>() = Rt;
    out.template topRightCorner<3, 1>() = -Rt * g.template topRightCorner<3, 1>();
    return out;
  }

  /// (|γ|², π·γ).
  /// The spectral radius of ad_(ω,v): ±i|ω| (twice) and 0, from the rotation part alone.
  static double adRadius(const Algebra<double>& x) { return x.head<3>().norm(); }

  template <class T>
  static Casimirs<T> casimirs(const Dual<T>& mu) {
    return Casimirs<T>(mu.template tail<3>().squaredNorm(),
                       mu.template head<3>().dot(mu.template tail<3>()));
  }

  /// cay(ω, v) = [[cay(ω), (I − ω̂/2)^{-1} v], [0, 1]] with the 3×3 matrix inverse
  /// (I − ω̂/2)^{-1} = 4/(4 + |ω|²) (I + ω̂/2 + ωωᵀ/4).
  template <class T>
  static Matrix<T> cay(const Algebra<T>& x) {
    const Eigen::Matrix<T, 3, 1> w = x.template head<3>(), v = x.template tail<3>();
    Matrix<T> g = Matrix<T>::Identity();
    g.template topLeftCorner<3, 3>() = SO3::cay(w);
    g.template topRightCorner<3, 1>() =
        (v + w.cross(v) * T(0.5) + w * (w.dot(v) * T(0.25))) * (T(4) / (T(4) + w.squaredNorm()));
    return g;
  }
  /// dcay^{-1}_x η = (I − X/2) H (I + X/2) = η − ad_x η/2 − XHX/4, where
  /// XHX = hat(−(ω·η_ω) ω, ω × (η_ω × v)).
  template <class T>
  static Algebra<T> dcayInv(const Algebra<T>& x, const Algebra<T>& eta) {
    const Eigen::Matrix<T, 3, 1> w = x.template head<3>(), v = x.template tail<3>();
    const Eigen::Matrix<T, 3, 1> ew = eta.template head<3>();
    Algebra<T> quarter;
    quarter << w * w.dot(ew), -w.cross(ew.cross(v));
    return eta - bracket(x, eta) * T(0.5) + quarter * T(0.25);
  }
  /// (dcay^{-1}_x)* μ = μ − ad*_x μ/2 + ¼((π·ω) ω − v × (γ × ω), 0), the transpose of dcayInv.
  /// Written on the 3-vector halves (the same operations in the same order as the formula):
  /// it is the residual of every SE(3) Legendre solve, and the 6-vector form through adDual and
  /// comma initialisers took 15% of a heavy-top DDB step (perf, docs/design/architecture.md).
  template <class T>
  EIGEN_ALWAYS_INLINE static Dual<T> dcayInvDual(const Algebra<T>& x, const Dual<T>& mu) {
    const Eigen::Matrix<T, 3, 1> w = x.template head<3>(), v = x.template tail<3>();
    const Eigen::Matrix<T, 3, 1> pi = mu.template head<3>(), gamma = mu.template tail<3>();
    const Eigen::Matrix<T, 3, 1> gw = gamma.cross(w);
    Dual<T> out;
    out.template head<3>() =
        pi - (pi.cross(w) + gamma.cross(v)) * T(0.5) + (w * pi.dot(w) - v.cross(gw)) * T(0.25);
    out.template tail<3>() = gamma - gw * T(0.5);
    return out;
  }
  /// Ad*_{cay(x)} mu = (Rᵀ(π + γ × r), Rᵀγ) with R = cay(ω), r = (I − ω̂/2)^{-1} v (cay above),
  /// Rᵀ applied as SO3::cayAdDual does, without forming R (docs/results/casimir-drift.md).
  template <class T>
  EIGEN_ALWAYS_INLINE static Dual<T> cayAdDual(const Algebra<T>& x, const Dual<T>& mu) {
    const Eigen::Matrix<T, 3, 1> w = x.template head<3>(), v = x.template tail<3>();
    const Eigen::Matrix<T, 3, 1> gamma = mu.template tail<3>();
    const Eigen::Matrix<T, 3, 1> r =
        (v + w.cross(v) * T(0.5) + w * (w.dot(v) * T(0.25))) * (T(4) / (T(4) + w.squaredNorm()));
    Dual<T> out;
    out.template head<3>() =
        SO3::cayAdDual<T>(w, Eigen::Matrix<T, 3, 1>(mu.template head<3>() + gamma.cross(r)));
    out.template tail<3>() = SO3::cayAdDual<T>(w, gamma);
    return out;
  }
  /// Ad*_{cay(a) cay(b)} mu = Ad*_{cay(b)} Ad*_{cay(a)} mu, the DDB update (paper, eq. (4.12)),
  /// without the two 4×4 Cayley matrices and their product (12% of a heavy-top DDB step).
  template <class T>
  EIGEN_ALWAYS_INLINE static Dual<T> cayTransport(const Algebra<T>& a, const Algebra<T>& b,
                                                  const Dual<T>& mu) {
    return cayAdDual(b, cayAdDual(a, mu));
  }
  /// The matrix of (dcay^{-1}_x)*, from dcayInvDual (linear in μ = (π, γ)):
  ///   [[I + W/2 + ω ωᵀ/4, V/2 + V W/4], [0, I + W/2]], W, V the hats of ω, v.
  EIGEN_ALWAYS_INLINE static Eigen::Matrix<double, 6, 6> dcayInvDualMatrix(
      const Algebra<double>& x) {
    const Eigen::Vector3d w = x.head<3>();
    const Eigen::Matrix3d W = SO3::hat<double>(w), V = SO3::hat<double>(x.tail<3>());
    const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
    Eigen::Matrix<double, 6, 6> D;
    D.topLeftCorner<3, 3>() = I + 0.5 * W + 0.25 * w * w.transpose();
    D.topRightCorner<3, 3>() = 0.5 * V + 0.25 * V * W;
    D.bottomLeftCorner<3, 3>().setZero();
    D.bottomRightCorner<3, 3>() = I + 0.5 * W;
    return D;
  }
  /// ∂/∂x [(dcay^{-1}_x)* mu], differentiating dcayInvDual in ω and v:
  ///   [[-Π/2 + ((π·ω) I + ω πᵀ - V Γ)/4,  -Γ/2 + hat(γ × ω)/4], [-Γ/2, 0]],
  /// with Π, Γ, V the hats of π, γ, v.
  EIGEN_ALWAYS_INLINE static Eigen::Matrix<double, 6, 6> dcayInvDualJacobian(
      const Algebra<double>& x, const Dual<double>& mu) {
    const Eigen::Vector3d w = x.head<3>(), v = x.tail<3>();
    const Eigen::Vector3d pi = mu.head<3>(), gamma = mu.tail<3>();
    const Eigen::Matrix3d Pi = SO3::hat<double>(pi), Gamma = SO3::hat<double>(gamma);
    Eigen::Matrix<double, 6, 6> J;
    J.topLeftCorner<3, 3>() = -0.5 * Pi + 0.25 * (pi.dot(w) * Eigen::Matrix3d::Identity() +
                                                  w * pi.transpose() - SO3::hat<double>(v) * Gamma);
    J.topRightCorner<3, 3>() = -0.5 * Gamma + 0.25 * SO3::hat<double>(gamma.cross(w));
    J.bottomLeftCorner<3, 3>() = -0.5 * Gamma;
    J.bottomRightCorner<3, 3>().setZero();
    return J;
  }

  /// exp(ω, v) = [[exp ω̂, V v], [0, 1]], V v = dexp_ω(v) of SO(3).
  template <class T>
  static Matrix<T> exp(const Algebra<T>& x) {
    const Eigen::Matrix<T, 3, 1> w = x.template head<3>(), v = x.template tail<3>();
    Matrix<T> g = Matrix<T>::Identity();
    g.template topLeftCorner<3, 3>() = SO3::exp(w);
    g.template topRightCorner<3, 1>() = SO3::dexp(w, v);
    return g;
  }
  template <class T>
  static Algebra<T> log(const Matrix<T>& g) {
    const Eigen::Matrix<T, 3, 3> R = g.template topLeftCorner<3, 3>();
    const Eigen::Matrix<T, 3, 1> w = SO3::log(R);
    const Eigen::Matrix<T, 3, 1> r = g.template topRightCorner<3, 1>();
    Algebra<T> x;
    x << w, SO3::dexpInv(w, r);
    return x;
  }
};

/// SO(3) ⋉ R³ composed (SemidirectProduct<SO3>): SE3's name with its coordinates, its Casimirs
/// (|γ|², π·γ), and φ(ω̂) = dexp_ω, since ω̂v = ω × v = [ω, v] on so(3).
template <>
struct SemidirectProductTraits<SO3> {
  static constexpr const char* kName = "SO3xR3";
  static constexpr int kNumCasimirs = 2;
  template <class T>
  static Eigen::Matrix<T, 2, 1> casimirs(const Eigen::Matrix<T, 3, 1>& pi,
                                         const Eigen::Matrix<T, 3, 1>& gamma) {
    return Eigen::Matrix<T, 2, 1>(gamma.squaredNorm(), pi.dot(gamma));
  }
  template <class T>
  static Eigen::Matrix<T, 3, 1> expIntegral(const Eigen::Matrix<T, 3, 1>& w,
                                            const Eigen::Matrix<T, 3, 1>& v) {
    return SO3::dexp(w, v);
  }
  template <class T>
  static Eigen::Matrix<T, 3, 1> expIntegralInverse(const Eigen::Matrix<T, 3, 1>& w,
                                                   const Eigen::Matrix<T, 3, 1>& r) {
    return SO3::dexpInv(w, r);
  }
  // The action as vector operations: cay(ω)ᵀγ is SO3::cayAdDual(ω, γ), and cay(ω)v = cay(−ω)ᵀv;
  // ω̂ᵀγ = γ × ω = ad*_ω γ; v ⋄ γ = vee(γvᵀ − vγᵀ) = v × γ.
  template <class T>
  static Eigen::Matrix<T, 3, 1> cayAction(const Eigen::Matrix<T, 3, 1>& w,
                                          const Eigen::Matrix<T, 3, 1>& v) {
    return SO3::cayAdDual<T>(Eigen::Matrix<T, 3, 1>(-w), v);
  }
  template <class T>
  static Eigen::Matrix<T, 3, 1> cayActionTransposed(const Eigen::Matrix<T, 3, 1>& w,
                                                    const Eigen::Matrix<T, 3, 1>& gamma) {
    return SO3::cayAdDual<T>(w, gamma);
  }
  template <class T>
  EIGEN_ALWAYS_INLINE static Eigen::Matrix<T, 3, 1> algebraActionTransposed(
      const Eigen::Matrix<T, 3, 1>& w, const Eigen::Matrix<T, 3, 1>& gamma) {
    return SO3::adDual<T>(w, gamma);
  }
  template <class T>
  EIGEN_ALWAYS_INLINE static Eigen::Matrix<T, 3, 1> diamond(const Eigen::Matrix<T, 3, 1>& v,
                                                            const Eigen::Matrix<T, 3, 1>& gamma) {
    return v.cross(gamma);
  }
  // ω̂'s eigenvalues are 0 and ±i|ω|.
  static double algebraActionRadius(const Eigen::Vector3d& w) { return w.norm(); }
};

}  // namespace ddb
