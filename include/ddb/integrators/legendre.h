// The discrete Legendre transform of a DDB step (paper, Section 4.1):
//   (dτ^{-1}_{hξ})* p = target(ξ, p),  p = ∂l/∂ξ(ξ)  (Lagrangian form, unknown ξ)
//                                      ξ = ∂H/∂μ(p)  (Hamiltonian form, unknown p)
// solved by Ceres TinySolver, warm-started from the previous solution. DDB's target
// is the momentum M_k; the symmetric variants' targets depend on the unknown too.
#pragma once

#include <ddb/core/lie_poisson_system.h>
#include <ddb/core/tiny_solver.h>
#include <ddb/integrators/injectivity_guard.h>

#include <Eigen/Core>

namespace ddb {

enum class LegendreForm { kLagrangian, kHamiltonian };

/// The target of DDB's Legendre equation: a fixed momentum.
template <class G>
struct FixedMomentum {
  const typename G::template Dual<double>& momentum;
  template <class A, class D>
  D operator()(const A&, const D&) const {
    return momentum.template cast<typename D::Scalar>();
  }
};

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
  LegendreForm form() const { return form_; }

  /// Solves (dτ^{-1}_{hξ})* p = target(ξ, p); returns ξ and sets p. `near` is a momentum
  /// close to the solution (the first guess when there is no warm start); `scale` the
  /// size of the equation's data for the relative tolerance.
  template <class Target>
  Algebra solve(const Target& target, const Dual& near, double t, double h, Dual& p) {
    if (!has_guess_) {
      unknown_ = form_ == LegendreForm::kLagrangian ? Vector(system_.velocity(near)) : near;
    }
    InjectivityGuard<R>::beforeSolve(system_, near, t, h);
    const Equation<Target> equation{system_, retraction_, target, h, form_};
    solveTiny<kDim>(equation, unknown_, near.norm(), options_, "discrete Legendre equation", t, h);
    has_guess_ = true;
    Algebra xi;
    if (form_ == LegendreForm::kLagrangian) {
      p = system_.lagrangian()->gradient(unknown_);
      xi = unknown_;
    } else {
      p = unknown_;
      xi = system_.velocity(p);
    }
    InjectivityGuard<R>::afterSolve(system_, near, xi, t, h);
    return xi;
  }

  /// DDB's equation M = (dτ^{-1}_{hξ})* ∂l/∂ξ(ξ).
  Algebra solve(const Dual& momentum, double t, double h, Dual& p) {
    return solve(FixedMomentum<G>{momentum}, momentum, t, h, p);
  }

 private:
  template <class Target>
  struct Equation {
    const LiePoissonSystem<G>& system;
    const R& retraction;
    const Target& target;
    double h;
    LegendreForm form;
    template <class T>
    bool operator()(const T* x, T* r) const {
      using A = typename G::template Algebra<T>;
      using D = typename G::template Dual<T>;
      A xi;
      D p;
      if (form == LegendreForm::kLagrangian) {
        xi = Eigen::Map<const A>(x);
        p = liftGradient(*system.lagrangian(), xi);
      } else {
        p = Eigen::Map<const D>(x);
        xi = system.velocity(p);
      }
      const A hxi = xi * T(h);
      Eigen::Map<D> out(r);
      out = retraction.dTauInverseDual(hxi, p) - target(xi, p);
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
