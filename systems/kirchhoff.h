// Kirchhoff's equations for a rigid body in ideal fluid, on se(3)*: ξ = (Ω, v),
// l(ξ) = ½ Ω·𝕀Ω + ½ v·𝕄v (diagonal added-mass tensors), μ = (π, P) = (𝕀Ω, 𝕄v),
// H = ½ π·𝕀^{-1}π + ½ P·𝕄^{-1}P; μ̇ = ad*_ξ μ gives π̇ = π×Ω + P×v, Ṗ = P×Ω.
// Dissipation k♯ = α diag(k); Casimirs |P|², π·P. The group is a parameter: SE3, or SO(3) ⋉ R³
// composed (SemidirectProduct<SO3>), whose coordinates are the same.
#pragma once

#include <ddb/core/autodiff.h>
#include <ddb/core/dissipation_metric.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/groups/se3.h>

#include <memory>

namespace ddb {

namespace detail {
/// (𝕀, 𝕄) stacked: the diagonal of the Lagrangian's quadratic form.
inline Eigen::Matrix<double, 6, 1> kirchhoffWeights(const Eigen::Vector3d& inertia,
                                                    const Eigen::Vector3d& mass) {
  return (Eigen::Matrix<double, 6, 1>() << requirePositive("inertia", inertia),
          requirePositive("mass", mass))
      .finished();
}
/// ½ Σ_i w_i x_i² in any scalar type (the quadratic form of a diagonal tensor).
template <class T, int N, class Weights>
T halfWeightedSquares(const Eigen::Matrix<T, N, 1>& x, const Weights& w) {
  T sum = constant<T>(0.0);
  for (int i = 0; i < N; ++i) sum += constant<T>(w(i)) * x(i) * x(i);
  return constant<T>(0.5) * sum;
}
}  // namespace detail

template <class G>
class KirchhoffLagrangianOn final : public AutoDiffLagrangian<KirchhoffLagrangianOn<G>, G> {
  static_assert(G::kDim == 6, "Kirchhoff's coordinates are (Omega, v) in R^6");

 public:
  KirchhoffLagrangianOn(const Eigen::Vector3d& inertia, const Eigen::Vector3d& mass)
      : weights_(detail::kirchhoffWeights(inertia, mass)) {}
  template <class T>
  T evaluate(const Eigen::Matrix<T, 6, 1>& xi) const {
    return detail::halfWeightedSquares(xi, weights_);
  }
  // Analytic overrides for speed (checked against the autodiff versions in the tests).
  Eigen::Matrix<double, 6, 1> gradient(const Eigen::Matrix<double, 6, 1>& xi) const override {
    return weights_.cwiseProduct(xi);
  }
  Eigen::Matrix<double, 6, 1> hessianTimes(const Eigen::Matrix<double, 6, 1>&,
                                           const Eigen::Matrix<double, 6, 1>& v) const override {
    return weights_.cwiseProduct(v);
  }
  Eigen::Matrix<double, 6, 6> hessian(const Eigen::Matrix<double, 6, 1>&) const override {
    return weights_.asDiagonal();
  }

 private:
  Eigen::Matrix<double, 6, 1> weights_;
};

template <class G>
class KirchhoffHamiltonianOn final : public AutoDiffHamiltonian<KirchhoffHamiltonianOn<G>, G> {
  static_assert(G::kDim == 6, "Kirchhoff's coordinates are (pi, P) in R^6");

 public:
  KirchhoffHamiltonianOn(const Eigen::Vector3d& inertia, const Eigen::Vector3d& mass)
      : inverse_weights_(detail::kirchhoffWeights(inertia, mass).cwiseInverse()) {}
  template <class T>
  T evaluate(const Eigen::Matrix<T, 6, 1>& mu) const {
    return detail::halfWeightedSquares(mu, inverse_weights_);
  }
  Eigen::Matrix<double, 6, 1> gradient(const Eigen::Matrix<double, 6, 1>& mu) const override {
    return inverse_weights_.cwiseProduct(mu);
  }
  Eigen::Matrix<double, 6, 1> hessianTimes(const Eigen::Matrix<double, 6, 1>&,
                                           const Eigen::Matrix<double, 6, 1>& v) const override {
    return inverse_weights_.cwiseProduct(v);
  }
  Eigen::Matrix<double, 6, 6> hessian(const Eigen::Matrix<double, 6, 1>&) const override {
    return inverse_weights_.asDiagonal();
  }

 private:
  Eigen::Matrix<double, 6, 1> inverse_weights_;
};

using KirchhoffLagrangian = KirchhoffLagrangianOn<SE3>;
using KirchhoffHamiltonian = KirchhoffHamiltonianOn<SE3>;

/// Kirchhoff's body on G (SE3 or SemidirectProduct<SO3>); `metric` k gives k♯ = α diag(k).
template <class G>
std::shared_ptr<const LiePoissonSystem<G>> makeKirchhoffBodyOn(
    const Eigen::Vector3d& inertia, const Eigen::Vector3d& mass, double alpha,
    const Eigen::Matrix<double, 6, 1>& metric) {
  return makeLiePoissonSystem("kirchhoff",
                              std::make_shared<const KirchhoffHamiltonianOn<G>>(inertia, mass),
                              std::make_shared<const DiagonalMetric<G>>(alpha, metric),
                              std::make_shared<const KirchhoffLagrangianOn<G>>(inertia, mass));
}

/// Kirchhoff's body on SE3 (makeKirchhoffBodyOn<SE3>, compiled once).
std::shared_ptr<const LiePoissonSystem<SE3>> makeKirchhoffBody(
    const Eigen::Vector3d& inertia, const Eigen::Vector3d& mass, double alpha,
    const Eigen::Matrix<double, 6, 1>& metric);

}  // namespace ddb

// The generic system of SE(3) compiled once (instantiations/lie_poisson_systems.cc).
DDB_LIE_POISSON_SYSTEM_INSTANCE(extern, ::ddb::SE3);
