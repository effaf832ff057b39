// The update of a DDB step with the exponential retraction on a matrix group, in place
// (docs/reference/conventions.md §1, "Matrix algebras"):
//   M_{k+1} = Ad*_{exp(hξ) exp(hφ)} M_k = Ad*_{exp(hφ)} Ad*_{exp(hξ)} M_k,  φ = k♯([p, ξ]),
// each factor applied as an increment of M in its argument's eigenbasis
// (matrix_conjugation.h): the first in ξ's, which the Legendre solver leaves, the second,
// with dissipation, in hφ's. The workspaces are allocated when the size first appears, then
// reused. Written against the matrix backend (core/matrix_backend.h) and the system's type,
// as the Cayley transport (matrix_cayley_transport.h).
#pragma once

#include <ddb/core/lie_poisson_system.h>
#include <ddb/core/matrix_backend.h>
#include <ddb/integrators/matrix_kernels/matrix_conjugation.h>

namespace ddb {

template <class R, class System = LiePoissonSystem<typename R::Group>>
class MatrixExponentialTransport {
 public:
  using G = typename R::Group;
  using Dual = typename System::Dual;
  using B = MatrixBackend<Dual>;

  /// mu ← Ad*_{exp(hξ) exp(hφ)} mu from the solver's p, ξ and ξ's eigenbasis.
  template <class Solver>
  void apply(const System& system, Solver& solver, double h, Dual& mu) {
    conjugation_.applyWith(solver.eigenbasis(), h, mu);
    allocate(mu);
    system.dissipationInto(solver.solution(), solver.velocity(), h, product_, commutator_, phi_);
    if (B::isZero(phi_)) return;
    conjugation_.prepare(phi_);
    conjugation_.apply(mu);
  }

 private:
  void allocate(const Dual& like) {
    if (B::sameShape(phi_, like)) return;
    for (Dual* m : {&product_, &commutator_, &phi_}) B::zeroLike(*m, like);
  }

  Dual product_, commutator_, phi_;
  MatrixExponentialConjugation<G, Dual> conjugation_;
};

}  // namespace ddb
