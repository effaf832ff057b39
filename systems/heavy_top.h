// The heavy top on se(3)* (docs/reference/conventions.md §2): μ = (π, γ), H = ½ π·𝕀^{-1}π + mgℓ
// χ·γ, so ξ = ∂H/∂μ = (𝕀^{-1}π, mgℓ χ) and μ̇ = ad*_ξ μ gives π̇ = π×Ω + mgℓ γ×χ,
// γ̇ = γ×Ω. H is linear in γ: there is no regular Lagrangian, so DDB runs in its
// Hamiltonian form. Dissipation k♯ = α diag(k); Casimirs |γ|², π·γ. The group is a parameter:
// SE3, or SO(3) ⋉ R³ composed (SemidirectProduct<SO3>), whose coordinates are the same.
#pragma once

#include <ddb/core/autodiff.h>
#include <ddb/core/dissipation_metric.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/groups/se3.h>
#include <ddb/systems/rigid_body.h>

#include <memory>

namespace ddb {

/// H on G's dual, G any group with μ = (π, γ) ∈ R⁶ and the dot pairing (SE3,
/// SemidirectProduct<SO3>).
template <class G>
class HeavyTopHamiltonianOn final : public AutoDiffHamiltonian<HeavyTopHamiltonianOn<G>, G> {
  static_assert(G::kDim == 6, "the heavy top's coordinates are (pi, gamma) in R^6");

 public:
  HeavyTopHamiltonianOn(const Eigen::Vector3d& inertia, double mgl, const Eigen::Vector3d& chi)
      : inverse_inertia_(invertInertia(inertia)),
        mgl_(requireFinite("mgl", mgl)),
        chi_(requireFinite("chi", chi)) {}

  template <class T>
  T evaluate(const Eigen::Matrix<T, 6, 1>& mu) const {
    T kinetic = constant<T>(0.0), potential = constant<T>(0.0);
    for (int i = 0; i < 3; ++i) {
      kinetic += mu(i) * mu(i) * constant<T>(inverse_inertia_(i));
      potential += constant<T>(mgl_ * chi_(i)) * mu(3 + i);
    }
    return constant<T>(0.5) * kinetic + potential;
  }
  // Analytic overrides for speed (checked against the autodiff versions in the tests); 𝕀⁻¹ is
  // stored, so that they multiply.
  Eigen::Matrix<double, 6, 1> gradient(const Eigen::Matrix<double, 6, 1>& mu) const override {
    Eigen::Matrix<double, 6, 1> out;  // halves assigned: a comma initialiser stores and reloads
    out.head<3>() = inverse_inertia_.cwiseProduct(mu.head<3>());
    out.tail<3>() = mgl_ * chi_;
    return out;
  }
  Eigen::Matrix<double, 6, 1> hessianTimes(const Eigen::Matrix<double, 6, 1>&,
                                           const Eigen::Matrix<double, 6, 1>& v) const override {
    return (Eigen::Matrix<double, 6, 1>() << inverse_inertia_.cwiseProduct(v.head<3>()),
            Eigen::Vector3d::Zero())
        .finished();
  }
  Eigen::Matrix<double, 6, 6> hessian(const Eigen::Matrix<double, 6, 1>&) const override {
    Eigen::Matrix<double, 6, 6> out = Eigen::Matrix<double, 6, 6>::Zero();
    out.topLeftCorner<3, 3>() = inverse_inertia_.asDiagonal();
    return out;
  }

 private:
  Eigen::Vector3d inverse_inertia_;
  double mgl_;
  Eigen::Vector3d chi_;
};

using HeavyTopHamiltonian = HeavyTopHamiltonianOn<SE3>;

/// The heavy top on G (SE3 or SemidirectProduct<SO3>); `metric` k (6 entries >= 0) gives
/// k♯ = α diag(k).
template <class G>
std::shared_ptr<const LiePoissonSystem<G>> makeHeavyTopOn(
    const Eigen::Vector3d& inertia, double mgl, const Eigen::Vector3d& chi, double alpha,
    const Eigen::Matrix<double, 6, 1>& metric) {
  return makeLiePoissonSystem("heavy-top",
                              std::make_shared<const HeavyTopHamiltonianOn<G>>(inertia, mgl, chi),
                              std::make_shared<const DiagonalMetric<G>>(alpha, metric));
}

/// The heavy top on SE3 (makeHeavyTopOn<SE3>, compiled once).
std::shared_ptr<const LiePoissonSystem<SE3>> makeHeavyTop(
    const Eigen::Vector3d& inertia, double mgl, const Eigen::Vector3d& chi, double alpha,
    const Eigen::Matrix<double, 6, 1>& metric);

}  // namespace ddb
