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

/// DDB's update (ii), M ← Ad*_{τ(hξ) τ(hφ)} M with φ = k♯(ad*_ξ p) (eq. (4.12)), on the small
/// groups: the retraction's transport of the solver's ξ and p, which a group may apply without
/// forming the product (SO3::cayTransport).
template <class R>
struct FixedSizeDdbTransport {
  using G = typename R::Group;
  using Algebra = typename G::template Algebra<double>;
  using Dual = typename G::template Dual<double>;

  template <class Solver>
  void apply(const LiePoissonSystem<G>& system, const Solver& solver, double h, Dual& mu) const {
    const Algebra phi = system.dissipation(solver.velocity(), solver.solution());
    const Algebra hxi = h * solver.velocity(), hphi = h * phi;
    mu = solver.retraction().transport(hxi, hphi, mu);
  }
};

/// The update (ii) of R, chosen by its group's traits: MatrixRetraction<R>::Transport (in place,
/// preallocated) on matrix groups, FixedSizeDdbTransport on the small ones.
template <class R, bool kMatrix = isDynamicGroup<typename R::Group>>
struct DdbTransportOf {
  using type = FixedSizeDdbTransport<R>;
};
template <class R>
struct DdbTransportOf<R, true> {
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

  Dual step(const Dual& mu, double t, double h) override { return this->stepInPlace(mu, t, h); }

  /// DDB's step (i) and (ii) in place on any group and backend (docs/design/matrix-backend.md):
  /// the solver's solution, and on matrix groups its certified frozen solution, into the
  /// retraction's update (no allocation once the size is known).
  void advance(Dual& mu, double t, double h) override {
    this->legendre_.solveInPlace(FixedMomentum<G, Dual>{mu}, mu, t, h);
    transport_.apply(*this->system_, this->legendre_, h, mu);
  }

 private:
  typename DdbTransportOf<R>::type transport_;
};

}  // namespace ddb
