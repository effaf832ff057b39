// Zeitlin's fluid (systems/zeitlin_fluid.h) on matrices distributed over MPI ranks: the
// system that MatrixLegendreSolver and MatrixCayleyTransport are instantiated with for the
// distributed DDB Cayley step (docs/distributed.md, "One step formula"). It evaluates the
// same formulas as the dense system through the matrix backend: ξ = P ∂H/∂μ(Pμ)
// (matrixVelocityInto) with ∂H/∂W = −Δ⁻¹W/ħ (zeitlinVelocityInto) solved by
// DistributedPoissonSolver, and hφ/2 = k♯([p, a]) with k♯ = α·Id, the fluid's metric
// (ScaledIdentityMetric).
#pragma once

#include <ddb/core/errors.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/distributed/distributed_backend.h>
#include <ddb/distributed/distributed_poisson_solver.h>
#include <ddb/groups/sun.h>
#include <ddb/systems/zeitlin_fluid.h>

namespace ddb {

class DistributedZeitlinFluid {
 public:
  using Dual = DistributedMatrix;
  using Algebra = DistributedMatrix;
  using B = MatrixBackend<DistributedMatrix>;

  DistributedZeitlinFluid(const BlockCyclicLayout& layout, double alpha)
      : hamiltonian_(layout), alpha_(requireFinite("alpha", alpha)) {}

  double hbar() const { return hamiltonian_.hbar; }
  double alpha() const { return alpha_; }

  /// ξ = P ∂H/∂μ(P p) into xi, P p into `argument`; collective.
  void velocityInto(const Dual& p, Dual& argument, Algebra& xi) const {
    matrixVelocityInto<SUN>(hamiltonian_, p, argument, xi);
  }
  /// P D²H(P p)[P v] given `argument` = P p; collective.
  void velocityDerivativeInto(const Dual& argument, const Dual& v, Dual& direction,
                              Algebra& out) const {
    matrixVelocityDerivativeInto<SUN>(hamiltonian_, argument, v, direction, out);
  }
  /// out = hφ/2 = k♯([p, a]) from the product ap = a p; collective, no product.
  void halfStepDissipationInto(const Dual& ap, Dual& commutator, Algebra& out) const {
    SUN::commutatorFromProduct(ap, commutator);
    B::scale(alpha_, commutator, out);
  }

  /// The stream matrix P = Δ⁻¹W of a skew-Hermitian W; collective.
  void streamMatrixInto(const Dual& W, Dual& P) const { hamiltonian_.poisson.solve(W, P); }
  /// E = Re tr(WP)/(2N) = −Re⟨P, W⟩/(2N) (P skew-Hermitian), given P; collective.
  static double energy(const Dual& W, const Dual& P) {
    return -B::innerProduct(P, W) / (2.0 * W.size());
  }
  /// dH/dt = −α‖[P, W]‖_F²/ħ² of the flow at W, H = N·E/ħ (SteadyStateProbe::energyRate:
  /// −k(ad*_ξ W, ad*_ξ W) with ad*_ξ W = −[W, P]/ħ and k♯ = α·Id), given ‖[P, W]‖_F.
  double energyRate(double commutator_norm) const {
    const double rate = commutator_norm / hbar();
    return -alpha_ * rate * rate;
  }
  /// ‖[P, W]‖_F = ‖[W, P]‖_F, [W, P] = (PW)ᴴ − PW (both skew-Hermitian): one product;
  /// `product` and `commutator` are workspaces of W's layout. Collective.
  static double commutatorNorm(const Dual& W, const Dual& P, Dual& product, Dual& commutator) {
    B::multiply(P, W, product);
    SUN::commutatorFromProduct(product, commutator);
    return B::frobeniusNorm(commutator);
  }

 private:
  // ∂H/∂W = −Δ⁻¹W/ħ on the distributed matrices (the Poisson solver keeps workspaces).
  struct Hamiltonian {
    explicit Hamiltonian(const BlockCyclicLayout& layout)
        : poisson(layout), hbar(zeitlinHbar(layout.size())) {}
    void gradientInto(const Dual& W, Dual& out) const {
      zeitlinVelocityInto(poisson, hbar, W, out);
    }
    void hessianTimesInto(const Dual&, const Dual& V, Dual& out) const {
      zeitlinVelocityInto(poisson, hbar, V, out);
    }
    mutable DistributedPoissonSolver poisson;
    double hbar;
  };

  Hamiltonian hamiltonian_;
  double alpha_;
};

}  // namespace ddb
