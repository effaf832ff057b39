// LiePoissonSystem: a group, a Hamiltonian (and optionally the Lagrangian it comes
// from) and a dissipation metric. The continuous dynamics (paper, eq. (3.4)):
//   μ̇ = ad*_{ξ + φ(ξ)} μ,   ξ = ∂H/∂μ,   φ(ξ) = k♯(ad*_ξ μ),
// so Casimirs are constant and dH/dt = -k(ad*_ξ μ, ad*_ξ μ) (Proposition 3.3).
#pragma once

#include <ddb/core/detail/jet_lift.h>
#include <ddb/core/dissipation_metric.h>
#include <ddb/core/errors.h>
#include <ddb/core/group_traits.h>
#include <ddb/core/lagrangian.h>

#include <memory>
#include <string>
#include <type_traits>
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
  virtual ~LiePoissonSystem() = default;
  // Copies share the Hamiltonian and metric; a copy of a TypedLiePoissonSystem through this
  // class is a generic system of the same parts. No assignment: TypedLiePoissonSystem relies on
  // its parts keeping their types.
  LiePoissonSystem(const LiePoissonSystem&) = default;
  LiePoissonSystem(LiePoissonSystem&&) = default;
  LiePoissonSystem& operator=(const LiePoissonSystem&) = delete;
  LiePoissonSystem& operator=(LiePoissonSystem&&) = delete;

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
    return velocityOf(*hamiltonian_, mu);
  }

  /// φ(ξ) = k♯(ad*_ξ μ), where μ is the momentum paired with ξ (double or Jet).
  template <class T>
  AlgebraT<T> dissipation(const AlgebraT<T>& xi, const DualT<T>& mu) const {
    return dissipationOf(*metric_, xi, mu);
  }

  /// μ̇ = ad*_{ξ + φ(ξ)} μ (double or Jet). In double through fieldAt: one virtual call in a
  /// TypedLiePoissonSystem with `final` parts, three in one built by LiePoissonSystem's own
  /// constructor.
  template <class T>
  DualT<T> vectorField(const DualT<T>& mu) const {
    if constexpr (std::is_same_v<T, double>) {
      return fieldAt(mu);
    } else {
      return vectorFieldOf(*hamiltonian_, *metric_, mu);
    }
  }

 protected:
  /// μ̇ at a double μ. TypedLiePoissonSystem overrides it to call its Hamiltonian and metric
  /// through their concrete types.
  virtual Dual fieldAt(const Dual& mu) const { return vectorFieldOf(*hamiltonian_, *metric_, mu); }

  // Eq. (3.4) for any Hamiltonian type H and metric type K: the base classes here, the
  // concrete ones in TypedLiePoissonSystem.
  template <class H, class T>
  static AlgebraT<T> velocityOf(const H& hamiltonian, const DualT<T>& mu) {
    return liftGradient(hamiltonian, mu);
  }
  template <class K, class T>
  static AlgebraT<T> dissipationOf(const K& metric, const AlgebraT<T>& xi, const DualT<T>& mu) {
    return liftLinear([&metric](const Dual& m) { return metric.sharp(m); },
                      G::adDual(xi, mu).eval());
  }
  template <class H, class K, class T>
  static DualT<T> vectorFieldOf(const H& hamiltonian, const K& metric, const DualT<T>& mu) {
    const AlgebraT<T> xi = velocityOf(hamiltonian, mu);
    const AlgebraT<T> forced = xi + dissipationOf(metric, xi, mu);
    return G::adDual(forced, mu);
  }

 private:
  std::string name_;
  std::shared_ptr<const Hamiltonian<G>> hamiltonian_;
  std::shared_ptr<const DissipationMetric<G>> metric_;
  std::shared_ptr<const Lagrangian<G>> lagrangian_;
};

/// A LiePoissonSystem that knows the concrete types H of its Hamiltonian and K of its metric.
/// Its double vector field calls `gradient` and `sharp` by name through those types, so that
/// when they are `final` the compiler inlines ∂H/∂μ and k♯ into the field: one virtual call
/// per evaluation (fieldAt) instead of two (∂H/∂μ and k♯ through their base classes), and ξ
/// stays in registers. For a small system that is most of the explicit methods' overhead over
/// hand-written code (docs/design.md, "Explicit steps"). Built by makeLiePoissonSystem.
template <class G, class H, class K>
class TypedLiePoissonSystem final : public LiePoissonSystem<G> {
  static_assert(std::is_base_of_v<Hamiltonian<G>, H>, "H must derive from Hamiltonian<G>");
  static_assert(std::is_base_of_v<DissipationMetric<G>, K>,
                "K must derive from DissipationMetric<G>");

 public:
  using typename LiePoissonSystem<G>::Dual;

  TypedLiePoissonSystem(std::string name, const std::shared_ptr<const H>& hamiltonian,
                        const std::shared_ptr<const K>& metric,
                        std::shared_ptr<const Lagrangian<G>> lagrangian = nullptr)
      : LiePoissonSystem<G>(std::move(name), hamiltonian, metric, std::move(lagrangian)) {}

 protected:
  // The base holds exactly these objects (it has no assignment), so the casts are exact.
  Dual fieldAt(const Dual& mu) const override {
    return this->vectorFieldOf(static_cast<const H&>(this->hamiltonian()),
                               static_cast<const K&>(this->metric()), mu);
  }
};

/// The system of `hamiltonian` and `metric` (and optionally the Lagrangian they come from),
/// keeping their concrete types (TypedLiePoissonSystem): declare them `final` for the fastest
/// explicit steps.
template <class HP, class KP>
std::shared_ptr<const LiePoissonSystem<typename HP::Group>> makeLiePoissonSystem(
    std::string name, const std::shared_ptr<HP>& hamiltonian, const std::shared_ptr<KP>& metric,
    std::shared_ptr<const Lagrangian<typename HP::Group>> lagrangian = nullptr) {
  using H = std::remove_const_t<HP>;
  using K = std::remove_const_t<KP>;
  return std::make_shared<const TypedLiePoissonSystem<typename H::Group, H, K>>(
      std::move(name), hamiltonian, metric, std::move(lagrangian));
}

}  // namespace ddb
