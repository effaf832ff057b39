// The discrete Legendre transform of a DDB step (paper, Section 4.1):
//   M = (dτ^{-1}_{hξ})* ∂l/∂ξ(ξ)                     (Lagrangian form, unknown ξ)
//   M = (dτ^{-1}_{h ∂H/∂μ(p)})* p                     (Hamiltonian form, unknown p)
// solved for the pair (ξ, p = ∂l/∂ξ(ξ)) by Ceres TinySolver, warm-started.
#pragma once

#include <Eigen/Core>

#include "core/lie_poisson_system.h"
#include "integrators/tiny_solver.h"

namespace ddb {

enum class LegendreForm { kLagrangian, kHamiltonian };

inline const char* toString(LegendreForm form) {
  return form == LegendreForm::kLagrangian ? "lagrangian" : "hamiltonian";
}

/// Solves the discrete Legendre equation for a fixed-size group; keeps the last
/// solution as the next warm start.
template <class R>
class DiscreteLegendreSolver {
 public:
  using G = typename R::Group;
  static constexpr int kDim = G::kDim;
  using Algebra = typename G::template Algebra<double>;
  using Dual = typename G::template Dual<double>;
  using Vector = Eigen::Matrix<double, kDim, 1>;

  DiscreteLegendreSolver(const LiePoissonSystem<G>& system, const R& retraction, LegendreForm form,
                         SolverOptions options)
      : system_(system), retraction_(retraction), form_(form), options_(options) {
    if (form_ == LegendreForm::kLagrangian && system_.lagrangian() == nullptr) {
      throw InvalidArgument("form = lagrangian is invalid: system '" + system_.name() +
                            "' has no Lagrangian (use the Hamiltonian form)");
    }
  }

  void reset() { has_guess_ = false; }

  /// Solves (dτ^{-1}_{hξ})* ∂l/∂ξ(ξ) = target; returns ξ and sets p = ∂l/∂ξ(ξ).
  Algebra solve(const Dual& target, double t, double h, Dual& p) {
    const double scale = target.norm();
    if (form_ == LegendreForm::kLagrangian) {
      if (!has_guess_) unknown_ = system_.velocity(target);
      const LagrangianEquation equation{system_, retraction_, target, h};
      solveTiny<kDim>(equation, unknown_, scale, options_, "discrete Legendre equation", t, h);
      has_guess_ = true;
      p = system_.lagrangian()->gradient(unknown_);
      return unknown_;
    }
    if (!has_guess_) unknown_ = target;
    const HamiltonianEquation equation{system_, retraction_, target, h};
    solveTiny<kDim>(equation, unknown_, scale, options_, "discrete Legendre equation", t, h);
    has_guess_ = true;
    p = unknown_;
    return system_.velocity(p);
  }

 private:
  // r(ξ) = (dτ^{-1}_{hξ})* ∂l/∂ξ(ξ) - M
  struct LagrangianEquation {
    const LiePoissonSystem<G>& system;
    const R& retraction;
    const Dual& target;
    double h;
    template <class T>
    bool operator()(const T* x, T* r) const {
      using A = typename G::template Algebra<T>;
      const A xi = Eigen::Map<const A>(x);
      const auto p = liftGradient(*system.lagrangian(), xi);
      const A hxi = xi * T(h);
      Eigen::Map<A> out(r);
      out = retraction.dTauInverseDual(hxi, p) - target.template cast<T>();
      return true;
    }
  };
  // r(p) = (dτ^{-1}_{h ∂H/∂μ(p)})* p - M
  struct HamiltonianEquation {
    const LiePoissonSystem<G>& system;
    const R& retraction;
    const Dual& target;
    double h;
    template <class T>
    bool operator()(const T* x, T* r) const {
      using D = typename G::template Dual<T>;
      using A = typename G::template Algebra<T>;
      const D p = Eigen::Map<const D>(x);
      const A hxi = system.velocity(p) * T(h);
      Eigen::Map<D> out(r);
      out = retraction.dTauInverseDual(hxi, p) - target.template cast<T>();
      return true;
    }
  };

  const LiePoissonSystem<G>& system_;
  const R& retraction_;
  LegendreForm form_;
  SolverOptions options_;
  bool has_guess_ = false;
  Vector unknown_ = Vector::Zero();
};

}  // namespace ddb
