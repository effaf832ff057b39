// The heavy top on se(3)* (docs/reference/conventions.md §2): μ = (π, γ), H = ½ π·𝕀^{-1}π + mgℓ
// χ·γ, so ξ = ∂H/∂μ = (𝕀^{-1}π, mgℓ χ) and μ̇ = ad*_ξ μ gives π̇ = π×Ω + mgℓ γ×χ,
// γ̇ = γ×Ω. H is linear in γ: there is no regular Lagrangian, so DDB runs in its
// Hamiltonian form. Dissipation k♯ = α diag(k); Casimirs |γ|², π·γ. The group is a parameter:
// SE3, or SO(3) ⋉ R³ composed (SemidirectProduct<SO3>), whose coordinates are the same, or
// SE(N) = SpecialEuclidean<N> (groups/special_euclidean.h) for Ratiu's N-dimensional heavy top
// (Ratiu 1982, "Euler–Poisson equations on Lie algebras and the N-dimensional heavy rigid body"):
// the same H with π ∈ so(N)* ≅ R^{N(N−1)/2} and γ, χ ∈ Rᴺ, and a diagonal 𝕀 in
// SpecialOrthogonal<N>'s coordinates, for a body of mass moments J that of 𝕁Ω = ΩJ + JΩ
// (systems/body_inertia.h).
#pragma once

#include <ddb/core/autodiff.h>
#include <ddb/core/dissipation_metric.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/groups/se3.h>
#include <ddb/systems/rigid_body.h>

#include <memory>
#include <type_traits>

namespace ddb {

namespace detail {
/// n, the dimension of the space G moves: G::kVectorDim for a SemidirectProduct, 3 for SE3.
template <class G, class = void>
struct HeavyTopVectorDim : std::integral_constant<int, 3> {
  static_assert(G::kDim == 6, "the heavy top lives on SE3 or on a SemidirectProduct");
};
template <class G>
struct HeavyTopVectorDim<G, std::void_t<decltype(G::kVectorDim)>>
    : std::integral_constant<int, G::kVectorDim> {};
}  // namespace detail

/// H on G's dual, G any group with μ = (π, γ), π of G::kDim − n entries and γ ∈ Rⁿ, and the dot
/// pairing (SE3, SemidirectProduct<SO3>, SpecialEuclidean<N>).
template <class G>
class HeavyTopHamiltonianOn final : public AutoDiffHamiltonian<HeavyTopHamiltonianOn<G>, G> {
 public:
  /// n and the number of principal moments.
  static constexpr int kVectorDim = detail::HeavyTopVectorDim<G>::value;
  static constexpr int kFactorDim = G::kDim - kVectorDim;
  using Inertia = Eigen::Matrix<double, kFactorDim, 1>;
  using Vector = Eigen::Matrix<double, kVectorDim, 1>;
  using State = Eigen::Matrix<double, G::kDim, 1>;

  HeavyTopHamiltonianOn(const Inertia& inertia, double mgl, const Vector& chi)
      : inverse_inertia_(invertInertia(inertia)),
        mgl_(requireFinite("mgl", mgl)),
        chi_(requireFinite("chi", chi)) {}

  template <class T>
  T evaluate(const Eigen::Matrix<T, G::kDim, 1>& mu) const {
    T kinetic = constant<T>(0.0), potential = constant<T>(0.0);
    for (int i = 0; i < kFactorDim; ++i) {
      kinetic += mu(i) * mu(i) * constant<T>(inverse_inertia_(i));
    }
    for (int i = 0; i < kVectorDim; ++i) {
      potential += constant<T>(mgl_ * chi_(i)) * mu(kFactorDim + i);
    }
    return constant<T>(0.5) * kinetic + potential;
  }
  // Analytic overrides for speed (checked against the autodiff versions in the tests); 𝕀⁻¹ is
  // stored, so that they multiply.
  State gradient(const State& mu) const override {
    State out;  // halves assigned: a comma initialiser stores and reloads
    out.template head<kFactorDim>() = inverse_inertia_.cwiseProduct(mu.template head<kFactorDim>());
    out.template tail<kVectorDim>() = mgl_ * chi_;
    return out;
  }
  State hessianTimes(const State&, const State& v) const override {
    State out;
    out.template head<kFactorDim>() = inverse_inertia_.cwiseProduct(v.template head<kFactorDim>());
    out.template tail<kVectorDim>().setZero();
    return out;
  }
  Eigen::Matrix<double, G::kDim, G::kDim> hessian(const State&) const override {
    Eigen::Matrix<double, G::kDim, G::kDim> out = Eigen::Matrix<double, G::kDim, G::kDim>::Zero();
    out.template topLeftCorner<kFactorDim, kFactorDim>() = inverse_inertia_.asDiagonal();
    return out;
  }

 private:
  Inertia inverse_inertia_;
  double mgl_;
  Vector chi_;
};

using HeavyTopHamiltonian = HeavyTopHamiltonianOn<SE3>;

/// The heavy top on G (SE3, SemidirectProduct<SO3> or SpecialEuclidean<N>); `metric` k
/// (G::kDim entries >= 0) gives k♯ = α diag(k).
template <class G>
std::shared_ptr<const LiePoissonSystem<G>> makeHeavyTopOn(
    const typename HeavyTopHamiltonianOn<G>::Inertia& inertia, double mgl,
    const typename HeavyTopHamiltonianOn<G>::Vector& chi, double alpha,
    const Eigen::Matrix<double, G::kDim, 1>& metric) {
  return makeLiePoissonSystem("heavy-top",
                              std::make_shared<const HeavyTopHamiltonianOn<G>>(inertia, mgl, chi),
                              std::make_shared<const DiagonalMetric<G>>(alpha, metric));
}

/// The heavy top on SE3 (makeHeavyTopOn<SE3>, compiled once).
std::shared_ptr<const LiePoissonSystem<SE3>> makeHeavyTop(
    const Eigen::Vector3d& inertia, double mgl, const Eigen::Vector3d& chi, double alpha,
    const Eigen::Matrix<double, 6, 1>& metric);

}  // namespace ddb

// The generic system of SE(3) compiled once (instantiations/lie_poisson_systems.cc).
DDB_LIE_POISSON_SYSTEM_INSTANCE(extern, ::ddb::SE3);
