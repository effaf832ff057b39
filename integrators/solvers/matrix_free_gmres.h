// Restarted GMRES for a real-linear operator on N×N (real or complex) matrices, given only
// as a function v ↦ A v (docs/reference/conventions.md §4: no operator on the N²-dimensional space
// is ever formed). The inner product is the real one, Re tr(XᴴY), so operators that are
// only real-linear (as on u(N)) are handled. The Krylov basis and the small Hessenberg
// system are allocated by resize() once; solve() does not allocate. Written against the
// matrix backend (core/matrix_backend.h): dense or distributed matrices alike.
#pragma once

#include <ddb/core/matrix_backend.h>

#include <Eigen/Core>
#include <cmath>
#include <vector>

namespace ddb {

template <class X>
class MatrixFreeGmres {
  using B = MatrixBackend<X>;

 public:
  struct Result {
    int iterations = 0;     // operator applications
    double residual = 0.0;  // ‖b − A x‖ (the GMRES estimate)
  };

  explicit MatrixFreeGmres(int restart = 30) : restart_(restart) {}

  /// Allocates the workspace for matrices shaped like `like` (a no-op when kept).
  void resize(const X& like) {
    if (!basis_.empty() && B::sameShape(basis_[0], like)) return;
    basis_.resize(static_cast<std::size_t>(restart_ + 1));
    for (X& v : basis_) B::zeroLike(v, like);
    hessenberg_ = Eigen::MatrixXd::Zero(restart_ + 1, restart_);
    g_ = Eigen::VectorXd::Zero(restart_ + 1);
    y_ = Eigen::VectorXd::Zero(restart_);
    cosines_ = Eigen::VectorXd::Zero(restart_);
    sines_ = Eigen::VectorXd::Zero(restart_);
  }

  /// Solves A x = b from the initial x (in place) until ‖b − A x‖ <= tolerance or
  /// max_iterations operator applications. apply(v, out) must write A v into out.
  template <class Apply>
  Result solve(const Apply& apply, const X& b, X& x, double tolerance, int max_iterations) {
    resize(b);
    Result result;
    while (true) {
      X& r = basis_[0];
      apply(x, r);
      ++result.iterations;
      B::sum(1.0, b, -1.0, r, r);
      const double beta = B::frobeniusNorm(r);
      result.residual = beta;
      if (beta <= tolerance || beta == 0.0 || result.iterations >= max_iterations) return result;
      B::divide(r, beta);
      g_.setZero();
      g_(0) = beta;
      int k = 0;
      for (; k < restart_ && result.iterations < max_iterations; ++k) {
        X& w = basis_[static_cast<std::size_t>(k + 1)];
        apply(basis_[static_cast<std::size_t>(k)], w);
        ++result.iterations;
        for (int i = 0; i <= k; ++i) {  // modified Gram–Schmidt in Re tr(XᴴY)
          const X& v = basis_[static_cast<std::size_t>(i)];
          const double hik = B::innerProduct(v, w);
          hessenberg_(i, k) = hik;
          B::axpy(-hik, v, w);
        }
        const double norm = B::frobeniusNorm(w);
        hessenberg_(k + 1, k) = norm;
        if (norm > 0.0) B::divide(w, norm);
        for (int i = 0; i < k; ++i) rotate(i, hessenberg_(i, k), hessenberg_(i + 1, k));
        const double a = hessenberg_(k, k), c = hessenberg_(k + 1, k);
        const double rho = std::hypot(a, c);
        cosines_(k) = rho > 0.0 ? a / rho : 1.0;
        sines_(k) = rho > 0.0 ? c / rho : 0.0;
        hessenberg_(k, k) = rho;
        hessenberg_(k + 1, k) = 0.0;
        g_(k + 1) = -sines_(k) * g_(k);
        g_(k) = cosines_(k) * g_(k);
        result.residual = std::abs(g_(k + 1));
        if (result.residual <= tolerance || norm == 0.0) {
          ++k;
          break;
        }
      }
      // x += V_k y, with H_k y = g_k (upper triangular after the rotations).
      for (int i = k - 1; i >= 0; --i) {
        double s = g_(i);
        for (int j = i + 1; j < k; ++j) s -= hessenberg_(i, j) * y_(j);
        y_(i) = s / hessenberg_(i, i);
      }
      for (int i = 0; i < k; ++i) B::axpy(y_(i), basis_[static_cast<std::size_t>(i)], x);
      if (result.residual <= tolerance || result.iterations >= max_iterations) return result;
    }
  }

 private:
  void rotate(int i, double& a, double& b) const {
    const double t = cosines_(i) * a + sines_(i) * b;
    b = -sines_(i) * a + cosines_(i) * b;
    a = t;
  }

  int restart_;
  std::vector<X> basis_;
  Eigen::MatrixXd hessenberg_;
  Eigen::VectorXd g_, y_, cosines_, sines_;
};

}  // namespace ddb
