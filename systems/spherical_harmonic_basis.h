// The real spherical-harmonic basis T_lm of su(N) ⊕ i·I (docs/conventions.md §2): the
// eigenmatrices of the Hoppe–Yau Laplacian, ΔT_lm = −l(l+1) T_lm, orthonormal for
// Re tr(AᴴB)/N, so that ω_lm = Re tr(T_lmᴴ W)/N are the real spherical-harmonic
// coefficients of the vorticity W: ω(θ, φ) = Σ ω_lm Y_lm(θ, φ).
// For each m >= 0 the eigenvectors v_{l,m} (l = m..N−1) of the m-th diagonal block are
// scaled to ‖v‖ = √N with the sign of their last component (−1)^m, and
//   T_l0 = i diag(v_{l,0}),
//   m > 0: T_lm[k, k+m] = T_lm[k+m, k] = i (−1)^m v_{l,m}[k]/√2,
//   m < 0: T_lm[k, k+|m|] = (−1)^m v_{l,|m|}[k]/√2 = −T_lm[k+|m|, k].
// Coefficients are stored at index l² + l + m (l = 0..N−1, |m| <= l): N² of them.
#pragma once

#include <ddb/systems/hoppe_yau_laplacian.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <vector>

namespace ddb {

class SphericalHarmonicBasis {
 public:
  explicit SphericalHarmonicBasis(const HoppeYauLaplacian& laplacian)
      : n_(laplacian.size()), vectors_(static_cast<std::size_t>(n_)) {
    Eigen::VectorXd diagonal, subdiagonal;
    for (Eigen::Index m = 0; m < n_; ++m) {
      laplacian.block(m, diagonal, subdiagonal);
      Eigen::MatrixXd& v = vectors_[static_cast<std::size_t>(m)];
      if (diagonal.size() == 1) {
        v = Eigen::MatrixXd::Ones(1, 1);
      } else {
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen;
        eigen.computeFromTridiagonal(diagonal, subdiagonal);
        v = eigen.eigenvectors().rowwise().reverse();  // column l − m: eigenvalue −l(l+1)
      }
      const double sign = (m % 2 == 0) ? 1.0 : -1.0;
      for (Eigen::Index c = 0; c < v.cols(); ++c) {
        v.col(c) *= std::sqrt(double(n_)) / v.col(c).norm();
        if (v(v.rows() - 1, c) * sign < 0) v.col(c) *= -1.0;
      }
    }
  }

  Eigen::Index size() const { return n_; }
  static Eigen::Index index(Eigen::Index l, Eigen::Index m) { return l * l + l + m; }

  /// T_lm as an N×N complex matrix.
  Eigen::MatrixXcd element(Eigen::Index l, Eigen::Index m) const {
    Eigen::VectorXd coefficients = Eigen::VectorXd::Zero(n_ * n_);
    coefficients(index(l, m)) = 1.0;
    return matrix(coefficients);
  }

  /// ω_lm = Re tr(T_lmᴴ W)/N for every (l, m), at index(l, m).
  Eigen::VectorXd coefficients(const Eigen::MatrixXcd& W) const {
    Eigen::VectorXd omega = Eigen::VectorXd::Zero(n_ * n_);
    for (Eigen::Index m = 0; m < n_; ++m) {
      const Eigen::MatrixXd& v = vectors_[static_cast<std::size_t>(m)];
      const double sign = (m % 2 == 0) ? 1.0 : -1.0;
      for (Eigen::Index l = m; l < n_; ++l) {
        const auto vl = v.col(l - m);
        double plus = 0.0, minus = 0.0;
        for (Eigen::Index k = 0; k < n_ - m; ++k) {
          if (m == 0) {
            plus += vl(k) * W(k, k).imag();  // Re(conj(i v) w) = v Im w
          } else {
            // m > 0: Re(conj(i s v/√2)(W[k,k+m] + W[k+m,k])); m < 0: s v/√2 (W[k,k+m] − W[k+m,k]).
            plus += vl(k) * (W(k, k + m) + W(k + m, k)).imag();
            minus += vl(k) * (W(k, k + m) - W(k + m, k)).real();
          }
        }
        if (m == 0) {
          omega(index(l, 0)) = plus / double(n_);
        } else {
          omega(index(l, m)) = sign * plus / (std::sqrt(2.0) * double(n_));
          omega(index(l, -m)) = sign * minus / (std::sqrt(2.0) * double(n_));
        }
      }
    }
    return omega;
  }

  /// W = Σ ω_lm T_lm.
  Eigen::MatrixXcd matrix(const Eigen::VectorXd& omega) const {
    if (omega.size() != n_ * n_) {
      throwInvalid("coefficients", std::to_string(omega.size()) + " values",
                   "must be N^2 = " + std::to_string(n_ * n_));
    }
    Eigen::MatrixXcd W = Eigen::MatrixXcd::Zero(n_, n_);
    const std::complex<double> i(0, 1);
    for (Eigen::Index m = 0; m < n_; ++m) {
      const Eigen::MatrixXd& v = vectors_[static_cast<std::size_t>(m)];
      const double scale = ((m % 2 == 0) ? 1.0 : -1.0) / std::sqrt(2.0);
      for (Eigen::Index l = m; l < n_; ++l) {
        const auto vl = v.col(l - m);
        for (Eigen::Index k = 0; k < n_ - m; ++k) {
          if (m == 0) {
            W(k, k) += i * (omega(index(l, 0)) * vl(k));
            continue;
          }
          const std::complex<double> plus = i * (scale * omega(index(l, m)) * vl(k));
          const double minus = scale * omega(index(l, -m)) * vl(k);
          W(k, k + m) += plus + minus;
          W(k + m, k) += plus - minus;
        }
      }
    }
    return W;
  }

 private:
  Eigen::Index n_;
  std::vector<Eigen::MatrixXd> vectors_;  // vectors_[m].col(l − m) = v_{l,m}
};

}  // namespace ddb
