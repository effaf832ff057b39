// SO(3): rotations; so(3) ≅ R^3 with [x, y] = x × y, so(3)* ≅ R^3 with the dot
// pairing (docs/reference/conventions.md §1). Closed forms shadow the generic LieGroupBase
// versions.
#pragma once

#include <ddb/core/lie_group.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>

namespace ddb {

struct SO3 : LieGroupBase<SO3> {
  static constexpr const char* kName = "SO3";
  static constexpr int kDim = 3;
  static constexpr int kNumCasimirs = 1;

  template <class T>
  using Algebra = Eigen::Matrix<T, 3, 1>;
  template <class T>
  using Dual = Eigen::Matrix<T, 3, 1>;
  template <class T>
  using Matrix = Eigen::Matrix<T, 3, 3>;
  template <class T>
  using Casimirs = Eigen::Matrix<T, 1, 1>;

  template <class T>
  EIGEN_ALWAYS_INLINE static Matrix<T> hat(const Algebra<T>& x) {
    Matrix<T> X;
    X << T(0), -x(2), x(1), x(2), T(0), -x(0), -x(1), x(0), T(0);
    return X;
  }
  template <class T>
  static Algebra<T> vee(const Matrix<T>& X) {
    return Algebra<T>(X(2, 1), X(0, 2), X(1, 0));
  }
  /// <mu, x> = mu·x = (1/2) tr(hat(mu)^T hat(x)) (paper, Section 4: the so(3)* pairing).
  template <class T>
  static Matrix<T> dualHat(const Dual<T>& mu) {
    return hat<T>(mu) * T(0.5);
  }
  /// y_i = tr(Y^T hat(e_i)), i.e. vee(Y - Y^T).
  template <class T>
  static Dual<T> dualVee(const Matrix<T>& Y) {
    return vee<T>(Matrix<T>(Y - Y.transpose()));
  }

  template <class T>
  static T pairing(const Dual<T>& mu, const Algebra<T>& x) {
    return mu.dot(x);
  }
  template <class T>
  static Algebra<T> bracket(const Algebra<T>& x, const Algebra<T>& y) {
    return x.cross(y);
  }
  /// ad*_x mu = mu × x.
  template <class T>
  EIGEN_ALWAYS_INLINE static Dual<T> adDual(const Algebra<T>& x, const Dual<T>& mu) {
    return mu.cross(x);
  }
  template <class T>
  static Algebra<T> Ad(const Matrix<T>& R, const Algebra<T>& x) {
    return R * x;
  }
  /// Ad*_R mu = R^T mu.
  template <class T>
  static Dual<T> AdDual(const Matrix<T>& R, const Dual<T>& mu) {
    return R.transpose() * mu;
  }
  template <class T>
  static Matrix<T> inverse(const Matrix<T>& R) {
    return R.transpose();
  }

  /// The spectral radius of ad_x (its eigenvalues are 0, ±i|x|): exp is one-to-one for
  /// adRadius < π and dexp^{-1} has its poles at 2π (docs/reference/guarantees.md §2).
  static double adRadius(const Algebra<double>& x) { return x.norm(); }

  /// Casimir |mu|.
  template <class T>
  static Casimirs<T> casimirs(const Dual<T>& mu) {
    return Casimirs<T>(mu.norm());
  }

  /// Rodrigues: exp(x) = I + a X + b X², a = sin θ/θ, b = (1 - cos θ)/θ², θ = |x|.
  template <class T>
  static Matrix<T> exp(const Algebra<T>& x) {
    const T theta2 = x.squaredNorm();
    T a, b;
    if (scalarPart(theta2) < 1e-8) {  // Taylor branch: error O(θ^6) < 1e-24
      a = T(1) - theta2 / T(6) + theta2 * theta2 / T(120);
      b = T(0.5) - theta2 / T(24) + theta2 * theta2 / T(720);
    } else {
      const T theta = sqrt(theta2);
      a = sin(theta) / theta;
      b = (T(1) - cos(theta)) / theta2;
    }
    const Matrix<T> X = hat(x);
    return Matrix<T>::Identity() + X * a + X * X * b;
  }

