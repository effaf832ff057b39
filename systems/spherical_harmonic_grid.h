// The vorticity of Zeitlin's fluid on a latitude–longitude grid: the function f(θ, φ) that a
// matrix W quantises (docs/reference/conventions.md §2), from its coefficients ω_lm
// (SphericalHarmonicBasis::coefficients):
//   f(θ, φ) = √(4π) Σ_lm ω_lm Y_lm(θ, φ),
// Y_lm the real orthonormal harmonics of the conventions (Y_l0 = N_l0 P_l(cos θ);
// m > 0: √2 N_lm P_l^m(cos θ) cos mφ; m < 0: √2 N_l|m| P_l^|m|(cos θ) sin |m|φ; P_l^m without the
// Condon–Shortley phase). The factor √(4π) is the quantisation's: X₃ = T_10/√3 is cos θ, so that
// F = 2Ω X₃ is 2Ω cos θ. The grid is quflow's "fun" layout (McEwen–Wiaux sampling, N rows
// θ_j = π(2j + 1)/(2N − 1), 2N − 1 columns φ_k = 2πk/(2N − 1)), so that f is quflow's
// shr2fun(ω, berezin=False).
#pragma once

#include <Eigen/Core>

namespace ddb {

class SphericalHarmonicGrid {
 public:
  /// The grid of resolution N (N rows, 2N − 1 columns) for coefficients of degree l < N.
  explicit SphericalHarmonicGrid(Eigen::Index n);

  Eigen::Index n() const { return n_; }
  /// θ_j = π(2j + 1)/(2N − 1), j = 0..N − 1 (colatitudes).
  const Eigen::VectorXd& colatitudes() const { return theta_; }
  /// φ_k = 2πk/(2N − 1), k = 0..2N − 2 (longitudes).
  const Eigen::VectorXd& longitudes() const { return phi_; }

  /// f(θ_j, φ_k) at (j, k) for the N² coefficients ω (index l² + l + m). O(N³): the normalised
  /// associated Legendre functions by their three-term recurrence in l at each θ_j, then the
  /// sums over m at each φ_k. Throws InvalidArgument unless ω has N² entries.
  Eigen::MatrixXd evaluate(const Eigen::VectorXd& omega) const;

 private:
  Eigen::Index n_;
  Eigen::VectorXd theta_, phi_;
  // The sums over m at the longitudes, w_m cos mφ_k and w_m sin mφ_k (w_0 = 1, w_m = √2): built
  // once, as evaluate() runs once per saved frame.
  Eigen::MatrixXd cos_table_, sin_table_;
};

}  // namespace ddb
