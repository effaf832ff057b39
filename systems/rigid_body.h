// The free rigid body with double-bracket dissipation (paper, Sections 3 and 5):
//   l(Ω) = ½ Ω·𝕀Ω,  H(M) = ½ M·𝕀^{-1}M,  k♯ = α I,  φ(Ω) = α 𝕀Ω × Ω,
//   Ṁ = M × Ω + α M × (M × Ω)   (eq. (3.6)),  Casimir |M|.
#pragma once

#include <ddb/core/autodiff.h>
#include <ddb/core/dissipation_metric.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/groups/so3.h>

#include <memory>

namespace ddb {

/// 𝕀⁻¹ of principal moments that must be finite and > 0, with 1/𝕀 finite too (a moment
/// below ~1e-308 would make it inf). Any number of moments: the N-dimensional heavy top has
/// N(N−1)/2 (systems/heavy_top.h).
template <int D>
Eigen::Matrix<double, D, 1> invertInertia(const Eigen::Matrix<double, D, 1>& inertia) {
  const Eigen::Matrix<double, D, 1> inverse = requirePositive("inertia", inertia).cwiseInverse();
  if (!inverse.allFinite()) throwInvalid("inertia", formatValue(inertia), "1/inertia overflows");
  return inverse;
}

class RigidBodyLagrangian final : public AutoDiffLagrangian<RigidBodyLagrangian, SO3> {
 public:
  explicit RigidBodyLagrangian(const Eigen::Vector3d& inertia)
      : inertia_(requirePositive("inertia", inertia)) {}

  template <class T>
  T evaluate(const Eigen::Matrix<T, 3, 1>& omega) const {
    T sum = constant<T>(0.0);
    for (int i = 0; i < 3; ++i) sum += constant<T>(inertia_(i)) * omega(i) * omega(i);
    return constant<T>(0.5) * sum;
  }
  // Analytic overrides for speed (checked against the autodiff versions in the tests).
  Eigen::Vector3d gradient(const Eigen::Vector3d& omega) const override {
    return inertia_.cwiseProduct(omega);
  }
  Eigen::Vector3d hessianTimes(const Eigen::Vector3d&, const Eigen::Vector3d& v) const override {
    return inertia_.cwiseProduct(v);
  }
  Eigen::Matrix3d hessian(const Eigen::Vector3d&) const override { return inertia_.asDiagonal(); }

 private:
  Eigen::Vector3d inertia_;
};

class RigidBodyHamiltonian final : public AutoDiffHamiltonian<RigidBodyHamiltonian, SO3> {
 public:
  explicit RigidBodyHamiltonian(const Eigen::Vector3d& inertia)
      : inverse_inertia_(invertInertia(inertia)) {}

  template <class T>
  T evaluate(const Eigen::Matrix<T, 3, 1>& m) const {
    T sum = constant<T>(0.0);
    for (int i = 0; i < 3; ++i) sum += m(i) * m(i) * constant<T>(inverse_inertia_(i));
    return constant<T>(0.5) * sum;
  }
  // 𝕀⁻¹ is stored: a product, not a division, in every vector-field evaluation.
  Eigen::Vector3d gradient(const Eigen::Vector3d& m) const override {
    return inverse_inertia_.cwiseProduct(m);
  }
  Eigen::Vector3d hessianTimes(const Eigen::Vector3d&, const Eigen::Vector3d& v) const override {
    return inverse_inertia_.cwiseProduct(v);
  }
  Eigen::Matrix3d hessian(const Eigen::Vector3d&) const override {
    return inverse_inertia_.asDiagonal();
  }

 private:
  Eigen::Vector3d inverse_inertia_;
};

/// The rigid body of principal moments `inertia` (all > 0) and damping `alpha`.
std::shared_ptr<const LiePoissonSystem<SO3>> makeRigidBody(const Eigen::Vector3d& inertia,
                                                           double alpha);

}  // namespace ddb

// The generic system of SO(3) compiled once (instantiations/lie_poisson_systems.cc).
DDB_LIE_POISSON_SYSTEM_INSTANCE(extern, ::ddb::SO3);
