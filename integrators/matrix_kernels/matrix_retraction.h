// MatrixRetraction<R>: what the matrix groups' steps need of a retraction R, in one place,
// so that the Legendre solver, DDB and the symmetric DDB name no retraction (issue 41):
//   - kSweep, how the solver sweeps the fixed point of the discrete Legendre equation
//     (matrix_legendre.h): in product form, p ← W − [a, p] + a p a with a = hξ/2, whose
//     a p the update reuses, with a certified frozen solution and Newton–Krylov as the
//     fallback (Cayley); in ξ's eigenbasis, which the update reuses (exp with the closed
//     form dexp⁻¹); or by the truncated dexp⁻¹ series (the paper's ddb-exp);
//   - Conjugation, μ ← Ad*_{τ(x)} μ as an increment (matrix_conjugation.h);
//   - Transport, DDB's update M ← Ad*_{τ(hξ) τ(hφ)} M from the solver's results;
//   - applySolvedFlow, Ad*_{τ(hξ)} μ from what the solver left, where it can.
// Each is written against the matrix backend (core/matrix_backend.h), the exponential's
// spectral calculus through the backend's Eigenbasis, so every retraction runs on any
// backend.
// A new retraction of matrix groups is one more specialisation (and a row in the method
// table, method_table.h).
#pragma once

#include <ddb/core/lie_poisson_system.h>
#include <ddb/groups/cayley.h>
#include <ddb/groups/exponential.h>
#include <ddb/integrators/matrix_kernels/matrix_cayley_transport.h>
#include <ddb/integrators/matrix_kernels/matrix_conjugation.h>
#include <ddb/integrators/matrix_kernels/matrix_exponential_transport.h>

namespace ddb {

/// How the matrix-free Legendre solver sweeps its fixed point (see above).
enum class MatrixSweep { kProductForm, kEigenbasis, kSeries };

/// Declared only: a retraction without a specialisation has no matrix-group step.
template <class R>
struct MatrixRetraction;

template <class G>
struct MatrixRetraction<Cayley<G>> {
  static constexpr MatrixSweep kSweep = MatrixSweep::kProductForm;
  template <class Dual>
  using Conjugation = MatrixCayleyConjugation<G, Dual>;
  template <class System>
  using Transport = MatrixCayleyTransport<G, System>;

  /// μ ← Ad*_{cay(hξ)} μ with the solver's certified frozen solution (one product);
  /// false, μ unchanged, when it could not certify one.
  template <class Solver, class Dual>
  static bool applySolvedFlow(const Solver& solver, double, Conjugation<Dual>& flow, Dual& mu) {
    const Dual* frozen = solver.frozenSolution();
    if (frozen == nullptr) return false;
    flow.applyWithSolution(solver.halfStep(), *frozen, mu);
    return true;
  }
};

template <class G>
struct MatrixRetraction<Exponential<G>> {
  static constexpr MatrixSweep kSweep = MatrixSweep::kEigenbasis;
  template <class Dual>
  using Conjugation = MatrixExponentialConjugation<G, Dual>;
  template <class System>
  using Transport = MatrixExponentialTransport<Exponential<G>, System>;

  /// μ ← Ad*_{exp(hξ)} μ in ξ's eigenbasis, which the solve left.
  template <class Solver, class Dual>
  static bool applySolvedFlow(Solver& solver, double h, Conjugation<Dual>& flow, Dual& mu) {
    flow.applyWith(solver.eigenbasis(), h, mu);
    return true;
  }
};

template <class G>
struct MatrixRetraction<TruncatedExponential<G>> {
  static constexpr MatrixSweep kSweep = MatrixSweep::kSeries;
  template <class Dual>
  using Conjugation = MatrixExponentialConjugation<G, Dual>;
  template <class System>
  using Transport = MatrixExponentialTransport<TruncatedExponential<G>, System>;

  /// The series sweep leaves no eigenbasis: the caller forms exp(hξ).
  template <class Solver, class Dual>
  static bool applySolvedFlow(const Solver&, double, Conjugation<Dual>&, Dual&) {
    return false;
  }
};

/// μ ← Ad*_{τ(x)} μ of the retraction R (matrix_conjugation.h).
template <class R, class Dual = typename R::Group::template Dual<double>>
using MatrixConjugation = typename MatrixRetraction<R>::template Conjugation<Dual>;

}  // namespace ddb
