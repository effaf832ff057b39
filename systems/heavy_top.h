// The heavy top on se(3)* (docs/reference/conventions.md §2): μ = (π, γ), H = ½ π·𝕀^{-1}π + mgℓ
// χ·γ, so ξ = ∂H/∂μ = (𝕀^{-1}π, mgℓ χ) and μ̇ = ad*_ξ μ gives π̇ = π×Ω + mgℓ γ×χ,
// γ̇ = γ×Ω. H is linear in γ: there is no regular Lagrangian, so DDB runs in its
// Hamiltonian form. Dissipation k♯ = α diag(k); Casimirs |γ|², π·γ.
#pragma once

#include <ddb/core/autodiff.h>
#include <ddb/core/dissipation_metric.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/groups/se3.h>
#include <ddb/systems/rigid_body.h>

#include <memory>

namespace ddb {

class HeavyTopHamiltonian final : public AutoDiffHamiltonian<HeavyTopHamiltonian, SE3> {
 public:
  HeavyTopHamiltonian(const Eigen::Vector3d& inertia, double mgl, const Eigen::Vector3d& chi)
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

/// The heavy top; `metric` k (6 entries >= 0) gives k♯ = α diag(k).
std::shared_ptr<const LiePoissonSystem<SE3>> makeHeavyTop(
    const Eigen::Vector3d& inertia, double mgl, const Eigen::Vector3d& chi, double alpha,
    const Eigen::Matrix<double, 6, 1>& metric);

}  // namespace ddb
