// The viscous flow's implicit step (ZeitlinViscousScheme::kImplicit, systems/zeitlin_viscosity.h):
// in place of exp(−hA), A = ν (−Δ)^p + γ, the rational function
//   R(hA) = (I + hA + (hA)²/2)⁻¹,
// second order (R(z) = e^{−z} + O(z³)) and L-stable (R(z) → 0 as z → ∞, 0 < R(z) < 1 for z > 0:
// every mode decays, none changes sign), so that a split step stays second order and a stiff
// hyperviscosity damps the small scales as the exact flow does. Each diagonal m of W is its own
// system, −Δ being the tridiagonal block T_m there (HoppeYauLaplacian::blockCoefficients), so A is
// banded (half-width p): a step costs O(N² p), about a quarter of a matrix product at N = 512
// where the exact flow costs 1.7 (docs/results/benchmarks.md, "The viscous flow's implicit step,
// and subnormal operators"), and holds (p + 1) N²/2 complex numbers (the factors) where the exact
// one holds N³/6 reals.
// A² is not formed: I + z + z²/2 = (1 + a z)(1 + ā z) with a = (1 + i)/2, and by partial
// fractions
//   R(z) = 2 Re(α / (1 + a z)),  α = (1 − i)/2,
// so a real vector u goes to 2 Re(α C⁻¹ u), C = I + a hA, one complex banded solve. C is complex
// symmetric with positive definite real part I + hA/2 and semidefinite imaginary part hA/2, so its
// LDLᵀ factorisation needs no pivoting (N. J. Higham, "Factorizing complex symmetric matrices with
// positive definite real and imaginary parts", Math. Comp. 67 (1998) 1591–1599: growth below 3).
// Rounding: forming T^p costs about ε ‖hA‖ on the slowest modes per step (ε ‖hA‖² had A² been
// formed).
#pragma once

#include <ddb/core/errors.h>
#include <ddb/systems/hoppe_yau_laplacian.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdlib>
#include <string>
#include <vector>

namespace ddb {

class ZeitlinImplicitViscousStep {
 public:
  using Complex = std::complex<double>;

  /// The step of ν (−Δ)^p + γ (ν, γ >= 0, p >= 1, checked by the caller's ZeitlinViscosity) at
  /// resolution N on the blocks m in `blocks` (diagonals m and −m; all of them: every m < N).
  ZeitlinImplicitViscousStep(Eigen::Index n, double viscosity, int order, double drag,
                             const std::vector<Eigen::Index>& blocks);

  bool kept(Eigen::Index m) const { return m >= 0 && m < n_ && kept_[std::size_t(m)]; }

  /// Factors C = I + a h A of every kept block for the step h > 0: O(N² p²) in all, (−Δ)^p's
  /// band made again (it is not kept: as many numbers as the factors).
  void setStep(double h);

  /// Diagonals of block m of a matrix W (W's diagonal m or −m, entries in the order
  /// k = min(i, j)), one (`second` null) or both, each replaced by R(hA) applied to it. Block m
  /// must be kept and setStep called. Allocates nothing.
  void applyToDiagonals(Eigen::Index m, Complex* first, Complex* second = nullptr);

 private:
  Complex* lower(Eigen::Index m) {
    return lower_.data() + offsets_[std::size_t(m)] * std::size_t(order_);
  }

  /// The lower band of T^p into `band`, T symmetric tridiagonal (diagonal t, couplings s(k) of
  /// k − 1 and k): (p + 1) numbers per row j, T^p(j + d, j) at j (p + 1) + d; p products by T,
  /// each widening the band by one (`next` their scratch).
  void power(const Eigen::VectorXd& t, const Eigen::VectorXd& s, std::vector<double>& band,
             std::vector<double>& next) const;

  // A diagonal x (complex entries: its real and imaginary parts two real vectors u, v) ←
  // 2 Re(α C⁻¹ u) + 2i Re(α C⁻¹ v), both solves in one pass.
  void solve(Eigen::Index m, Complex* x);

  // (a, b) −= l · (the two unknowns at `other`), complex l = (l[0], l[1]).
  static void subtract(const double* l, const double* other, double& ar, double& ai, double& br,
                       double& bi);
  // C⁻¹ of two right-hand sides at once, interleaved in y (entry i: Re, Im of the first, Re, Im
  // of the second, at 4i..4i + 3): L z = y, z ← D⁻¹ z, Lᵀ y = z. L's p subdiagonals by column
  // (L(j + d, j) at 2 (j p + d − 1), real then imaginary), D⁻¹ likewise (2 j). Restrict-qualified
  // real arrays: std::complex's products check for infinities through a library call (C99
  // Annex G), and pointers that might alias make every unknown a reload.
  static void substitute(Eigen::Index length, int p, const double* __restrict L,
                         const double* __restrict D, double* __restrict y);

  Eigen::Index n_;
  double viscosity_, drag_;
  int order_;
  std::vector<bool> kept_;
  std::vector<std::size_t> offsets_;  // where block m's rows start (n_ − m rows if kept)
  std::vector<Complex> lower_;        // L's p subdiagonals per row, by column: L(j + d, j)
  std::vector<Complex> inverse_pivot_;
  std::vector<double> solved_;  // the two solves' unknowns, real and imaginary parts (4 N)
};

}  // namespace ddb
