// Zeitlin's magnetic fluid: magnetohydrodynamics on the sphere, quantised (docs/reference/
// conventions.md §2, "Magnetohydrodynamics on the sphere"). Vorticity W and magnetic potential Θ
// in su(N), stream matrix P = Δ_N⁻¹W, current B = Δ_N Θ:
//   Ẇ = (1/ħ)([P, W] + [B, Θ]),  Θ̇ = (1/ħ)[P, Θ]
// (quflow's MHD in the fluid's time unit), a Lie–Poisson flow on SU(N) ⋉ su(N)* with the state
// μ = Θ + εW (groups/dual_number_sun.h) and
//   H(μ) = H_kin(W) + H_mag(Θ) = Re tr(WP)/(2ħ) + Re tr(ΘB)/(2ħ)  (both ≥ 0),
//   ξ = ∂H/∂μ = ξ₀ + εξ₁,  ξ₀ = ∂H/∂W = −P/ħ,  ξ₁ = ∂H/∂Θ = −B/ħ,
// so that ad*_ξ μ = [μ, ξ] has 1-part [Θ, ξ₀] = (1/ħ)[P, Θ] and ε-part [Θ, ξ₁] + [W, ξ₀]
// = (1/ħ)([B, Θ] + [P, W]). The double bracket with k♯ = α·(swap of the parts)
// (SwappedPartsMetric) lowers H at the rate α(‖[P, Θ]‖² + ‖[P, W] + [B, Θ]‖²)/ħ² and keeps
// every tr Θᵏ and tr(WΘᵏ); its rest points are the magnetic equilibria [P, Θ] = 0 and
// [P, W] + [B, Θ] = 0. With Θ = 0 it is Zeitlin's fluid (systems/zeitlin_fluid.h), to the bit.
#pragma once

#include <ddb/core/detail/evaluation_scratch.h>
#include <ddb/core/dual_matrix.h>
#include <ddb/core/errors.h>
#include <ddb/core/lagrangian.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/core/matrix_backend.h>
#include <ddb/groups/dual_number_sun.h>
#include <ddb/groups/swapped_parts_metric.h>
#include <ddb/systems/hoppe_yau_laplacian.h>
#include <ddb/systems/zeitlin_hamiltonian.h>

#include <Eigen/Core>
#include <memory>
#include <utility>

namespace ddb {

/// The magnetic fluid's Hamiltonian on matrices X, with `Poisson::solve(W, out)` (Δ_N⁻¹ of W's
/// traceless part) and `Poisson::apply(Θ, out)` (Δ_N Θ, out not Θ). The functions' `out` is not
/// their argument.
template <class X, class Poisson>
class ZeitlinMhdHamiltonianOf : public Hamiltonian<DualNumberSUNOn<X>> {
 public:
  using D = DualMatrix<X>;
  using B = MatrixBackend<X>;

  ZeitlinMhdHamiltonianOf(Poisson poisson, Eigen::Index n)
      : poisson_(std::move(poisson)), hbar_(zeitlinHbar(n)) {}

  double hbar() const { return hbar_; }
  const Poisson& poisson() const { return poisson_; }

  /// H = H_kin(W) + H_mag(Θ).
  double value(const D& mu) const override { return kineticValue(mu.eps) + magneticValue(mu.real); }
  /// H_kin(W) = −⟨P, W⟩/(2ħ), P = Δ⁻¹W: the fluid's Hamiltonian.
  double kineticValue(const X& W) const {
    X& stream = scratch().stream;
    if (!B::sameShape(stream, W)) B::zeroLike(stream, W);
    poisson_.solve(W, stream);
    return -B::innerProduct(stream, W) / (2.0 * hbar_);
  }
  /// H_mag(Θ) = −⟨Θ, ΔΘ⟩/(2ħ) ≥ 0.
  double magneticValue(const X& Theta) const {
    X& current = scratch().current;
    if (!B::sameShape(current, Theta)) B::zeroLike(current, Theta);
    poisson_.apply(Theta, current);
    return -B::innerProduct(Theta, current) / (2.0 * hbar_);
  }
  D gradient(const D& mu) const override {
    D out;
    MatrixBackend<D>::zeroLike(out, mu);
    gradientInto(mu, out);
    return out;
  }
  D hessianTimes(const D& mu, const D& v) const override {
    D out;
    MatrixBackend<D>::zeroLike(out, mu);
    hessianTimesInto(mu, v, out);
    return out;
  }
  /// ξ₀ = −Δ⁻¹W/ħ, ξ₁ = −ΔΘ/ħ.
  void gradientInto(const D& mu, D& out) const override { hessianTimesInto(mu, mu, out); }
  /// H is quadratic: its Hessian maps v = v₀ + εv₁ to −Δ⁻¹v₁/ħ + ε(−Δv₀/ħ).
  void hessianTimesInto(const D&, const D& v, D& out) const override {
    zeitlinVelocityInto(poisson_, hbar_, v.eps, out.real);
    poisson_.apply(v.real, out.eps);
    B::scale(-1.0 / hbar_, out.eps, out.eps);
  }

