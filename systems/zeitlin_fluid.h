// Zeitlin's SU(N) fluid on the sphere with double-bracket dissipation
// (docs/reference/conventions.md §2): vorticity W ∈ su(N), ħ = 2/√(N² − 1), stream matrix
// P = Δ_N⁻¹ W, and
//   Ẇ = (1/ħ)([P, W] + α [W, [P, W]]),  dE/dt = −α ‖[P, W]‖_F²/(ħN),
// with energy E = Re tr(WP)/(2N) >= 0, enstrophy Z = ‖W‖_F²/(2N) (constant), and the
// spectrum of W as Casimirs. As a Lie–Poisson system with the pairing Re tr(AᴴB):
// μ = W, H(W) = Re tr(WP)/(2ħ) = N·E/ħ, ξ = ∂H/∂μ = −P/ħ, ad*_ξ μ = [μ, ξ] and
// k♯ = α·Id (ScaledIdentityMetric), so φ = α[p, ξ] = (α/ħ)[P(p), p]. On a rotating sphere and in
// quasi-geostrophic flow (ZeitlinPhysics) the state is the absolute vorticity Q = W + F and
// P = (Δ_N − κ²)⁻¹(Q − F) (systems/zeitlin_hamiltonian.h); the rest reads the same with Q for W.
#pragma once

#include <ddb/core/dissipation_metric.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/core/matrix_backend.h>
#include <ddb/groups/sun.h>
#include <ddb/systems/hoppe_yau_laplacian.h>
#include <ddb/systems/zeitlin_hamiltonian.h>

#include <cmath>
#include <memory>

namespace ddb {

// Compiled once, in the library (systems/zeitlin_fluid.cc): a file that includes this header does
// not instantiate the dense fluid's Hamiltonian again (docs/results/compile-costs.md).
extern template class ZeitlinHamiltonianOf<SUN, HoppeYauLaplacian>;

/// Zeitlin's Hamiltonian on dense matrices (ZeitlinHamiltonianOf, systems/zeitlin_hamiltonian.h),
/// with the dense solver's own accessors.
class ZeitlinHamiltonian final : public ZeitlinHamiltonianOf<SUN, HoppeYauLaplacian> {
 public:
  using Matrix = Eigen::MatrixXcd;

  /// At resolution N on a resting sphere, or with `physics` (rotation, deformation radius;
  /// InvalidArgument naming the parameter if it is out of range).
  explicit ZeitlinHamiltonian(Eigen::Index n, const ZeitlinPhysics& physics = {});

  /// The Poisson solver: Δ_N − κ² (κ = 0: the Laplacian).
  const HoppeYauLaplacian& laplacian() const { return poisson(); }

  /// ψ = (Δ − κ²)⁻¹ of the traceless part of Q − F (P = Δ⁻¹W on a resting sphere).
  Matrix streamMatrix(const Matrix& Q) const;

 private:
  static const ZeitlinPhysics& checked(const ZeitlinPhysics& physics);
};

/// The fluid's diagnostics, in its own units (E, Z as in the header comment), of the state Q
/// (the vorticity W on a resting sphere, the absolute vorticity W + F on a rotating one).
class ZeitlinDiagnostics {
 public:
  using Matrix = Eigen::MatrixXcd;
  explicit ZeitlinDiagnostics(const ZeitlinHamiltonian& hamiltonian) : h_(hamiltonian) {}

  /// E = ħ H / N (H = Re tr((Q − F)ψ)/(2ħ), the system's Hamiltonian).
  double energy(const Matrix& Q) const;
  /// Z = ‖W‖²_F/(2N) of the relative vorticity W = Q − F.
  double enstrophy(const Matrix& Q) const;
  /// ‖[ψ, Q]‖_F: zero exactly at steady states of the Euler flow.
  double commutatorNorm(const Matrix& Q) const;

 private:
  const ZeitlinHamiltonian& h_;
};

/// Zeitlin's fluid at resolution N with double-bracket coefficient α (any finite sign).
std::shared_ptr<const LiePoissonSystem<SUN>> makeZeitlinFluid(Eigen::Index n, double alpha);
/// ... on a rotating sphere and/or quasi-geostrophic (ZeitlinPhysics): its states are absolute
/// vorticities Q = W + F.
std::shared_ptr<const LiePoissonSystem<SUN>> makeZeitlinFluid(Eigen::Index n, double alpha,
                                                              const ZeitlinPhysics& physics);

}  // namespace ddb

// The generic system of SU(N) compiled once (instantiations/lie_poisson_systems.cc).
DDB_LIE_POISSON_SYSTEM_INSTANCE(extern, ::ddb::SUN);
