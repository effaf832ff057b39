// Zeitlin's fluid (systems/zeitlin_fluid.h) on any matrix backend (docs/design/matrix-backend.md),
// given that backend's Poisson solve: the same system as makeZeitlinFluid's, a
// LiePoissonSystem on SUNOn<X> with k♯ = α·Id (ScaledIdentityMetric), whose Hamiltonian
// evaluates through the backend: H(W) = Re tr(WP)/(2ħ) = −Re⟨P, W⟩/(2ħ) (P skew-Hermitian),
// ∂H/∂W = −Δ⁻¹W/ħ (zeitlinVelocityInto), the Hessian the same map. On MPI ranks it is the
// distributed fluid (distributed/distributed_zeitlin_fluid.h); every method of the method
// table's kBackendMatrixGroups family and Relaxation run on it.
#pragma once

#include <ddb/core/dissipation_metric.h>
#include <ddb/core/errors.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/core/matrix_backend.h>
#include <ddb/groups/sun.h>
#include <ddb/systems/zeitlin_fluid.h>

#include <memory>
#include <utility>

namespace ddb {

/// Zeitlin's Hamiltonian on matrices X, with `Poisson::solve(const X& W, X& out)` solving
/// Δ out = W for a skew-Hermitian W. Every function is collective where the backend's are;
/// value() keeps the stream matrix in a workspace (one evaluation at a time).
template <class X, class Poisson>
class ZeitlinHamiltonianOn final : public Hamiltonian<SUNOn<X>> {
 public:
  using B = MatrixBackend<X>;

  ZeitlinHamiltonianOn(Poisson poisson, Eigen::Index n)
      : poisson_(std::move(poisson)), hbar_(zeitlinHbar(n)) {}

  double hbar() const { return hbar_; }

  /// H(W) = −Re⟨P, W⟩/(2ħ), P = Δ⁻¹W: one Poisson solve.
  double value(const X& W) const override {
    if (!B::sameShape(stream_, W)) B::zeroLike(stream_, W);
    poisson_.solve(W, stream_);
    return -B::innerProduct(stream_, W) / (2.0 * hbar_);
  }
  X gradient(const X& W) const override {
    X out;
    B::zeroLike(out, W);
    gradientInto(W, out);
    return out;
  }
  X hessianTimes(const X& W, const X& V) const override {
    X out;
    B::zeroLike(out, W);
    hessianTimesInto(W, V, out);
    return out;
  }
  void gradientInto(const X& W, X& out) const override {
    zeitlinVelocityInto(poisson_, hbar_, W, out);
  }
  void hessianTimesInto(const X&, const X& V, X& out) const override {
    zeitlinVelocityInto(poisson_, hbar_, V, out);
  }

 private:
  mutable Poisson poisson_;  // keeps workspaces
  double hbar_;
  mutable X stream_;
};

/// Zeitlin's fluid at resolution n on matrices X with k♯ = α·Id, given X's Poisson solve.
template <class X, class Poisson>
std::shared_ptr<const LiePoissonSystem<SUNOn<X>>> makeZeitlinFluidOn(Poisson poisson,
                                                                     Eigen::Index n, double alpha) {
  return makeLiePoissonSystem(
      "zeitlin", std::make_shared<const ZeitlinHamiltonianOn<X, Poisson>>(std::move(poisson), n),
      std::make_shared<const ScaledIdentityMetric<SUNOn<X>>>(alpha));
}

}  // namespace ddb