  /// log via the unit quaternion of R (Shepperd's method), robust near θ = 0 and θ = π.
  template <class T>
  static Algebra<T> log(const Matrix<T>& R) {
    const T trace = R.trace();
    T w;
    Algebra<T> v;
    const double d0 = scalarPart(R(0, 0)), d1 = scalarPart(R(1, 1)), d2 = scalarPart(R(2, 2));
    const double dt = scalarPart(trace);
    if (dt >= d0 && dt >= d1 && dt >= d2) {
      const T s = sqrt(T(1) + trace) * T(2);  // s = 4w
      w = s / T(4);
      v = Algebra<T>(R(2, 1) - R(1, 2), R(0, 2) - R(2, 0), R(1, 0) - R(0, 1)) / s;
    } else {
      int i = 0;
      if (d1 > d0) i = 1;
      if (d2 > (i == 0 ? d0 : d1)) i = 2;
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      const T s = sqrt(T(1) + R(i, i) - R(j, j) - R(k, k)) * T(2);  // s = 4 v_i
      v(i) = s / T(4);
      v(j) = (R(j, i) + R(i, j)) / s;
      v(k) = (R(k, i) + R(i, k)) / s;
      w = (R(k, j) - R(j, k)) / s;
    }
    if (scalarPart(w) < 0) {
      w = -w;
      v = -v;
    }
    const T vn2 = v.squaredNorm();
    if (scalarPart(vn2) < 1e-16) {
      // θ = 2 atan2(|v|, w) ≈ 2|v|/w (1 - |v|²/(3w²)); x = θ v/|v|.
      return v * (T(2) / w * (T(1) - vn2 / (T(3) * w * w)));
    }
    const T vn = sqrt(vn2);
    return v * (T(2) * atan2(vn, w) / vn);
  }

  /// Closed form cay(x) = I + 4/(4 + |x|²) (X + X²/2).
  template <class T>
  static Matrix<T> cay(const Algebra<T>& x) {
    const Matrix<T> X = hat(x);
    const T c = T(4) / (T(4) + x.squaredNorm());
    return Matrix<T>::Identity() + (X + X * X * T(0.5)) * c;
  }
  /// Ad*_{cay(x)} mu = cay(x)ᵀ mu = mu + c (−x × mu + ½ x × (x × mu)), c = 4/(4 + |x|²),
  /// as vector operations: forming cay(x) rounds its diagonal 1 − O(|x|²) the same way at
  /// every step of a steady rotation, and that bias adds up linearly in |M|
  /// (docs/results/casimir-drift.md); here the only rounding of order ulp(mu) is the final sum.
  template <class T>
  EIGEN_ALWAYS_INLINE static Dual<T> cayAdDual(const Algebra<T>& x, const Dual<T>& mu) {
    const Algebra<T> xm = x.cross(mu);
    return mu + (x.cross(xm) * T(0.5) - xm) * (T(4) / (T(4) + x.squaredNorm()));
  }
  /// Ad*_{cay(a) cay(b)} mu = Ad*_{cay(b)} Ad*_{cay(a)} mu, the DDB update (paper, eq. (4.12)).
  template <class T>
  EIGEN_ALWAYS_INLINE static Dual<T> cayTransport(const Algebra<T>& a, const Algebra<T>& b,
                                                  const Dual<T>& mu) {
    return cayAdDual(b, cayAdDual(a, mu));
  }
  /// dcay_x = 4/(4 + |x|²) (I + X/2) (paper, Section 4.1).
  template <class T>
  static Algebra<T> dcay(const Algebra<T>& x, const Algebra<T>& y) {
    return (y + x.cross(y) * T(0.5)) * (T(4) / (T(4) + x.squaredNorm()));
  }
  /// dcay^{-1}_x = I - X/2 + x xᵀ/4 (paper, Section 4.1).
  template <class T>
  static Algebra<T> dcayInv(const Algebra<T>& x, const Algebra<T>& y) {
    return y - x.cross(y) * T(0.5) + x * (x.dot(y) * T(0.25));
  }
  /// (dcay^{-1}_x)* = I + X/2 + x xᵀ/4 (paper, Section 4.1).
  template <class T>
  EIGEN_ALWAYS_INLINE static Dual<T> dcayInvDual(const Algebra<T>& x, const Dual<T>& mu) {
    return mu + x.cross(mu) * T(0.5) + x * (x.dot(mu) * T(0.25));
  }
  /// The matrix of (dcay^{-1}_x)*: I + X/2 + x xᵀ/4.
  EIGEN_ALWAYS_INLINE static Eigen::Matrix3d dcayInvDualMatrix(const Eigen::Vector3d& x) {
    return Eigen::Matrix3d::Identity() + 0.5 * hat<double>(x) + 0.25 * x * x.transpose();
  }
  /// ∂/∂x [(dcay^{-1}_x)* mu] = -M/2 + (x·mu)/4 I + x muᵀ/4, M = hat(mu).
  EIGEN_ALWAYS_INLINE static Eigen::Matrix3d dcayInvDualJacobian(const Eigen::Vector3d& x,
                                                                 const Eigen::Vector3d& mu) {
    return hat<double>(mu) * -0.5 + Eigen::Matrix3d::Identity() * (0.25 * x.dot(mu)) +
           x * (0.25 * mu.transpose());
  }

