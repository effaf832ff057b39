// Viscosity, hyperviscosity and linear drag of Zeitlin's fluid (docs/reference/conventions.md §2):
//   Ẇ = ν (−1)^{p+1} Δ^p W − γ W
// on the relative vorticity W = Q − F (the planetary vorticity F is the frame's, not the flow's,
// and is not damped). Each T_lm is an eigenmatrix, of rate −(ν (l(l + 1))^p + γ), so the exact
// flow over h multiplies ω_lm by exp(−(ν (l(l + 1))^p + γ) h) (SphericalHarmonicBasis::
// applyDegreeFunction); the implicit scheme by R(z) = 1/(1 + z + z²/2) of z = (ν (l(l + 1))^p + γ)
// h instead, through a banded solve per diagonal (systems/zeitlin_implicit_viscous_step.h). With
// the Lie–Poisson part by any method of the table it is a StrangSplitting
// (integrators/methods/strang_splitting.h); it leaves the coadjoint orbit by design, and combines
// with the double bracket (α) freely.
#pragma once

#include <ddb/core/errors.h>
#include <ddb/core/exact_flow.h>
#include <ddb/groups/sun.h>
#include <ddb/systems/hoppe_yau_laplacian.h>
#include <ddb/systems/spherical_harmonic_basis.h>
#include <ddb/systems/spherical_harmonic_degree_operator.h>
#include <ddb/systems/zeitlin_implicit_viscous_step.h>

#include <Eigen/Core>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ddb {

/// How the viscous flow steps: exactly (exp(−hA) in the spherical harmonics, kept as an operator
/// of N³/6 numbers), or by the implicit step (I + hA + (hA)²/2)⁻¹, second order and L-stable, a
/// banded solve per diagonal (ZeitlinImplicitViscousStep): O(N² p) numbers and work.
enum class ZeitlinViscousScheme { kExact, kImplicit };

/// ν, p and γ of Ẇ = ν (−1)^{p+1} Δ^p W − γ W, and the scheme of its flow.
struct ZeitlinViscosity {
  double viscosity = 0.0;  ///< ν >= 0
  int order = 1;           ///< p >= 1: 1 is Laplacian viscosity, p > 1 hyperviscosity
  double drag = 0.0;       ///< γ >= 0, linear (Rayleigh) drag
  ZeitlinViscousScheme scheme = ZeitlinViscousScheme::kExact;

  /// Throws InvalidArgument naming the parameter unless ν, γ are finite and >= 0 and p >= 1.
  void validate() const {
    if (!(viscosity >= 0 && std::isfinite(viscosity))) {
      throwInvalid("viscosity", formatValue(viscosity), "must be finite and >= 0");
    }
    if (order < 1) throwInvalid("order", std::to_string(order), "must be >= 1");
    if (!(drag >= 0 && std::isfinite(drag))) {
      throwInvalid("drag", formatValue(drag), "must be finite and >= 0");
    }
  }
  /// Whether anything is damped (ν > 0 or γ > 0).
  bool damps() const { return viscosity > 0 || drag > 0; }
  /// The decay rate of degree l: ν (l(l + 1))^p + γ (γ alone for ν = 0, whatever p: no 0 · ∞).
  double rate(Eigen::Index l) const {
    if (viscosity == 0) return drag;
    return viscosity * std::pow(double(l) * double(l + 1), order) + drag;
  }
};

/// The flow of ZeitlinViscosity at resolution N (exact, or its implicit step by
/// viscosity.scheme), of the states Q = W + F of a fluid whose planetary vorticity is `planetary`
/// (ZeitlinHamiltonian::planetaryVorticity; zero or empty on a resting sphere).
class ZeitlinViscousFlow final : public ExactFlow<SUN> {
 public:
  ZeitlinViscousFlow(Eigen::Index n, const ZeitlinViscosity& viscosity,
                     Eigen::MatrixXcd planetary = Eigen::MatrixXcd());

  /// The memory the flow may keep its operator in (SphericalHarmonicDegreeOperator::bytes:
  /// 179 MB at N = 512, 2 GiB at N = 1172). Up to it a step reads the operator; above it, each
  /// step computes the basis's eigenvectors instead, about 30 times slower
  /// (docs/results/benchmarks.md, "The viscous flow through a kept operator").
  static constexpr double kOperatorBytes = 2.0 * 1024.0 * 1024.0 * 1024.0;

  std::string name() const override { return "viscosity"; }

  /// Q ← F + exp(h L)(Q − F), L = ν (−1)^{p+1} Δ^p − γ (the implicit step: F + R(−hL)(Q − F)).
  void advance(Eigen::MatrixXcd& Q, double h) override;

 private:
  // Each diagonal of Q − F through the implicit step. Q − F is skew-Hermitian and the step real
  // and alike on diagonals m and −m, so diagonal m's result is −conj of −m's: the lower diagonals
  // alone are solved, and the upper triangle is made from them (exactly skew-Hermitian). The
  // diagonals are taken out and put back walking Q's columns in order (a diagonal read along
  // itself touches one cache line per entry): entry k of diagonal −a at diagonals_[start(a) + k],
  // start(a) = Σ_{b < a} (N − b).
  void advanceImplicitly(Eigen::MatrixXcd& Q, double h);

  SphericalHarmonicBasis basis_;
  // The transform's workspace, where neither the operator nor the implicit step is kept (3 N²
  // numbers): the flow allocates nothing once built.
  std::optional<SphericalHarmonicBasis::Workspace> workspace_;
  std::optional<SphericalHarmonicDegreeOperator> operator_;  // exp(h_ L), within kOperatorBytes
  Eigen::VectorXd rates_, factors_;  // per degree l: the decay rate, exp(−rate h) for h_
  double h_ = std::nan("");
  Eigen::MatrixXcd planetary_;
  bool rotating_;
  bool keeps_operator_;  // whether operator_ fits in kOperatorBytes at this N
  std::optional<ZeitlinImplicitViscousStep> implicit_;  // the implicit scheme's
  Eigen::VectorXcd diagonals_;  // Q − F's diagonals, for the implicit step
};

}  // namespace ddb
