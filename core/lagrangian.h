// Lagrangian and Hamiltonian interfaces (paper, Section 2): a reduced Lagrangian
// l: g → R with ∂l/∂ξ ∈ g*, and a Hamiltonian H: g* → R with ∂H/∂μ ∈ g.
#pragma once

#include <ddb/core/smooth_function.h>

namespace ddb {

template <class G>
class Lagrangian : public SmoothFunctionFor<typename G::template Algebra<double>,
                                            typename G::template Dual<double>> {
 public:
  using Group = G;
};

template <class G>
class Hamiltonian : public SmoothFunctionFor<typename G::template Dual<double>,
                                             typename G::template Algebra<double>> {
 public:
  using Group = G;
  /// Whether the gradient ξ = ∂H/∂μ solves an equation of its own (LegendreHamiltonian)
  /// instead of evaluating a formula: the small Legendre solver then runs no fixed-point
  /// sweeps, each of which would be such a solve (integrators/solvers/legendre.h,
  /// docs/design/architecture.md).
  virtual bool gradientIsASolve() const { return false; }
};

}  // namespace ddb
