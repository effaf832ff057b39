// The Cayley retraction cay(x) = (I - X/2)^{-1}(I + X/2) on any group with a
// matrix representation (paper, Section 4.1 b), eqs. "dcay", "dcayinv").
#pragma once

#include <Eigen/LU>

#include "core/retraction.h"

namespace ddb {

template <class G>
class Cayley : public Retraction<Cayley<G>, G> {
 public:
  static constexpr const char* kName = "cay";

  template <class T>
  using Algebra = typename G::template Algebra<T>;
  template <class T>
  using Dual = typename G::template Dual<T>;
  template <class T>
  using Matrix = typename G::template Matrix<T>;

  template <class T>
  Matrix<T> tau(const Algebra<T>& x) const {
    const Matrix<T> half = G::hat(x) * T(0.5);
    const Matrix<T> I = identityLike(half);
    return (I - half).partialPivLu().solve(I + half);
  }

  /// cay^{-1}(g) = 2 (g - I)(g + I)^{-1} (g and its Cayley generator commute).
  template <class T>
  Algebra<T> tauInverse(const Matrix<T>& g) const {
    const Matrix<T> I = identityLike(g);
    const Matrix<T> X = (g + I).transpose().partialPivLu().solve((g - I).transpose()).transpose();
    return G::vee(Matrix<T>(X * T(2)));
  }

  /// dcay_x y = (I - X/2)^{-1} Y (I + X/2)^{-1}.
  template <class T>
  Algebra<T> dTau(const Algebra<T>& x, const Algebra<T>& y) const {
    const Matrix<T> half = G::hat(x) * T(0.5);
    const Matrix<T> I = identityLike(half);
    const Matrix<T> left = (I - half).partialPivLu().solve(G::hat(y));
    const Matrix<T> both = (I + half).transpose().partialPivLu().solve(left.transpose());
    return G::vee(Matrix<T>(both.transpose()));
  }

  /// dcay^{-1}_x y = (I - X/2) Y (I + X/2).
  template <class T>
  Algebra<T> dTauInverse(const Algebra<T>& x, const Algebra<T>& y) const {
    const Matrix<T> half = G::hat(x) * T(0.5);
    const Matrix<T> I = identityLike(half);
    return G::vee(Matrix<T>((I - half) * G::hat(y) * (I + half)));
  }

  /// (dcay^{-1}_x)* mu = dualVee((I - X/2)^H M (I + X/2)^H), M = dualHat(mu);
  /// on so(3) this is I + x̂/2 + x xᵀ/4 (paper, Section 4.1).
  template <class T>
  Dual<T> dTauInverseDual(const Algebra<T>& x, const Dual<T>& mu) const {
    const Matrix<T> half = G::hat(x) * T(0.5);
    const Matrix<T> I = identityLike(half);
    return G::dualVee(Matrix<T>((I - half).adjoint() * G::dualHat(mu) * (I + half).adjoint()));
  }

 private:
  template <class M>
  static M identityLike(const M& m) {
    return M::Identity(m.rows(), m.cols());
  }
};

}  // namespace ddb
