// SE(2) = SO(2) ⋉ R², the planar rigid motions, composed by SemidirectProduct
// (groups/semidirect_product.h): ξ = (ω, v₁, v₂), μ = (π, γ₁, γ₂), elements the 3×3 matrices
// [[R, r], [0, 1]]. With J the quarter turn, v ⋄ γ = γ·Jv = v₁γ₂ − v₂γ₁ (= v × γ, the planar
// cross product) and
//   ad*_(ω,v)(π, γ) = (γ × v, −ωJγ),   Ad*_(R,r)(π, γ) = (π + γ × r, Rᵀγ),   Casimir |γ|²
// (the coadjoint orbits are the cylinders |γ| = c > 0, and points where γ = 0).
#pragma once

#include <ddb/groups/semidirect_product.h>
#include <ddb/groups/so2.h>

#include <Eigen/Core>
#include <cmath>
#include <utility>

namespace ddb {

template <>
struct SemidirectProductTraits<SO2> {
  static constexpr const char* kName = "SE2";
  static constexpr int kNumCasimirs = 1;

  /// |γ|².
  template <class T>
  static Eigen::Matrix<T, 1, 1> casimirs(const Eigen::Matrix<T, 1, 1>&,
                                         const Eigen::Matrix<T, 2, 1>& gamma) {
    return Eigen::Matrix<T, 1, 1>(gamma.squaredNorm());
  }

  /// φ(θJ)v = (a I + b J)v, a = sin θ/θ, b = (1 − cos θ)/θ (Taylor branch below θ² = 1e-8: the
  /// next terms are under 1e-24).
  template <class T>
  static Eigen::Matrix<T, 2, 1> expIntegral(const Eigen::Matrix<T, 1, 1>& w,
                                            const Eigen::Matrix<T, 2, 1>& v) {
    const auto [a, b] = coefficients(w(0));
    return Eigen::Matrix<T, 2, 1>(a * v(0) - b * v(1), b * v(0) + a * v(1));
  }
  /// (a I + b J)⁻¹ r = (a I − b J) r/(a² + b²).
  template <class T>
  static Eigen::Matrix<T, 2, 1> expIntegralInverse(const Eigen::Matrix<T, 1, 1>& w,
                                                   const Eigen::Matrix<T, 2, 1>& r) {
    const auto [a, b] = coefficients(w(0));
    const T scale = T(1) / (a * a + b * b);
    return Eigen::Matrix<T, 2, 1>((a * r(0) + b * r(1)) * scale, (a * r(1) - b * r(0)) * scale);
  }

 private:
  template <class T>
  static std::pair<T, T> coefficients(const T& theta) {
    using std::cos;
    using std::sin;
    const T theta2 = theta * theta;
    if (scalarPart(theta2) < 1e-8) {
      return {T(1) - theta2 / T(6) + theta2 * theta2 / T(120),
              theta * (T(0.5) - theta2 / T(24) + theta2 * theta2 / T(720))};
    }
    return {sin(theta) / theta, (T(1) - cos(theta)) / theta};
  }
};

/// SE(2), planar rigid motions.
using SE2 = SemidirectProduct<SO2>;

}  // namespace ddb
