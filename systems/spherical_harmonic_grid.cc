#include <ddb/core/errors.h>
#include <ddb/systems/spherical_harmonic_grid.h>

#include <cmath>
#include <string>

namespace ddb {

namespace {

constexpr double kPi = 3.14159265358979323846;

/// ω_lm's index, l² + l + m (SphericalHarmonicBasis::index).
Eigen::Index at(Eigen::Index l, Eigen::Index m) { return l * l + l + m; }

}  // namespace

SphericalHarmonicGrid::SphericalHarmonicGrid(Eigen::Index n) : n_(n) {
  if (n < 1) throwInvalid("n", std::to_string(n), "must be >= 1");
  const double columns = double(2 * n - 1);
  theta_.resize(n);
  for (Eigen::Index j = 0; j < n; ++j) theta_(j) = kPi * double(2 * j + 1) / columns;
  phi_.resize(2 * n - 1);
  for (Eigen::Index k = 0; k < 2 * n - 1; ++k) phi_(k) = 2.0 * kPi * double(k) / columns;
  // C(m, k) = w_m cos mφ_k, S(m, k) = w_m sin mφ_k with w_0 = 1, w_m = √2.
  cos_table_.resize(n, phi_.size());
  sin_table_.resize(n, phi_.size());
  for (Eigen::Index m = 0; m < n; ++m) {
    const double weight = m == 0 ? 1.0 : std::sqrt(2.0);
    for (Eigen::Index k = 0; k < phi_.size(); ++k) {
      cos_table_(m, k) = weight * std::cos(double(m) * phi_(k));
      sin_table_(m, k) = weight * std::sin(double(m) * phi_(k));
    }
  }
}

Eigen::MatrixXd SphericalHarmonicGrid::evaluate(const Eigen::VectorXd& omega) const {
  const Eigen::Index n = n_;
  if (omega.size() != n * n) {
    throwInvalid("omega", std::to_string(omega.size()) + " coefficients",
                 "must be N^2 = " + std::to_string(n * n));
  }
  // cosines(j, m) = Σ_l ω_lm P̄_lm(cos θ_j), sines(j, m) = Σ_l ω_l,−m P̄_lm(cos θ_j), P̄_lm the
  // orthonormal associated Legendre functions, N_lm P_l^m (Y_lm = P̄_lm at φ = 0 for m = 0).
  Eigen::MatrixXd cosines = Eigen::MatrixXd::Zero(n, n), sines = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const double x = std::cos(theta_(j)), s = std::sin(theta_(j));
    double diagonal = 1.0 / std::sqrt(4.0 * kPi);  // P̄_mm, from P̄_00
    for (Eigen::Index m = 0; m < n; ++m) {
      if (m > 0) diagonal *= std::sqrt(double(2 * m + 1) / double(2 * m)) * s;
      // P̄_lm for l = m, m + 1, ...: P̄_{m+1,m} = √(2m + 3) x P̄_mm, then
      // P̄_lm = a_lm (x P̄_{l−1,m} − b_lm P̄_{l−2,m}).
      double previous = 0.0, current = diagonal;
      for (Eigen::Index l = m; l < n; ++l) {
        if (l == m + 1) {
          previous = current;
          current = std::sqrt(double(2 * m + 3)) * x * previous;
        } else if (l > m + 1) {
          const double ll = double(l) * double(l), mm = double(m) * double(m);
          const double lm1 = double(l - 1) * double(l - 1);
          const double a = std::sqrt((4.0 * ll - 1.0) / (ll - mm));
          const double b = std::sqrt((lm1 - mm) / (4.0 * lm1 - 1.0));
          const double next = a * (x * current - b * previous);
          previous = current;
          current = next;
        }
        cosines(j, m) += omega(at(l, m)) * current;
        if (m > 0) sines(j, m) += omega(at(l, -m)) * current;
      }
    }
  }
  // f = √(4π) (cosines · C + sines · S), the longitudes' tables C and S built once.
  Eigen::MatrixXd f = cosines * cos_table_;
  f.noalias() += sines * sin_table_;
  return std::sqrt(4.0 * kPi) * f;
}

}  // namespace ddb
