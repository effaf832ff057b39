// SU(N) ⋉ su(N)*, the group of magnetohydrodynamics on the sphere, as SU(N) over the dual numbers
// R[ε], ε² = 0 (docs/reference/conventions.md §1, "SU(N) over the dual numbers"): its algebra is
// su(N) ⊗ R[ε], ξ = ξ₀ + εξ₁ with [ξ, η] = [ξ₀, η₀] + ε([ξ₀, η₁] + [ξ₁, η₀]), the semidirect
// product of su(N) with su(N) by the adjoint action. With the pairing
//   ⟨μ, ξ⟩ = the ε-coefficient of Re tr(μᴴξ) = Re tr(μ₀ᴴξ₁) + Re tr(μ₁ᴴξ₀)
// the dual is su(N) ⊗ R[ε] again, and every formula of SkewHermitianGroup holds verbatim in
// dual-number arithmetic (trace cyclicity holds over the commutative R[ε]): ad*_ξ μ = [μ, ξ],
// Ad*_g μ = gᴴμg, (dcay⁻¹_x)*μ = (I + x/2)μ(I − x/2) and the Cayley step's kernels. So the group
// is SkewHermitianGroup on DualMatrix<X> (core/dual_matrix.h), whose backend does the arithmetic.
// For the magnetic fluid the state is μ = Θ + εW (magnetic potential, vorticity): ξ₀ = ∂H/∂W
// pairs with W and ξ₁ = ∂H/∂Θ with Θ (systems/zeitlin_mhd.h).
// Casimirs: tr μᵏ = tr Θᵏ + ε k tr(Θᵏ⁻¹W), both parts of every power trace (casimirs below).
#pragma once

#include <ddb/core/dual_eigenbasis.h>
#include <ddb/core/dual_matrix.h>
#include <ddb/core/errors.h>
#include <ddb/groups/skew_hermitian_group.h>
#include <ddb/groups/sun.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <complex>
#include <string>

namespace ddb {

/// SU(N) ⋉ su(N)* with its states in two of a backend's matrices X (DualMatrix<X>): the closed
/// forms of SkewHermitianGroup in dual-number arithmetic. As for SUNOn<X>, what runs is what is
/// written against the matrix backend: the system's in-place evaluations, integrate(), and the
/// methods of the method table: the exponential ones on parts whose eigenbasis has coordinates,
/// the dense, distributed and CUDA ones (their spectral calculus is core/dual_eigenbasis.h), the
/// linearly implicit Cayley step and the Newton search on any part (their preconditioner is the
/// shift's, integrators/solvers/orbit_preconditioner.h). The Casimirs need dense parts.
template <class X>
struct DualNumberSUNOn : SkewHermitianGroup<DualNumberSUNOn<X>, detail::ComplexScalar> {
  using Base = SkewHermitianGroup<DualNumberSUNOn<X>, detail::ComplexScalar>;
  static constexpr const char* kName = "SU(N) x| su(N)*";
  static constexpr const char* kAlgebraName = "skew-Hermitian";
  template <class T>
  using Algebra = DualMatrix<X>;
  template <class T>
  using Dual = DualMatrix<X>;

  /// The pairing is not the backend's inner product (dualPairing, core/lie_poisson_system.h).
  static constexpr bool kIndefinitePairing = true;
  /// ⟨μ, ξ⟩ = Re tr(μ₀ᴴξ₁) + Re tr(μ₁ᴴξ₀), the ε-coefficient of Re tr(μᴴξ): indefinite, unlike
  /// the backend's innerProduct, which the solvers use to measure iterates.
  static double pairing(const DualMatrix<X>& mu, const DualMatrix<X>& xi) {
    using P = MatrixBackend<X>;
    return P::innerProduct(mu.real, xi.eps) + P::innerProduct(mu.eps, xi.real);
  }

  /// x ← its Riesz representer for the backend's innerProduct, ν₀ + εν₁ ↦ ν₁ + εν₀ (pairing
  /// above): the parts exchanged, no entry copied (rieszMapInPlace, core/group_traits.h).
  static void rieszMap(DualMatrix<X>& x) { x.real.swap(x.eps); }

