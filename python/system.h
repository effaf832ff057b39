// ddb.System: a LiePoissonSystem on one of the groups the module binds (SO(3), SE(2), SE(3),
// SO(N), SU(N), SU(N) ⋉ su(N)*), with N for the matrix groups; what integrate() and the diagnostics
// take.
#pragma once

#include <ddb/core/lie_poisson_system.h>
#include <ddb/groups/dual_number_sun.h>
#include <ddb/groups/se2.h>
#include <ddb/groups/se3.h>
#include <ddb/groups/so3.h>
#include <ddb/groups/son.h>
#include <ddb/groups/sun.h>
#include <ddb/integrators/methods/one_step_method.h>

#include <memory>
#include <string>
#include <utility>
#include <variant>

namespace ddb::python {

template <class G>
using SystemPointer = std::shared_ptr<const LiePoissonSystem<G>>;

using AnySystem =
    std::variant<SystemPointer<SO3>, SystemPointer<SE2>, SystemPointer<SE3>, SystemPointer<SON>,
                 SystemPointer<SUN>, SystemPointer<DualNumberSUN>>;

/// G of a SystemPointer<G> (as a generic lambda given to System::visit sees it).
template <class P>
using GroupOf = typename std::decay_t<decltype(*std::declval<P>())>::Group;

class System {
 public:
  /// `n`: N of a matrix group (unused on SO(3), SE(2), SE(3)).
  template <class G>
  explicit System(SystemPointer<G> system, Eigen::Index n = 0)
      : system_(std::move(system)), n_(n) {}
  virtual ~System() = default;

  const AnySystem& system() const { return system_; }
  /// f(system) with the system's typed pointer, SystemPointer<G> for its group G.
  template <class F>
  decltype(auto) visit(F&& f) const {
    return std::visit(std::forward<F>(f), system_);
  }
  Eigen::Index n() const { return n_; }
  /// The method as integrate() steps this system: Strang-split with the system's exact flows
  /// (ddb.zeitlin's viscosity, drag and forcing); the method itself for the others.
  virtual std::unique_ptr<OneStepMethod<SUN>> withExactFlows(
      std::unique_ptr<OneStepMethod<SUN>> method) const {
    return method;
  }
  std::string name() const {
    return visit([](const auto& s) { return s->name(); });
  }
  std::string group() const {
    return visit([](const auto& s) { return std::string(GroupOf<decltype(s)>::kName); });
  }

 private:
  AnySystem system_;
  Eigen::Index n_;
};

}  // namespace ddb::python
