// The Hoppe–Yau Laplacian Δ_N on N×N matrices, the quantised Laplace–Beltrami operator
// of Zeitlin's fluid on the sphere (docs/conventions.md §2), indices 0-based:
//   (Δ P)_ij = −((N−1)(i+j+1) − 2ij) P_ij + √(i(N−i) j(N−j)) P_{i−1,j−1}
//              + √((i+1)(N−i−1)(j+1)(N−j−1)) P_{i+1,j+1}.
// Each diagonal m = j − i is an invariant tridiagonal block (the same coefficients for
// −m), with eigenvalues −l(l+1), l = |m|..N−1; the kernel on gl(N) is the identity.
// apply and solve cost O(N²): the solve is one Thomas (LDLᵀ) sweep per diagonal on
// factors computed once here; the blocks are negative definite except m = 0, which is
// solved on the traceless part with one unknown pinned and the mean removed afterwards.
#pragma once

#include <ddb/core/errors.h>

#include <Eigen/Core>
#include <cmath>
#include <string>
#include <vector>

namespace ddb {

class HoppeYauLaplacian {
 public:
  explicit HoppeYauLaplacian(Eigen::Index n) : n_(n), blocks_(static_cast<std::size_t>(n)) {
    if (n < 2) throwInvalid("N", std::to_string(n), "must be >= 2");
    for (Eigen::Index m = 0; m < n; ++m) {
      Block& b = blocks_[static_cast<std::size_t>(m)];
      const Eigen::Index length = n - m;
      b.diagonal.resize(length);
      b.off.resize(length);  // off(k) couples k−1 and k along the diagonal; off(0) unused
      for (Eigen::Index k = 0; k < length; ++k) {
        const double i = double(k), j = double(k + m), N = double(n);
        b.diagonal(k) = -((N - 1) * (i + j + 1) - 2 * i * j);
        b.off(k) = k == 0 ? 0.0 : std::sqrt(i * (N - i) * j * (N - j));
      }
      factor(b, m == 0 ? 1 : 0);
    }
  }

  Eigen::Index size() const { return n_; }

  /// The tridiagonal block of diagonal m (and −m): its diagonal and its sub-diagonal
  /// (entry k couples k and k+1), for eigen-decompositions (spherical harmonics).
  void block(Eigen::Index m, Eigen::VectorXd& diagonal, Eigen::VectorXd& subdiagonal) const {
    const Block& b = block(m);
    diagonal = b.diagonal;
    subdiagonal = b.off.tail(b.off.size() - 1);
  }

  /// out = Δ P (out must not alias P).
  template <class X>
  void apply(const X& P, X& out) const {
    requireSize(P);
    out.resize(n_, n_);
    for (Eigen::Index m = -(n_ - 1); m < n_; ++m) {
      const Block& b = block(m);
      const Eigen::Index length = n_ - std::abs(m);
      for (Eigen::Index k = 0; k < length; ++k) {
        auto value = b.diagonal(k) * at(P, m, k);
        if (k > 0) value += b.off(k) * at(P, m, k - 1);
        if (k + 1 < length) value += b.off(k + 1) * at(P, m, k + 1);
        at(out, m, k) = value;
      }
    }
  }

  /// out = Δ⁻¹ (W − tr(W)/N · I), the traceless solution (Poisson solve, O(N²)).
  /// out may alias W.
  template <class X>
  void solve(const X& W, X& out) const {
    requireSize(W);
    const auto mean = W.trace() / typename X::Scalar(double(n_));
    if (&out != &W) out = W;
    out.diagonal().array() -= mean;
    for (Eigen::Index m = -(n_ - 1); m < n_; ++m) {
      const Block& b = block(m);
      const Eigen::Index length = n_ - std::abs(m);
      const Eigen::Index first = m == 0 ? 1 : 0;  // m = 0: x_0 pinned to 0
      // Forward sweep L y = b, then back substitution D Lᵀ x = y.
      for (Eigen::Index k = first + 1; k < length; ++k) {
        at(out, m, k) -= b.lower(k) * at(out, m, k - 1);
      }
      at(out, m, length - 1) *= b.inverse_pivot(length - 1);
      for (Eigen::Index k = length - 2; k >= first; --k) {
        at(out, m, k) = at(out, m, k) * b.inverse_pivot(k) - b.lower(k + 1) * at(out, m, k + 1);
      }
      if (m == 0) {
        at(out, 0, 0) = 0.0;
        out.diagonal().array() -= out.diagonal().mean();
      }
    }
  }

 private:
  struct Block {
    Eigen::VectorXd diagonal, off, lower, inverse_pivot;
  };

  // LDLᵀ of the tridiagonal block restricted to indices first..end: lower(k) = off(k)/w_{k−1},
  // w_k = d_k − lower(k) off(k); stored as inverse_pivot = 1/w.
  static void factor(Block& b, Eigen::Index first) {
    const Eigen::Index length = b.diagonal.size();
    b.lower = Eigen::VectorXd::Zero(length);
    b.inverse_pivot = Eigen::VectorXd::Zero(length);
    double w = 0.0;
    for (Eigen::Index k = first; k < length; ++k) {
      if (k > first) b.lower(k) = b.off(k) / w;
      w = b.diagonal(k) - (k > first ? b.lower(k) * b.off(k) : 0.0);
      b.inverse_pivot(k) = 1.0 / w;
    }
  }

  const Block& block(Eigen::Index m) const {
    return blocks_[static_cast<std::size_t>(std::abs(m))];
  }

  // The k-th entry of diagonal m: (k, k+m) for m >= 0, (k−m, k) for m < 0.
  template <class X>
  static auto& at(X& P, Eigen::Index m, Eigen::Index k) {
    return m >= 0 ? P(k, k + m) : P(k - m, k);
  }
  template <class X>
  static auto at(const X& P, Eigen::Index m, Eigen::Index k) {
    return m >= 0 ? P(k, k + m) : P(k - m, k);
  }

  template <class X>
  void requireSize(const X& P) const {
    if (P.rows() != n_ || P.cols() != n_) {
      throwInvalid(
          "matrix", std::to_string(P.rows()) + "x" + std::to_string(P.cols()),
          "must be " + std::to_string(n_) + "x" + std::to_string(n_) + " for this Laplacian");
    }
  }

  Eigen::Index n_;
  std::vector<Block> blocks_;
};

}  // namespace ddb
