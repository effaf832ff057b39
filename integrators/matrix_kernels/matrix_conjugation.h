// The conjugations μ ← Ad*_{τ(x)} μ = τ(x)ᴴ μ τ(x) on a matrix group (SO(N), SU(N)),
// in place and as an increment of μ (docs/reference/conventions.md §1, "Matrix algebras"):
// prepare(x) once, then apply(μ) to any number of momenta. Conjugating by a formed τ(x)
// puts the same rounding of τ(x) into every step of a steady flow and the spectrum drifts
// linearly; the increment's rounding is relative to the change, which vanishes at a steady
// state (docs/results/casimir-drift.md, "Matrix groups").
//   Cayley, τ(x) = cay(2b), b = x/2: with q = (I + b)⁻¹ μ (I − b)⁻¹,
//     Ad*_{cay(2b)} μ = (I − b) q (I + b) = μ − 2[b, q]      (an LU, two solves, a product);
//   exp: Ad*_{exp x} multiplies entry (a, b) of x's eigenbasis by e^{−iδ}, δ = θ_a − θ_b:
//     μ + V [(e^{−iδ} − 1) ∘ Vᴴ μ V] Vᴴ                      (a decomposition, four products).
// Workspaces are allocated when a size first appears, then reused. Both are written against
// the matrix backend (core/matrix_backend.h): Dual may be a distributed matrix. Which one a
// retraction uses is MatrixRetraction<R>::Conjugation (matrix_retraction.h).
#pragma once

#include <ddb/core/errors.h>
#include <ddb/core/matrix_backend.h>
#include <ddb/core/skew_hermitian_eigenbasis.h>

#include <cmath>

namespace ddb {

/// The Cayley map.
template <class G, class Dual = typename G::template Dual<double>>
class MatrixCayleyConjugation {
  using B = MatrixBackend<Dual>;

 public:
  /// For τ(x) = cay(x): b = x/2 and the LU factors of I + b.
  void prepare(const Dual& x) {
    allocate(x);
    B::scale(0.5, x, half_);
    B::copy(half_, resolvent_);
    B::addToDiagonal(resolvent_, 1.0);
    if (!lu_.factor(resolvent_)) {
      throw NonFiniteState("Cayley conjugation", -1, NAN, NAN, B::describe(x),
                           "Cayley argument (I + x/2 singular)");
    }
  }

  /// μ ← μ − 2[b, q], q = (I + b)⁻¹ μ (I − b)⁻¹. As b and μ are skew-Hermitian,
  /// μ (I − b)⁻¹ = −((I + b)⁻¹ μ)ᴴ, so q = (I + b)⁻¹ (−((I + b)⁻¹ μ)ᴴ): two solves with the
  /// factors of I + b, cheaper than forming the inverse and multiplying by it twice
  /// (docs/design/architecture.md, "The Cayley conjugation by solves").
  void apply(Dual& mu) {
    B::copy(mu, product_);
    lu_.solve(resolvent_, product_);  // (I + b)⁻¹ μ
    B::setZero(q_);
    B::addAdjoint(-1.0, product_, q_);
    lu_.solve(resolvent_, q_);
    applyWithSolution(half_, q_, mu);
  }

  /// μ ← Ad*_{cay(2b)} μ = μ − 2[b, q] given q with (I + b) q (I − b) = μ (a Legendre
  /// solver's certified frozen solution): one product, [b, q] = bq − (bq)ᴴ as q is
  /// skew-Hermitian. No prepare() needed.
  void applyWithSolution(const Dual& b, const Dual& q, Dual& mu) {
    if (!B::sameShape(product_, b)) B::zeroLike(product_, b);
    if (!B::sameShape(commutator_, b)) B::zeroLike(commutator_, b);
    B::multiply(b, q, product_);
    // The commutator first, then one sum into μ: bq itself does not vanish at a steady state,
    // and μ − 2bq + 2(bq)ᴴ in two passes rounds μ − 2bq to full size, with the same rounding
    // at every step of a steady flow (a linear drift of the spectrum,
    // docs/results/casimir-drift.md).
    G::commutatorFromProduct(product_, commutator_);  // (bq)ᴴ − bq = −[b, q]
    B::axpy(2.0, commutator_, mu);
  }

 private:
  void allocate(const Dual& like) {
    if (B::sameShape(half_, like)) return;
    for (Dual* m : {&half_, &resolvent_, &product_, &commutator_, &q_}) B::zeroLike(*m, like);
  }

  Dual half_, resolvent_, product_, commutator_, q_;
  typename B::Lu lu_;
};

/// The exponential (closed form or truncated dexp⁻¹ alike: τ is exp), in the backend's
/// eigenbasis (MatrixBackend<Dual>::Eigenbasis).
template <class G, class Dual = typename G::template Dual<double>>
class MatrixExponentialConjugation {
  using B = MatrixBackend<Dual>;

 public:
  using Eigenbasis = typename B::Eigenbasis;

  /// x's eigenbasis.
  void prepare(const Dual& x) {
    if (!basis_.compute(x)) {
      throw NonFiniteState("exponential conjugation", -1, NAN, NAN, B::describe(x), "argument");
    }
  }
  void apply(Dual& mu) { applyWith(basis_, 1.0, mu); }

  /// μ ← Ad*_{exp(scale·y)} μ, given the eigenbasis of y.
  void applyWith(Eigenbasis& basis, double scale, Dual& mu) {
    if (!B::sameShape(increment_, mu)) B::zeroLike(increment_, mu);
    basis.apply(PhaseFunction::kCoadjointIncrement, scale, mu, increment_);
    B::axpy(1.0, increment_, mu);
  }

 private:
  Eigenbasis basis_;
  Dual increment_;
};

}  // namespace ddb
