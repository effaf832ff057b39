// LiePoissonSystem: a group, a Hamiltonian (and optionally the Lagrangian it comes
// from) and a dissipation metric. The continuous dynamics (paper, eq. (3.4)):
//   μ̇ = ad*_{ξ + φ(ξ)} μ,   ξ = ∂H/∂μ,   φ(ξ) = k♯(ad*_ξ μ),
// so Casimirs are constant and dH/dt = -k(ad*_ξ μ, ad*_ξ μ) (Proposition 3.3).
#pragma once

#include <ddb/core/dissipation_metric.h>
#include <ddb/core/errors.h>
#include <ddb/core/group_traits.h>
#include <ddb/core/jet_lift.h>
#include <ddb/core/lagrangian.h>

#include <memory>
#include <string>
#include <utility>

namespace ddb {

template <class G>
class LiePoissonSystem {
  static_assert(sizeof(GroupTraits<G>) > 0, "checks G's minimum API (core/group_traits.h)");

 public:
  using Group = G;
  template <class T>
  using AlgebraT = typename G::template Algebra<T>;
  template <class T>
  using DualT = typename G::template Dual<T>;
  using Algebra = AlgebraT<double>;
  using Dual = DualT<double>;
  using Casimirs = typename G::template Casimirs<double>;

  LiePoissonSystem(std::string name, std::shared_ptr<const Hamiltonian<G>> hamiltonian,
                   std::shared_ptr<const DissipationMetric<G>> metric,
                   std::shared_ptr<const Lagrangian<G>> lagrangian = nullptr)
      : name_(std::move(name)),
        hamiltonian_(std::move(hamiltonian)),
        metric_(std::move(metric)),
        lagrangian_(std::move(lagrangian)) {
    if (!hamiltonian_) throw InvalidArgument("hamiltonian must not be null");
    if (!metric_) throw InvalidArgument("metric must not be null");
  }

  const std::string& name() const { return name_; }
  const Hamiltonian<G>& hamiltonian() const { return *hamiltonian_; }
  const DissipationMetric<G>& metric() const { return *metric_; }
  /// The Lagrangian l with ∂l/∂ξ = μ ⇔ ξ = ∂H/∂μ, or nullptr (e.g. the heavy top).
  const Lagrangian<G>* lagrangian() const { return lagrangian_.get(); }

  double energy(const Dual& mu) const { return hamiltonian_->value(mu); }
  Casimirs casimirs(const Dual& mu) const { return G::casimirs(mu); }

  /// ξ = ∂H/∂μ (double or Jet).
  template <class T>
  AlgebraT<T> velocity(const DualT<T>& mu) const {
    return liftGradient(*hamiltonian_, mu);
  }

  /// φ(ξ) = k♯(ad*_ξ μ), where μ is the momentum paired with ξ (double or Jet).
  template <class T>
  AlgebraT<T> dissipation(const AlgebraT<T>& xi, const DualT<T>& mu) const {
    return liftLinear([this](const Dual& m) { return metric_->sharp(m); },
                      G::adDual(xi, mu).eval());
  }

  /// μ̇ = ad*_{ξ + φ(ξ)} μ (double or Jet).
  template <class T>
  DualT<T> vectorField(const DualT<T>& mu) const {
    const AlgebraT<T> xi = velocity(mu);
    const AlgebraT<T> forced = xi + dissipation(xi, mu);
    return G::adDual(forced, mu);
  }

 private:
  std::string name_;
  std::shared_ptr<const Hamiltonian<G>> hamiltonian_;
  std::shared_ptr<const DissipationMetric<G>> metric_;
  std::shared_ptr<const Lagrangian<G>> lagrangian_;
};

}  // namespace ddb
