// Zeitlin's Hamiltonian, once for every backend (docs/reference/conventions.md §2): on the
// absolute vorticity Q = W + F, with F the planetary vorticity of a sphere rotating at Ω
// (F = 2Ω X₃, X₃ = ħ i diag(j − (N−1)/2), the quantised 2Ω cos θ; zero without rotation), and
// the stream matrix ψ = (Δ_N − κ²)⁻¹(Q − F) (κ = 1/deformation radius; κ = 0: Euler, the
// Laplacian; κ > 0: quasi-geostrophic flow):
//   H(Q) = −Re⟨ψ, Q − F⟩/(2ħ) = Re tr((Q − F) ψ)/(2ħ) >= 0,  ∂H/∂Q = −ψ/ħ,
// and the Hessian V ↦ −(Δ_N − κ²)⁻¹V/ħ. The flow Q̇ = (1/ħ)[ψ, Q] keeps Q's spectrum (the
// Casimirs), so every DDB method keeps it exactly on the rotating sphere too. Poisson is the
// backend's solve of Δ_N − κ² (HoppeYauLaplacian, DistributedPoissonSolver, CudaPoissonSolver),
// with `solve(const X& W, X& out)`, out = (Δ_N − κ²)⁻¹ of W's traceless part, out may be W.
#pragma once

#include <ddb/core/detail/evaluation_scratch.h>
#include <ddb/core/errors.h>
#include <ddb/core/lagrangian.h>
#include <ddb/core/matrix_backend.h>
#include <ddb/core/matrix_traits.h>

#include <Eigen/Core>
#include <cmath>
#include <complex>
#include <limits>
#include <string>
#include <utility>

namespace ddb {

/// ħ = 2/√(N² − 1).
inline double zeitlinHbar(Eigen::Index n) { return 2.0 / std::sqrt(double(n * n - 1)); }

/// What Zeitlin's fluid models besides Euler on a resting sphere (the double bracket's α is the
/// system's metric): the sphere's rotation and quasi-geostrophy's deformation radius.
struct ZeitlinPhysics {
  /// Ω, the sphere's angular velocity (any finite sign): planetary vorticity F = 2Ω X₃.
  double rotation = 0.0;
  /// L_d > 0, the deformation radius in units of the sphere's radius: ψ = (Δ − 1/L_d²)⁻¹(Q − F).
  /// Infinite: the Laplacian (Euler).
  double deformation_radius = std::numeric_limits<double>::infinity();

  /// κ² = 1/L_d² (0 for an infinite L_d).
  double kappaSquared() const {
    return std::isinf(deformation_radius) ? 0.0 : 1.0 / (deformation_radius * deformation_radius);
  }
  /// Throws InvalidArgument naming the parameter unless Ω is finite and L_d > 0.
  void validate() const {
    if (!std::isfinite(rotation)) {
      throwInvalid("rotation", formatValue(rotation), "must be finite");
    }
    if (!(deformation_radius > 0)) {
      throwInvalid("deformation_radius", formatValue(deformation_radius),
                   "must be > 0 (infinite: no quasi-geostrophic shift)");
    }
  }
};

/// F = 2Ω X₃ = 2Ω ħ i diag(j − (N−1)/2), the planetary vorticity of a sphere rotating at Ω
/// (docs/reference/conventions.md §2: T_10 = √3 X₃ is the quantised √3 cos θ).
inline Eigen::MatrixXcd zeitlinPlanetaryVorticity(Eigen::Index n, double rotation) {
  if (n < 2) throwInvalid("N", std::to_string(n), "must be >= 2");
  const double hbar = zeitlinHbar(n);
  Eigen::MatrixXcd F = Eigen::MatrixXcd::Zero(n, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    F(j, j) = std::complex<double>(0.0, 2.0 * rotation * hbar * (double(j) - 0.5 * double(n - 1)));
  }
  return F;
}

/// ξ = ∂H/∂W = −Δ⁻¹W/ħ given a Poisson solver of W's layout; the Hessian applies the same map.
template <class Laplacian, class X>
void zeitlinVelocityInto(Laplacian& laplacian, double hbar, const X& W, X& out) {
  laplacian.solve(W, out);
  MatrixBackend<X>::scale(-1.0 / hbar, out, out);
}

/// H on the group G (SUN, or SUNOn<X> for another backend's matrices X) given G's Poisson solve.
template <class G, class Poisson>
class ZeitlinHamiltonianOf : public Hamiltonian<G> {
 public:
  using X = typename G::template Dual<double>;
  using B = MatrixBackend<X>;

