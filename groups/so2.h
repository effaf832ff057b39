// SO(2): rotations of the plane; so(2) ≅ R with hat(θ) = θJ, J = [[0, −1], [1, 0]], and
// so(2)* ≅ R with the product pairing, as SO(3)'s (docs/reference/conventions.md §1). The group
// is abelian: the bracket, ad* and Ad* are trivial, dexp is the identity, and every function of μ
// is a Casimir (the coadjoint orbits are points; casimirs(μ) = μ). Its use is as the rotation
// factor of SE(2) = SO(2) ⋉ R² (groups/se2.h).
#pragma once

#include <ddb/core/lie_group.h>

#include <Eigen/Core>
#include <cmath>

namespace ddb {

struct SO2 : LieGroupBase<SO2> {
  static constexpr const char* kName = "SO2";
  static constexpr int kDim = 1;
  static constexpr int kNumCasimirs = 1;

  template <class T>
  using Algebra = Eigen::Matrix<T, 1, 1>;
  template <class T>
  using Dual = Eigen::Matrix<T, 1, 1>;
  template <class T>
  using Matrix = Eigen::Matrix<T, 2, 2>;
  template <class T>
  using Casimirs = Eigen::Matrix<T, 1, 1>;

  template <class T>
  static Matrix<T> hat(const Algebra<T>& x) {
    Matrix<T> X;
    X << T(0), -x(0), x(0), T(0);
    return X;
  }
  template <class T>
  static Algebra<T> vee(const Matrix<T>& X) {
    return Algebra<T>(X(1, 0));
  }
  /// <μ, x> = μx = tr(dualHat(μ)ᵀ hat(x)) with dualHat(μ) = hat(μ)/2, as on SO(3).
  template <class T>
  static Matrix<T> dualHat(const Dual<T>& mu) {
    return hat<T>(mu) * T(0.5);
  }
  /// y = tr(Yᵀ J) = Y₁₀ − Y₀₁.
  template <class T>
  static Dual<T> dualVee(const Matrix<T>& Y) {
    return Dual<T>(Y(1, 0) - Y(0, 1));
  }

  template <class T>
  static T pairing(const Dual<T>& mu, const Algebra<T>& x) {
    return mu(0) * x(0);
  }
  template <class T>
  static Algebra<T> bracket(const Algebra<T>&, const Algebra<T>&) {
    return Algebra<T>(T(0));
  }
  template <class T>
  static Dual<T> adDual(const Algebra<T>&, const Dual<T>&) {
    return Dual<T>(T(0));
  }
  template <class T>
  static Algebra<T> Ad(const Matrix<T>&, const Algebra<T>& x) {
    return x;
  }
  template <class T>
  static Dual<T> AdDual(const Matrix<T>&, const Dual<T>& mu) {
    return mu;
  }
  template <class T>
  static Matrix<T> inverse(const Matrix<T>& R) {
    return R.transpose();
  }

  /// ad_x = 0: its spectral radius is 0, and dexp^{-1} has no poles.
  static double adRadius(const Algebra<double>&) { return 0.0; }

  /// Every function of μ is constant on the (one-point) coadjoint orbits; μ itself is kept.
  template <class T>
  static Casimirs<T> casimirs(const Dual<T>& mu) {
    return mu;
  }

  /// exp(θ) = [[cos θ, −sin θ], [sin θ, cos θ]].
  template <class T>
  static Matrix<T> exp(const Algebra<T>& x) {
    using std::cos;
    using std::sin;
    const T c = cos(x(0)), s = sin(x(0));
    Matrix<T> R;
    R << c, -s, s, c;
    return R;
  }
  /// θ in (−π, π].
  template <class T>
  static Algebra<T> log(const Matrix<T>& R) {
    using std::atan2;
    return Algebra<T>(atan2(R(1, 0), R(0, 0)));
  }

  /// cay(θ) = I + 4/(4 + θ²)(X + X²/2), SO(3)'s closed form in the plane.
  template <class T>
  static Matrix<T> cay(const Algebra<T>& x) {
    const Matrix<T> X = hat(x);
    const T c = T(4) / (T(4) + x(0) * x(0));
    return Matrix<T>(Matrix<T>::Identity() + (X + X * X * T(0.5)) * c);
  }
  /// Ad* is the identity: the DDB update leaves μ as it is.
  template <class T>
  static Dual<T> cayTransport(const Algebra<T>&, const Algebra<T>&, const Dual<T>& mu) {
    return mu;
  }
  /// X and Y commute: dcay_x y = (I − X²/4)^{-1} y = y/(1 + θ²/4).
  template <class T>
  static Algebra<T> dcay(const Algebra<T>& x, const Algebra<T>& y) {
    return y * (T(4) / (T(4) + x(0) * x(0)));
  }
  /// dcay^{-1}_x y = (1 + θ²/4) y.
  template <class T>
  static Algebra<T> dcayInv(const Algebra<T>& x, const Algebra<T>& y) {
    return y * (T(1) + x(0) * x(0) * T(0.25));
  }
  template <class T>
  static Dual<T> dcayInvDual(const Algebra<T>& x, const Dual<T>& mu) {
    return mu * (T(1) + x(0) * x(0) * T(0.25));
  }
  static Eigen::Matrix<double, 1, 1> dcayInvDualMatrix(const Algebra<double>& x) {
    return Eigen::Matrix<double, 1, 1>(1.0 + 0.25 * x(0) * x(0));
  }
  /// ∂/∂θ [(1 + θ²/4) μ] = θμ/2.
  static Eigen::Matrix<double, 1, 1> dcayInvDualJacobian(const Algebra<double>& x,
                                                         const Dual<double>& mu) {
    return Eigen::Matrix<double, 1, 1>(0.5 * x(0) * mu(0));
  }

  /// ad_x = 0: dexp, dexp^{-1} and its dual are the identity.
  template <class T>
  static Algebra<T> dexp(const Algebra<T>&, const Algebra<T>& y) {
    return y;
  }
  template <class T>
  static Algebra<T> dexpInv(const Algebra<T>&, const Algebra<T>& y) {
    return y;
  }
  template <class T>
  static Dual<T> dexpInvDual(const Algebra<T>&, const Dual<T>& mu) {
    return mu;
  }
  static Eigen::Matrix<double, 1, 1> dexpInvDualMatrix(const Algebra<double>&) {
    return Eigen::Matrix<double, 1, 1>(1.0);
  }
  static Eigen::Matrix<double, 1, 1> dexpInvDualJacobian(const Algebra<double>&,
                                                         const Dual<double>&) {
    return Eigen::Matrix<double, 1, 1>(0.0);
  }
};

}  // namespace ddb
