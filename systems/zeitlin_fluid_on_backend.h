// Zeitlin's fluid (systems/zeitlin_fluid.h) on any matrix backend (docs/matrix-backend.md),
// given that backend's Poisson solve: the system the matrix-free DDB Cayley step
// (MatrixLegendreSolver, MatrixCayleyTransport, advanceMatrixDdb) is instantiated with off
// the dense matrices: on MPI ranks (distributed/distributed_zeitlin_fluid.h) and on the
// test backend without element access (tests/test_opaque_backend.cc). It evaluates the
// dense system's formulas through the backend: ξ = P ∂H/∂μ(Pμ) (matrixVelocityInto) with
// ∂H/∂W = −Δ⁻¹W/ħ (zeitlinVelocityInto), and hφ/2 = k♯([p, a]) with k♯ = α·Id, the fluid's
// metric (ScaledIdentityMetric).
#pragma once

#include <ddb/core/errors.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/core/matrix_backend.h>
#include <ddb/groups/sun.h>
#include <ddb/systems/zeitlin_fluid.h>

#include <utility>

namespace ddb {

/// The fluid on matrices X, with `Poisson::solve(const X& W, X& out)` solving Δ out = W.
/// Every function is collective where the backend's are.
template <class X, class Poisson>
class ZeitlinFluidOnBackend {
 public:
  using Dual = X;
  using Algebra = X;
  using B = MatrixBackend<X>;

  ZeitlinFluidOnBackend(Poisson poisson, Eigen::Index n, double alpha)
      : hamiltonian_(std::move(poisson), n), alpha_(requireFinite("alpha", alpha)) {}

  double hbar() const { return hamiltonian_.hbar; }
  double alpha() const { return alpha_; }

  /// ξ = P ∂H/∂μ(P p) into xi, P p into `argument`.
  void velocityInto(const Dual& p, Dual& argument, Algebra& xi) const {
    matrixVelocityInto<SUN>(hamiltonian_, p, argument, xi);
  }
  /// P D²H(P p)[P v] given `argument` = P p.
  void velocityDerivativeInto(const Dual& argument, const Dual& v, Dual& direction,
                              Algebra& out) const {
    matrixVelocityDerivativeInto<SUN>(hamiltonian_, argument, v, direction, out);
  }
  /// out = hφ/2 = k♯([p, a]) from the product ap = a p; no product.
  void halfStepDissipationInto(const Dual& ap, Dual& commutator, Algebra& out) const {
    SUN::commutatorFromProduct(ap, commutator);
    B::scale(alpha_, commutator, out);
  }

  /// The stream matrix P = Δ⁻¹W of a skew-Hermitian W.
  void streamMatrixInto(const Dual& W, Dual& P) const { hamiltonian_.poisson.solve(W, P); }
  /// E = Re tr(WP)/(2N) = −Re⟨P, W⟩/(2N) (P skew-Hermitian), given P.
  static double energy(const Dual& W, const Dual& P) {
    return -B::innerProduct(P, W) / (2.0 * double(B::rows(W)));
  }
  /// dH/dt = −α‖[P, W]‖_F²/ħ² of the flow at W, H = N·E/ħ (SteadyStateProbe::energyRate:
  /// −k(ad*_ξ W, ad*_ξ W) with ad*_ξ W = −[W, P]/ħ and k♯ = α·Id), given ‖[P, W]‖_F.
  double energyRate(double commutator_norm) const {
    const double rate = commutator_norm / hbar();
    return -alpha_ * rate * rate;
  }
  /// ‖[P, W]‖_F = ‖[W, P]‖_F, [W, P] = (PW)ᴴ − PW (both skew-Hermitian): one product;
  /// `product` and `commutator` are workspaces of W's shape.
  static double commutatorNorm(const Dual& W, const Dual& P, Dual& product, Dual& commutator) {
    B::multiply(P, W, product);
    SUN::commutatorFromProduct(product, commutator);
    return B::frobeniusNorm(commutator);
  }

 private:
  // ∂H/∂W = −Δ⁻¹W/ħ (the Poisson solver keeps workspaces).
  struct Hamiltonian {
    Hamiltonian(Poisson solver, Eigen::Index n)
        : poisson(std::move(solver)), hbar(zeitlinHbar(n)) {}
    void gradientInto(const Dual& W, Dual& out) const {
      zeitlinVelocityInto(poisson, hbar, W, out);
    }
    void hessianTimesInto(const Dual&, const Dual& V, Dual& out) const {
      zeitlinVelocityInto(poisson, hbar, V, out);
    }
    mutable Poisson poisson;
    double hbar;
  };

  Hamiltonian hamiltonian_;
  double alpha_;
};

}  // namespace ddb
