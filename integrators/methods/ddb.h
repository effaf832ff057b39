// DDB: the discrete double-bracket method (paper, Section 4.1, "DDB method"):
//   (i)  find ξ_k with M_k = (dτ^{-1}_{hξ_k})* ∂l/∂ξ(ξ_k)      (discrete Legendre)
//   (ii) M_{k+1} = Ad*_{τ(hξ_k) τ(hφ(ξ_k))} M_k                 (eq. (4.12))
// with φ(ξ) = k♯(ad*_ξ ∂l/∂ξ(ξ)) (eq. (3.5)). Every M_k stays on the coadjoint
// orbit of M_0 exactly; first order for α ≠ 0, second order for α = 0
// (docs/reference/conventions.md §2).
#pragma once

#include <ddb/core/group_traits.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/integrators/matrix_kernels/matrix_retraction.h>
#include <ddb/integrators/methods/legendre_method.h>

#include <memory>
#include <string>

namespace ddb {

/// The DDB update of R on matrix groups (MatrixRetraction<R>::Transport), and an empty type on
/// the other groups, whose retractions need no matrix step.
template <class R, bool kMatrix = isDynamicGroup<typename R::Group>>
struct MatrixTransportOf {
  struct type {};
};
template <class R>
struct MatrixTransportOf<R, true> {
  using type =
      typename MatrixRetraction<R>::template Transport<LiePoissonSystem<typename R::Group>>;
};

template <class R>
class Ddb : public LegendreMethod<R> {
 public:
  using typename LegendreMethod<R>::G;
  using typename LegendreMethod<R>::Dual;
  using typename LegendreMethod<R>::Algebra;

  Ddb(std::shared_ptr<const LiePoissonSystem<G>> system, R retraction = R(),
      LegendreForm form = LegendreForm::kLagrangian, SolverOptions options = {})
      : LegendreMethod<R>(std::move(system), std::move(retraction), form, options) {}

  std::string name() const override { return this->nameWith("ddb-"); }

  Dual step(const Dual& mu, double t, double h) override {
    if constexpr (isDynamicGroup<G>) {
      return this->stepInPlace(mu, t, h);
    } else {
      Dual p;
      const Algebra xi = this->legendre_.solve(mu, t, h, p);
      const Algebra phi = this->system_->dissipation(xi, p);
      const Algebra hxi = h * xi, hphi = h * phi;
      return this->retraction_.transport(hxi, hphi, mu);
    }
  }

  /// Matrix groups (on any backend: docs/design/matrix-backend.md): DDB's step (i) and (ii) in
  /// place, with the solver's certified frozen solution and the preallocated transport of the
  /// retraction (no allocation once the size is known).
  void advance(Dual& mu, double t, double h) override {
    if constexpr (isDynamicGroup<G>) {
      this->legendre_.solveInPlace(FixedMomentum<G, Dual>{mu}, mu, t, h);
      transport_.apply(*this->system_, this->legendre_, h, mu);
    } else {
      mu = step(mu, t, h);
    }
  }

 private:
  typename MatrixTransportOf<R>::type transport_;
};

}  // namespace ddb
