// The integrators by their contract names (DESIGN.md §5), for any fixed-size group.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "groups/cayley.h"
#include "groups/exponential.h"
#include "integrators/ddb.h"
#include "integrators/reference.h"
#include "integrators/runge_kutta.h"

namespace ddb {

/// Names makeMethod() knows, in the order of the paper's comparison.
inline const std::vector<std::string>& methodNames() {
  static const std::vector<std::string> names{"ddb-cay", "ddb-exp",   "ddb-exp-exact",
                                              "rk4",     "lobatto3c", "reference"};
  return names;
}

/// `ddb-exp` truncates dexp^{-1} after ad^2, as in the paper's runs; `ddb-exp-exact`
/// uses the closed form. The DDB methods use the Lagrangian form when the system has
/// a Lagrangian and the Hamiltonian form otherwise.
template <class G>
std::unique_ptr<OneStepMethod<G>> makeMethod(const std::string& name,
                                             std::shared_ptr<const LiePoissonSystem<G>> system) {
  const LegendreForm form =
      system->lagrangian() ? LegendreForm::kLagrangian : LegendreForm::kHamiltonian;
  if (name == "ddb-cay") return std::make_unique<Ddb<Cayley<G>>>(system, Cayley<G>(), form);
  if (name == "ddb-exp")
    return std::make_unique<Ddb<TruncatedExponential<G>>>(system, TruncatedExponential<G>(2), form);
  if (name == "ddb-exp-exact")
    return std::make_unique<Ddb<Exponential<G>>>(system, Exponential<G>(), form);
  if (name == "rk4") return std::make_unique<ExplicitRungeKutta<G, 4>>(system, kClassicalRk4);
  if (name == "lobatto3c") return std::make_unique<ImplicitRungeKutta<G, 3>>(system, kLobattoIIIC3);
  if (name == "reference") return std::make_unique<ReferenceSolver<G>>(system);
  throwInvalid("method", name, "unknown method");
}

}  // namespace ddb
