// The field's diagnostics of Zeitlin's fluid (docs/reference/conventions.md §2), of the relative
// vorticity W with coefficients ω_lm = Re tr(T_lmᴴ W)/N (SphericalHarmonicBasis):
//   energy spectrum     E_l = ½ Σ_m ω_lm² / (l(l + 1) + κ²)   (l ≥ 1; Σ_l E_l = E = ħH/N)
//   enstrophy spectrum  Z_l = ½ Σ_m ω_lm²                     (Σ_l Z_l = Z = ‖W‖²_F/(2N))
//   γ = |(ω_1,−1, ω_1,0, ω_1,1)| / |ω|, the share of the l = 1 part (angular momentum), which
//       the field reads to predict how many vortex blobs a freely decaying flow ends in (one of
//       quflow's diagnostics);
//   W = W_s + W_r, the canonical scale decomposition: W_s the part of W diagonal in the stream
//       matrix's eigenbasis (it commutes with ψ; W_s = W at a steady state), W_r = W − W_s.
// The ½ makes the spectra sum to the fluid's E and Z (ZeitlinDiagnostics' units).
#pragma once

#include <ddb/systems/spherical_harmonic_basis.h>

#include <Eigen/Core>

namespace ddb {

/// E_l and Z_l, l = 0..N−1 (E_0 = 0: the l = 0 part is the trace, which su(N) has not).
struct ZeitlinSpectra {
  Eigen::VectorXd energy, enstrophy;
};

/// The spectra of coefficients ω (SphericalHarmonicBasis::coefficients, N² of them) of a fluid
/// whose stream matrix is (Δ − κ²)⁻¹W (κ² = 0: Euler).
ZeitlinSpectra zeitlinSpectra(const Eigen::VectorXd& omega, double kappa_squared = 0.0);

/// γ = |(ω_1,−1, ω_1,0, ω_1,1)| / |ω| (0 for ω = 0).
double zeitlinGamma(const Eigen::VectorXd& omega);

/// γ of a matrix W directly, from the three l = 1 harmonics: ω_1m = Re tr(T_1mᴴ W)/N and
/// |ω|² = ‖W‖²_F/N (the T_lm are orthonormal for Re tr(AᴴB)/N). O(N²) a call, where the
/// coefficients of every degree cost O(N³): for a history row at every step.
class ZeitlinGammaFromMatrix {
 public:
  explicit ZeitlinGammaFromMatrix(const SphericalHarmonicBasis& basis);

  double operator()(const Eigen::MatrixXcd& W) const;

 private:
  Eigen::Index n_;
  Eigen::MatrixXcd harmonics_[3];
};

/// W_s and W_r of the canonical scale decomposition.
struct ScaleDecomposition {
  Eigen::MatrixXcd steady, remainder;
};

/// W = W_s + W_r for the stream matrix ψ (skew-Hermitian: ZeitlinHamiltonian::streamMatrix):
/// with ψ = U (iΛ) Uᴴ, W_s = U diag(Uᴴ W U) Uᴴ, the part of W that commutes with ψ when ψ's
/// eigenvalues are distinct. O(N³): an eigendecomposition and four products.
ScaleDecomposition zeitlinScaleDecomposition(const Eigen::MatrixXcd& W,
                                             const Eigen::MatrixXcd& psi);

}  // namespace ddb