  /// On a resting sphere.
  ZeitlinHamiltonianOf(Poisson poisson, Eigen::Index n)
      : poisson_(std::move(poisson)), hbar_(zeitlinHbar(n)) {}
  /// On a sphere whose planetary vorticity is F (zeitlinPlanetaryVorticity, in X's layout).
  ZeitlinHamiltonianOf(Poisson poisson, Eigen::Index n, X planetary)
      : poisson_(std::move(poisson)),
        hbar_(zeitlinHbar(n)),
        planetary_(std::move(planetary)),
        rotating_(!B::isZero(planetary_)) {}

  double hbar() const { return hbar_; }
  /// F, the planetary vorticity (empty on a resting sphere: rotating() is false).
  const X& planetaryVorticity() const { return planetary_; }
  bool rotating() const { return rotating_; }

  /// H(Q) = −Re⟨ψ, Q − F⟩/(2ħ): one Poisson solve.
  double value(const X& Q) const override {
    Scratch& s = scratch();
    const X& relative = relativeVorticity(Q, s.relative);
    if (!B::sameShape(s.stream, Q)) B::zeroLike(s.stream, Q);
    poisson_.solve(relative, s.stream);
    if constexpr (isEigenMatrix<X>) {
      // Re tr((Q − F) ψ), summed as the dense fluid always has (the bits of its energies).
      return (relative.cwiseProduct(s.stream.transpose())).sum().real() / (2.0 * hbar_);
    } else {
      return -B::innerProduct(s.stream, relative) / (2.0 * hbar_);
    }
  }
  X gradient(const X& Q) const override {
    X out;
    B::zeroLike(out, Q);
    gradientInto(Q, out);
    return out;
  }
  X hessianTimes(const X& Q, const X& V) const override {
    X out;
    B::zeroLike(out, Q);
    hessianTimesInto(Q, V, out);
    return out;
  }
  /// ξ = −ψ/ħ; out may be Q.
  void gradientInto(const X& Q, X& out) const override {
    if (rotating_) {
      B::sum(1.0, Q, -1.0, planetary_, out);
      zeitlinVelocityInto(poisson_, hbar_, out, out);
    } else {
      zeitlinVelocityInto(poisson_, hbar_, Q, out);
    }
  }
  void hessianTimesInto(const X&, const X& V, X& out) const override {
    zeitlinVelocityInto(poisson_, hbar_, V, out);
  }

  /// out = ψ = (Δ − κ²)⁻¹(Q − F); out may be Q.
  void streamInto(const X& Q, X& out) const {
    if (!B::sameShape(out, Q)) B::zeroLike(out, Q);
    if (rotating_) {
      B::sum(1.0, Q, -1.0, planetary_, out);
      poisson_.solve(out, out);
    } else {
      poisson_.solve(Q, out);
    }
  }
  /// Q − F: Q itself on a resting sphere, else `workspace` holding it.
  const X& relativeVorticity(const X& Q, X& workspace) const {
    if (!rotating_) return Q;
    if (!B::sameShape(workspace, Q)) B::zeroLike(workspace, Q);
    B::sum(1.0, Q, -1.0, planetary_, workspace);
    return workspace;
  }

 protected:
  const Poisson& poisson() const { return poisson_; }

 private:
  struct Scratch {
    X relative, stream;
  };
  // value()'s workspaces (core/detail/evaluation_scratch.h).
  Scratch& scratch() const { return detail::evaluationScratch<X>(scratch_); }

  mutable Poisson poisson_;  // keeps workspaces
  double hbar_;
  X planetary_;
  bool rotating_ = false;
  mutable Scratch scratch_;
};

}  // namespace ddb
