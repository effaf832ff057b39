// DualEigenbasis<X>: the spectral calculus of a skew-Hermitian matrix over the dual numbers,
// x = x₀ + εx₁ (ε² = 0), MatrixBackend<DualMatrix<X>>::Eigenbasis for complex X whose own
// Eigenbasis works in its coordinates (kEigenbasisCoordinates: the dense, distributed and CUDA
// backends; core/dual_matrix.h), on which the exponential methods run on SU(N) ⋉ su(N)*
// (groups/dual_number_sun.h; docs/reference/conventions.md §1, "SU(N) over the dual numbers").
// A function of ad_x over R[ε] is its Taylor series in dual-number arithmetic: with
// A = A₀ + εA₁,
//   G(s ad_x) A = G(s ad_{x₀}) A₀ + ε [G(s ad_{x₀}) A₁ + DG(s ad_{x₀})[s ad_{x₁}] A₀],
// the first two terms in x₀'s eigenbasis (X's Eigenbasis), the last, a Fréchet
// derivative, by the Daleckii–Krein formula. The two functions an eigenbasis applies
// (core/phase_function.h) are conjugations and an integral of them,
//   kCoadjointIncrement:      G(s ad_x) A = e^{−sx} A e^{sx} − A,
//   kInverseDexpInverseDual:  G(s ad_x) A = ∫₀¹ e^{−tsx} A e^{tsx} dt,
// and the derivative of a conjugation by e^{τx} needs only the derivative of e^{τx}, whose
// Daleckii–Krein weights form a symmetric matrix in x₀'s eigenbasis (x₀ = V diag(iθ) Vᴴ,
// x̂ = Vᴴ x V):
//   (D e^{τ·}(x₀)[x₁])^ = Γ(τ) ∘ x̂₁,  Γ(τ)_ac = τ e^{iτ(θ_a + θ_c)/2} sinc(τ(θ_a − θ_c)/2),
// stable at equal and close phases (the divided differences of a general function of ad_x
// would need weights over three indices). With K = Γ(τ) ∘ x̂₁ (so Γ(−τ) ∘ x̂₁ = Kᴴ, x̂₁ being
// skew-Hermitian) and D = diag(e^{iτθ}), the derivative of e^{−τx} A₀ e^{τx} is, in the
// eigenbasis,
//   Kᴴ Â₀ D + D̄ Â₀ K = P − Pᴴ,  P = D̄ Â₀ K   (one product),
// and the integral over t is a composite Gauss–Legendre rule whose error bound is below 1e-17
// of the term (core/detail/gauss_legendre.h): the integrand's frequency in t is at most
// c = 1.5|s|(θ_max − θ_min), and ten nodes do for c ≤ 4, so every sweep within the
// exponential's injectivity limit (h·adRadius < π) takes at most two panels.
// An application with both parts of x and A nonzero costs x₀'s four products for the 1-part,
// six for the ε-part (Â₀, Â₁ and back) and one per node; compute() two more (x̂₁). Where x₁ or
// A₀ is zero the ε-part is x₀'s application alone, with its bits (the magnetic fluid with
// Θ = 0 is the fluid, systems/zeitlin_mhd.h). In the coordinates the part's eigenbasis weighs
// entries by the named weights of core/eigenbasis_weights.h, Γ(τ) and D̄ among them, so that a
// device backend applies them in its own kernels.
// Not here: the weights of the Newton search's preconditioner (setWeights, applyWeights); on
// dual-number matrices the search takes the shift's (integrators/solvers/orbit_preconditioner.h).
#pragma once

#include <ddb/core/detail/gauss_legendre.h>
#include <ddb/core/dual_matrix.h>
#include <ddb/core/eigenbasis_weights.h>
#include <ddb/core/matrix_backend.h>
#include <ddb/core/phase_function.h>

#include <Eigen/Core>
#include <cmath>

namespace ddb {

template <class X>
class DualEigenbasis {
  using D = DualMatrix<X>;
  using Part = MatrixBackend<X>;

 public:
  /// Decomposes x₀ and writes x₁ in its eigenbasis. Returns false when x is not finite.
  bool compute(const D& x) {
    if (!Part::allFinite(x.eps) || !real_.compute(x.real)) return false;
    eps_zero_ = Part::isZero(x.eps);
    if (!eps_zero_) real_.toBasis(x.eps, eps_hat_);
    return true;
  }

  /// θ_max − θ_min of x₀: the spectral radius of ad_x (its ε-part is nilpotent).
  double adRadius() const { return real_.adRadius(); }

  /// out = G(scale·ad_x) in for the named function (see the top of this file); `in`
  /// skew-Hermitian in both parts. out may be in.
  void apply(PhaseFunction f, double scale, const D& in, D& out) {
    if (eps_zero_ || Part::isZero(in.real)) {
      applyToPart(f, scale, in.eps, out.eps);
    } else {
      real_.toBasis(in.real, real_hat_);
      derivativeInBasis(f, scale);  // sum_, the derivative term being sum_ − sum_ᴴ
      real_.toBasis(in.eps, hat_);
      real_.weigh(PhaseFunctionWeights{f, scale}, hat_);
      Part::axpy(1.0, sum_, hat_);
      Part::addAdjoint(-1.0, sum_, hat_);
      real_.fromBasis(hat_, out.eps);
    }
    applyToPart(f, scale, in.real, out.real);
  }

 private:
  void applyToPart(PhaseFunction f, double scale, const X& in, X& out) {
    if (!Part::isZero(in)) {
      real_.apply(f, scale, in, out);
    } else if (Part::sameShape(out, in)) {
      Part::setZero(out);
    } else {
      Part::zeroLike(out, in);
    }
  }

  // sum_ = the derivative term's P (its integral over t for kInverseDexpInverseDual).
  void derivativeInBasis(PhaseFunction f, double scale) {
    if (Part::sameShape(sum_, real_hat_)) {
      Part::setZero(sum_);
    } else {
      Part::zeroLike(sum_, real_hat_);
    }
    if (f == PhaseFunction::kCoadjointIncrement) {
      addConjugationDerivative(scale, 1.0);
      return;
    }
    const detail::CompositeRule rule = detail::compositeRuleFor(1.5 * std::abs(scale) * adRadius());
    const detail::GaussLegendreRule gauss(rule.nodes);
    const double length = 1.0 / rule.panels;
    for (int panel = 0; panel < rule.panels; ++panel) {
      for (int q = 0; q < gauss.count; ++q) {
        addConjugationDerivative((panel + gauss.nodes[q]) * length * scale,
                                 gauss.weights[q] * length);
      }
    }
  }

  // sum_ += weight · D̄ Â₀ K, D = diag(e^{iτθ}), K = Γ(τ) ∘ x̂₁.
  void addConjugationDerivative(double tau, double weight) {
    Part::copy(eps_hat_, kernel_);
    real_.weigh(ConjugationDerivativeWeights{tau}, kernel_);
    Part::copy(real_hat_, scaled_);
    real_.weigh(RowPhaseWeights{tau}, scaled_);
    Part::multiplyAdd(weight, scaled_, kernel_, sum_);
  }

  typename Part::Eigenbasis real_;  // x₀'s
  bool eps_zero_ = true;            // x₁ = 0
  X eps_hat_;                       // x̂₁
  X real_hat_, hat_, sum_, kernel_, scaled_;
};

}  // namespace ddb
