// The update of a DDB Cayley step on a matrix group, in place (docs/conventions.md §2):
//   M_{k+1} = Ad*_U M_k = Uᴴ M_k U,  U = cay(hξ) cay(hφ),  cay(2x) = (I − x)⁻¹(I + x),
// with a = hξ/2 from the Legendre solution p and hφ/2 = k♯(ad*_{hξ/2} p) = k♯([p, a]).
// M_{k+1} is formed by conjugating M_k, not read out as (I − a) p (I + a): the read-out is
// isospectral to p, whose solver residual would enter the spectrum at every step and add
// up; the conjugation keeps the spectrum of M_k to round-off whatever the tolerance.
// Cost: one LU solve for cay(hξ), with dissipation one product for [p, a], one LU solve
// for cay(hφ) and one product for U, then two products for Uᴴ M U. The workspaces and
// the LU are allocated when the size first appears, then reused.
#pragma once

#include <ddb/core/dissipation_metric.h>

#include <Eigen/Core>
#include <Eigen/LU>

namespace ddb {

template <class G>
class MatrixCayleyTransport {
 public:
  using Dual = typename G::template Dual<double>;

  /// mu ← Uᴴ mu U with U = cay(2a) cay(2 k♯([p, a])).
  void apply(const DissipationMetric<G>& metric, const Dual& p, const Dual& a, Dual& mu) {
    allocate(p);
    cayleyOfTwice(a, rotation_);  // cay(hξ)
    product_.noalias() = p * a;
    commutator_ = product_ - product_.adjoint();  // [p, a] = pa − ap, ap = (pa)ᴴ
    metric.sharpInto(commutator_, half_);         // hφ/2
    const Dual* U = &rotation_;
    if (!half_.isZero(0.0)) {
      cayleyOfTwice(half_, kick_);  // cay(hφ)
      total_.noalias() = rotation_ * kick_;
      U = &total_;
    }
    product_.noalias() = mu * (*U);
    mu.noalias() = U->adjoint() * product_;
  }

 private:
  // out = cay(2x) = (I − x)⁻¹(I + x).
  void cayleyOfTwice(const Dual& x, Dual& out) {
    lhs_ = identity_ - x;
    lu_.compute(lhs_);
    rhs_ = identity_ + x;
    out.noalias() = lu_.solve(rhs_);
  }

  void allocate(const Dual& like) {
    if (identity_.rows() == like.rows()) return;
    const auto n = like.rows();
    for (Dual* m : {&rotation_, &kick_, &total_, &product_, &commutator_, &half_, &lhs_, &rhs_}) {
      m->setZero(n, n);
    }
    identity_ = Dual::Identity(n, n);
    lu_ = Eigen::PartialPivLU<Dual>(n);
  }

  Dual rotation_, kick_, total_, product_, commutator_, half_, lhs_, rhs_, identity_;
  Eigen::PartialPivLU<Dual> lu_;
};

}  // namespace ddb
