// Kirchhoff's body in the plane, on se(2)* (groups/se2.h): a rigid body moving in an ideal fluid
// in the plane, ξ = (Ω, v₁, v₂), l(ξ) = ½ IΩ² + ½ (m₁v₁² + m₂v₂²) with the added masses m₁, m₂,
// μ = (π, P) = (IΩ, m₁v₁, m₂v₂), H = ½ π²/I + ½ (P₁²/m₁ + P₂²/m₂). μ̇ = ad*_ξ μ gives
//   π̇ = P × v = (m₁ − m₂) v₁v₂,   Ṗ₁ = ΩP₂,   Ṗ₂ = −ΩP₁
// (the planar cross product a × b = a₁b₂ − a₂b₁; the Munk moment turns the body broadside on).
// Dissipation k♯ = α diag(k); Casimir |P|². With α > 0 and k > 0 the energy falls on the orbit
// |P| = c to its minimum c²/(2 max(m₁, m₂)): no rotation, P along the axis of the larger added
// mass (docs/guide/defining-a-system.md, "A group made of groups").
#pragma once

#include <ddb/core/autodiff.h>
#include <ddb/core/dissipation_metric.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/groups/se2.h>
#include <ddb/systems/kirchhoff.h>

#include <memory>

namespace ddb {

namespace detail {
/// (I, m₁, m₂): the diagonal of the planar Lagrangian's quadratic form.
inline Eigen::Vector3d planarKirchhoffWeights(double inertia, const Eigen::Vector2d& mass) {
  return Eigen::Vector3d(requirePositive("inertia", inertia), requirePositive("mass", mass)(0),
                         mass(1));
}
}  // namespace detail

class PlanarKirchhoffLagrangian final : public AutoDiffLagrangian<PlanarKirchhoffLagrangian, SE2> {
 public:
  PlanarKirchhoffLagrangian(double inertia, const Eigen::Vector2d& mass)
      : weights_(detail::planarKirchhoffWeights(inertia, mass)) {}
  template <class T>
  T evaluate(const Eigen::Matrix<T, 3, 1>& xi) const {
    return detail::halfWeightedSquares(xi, weights_);
  }
  Eigen::Vector3d gradient(const Eigen::Vector3d& xi) const override {
    return weights_.cwiseProduct(xi);
  }
  Eigen::Vector3d hessianTimes(const Eigen::Vector3d&, const Eigen::Vector3d& v) const override {
    return weights_.cwiseProduct(v);
  }
  Eigen::Matrix3d hessian(const Eigen::Vector3d&) const override { return weights_.asDiagonal(); }

 private:
  Eigen::Vector3d weights_;
};

class PlanarKirchhoffHamiltonian final
    : public AutoDiffHamiltonian<PlanarKirchhoffHamiltonian, SE2> {
 public:
  PlanarKirchhoffHamiltonian(double inertia, const Eigen::Vector2d& mass)
      : inverse_weights_(detail::planarKirchhoffWeights(inertia, mass).cwiseInverse()) {}
  template <class T>
  T evaluate(const Eigen::Matrix<T, 3, 1>& mu) const {
    return detail::halfWeightedSquares(mu, inverse_weights_);
  }
  Eigen::Vector3d gradient(const Eigen::Vector3d& mu) const override {
    return inverse_weights_.cwiseProduct(mu);
  }
  Eigen::Vector3d hessianTimes(const Eigen::Vector3d&, const Eigen::Vector3d& v) const override {
    return inverse_weights_.cwiseProduct(v);
  }
  Eigen::Matrix3d hessian(const Eigen::Vector3d&) const override {
    return inverse_weights_.asDiagonal();
  }

 private:
  Eigen::Vector3d inverse_weights_;
};

/// Kirchhoff's planar body: moment of inertia I > 0, added masses (m₁, m₂) > 0, and the metric
/// k (3 entries >= 0) of k♯ = α diag(k).
std::shared_ptr<const LiePoissonSystem<SE2>> makePlanarKirchhoffBody(double inertia,
                                                                     const Eigen::Vector2d& mass,
                                                                     double alpha,
                                                                     const Eigen::Vector3d& metric);

}  // namespace ddb

// The generic system of SE(2) compiled once (instantiations/lie_poisson_systems.cc).
DDB_LIE_POISSON_SYSTEM_INSTANCE(extern, ::ddb::SE2);
