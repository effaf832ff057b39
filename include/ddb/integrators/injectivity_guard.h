// The injectivity limit of the exponential retraction (docs/reliability.md §2). On SO(3)
// exp is injective on |x| < π, and dexp⁻¹_x has its poles at |x| = 2π (docs/conventions.md
// §1): a DDB step with |hξ| ≥ π has Legendre solutions on other branches, and the solver
// converges to one of them without a word (REVIEW §4: `--scenario B --h 5` climbs to the
// maximum-energy state). On SE(3) the limit applies to the rotation part ω of x = (ω, v),
// the only part with non-zero ad-eigenvalues (±i|ω|). Cayley has no such limit (cay maps
// so(3) one-to-one onto SO(3) minus the half-turns), and the matrix groups SO(N), SU(N)
// have Cayley methods only (method_registry.h), so the guard does nothing for them.
#pragma once

#include <ddb/core/errors.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/groups/exponential.h>
#include <ddb/groups/se3.h>
#include <ddb/groups/so3.h>

#include <cmath>
#include <type_traits>

namespace ddb {

template <class R>
class InjectivityGuard {
 public:
  using G = typename R::Group;
  using Algebra = typename G::template Algebra<double>;
  using Dual = typename G::template Dual<double>;

  static constexpr bool kApplies =
      std::is_base_of_v<Exponential<G>, R> && (std::is_same_v<G, SO3> || std::is_same_v<G, SE3>);
  static constexpr double kLimit = M_PI;

  /// Before the solve: h|ξ(M)| ≥ π with ξ(M) = ∂H/∂μ(M) at the momentum `near` the
  /// solution would start the solver towards a far branch; refuse it.
  static void beforeSolve(const LiePoissonSystem<G>& system, const Dual& near, double t, double h) {
    if constexpr (kApplies) {
      const double speed = rotationNorm(system.velocity(near));
      if (h * speed >= kLimit) refuse(h * speed, speed, t, h);
    }
  }

  /// After the solve: a solution ξ with |hξ| ≥ π lies on another branch; refuse it.
  static void afterSolve(const LiePoissonSystem<G>& system, const Dual& near, const Algebra& xi,
                         double t, double h) {
    if constexpr (kApplies) {
      const double norm = h * rotationNorm(xi);
      if (norm >= kLimit) refuse(norm, rotationNorm(system.velocity(near)), t, h);
    }
  }

 private:
  static double rotationNorm(const Algebra& x) {
    if constexpr (std::is_same_v<G, SE3>) {
      return x.template head<3>().norm();
    } else {
      return x.norm();
    }
  }

  // The largest admissible h at this state: π/|ξ(M_k)|.
  [[noreturn]] static void refuse(double norm, double speed, double t, double h) {
    throw InjectivityLimit(std::string("DDB with the ") + R::kName + " retraction", norm, kLimit,
                           kLimit / speed, -1, t, h);
  }
};

}  // namespace ddb