 private:
  struct Scratch {
    X stream, current;
  };
  // value()'s workspaces (core/detail/evaluation_scratch.h).
  Scratch& scratch() const { return detail::evaluationScratch<X>(scratch_); }

  mutable Poisson poisson_;  // keeps workspaces
  double hbar_;
  mutable Scratch scratch_;
};

/// The magnetic fluid's Hamiltonian on dense matrices (Δ_N by HoppeYauLaplacian).
using ZeitlinMhdHamiltonian = ZeitlinMhdHamiltonianOf<Eigen::MatrixXcd, HoppeYauLaplacian>;

/// The state μ = Θ + εW of vorticity W and magnetic potential Θ.
inline DualMatrix<Eigen::MatrixXcd> zeitlinMhdState(Eigen::MatrixXcd W, Eigen::MatrixXcd Theta) {
  return {std::move(Theta), std::move(W)};
}

/// The magnetic fluid at resolution N with double-bracket coefficient α (any finite sign):
/// k♯ = α·swap (SwappedPartsMetric). InvalidArgument naming N or alpha if out of range.
std::shared_ptr<const LiePoissonSystem<DualNumberSUN>> makeZeitlinMhd(Eigen::Index n, double alpha);

/// ... on matrices X given X's Poisson solver (solve and apply; on MPI ranks
/// DistributedPoissonSolver, distributed/distributed_zeitlin_mhd.h). InvalidArgument naming alpha.
template <class X, class Poisson>
std::shared_ptr<const LiePoissonSystem<DualNumberSUNOn<X>>> makeZeitlinMhdOn(Poisson poisson,
                                                                             Eigen::Index n,
                                                                             double alpha) {
  return makeLiePoissonSystem(
      "zeitlin-mhd",
      std::make_shared<const ZeitlinMhdHamiltonianOf<X, Poisson>>(std::move(poisson), n),
      std::make_shared<const SwappedPartsMetric<X>>(alpha));
}

/// The magnetic fluid's diagnostics in the fluid's units (ZeitlinDiagnostics: E = ħH/N).
class ZeitlinMhdDiagnostics {
 public:
  using Matrix = Eigen::MatrixXcd;
  using State = DualMatrix<Matrix>;
  explicit ZeitlinMhdDiagnostics(const ZeitlinMhdHamiltonian& hamiltonian) : h_(hamiltonian) {}

  /// E_kin = ħ H_kin/N = Re tr(WP)/(2N).
  double kineticEnergy(const State& mu) const;
  /// E_mag = ħ H_mag/N = Re tr(ΘB)/(2N), B = ΔΘ.
  double magneticEnergy(const State& mu) const;
  /// ⟨W, Θ⟩/(2N) = −Re tr(WΘ)/(2N): cross helicity, the ε-part's k = 1 Casimir.
  double crossHelicity(const State& mu) const;
  /// ‖[P, Θ]‖_F and ‖[P, W] + [B, Θ]‖_F together (hypot): zero exactly at magnetic equilibria.
  double equilibriumResidual(const State& mu) const;

 private:
  const ZeitlinMhdHamiltonian& h_;
};

}  // namespace ddb

// The generic system of SU(N) ⋉ su(N)* compiled once (instantiations/lie_poisson_systems.cc).
DDB_LIE_POISSON_SYSTEM_INSTANCE(extern, ::ddb::DualNumberSUN);
