// The integrators by their contract names (docs/file-formats.md), for every group.
#pragma once

#include <ddb/core/group_traits.h>
#include <ddb/groups/cayley.h>
#include <ddb/groups/exponential.h>
#include <ddb/integrators/composition.h>
#include <ddb/integrators/ddb.h>
#include <ddb/integrators/reference.h>
#include <ddb/integrators/runge_kutta.h>
#include <ddb/integrators/symmetric_ddb.h>

#include <memory>
#include <string>
#include <vector>

namespace ddb {

/// Names makeMethod() knows, in the order of the paper's comparison.
inline const std::vector<std::string>& methodNames() {
  static const std::vector<std::string> names{
      "ddb-cay",  "ddb-exp",   "ddb-exp-exact", "sddb-paper-cay", "sddb-paper-exp",
      "sddb-cay", "sddb-exp",  "ddb4-cay",      "ddb4-exp",       "ddb6-exp",
      "rk4",      "lobatto3c", "reference"};
  return names;
}

/// Whether `name` applies to the system: the paper's symmetric variant evaluates
/// ∂l/∂ξ at the midpoint (ξ_k + ξ_{k+1})/2, so it needs a Lagrangian.
template <class G>
bool methodApplies(const std::string& name, const LiePoissonSystem<G>& system) {
  return name.rfind("sddb-paper-", 0) != 0 || system.lagrangian() != nullptr;
}

/// The methods that run on matrix groups (SO(N), SU(N)): the Cayley DDB family in
/// Hamiltonian form with the matrix-free Legendre solver, RK4 (which leaves the orbit,
/// for comparison) and the adaptive reference (small N only: it is dense).
inline const std::vector<std::string>& matrixGroupMethodNames() {
  static const std::vector<std::string> names{"ddb-cay", "sddb-cay", "ddb4-cay", "rk4",
                                              "reference"};
  return names;
}

/// `ddb-exp` truncates dexp^{-1} after ad^2, as in the paper's runs; `ddb-exp-exact`
/// and every symmetric or composed exp method use the closed form (a truncated series
/// breaks (dτ^{-1}_{-x})* = Ad*_{τ(x)} (dτ^{-1}_x)*, which symmetry needs). The DDB
/// methods use the Lagrangian form when the system has a Lagrangian and the
/// Hamiltonian form otherwise. `ddb4-*` is the triple jump of `sddb-*`, `ddb6-exp`
/// Yoshida's 7-stage composition of `sddb-exp`. Matrix groups: matrixGroupMethodNames().
template <class G>
std::unique_ptr<OneStepMethod<G>> makeMethod(const std::string& name,
                                             std::shared_ptr<const LiePoissonSystem<G>> system) {
  if constexpr (isDynamicGroup<G>) {
    constexpr LegendreForm form = LegendreForm::kHamiltonian;
    if (name == "ddb-cay") return std::make_unique<Ddb<Cayley<G>>>(system, Cayley<G>(), form);
    if (name == "sddb-cay")
      return std::make_unique<SymmetricDdb<Cayley<G>>>(system, Cayley<G>(), form);
    if (name == "ddb4-cay")
      return std::make_unique<Composition<G>>(name, makeMethod<G>("sddb-cay", system),
                                              tripleJump());
    if (name == "rk4") return std::make_unique<ExplicitRungeKutta<G, 4>>(system, kClassicalRk4);
    if (name == "reference") return std::make_unique<ReferenceSolver<G>>(system);
    std::string valid;
    for (const auto& n : matrixGroupMethodNames()) valid += (valid.empty() ? "" : ", ") + n;
    throwInvalid("method", name, "is not one of the methods for matrix groups: " + valid);
  } else {
    const LegendreForm form =
        system->lagrangian() ? LegendreForm::kLagrangian : LegendreForm::kHamiltonian;
    if (name == "ddb-cay") return std::make_unique<Ddb<Cayley<G>>>(system, Cayley<G>(), form);
    if (name == "ddb-exp")
      return std::make_unique<Ddb<TruncatedExponential<G>>>(system, TruncatedExponential<G>(2),
                                                            form);
    if (name == "ddb-exp-exact")
      return std::make_unique<Ddb<Exponential<G>>>(system, Exponential<G>(), form);
    if (name == "sddb-paper-cay" || name == "sddb-paper-exp") {
      if (!methodApplies(name, *system)) {
        throwInvalid("method", name, "needs a Lagrangian, which '" + system->name() + "' has not");
      }
      if (name == "sddb-paper-cay") return std::make_unique<PaperSymmetricDdb<Cayley<G>>>(system);
      return std::make_unique<PaperSymmetricDdb<Exponential<G>>>(system);
    }
    if (name == "sddb-cay")
      return std::make_unique<SymmetricDdb<Cayley<G>>>(system, Cayley<G>(), form);
    if (name == "sddb-exp")
      return std::make_unique<SymmetricDdb<Exponential<G>>>(system, Exponential<G>(), form);
    if (name == "ddb4-cay")
      return std::make_unique<Composition<G>>(name, makeMethod<G>("sddb-cay", system),
                                              tripleJump());
    if (name == "ddb4-exp")
      return std::make_unique<Composition<G>>(name, makeMethod<G>("sddb-exp", system),
                                              tripleJump());
    if (name == "ddb6-exp")
      return std::make_unique<Composition<G>>(name, makeMethod<G>("sddb-exp", system), yoshida6());
    if (name == "rk4") return std::make_unique<ExplicitRungeKutta<G, 4>>(system, kClassicalRk4);
    if (name == "lobatto3c")
      return std::make_unique<ImplicitRungeKutta<G, 3>>(system, kLobattoIIIC3);
    if (name == "reference") return std::make_unique<ReferenceSolver<G>>(system);
    throwInvalid("method", name, "unknown method");
  }
}

}  // namespace ddb
