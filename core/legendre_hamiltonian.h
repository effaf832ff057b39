// LegendreHamiltonian: the Hamiltonian of a regular Lagrangian, so that a user who
// writes only l(ξ) gets a complete LiePoissonSystem (paper, Section 2.2):
//   ξ(μ) solves ∂l/∂ξ(ξ) = μ (inverse Legendre transform, core/detail/tiny_solver.h),
//   H(μ) = <μ, ξ(μ)> − l(ξ(μ)),  ∂H/∂μ = ξ(μ),  D²H(μ)[ν] = (D²l(ξ))^{-1} ν.
// For fixed-size algebras. The last ξ is kept as the next solve's start (a cache:
// one instance must not be shared between threads).
#pragma once

#include <ddb/core/detail/jet_lift.h>
#include <ddb/core/detail/tiny_solver.h>
#include <ddb/core/lagrangian.h>
#include <ddb/core/lie_poisson_system.h>

#include <Eigen/LU>
#include <memory>

namespace ddb {

template <class G>
class LegendreHamiltonian final : public Hamiltonian<G> {
 public:
  static constexpr int kDim = G::kDim;
  using Algebra = typename G::template Algebra<double>;
  using Dual = typename G::template Dual<double>;

  explicit LegendreHamiltonian(std::shared_ptr<const Lagrangian<G>> lagrangian,
                               SolverOptions options = {})
      : lagrangian_(std::move(lagrangian)), options_(options) {
    if (!lagrangian_) throw InvalidArgument("lagrangian must not be null");
  }

  double value(const Dual& mu) const override {
    const Algebra xi = velocity(mu);
    return G::pairing(mu, xi) - lagrangian_->value(xi);
  }
  Algebra gradient(const Dual& mu) const override { return velocity(mu); }
  bool gradientIsASolve() const override { return true; }
  Algebra hessianTimes(const Dual& mu, const Dual& nu) const override {
    return hessianMatrix(*lagrangian_, velocity(mu)).partialPivLu().solve(nu);
  }

 private:
  // ∂l/∂ξ(ξ) − μ = 0 for ξ.
  struct InverseLegendre {
    const Lagrangian<G>& lagrangian;
    const Dual& mu;
    template <class T>
    bool operator()(const T* x, T* r) const {
      using A = typename G::template Algebra<T>;
      const A xi = Eigen::Map<const A>(x);
      Eigen::Map<A> out(r);
      out = liftGradient(lagrangian, xi) - mu.template cast<T>();
      return true;
    }
  };

  Algebra velocity(const Dual& mu) const {
    const InverseLegendre equation{*lagrangian_, mu};
    // Time and step are the caller's: integrate() fills them in on failure.
    solveTiny<kDim>(equation, guess_, mu.norm(), options_, "inverse Legendre transform", NAN, NAN);
    return guess_;
  }

  std::shared_ptr<const Lagrangian<G>> lagrangian_;
  SolverOptions options_;
  mutable Algebra guess_ = Algebra::Zero();
};

/// A system from a Lagrangian and a metric alone: H by the Legendre transform.
template <class G>
std::shared_ptr<const LiePoissonSystem<G>> makeSystemFromLagrangian(
    std::string name, std::shared_ptr<const Lagrangian<G>> lagrangian,
    std::shared_ptr<const DissipationMetric<G>> metric) {
  auto hamiltonian = std::make_shared<const LegendreHamiltonian<G>>(lagrangian);
  return makeLiePoissonSystem(std::move(name), hamiltonian, metric, std::move(lagrangian));
}

}  // namespace ddb
