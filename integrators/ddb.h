// DDB: the discrete double-bracket method (paper, Section 4.1, "DDB method"):
//   (i)  find ξ_k with M_k = (dτ^{-1}_{hξ_k})* ∂l/∂ξ(ξ_k)      (discrete Legendre)
//   (ii) M_{k+1} = Ad*_{τ(hξ_k) τ(hφ(ξ_k))} M_k                 (eq. "evolution_of_Mk_in_tau")
// with φ(ξ) = k♯(ad*_ξ ∂l/∂ξ(ξ)) (eq. "varphi"). Every M_k stays on the coadjoint
// orbit of M_0 exactly; first order for α ≠ 0, second order for α = 0 (DESIGN.md §2).
#pragma once

#include <memory>
#include <string>

#include "core/lie_poisson_system.h"
#include "integrators/legendre.h"
#include "integrators/one_step_method.h"

namespace ddb {

template <class R>
class Ddb : public OneStepMethod<typename R::Group> {
 public:
  using G = typename R::Group;
  using Dual = typename G::template Dual<double>;
  using Algebra = typename G::template Algebra<double>;

  Ddb(std::shared_ptr<const LiePoissonSystem<G>> system, R retraction = R(),
      LegendreForm form = LegendreForm::kLagrangian, SolverOptions options = {})
      : system_(std::move(system)),
        retraction_(std::move(retraction)),
        form_(form),
        legendre_(*system_, retraction_, form, options) {}
  Ddb(const Ddb&) = delete;  // legendre_ refers to retraction_
  Ddb& operator=(const Ddb&) = delete;

  std::string name() const override {
    return std::string("ddb-") + R::kName +
           (form_ == LegendreForm::kHamiltonian ? "-hamiltonian" : "");
  }
  void reset() override { legendre_.reset(); }

  Dual step(const Dual& mu, double t, double h) override {
    Dual p;
    const Algebra xi = legendre_.solve(mu, t, h, p);
    const Algebra phi = system_->dissipation(xi, p);
    const Algebra hxi = h * xi, hphi = h * phi;
    return retraction_.transport(hxi, hphi, mu);
  }

 private:
  std::shared_ptr<const LiePoissonSystem<G>> system_;
  R retraction_;
  LegendreForm form_;
  DiscreteLegendreSolver<R> legendre_;
};

}  // namespace ddb
