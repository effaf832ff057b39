// The injectivity limit of the exponential retraction (docs/reference/guarantees.md §2). exp is
// injective while the spectral radius of ad_x (the group's adRadius: |x| on SO(3), |ω| on
// SE(3)) is below π, and dexp⁻¹_x has its poles at 2π (docs/reference/conventions.md §1): a DDB
// step with adRadius(hξ) ≥ π has Legendre solutions on other branches, and the solver converges
// to one of them without a word (`--scenario B --h 5` climbed to the maximum-energy state).
// Cayley has no such limit (cay maps so(3) one-to-one onto SO(3) minus the half-turns). On
// the matrix groups the matrix-free solver checks the same limit on ξ's eigenbasis
// (matrix_legendre.h), which it has at hand.
#pragma once

#include <ddb/core/errors.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/groups/exponential.h>

#include <cmath>
#include <type_traits>
#include <utility>

namespace ddb {

/// Whether group G states the spectral radius of its ad_x (`static double adRadius(x)`).
template <class G, class = void>
struct HasAdRadius : std::false_type {};
template <class G>
struct HasAdRadius<G, std::void_t<decltype(G::adRadius(
                          std::declval<const typename G::template Algebra<double>&>()))>>
    : std::true_type {};

template <class R>
class InjectivityGuard {
 public:
  using G = typename R::Group;
  using Algebra = typename G::template Algebra<double>;
  using Dual = typename G::template Dual<double>;

  static constexpr bool kApplies = std::is_base_of_v<Exponential<G>, R> && HasAdRadius<G>::value;
  static constexpr double kLimit = M_PI;

  /// Before the solve: h|ξ(M)| ≥ π with ξ(M) = ∂H/∂μ(M) at the momentum `near` the
  /// solution would start the solver towards a far branch; refuse it.
  static void beforeSolve(const LiePoissonSystem<G>& system, const Dual& near, double t, double h) {
    if constexpr (kApplies) {
      const double speed = G::adRadius(system.velocity(near));
      if (h * speed >= kLimit) refuse(h * speed, speed, t, h);
    }
  }

  /// After the solve: a solution ξ with |hξ| ≥ π lies on another branch; refuse it.
  static void afterSolve(const LiePoissonSystem<G>& system, const Dual& near, const Algebra& xi,
                         double t, double h) {
    if constexpr (kApplies) {
      const double norm = h * G::adRadius(xi);
      if (norm >= kLimit) refuse(norm, G::adRadius(system.velocity(near)), t, h);
    }
  }

 private:
  // The largest admissible h at this state: π/|ξ(M_k)|.
  [[noreturn]] static void refuse(double norm, double speed, double t, double h) {
    throw InjectivityLimit(std::string("DDB with the ") + R::kName + " retraction", norm, kLimit,
                           kLimit / speed, -1, t, h);
  }
};

}  // namespace ddb