  /// SkewHermitianGroup::cayleyFrozenErrors over the dual numbers, part by part: the frozen map
  /// L(x) = −[a, x] + a x a is block-triangular, its 1-part L₀x₀ by a₀ alone (rate λ₀ ≤ 2‖a₀‖ +
  /// ‖a₀‖²) and its ε-part L₀x₁ + L₁x₀ (‖L₁‖ ≤ μ₁ = 2‖a₁‖ + 2‖a₀‖‖a₁‖), so only λ₀ < 1 is needed
  /// where the generic bound, through ‖a‖₁ = ‖a₀‖₁ + ‖a₁‖₁, needs a small ε-part too (the
  /// current's ΔΘ weighs high degrees by l(l + 1)). With u = next − p and e = p̃ − next = L(e + u):
  ///   ‖e₀‖ ≤ λ₀/(1 − λ₀)‖u₀‖,  ‖e₁‖ ≤ (λ₀‖u₁‖ + μ₁(‖e₀‖ + ‖u₀‖))/(1 − λ₀);
  /// the refined q = M − [a, next] + a p a has p̃ − q = −[a, e] + a(e + u)a, of parts at most
  ///   d₀ = 2‖a₀‖‖e₀‖ + ‖a₀‖²(‖e₀‖ + ‖u₀‖),
  ///   d₁ = 2‖a₀‖‖e₁‖ + ‖a₀‖²(‖e₁‖ + ‖u₁‖) + 2‖a₁‖‖e₀‖ + 2‖a₀‖‖a₁‖(‖e₀‖ + ‖u₀‖);
  /// and 2[a, d] has parts at most 4‖a₀‖d₀ and 4(‖a₀‖d₁ + ‖a₁‖d₀), whose sum bounds its norm over
  /// both parts (the solver's, against which rounding is measured). Both bounds hold, so each
  /// error is the smaller of this and the generic one (which is smaller where a₁ is small and both
  /// parts moved). Each is written as the generic one in ‖a₀‖ and ‖u₁‖ plus what a₁, u₀ and e₀
  /// add, so that with Θ = 0 (u₀ = e₀ = 0, a₁ = 0) it is the fluid's, to the bit.
  static void cayleyFrozenErrors(const DualMatrix<X>& a, const DualMatrix<X>& p,
                                 const DualMatrix<X>& next, double update, double& next_error,
                                 double& refined_error) {
    using P = MatrixBackend<X>;
    Base::cayleyFrozenErrors(a, p, next, update, next_error, refined_error);
    const double a0 = P::oneNorm(a.real), a1 = P::oneNorm(a.eps);
    const double lambda = 2.0 * a0 + a0 * a0;
    if (!(lambda < 1.0)) return;  // the generic bounds are infinite too
    const double u0 = P::frobeniusDistance(next.real, p.real);
    const double u1 = P::frobeniusDistance(next.eps, p.eps);
    const double mu1 = 2.0 * a1 + 2.0 * a0 * a1;
    const double e0 = lambda / (1.0 - lambda) * u0;
    const double e1_added = mu1 * (e0 + u0) / (1.0 - lambda);  // ‖e₁‖ ≤ λ₀/(1 − λ₀)‖u₁‖ + this
    next_error = std::min(next_error, 4.0 * a0 * lambda / (1.0 - lambda) * u1 +
                                          (4.0 * (a0 * e1_added + a1 * e0) + 4.0 * a0 * e0));
    const double d0 = 2.0 * a0 * e0 + a0 * a0 * (e0 + u0);
    const double d1_added =
        2.0 * a0 * e1_added + a0 * a0 * e1_added + 2.0 * a1 * e0 + 2.0 * a0 * a1 * (e0 + u0);
    refined_error =
        std::min(refined_error, 4.0 * a0 * (2.0 * a0 * lambda + a0 * a0) / (1.0 - lambda) * u1 +
                                    (4.0 * (a0 * d1_added + a1 * d0) + 4.0 * a0 * d0));
  }

  /// The orthogonal projection onto su(N) ⊗ R[ε], part by part, in place (SUNOn's on each).
  static void projectToAlgebra(DualMatrix<X>& x) {
    Base::projectToAlgebra(x.real);
    Base::projectToAlgebra(x.eps);
  }

  /// With H = −iμ₀ and K = −iμ₁ (Hermitian; for the magnetic fluid H = −iΘ, K = −iW), the real
  /// numbers tr Hᵏ for k = 2, …, N, then tr(HᵏK) for k = 0, …, N − 1: up to the factors iᵏ, the
  /// 1- and ε-parts of tr μᵏ (tr Θᵏ and tr(Θᵏ⁻¹W) up to i^k), which are invariant under every
  /// Ad*_g. Dense parts only; O(N⁴).
  static Eigen::VectorXd casimirs(const DualMatrix<X>& mu) {
    static_assert(isEigenMatrix<X>, "the Casimirs of SU(N) x| su(N)* need dense matrices");
    const Eigen::Index n = mu.real.rows();
    const Eigen::MatrixXcd H = mu.real * std::complex<double>(0, -1);
    const Eigen::MatrixXcd K = mu.eps * std::complex<double>(0, -1);
    Eigen::VectorXd out(2 * n - 1);
    Eigen::MatrixXcd power = Eigen::MatrixXcd::Identity(n, n);  // Hᵏ
    for (Eigen::Index k = 0; k < n; ++k) {
      out(n - 1 + k) = traceOfProduct(power, K);
      power = (power * H).eval();
      if (k + 2 <= n) out(k) = traceOfProduct(power, H);
    }
    return out;
  }

  /// Re tr(AB) = Σ A_ij B_ji, without forming AB.
  static double traceOfProduct(const Eigen::MatrixXcd& a, const Eigen::MatrixXcd& b) {
    return a.cwiseProduct(b.transpose()).sum().real();
  }

  /// Checks a state: two N×N parts, 2 ≤ N ≤ kMaxN, each finite, skew-Hermitian and traceless to
  /// 1e-12 relative; `real_name` and `eps_name` are what the message calls the parts.
  static void requireState(const std::string& real_name, const std::string& eps_name,
                           const DualMatrix<X>& mu) {
    static_assert(isEigenMatrix<X>, "requireState reads dense matrices");
    SUNOn<X>::requireState(real_name, mu.real);
    SUNOn<X>::requireState(eps_name, mu.eps);
    if (mu.real.rows() != mu.eps.rows()) {
      throwInvalid(eps_name,
                   std::to_string(mu.eps.rows()) + "x" + std::to_string(mu.eps.cols()) + " matrix",
                   "must have the size of " + real_name + " (" + std::to_string(mu.real.rows()) +
                       "x" + std::to_string(mu.real.cols()) + ")");
    }
  }
};

/// SU(N) ⋉ su(N)* on dense matrices.
using DualNumberSUN = DualNumberSUNOn<Eigen::MatrixXcd>;

}  // namespace ddb
