// The update of a DDB Cayley step on a matrix group, in place (docs/conventions.md §2):
//   M_{k+1} = Ad*_U M_k = Uᴴ M_k U,  U = cay(hξ) cay(hφ),  cay(2x) = (I − x)⁻¹(I + x),
// with a = hξ/2 from the Legendre solution p and b = hφ/2 = k♯(ad*_{hξ/2} p) = k♯([p, a]).
// M_{k+1} is formed by conjugating M_k, not read out as (I − a) p (I + a): the read-out is
// isospectral to p, whose solver residual would enter the spectrum at every step and add
// up; the conjugation keeps the spectrum of M_k to rounding whatever the tolerance.
//
// The first factor: with p̃ = (I + a)⁻¹ M (I − a)⁻¹, the solution of the frozen-a equation
// (I + a) p̃ (I − a) = M, Ad*_{cay(2a)} M = (I − a) p̃ (I + a) = M − 2[a, p̃]: one product
// when the solver certified p̃ to rounding (MatrixLegendreSolver::frozenSolution), else
// cay(2a) = 2(I − a)⁻¹ − I by one inverse and Uᴴ M U by two products. The second, with
// dissipation: [p, a] = (ap)ᴴ − ap from the solver's a p, b = k♯([p, a]), and the same
// identity with b, M − 2[b, q], by one inverse and three products (dissipate below). The
// workspaces are allocated when the size first appears, then reused.
#pragma once

#include <ddb/core/detail/dense_inverse.h>
#include <ddb/core/dissipation_metric.h>
#include <ddb/core/errors.h>

#include <Eigen/Core>
#include <cmath>

namespace ddb {

template <class G>
class MatrixCayleyTransport {
 public:
  using Dual = typename G::template Dual<double>;

  /// mu ← Uᴴ mu U with U = cay(2a) cay(2 k♯([p, a])), given a, the product a p and, when
  /// certified, the frozen solution p̃ (else nullptr).
  void apply(const DissipationMetric<G>& metric, const Dual& a, const Dual& ap, const Dual* frozen,
             Dual& mu) {
    allocate(a);
    commutator_ = ap.adjoint() - ap;       // [p, a] = pa − ap, pa = (ap)ᴴ
    metric.sharpInto(commutator_, half_);  // hφ/2
    if (frozen != nullptr) {
      product_.noalias() = a * (*frozen);
      mu -= 2.0 * (product_ - product_.adjoint());  // mu − 2[a, p̃]
    } else {
      cayleyOfTwice(a, rotation_);  // cay(hξ)
      conjugate(rotation_, mu);
    }
    if (!half_.isZero(0.0)) dissipate(half_, mu);
  }

 private:
  // out = cay(2x) = (I − x)⁻¹(I + x) = 2(I − x)⁻¹ − I.
  void cayleyOfTwice(const Dual& x, Dual& out) {
    out = -x;
    out.diagonal().array() += 1.0;
    if (!inverse_.invert(out)) {
      throw NonFiniteState("Cayley transport", -1, NAN, NAN, x, "Cayley argument (I - x singular)");
    }
    out *= 2.0;
    out.diagonal().array() -= 1.0;
  }

  // mu ← C⁻¹ mu C with C = cay(2b), as the increment mu − 2[b, q], q = (I + b)⁻¹ mu (I − b)⁻¹
  // (docs/conventions.md §2). Conjugating by the formed C puts the same rounding of C into
  // every step of a steady flow, and the spectrum drifts linearly; the increment's rounding
  // is relative to the correction, which vanishes there (docs/long-run.md, "Matrix groups").
  // b is skew-Hermitian, so (I − b)⁻¹ = ((I + b)⁻¹)ᴴ, and [b, q] = bq − (bq)ᴴ as q is too.
  void dissipate(const Dual& b, Dual& mu) {
    rotation_ = b;
    rotation_.diagonal().array() += 1.0;
    if (!inverse_.invert(rotation_)) {
      throw NonFiniteState("Cayley transport", -1, NAN, NAN, b, "Cayley argument (I + b singular)");
    }
    product_.noalias() = mu * rotation_.adjoint();  // mu (I − b)⁻¹
    commutator_.noalias() = rotation_ * product_;   // q
    product_.noalias() = b * commutator_;           // b q
    mu -= 2.0 * (product_ - product_.adjoint());    // mu − 2[b, q]
  }

  // mu ← Uᴴ mu U.
  void conjugate(const Dual& U, Dual& mu) {
    product_.noalias() = mu * U;
    mu.noalias() = U.adjoint() * product_;
  }

  void allocate(const Dual& like) {
    if (product_.rows() == like.rows()) return;
    for (Dual* m : {&rotation_, &product_, &commutator_, &half_})
      m->setZero(like.rows(), like.cols());
  }

  Dual rotation_, product_, commutator_, half_;
  DenseInverse<Dual> inverse_;
};

}  // namespace ddb
