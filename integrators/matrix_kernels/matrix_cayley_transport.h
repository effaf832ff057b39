// The update of a DDB Cayley step on a matrix group, in place (docs/reference/conventions.md §2):
//   M_{k+1} = Ad*_U M_k = Uᴴ M_k U,  U = cay(hξ) cay(hφ),  cay(2x) = (I − x)⁻¹(I + x),
// with a = hξ/2 from the Legendre solution p and b = hφ/2 = k♯(ad*_{hξ/2} p) = k♯([p, a]).
// M_{k+1} is formed by conjugating M_k, not read out as (I − a) p (I + a): the read-out is
// isospectral to p, whose solver residual would enter the spectrum at every step and add
// up; the conjugation keeps the spectrum of M_k to rounding whatever the tolerance.
//
// The first factor: with p̃ = (I + a)⁻¹ M (I − a)⁻¹, the solution of the frozen-a equation
// (I + a) p̃ (I − a) = M, Ad*_{cay(2a)} M = (I − a) p̃ (I + a) = M − 2[a, p̃]: one product
// when the solver certified p̃ to rounding (MatrixLegendreSolver::frozenSolution), else the
// same identity with p̃ formed, by an LU factorisation, two solves and one product
// (matrix_conjugation.h). The
// second, with dissipation: [p, a] = (ap)ᴴ − ap from the solver's a p, b = k♯([p, a]), and
// the identity with b, M − 2[b, q]. The workspaces are allocated when the size first
// appears, then reused. Written against the matrix backend (core/matrix_backend.h) and the
// system's type: the distributed step uses it unchanged (docs/design/distributed.md).
#pragma once

#include <ddb/core/errors.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/core/matrix_backend.h>
#include <ddb/groups/cayley.h>
#include <ddb/integrators/matrix_kernels/matrix_conjugation.h>

#include <Eigen/Core>
#include <cmath>

namespace ddb {

template <class G, class System = LiePoissonSystem<G>>
class MatrixCayleyTransport {
 public:
  using Dual = typename System::Dual;
  using B = MatrixBackend<Dual>;

  /// mu ← Uᴴ mu U with U = cay(2a) cay(2 k♯([p, a])), from the solver's a, its product a p
  /// and, when certified, its frozen solution p̃ (MatrixLegendreSolver).
  template <class Solver>
  void apply(const System& system, const Solver& solver, double, Dual& mu) {
    const Dual& a = solver.halfStep();
    const Dual* frozen = solver.frozenSolution();
    allocate(a);
    system.halfStepDissipationInto(solver.halfStepTimesSolution(), commutator_, half_);  // hφ/2
    if (frozen != nullptr) {
      conjugation_.applyWithSolution(a, *frozen, mu);
    } else {
      B::scale(2.0, a, product_);  // hξ
      conjugation_.prepare(product_);
      conjugation_.apply(mu);
    }
    if (!B::isZero(half_)) {
      B::scale(2.0, half_, commutator_);  // hφ
      conjugation_.prepare(commutator_);
      conjugation_.apply(mu);
    }
  }

 private:
  void allocate(const Dual& like) {
    if (B::sameShape(product_, like)) return;
    for (Dual* m : {&product_, &commutator_, &half_}) B::zeroLike(*m, like);
  }

  Dual product_, commutator_, half_;
  MatrixCayleyConjugation<G, Dual> conjugation_;
};

}  // namespace ddb