  /// Closed form dexp_x = I + (1 - cos θ)/θ² X + (θ - sin θ)/θ³ X².
  template <class T>
  static Algebra<T> dexp(const Algebra<T>& x, const Algebra<T>& y) {
    const T theta2 = x.squaredNorm();
    T a, b;
    if (scalarPart(theta2) < 1e-8) {
      a = T(0.5) - theta2 / T(24) + theta2 * theta2 / T(720);
      b = T(1) / T(6) - theta2 / T(120) + theta2 * theta2 / T(5040);
    } else {
      const T theta = sqrt(theta2);
      a = (T(1) - cos(theta)) / theta2;
      b = (theta - sin(theta)) / (theta2 * theta);
    }
    const Algebra<T> xy = x.cross(y);
    return y + xy * a + x.cross(xy) * b;
  }

  /// Closed form dexp^{-1}_x = I - X/2 + c X², c = (1 - (θ/2) cot(θ/2))/θ²
  /// (docs/reference/conventions.md §1).
  template <class T>
  static Algebra<T> dexpInv(const Algebra<T>& x, const Algebra<T>& y) {
    const Algebra<T> xy = x.cross(y);
    return y - xy * T(0.5) + x.cross(xy) * dexpInvCoefficient(x);
  }

  /// (dexp^{-1}_x)* = I + X/2 + c X² (the transpose of dexpInv).
  template <class T>
  static Dual<T> dexpInvDual(const Algebra<T>& x, const Dual<T>& mu) {
    const Algebra<T> xm = x.cross(mu);
    return mu + xm * T(0.5) + x.cross(xm) * dexpInvCoefficient(x);
  }
  /// The matrix of (dexp^{-1}_x)*: I + X/2 + c X².
  static Eigen::Matrix3d dexpInvDualMatrix(const Eigen::Vector3d& x) {
    const Eigen::Matrix3d X = hat<double>(x);
    return Eigen::Matrix3d::Identity() + 0.5 * X + dexpInvCoefficient(x) * X * X;
  }
  /// ∂/∂x [(dexp^{-1}_x)* mu] = -M/2 - c (hat(x × mu) + X M) + 2 c'(θ²) (x × (x × mu)) xᵀ,
  /// X = hat(x), M = hat(mu), c as in dexpInv as a function of θ² (differentiating the line above).
  static Eigen::Matrix3d dexpInvDualJacobian(const Eigen::Vector3d& x, const Eigen::Vector3d& mu) {
    const Eigen::Vector3d xm = x.cross(mu);
    const Eigen::Matrix3d M = hat<double>(mu);
    return M * -0.5 - (hat<double>(xm) + hat<double>(x) * M) * dexpInvCoefficient(x) +
           x.cross(xm) * (2.0 * dexpInvCoefficientSlope(x.squaredNorm()) * x.transpose());
  }

 private:
  // c(θ) = (1 - (θ/2) cot(θ/2))/θ² with its Taylor branch 1/12 + θ²/720 + θ⁴/30240 near 0.
  template <class T>
  static T dexpInvCoefficient(const Algebra<T>& x) {
    const T theta2 = x.squaredNorm();
    if (scalarPart(theta2) < 1e-6) {
      return T(1) / T(12) + theta2 / T(720) + theta2 * theta2 / T(30240);
    }
    const T theta = sqrt(theta2);
    const T half = theta / T(2);
    return (T(1) - half * cos(half) / sin(half)) / theta2;
  }
  // dc/d(θ²) = f'/(2θ³) - f/θ⁴ with f = 1 - (θ/2) cot(θ/2), f' = -cot(θ/2)/2 + θ/(4 sin²(θ/2)).
  // Both terms are ~1/(12θ²), so below θ² = 1e-2 the series 1/720 + θ²/15120 + θ⁴/403200 +
  // θ⁶/11975040 (from the Bernoulli numbers; next term < 3e-17) replaces them.
  static double dexpInvCoefficientSlope(double theta2) {
    if (theta2 < 1e-2) {
      return 1.0 / 720 + theta2 * (1.0 / 15120 + theta2 * (1.0 / 403200 + theta2 / 11975040));
    }
    const double theta = std::sqrt(theta2), half = 0.5 * theta;
    const double s = std::sin(half), cot = std::cos(half) / s;
    const double f = 1.0 - half * cot, slope_f = -0.5 * cot + 0.25 * theta / (s * s);
    return slope_f / (2.0 * theta2 * theta) - f / (theta2 * theta2);
  }
};

}  // namespace ddb
