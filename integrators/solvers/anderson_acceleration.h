// AndersonAcceleration: the accelerated fixed point of the matrix-free Legendre solver for
// targets that move with the unknown (the symmetric DDB's half-force target).
// A fixed point p = G(p) whose map has a few eigenvalues near 1 among many small ones
// converges at the rate of the largest: measured on the fluid at N = 256
// (docs/design/architecture.md, "The symmetric DDB's fixed point"), the first sweeps remove the
// small scales and then the update shrinks by 0.89 per sweep for twenty sweeps. Anderson mixing
// (type II, depth m; Walker and Ni, SIAM J. Numer. Anal. 49, 2011) takes the next iterate as the
// image of the combination of the last m + 1 iterates whose residuals f = G(p) − p combine to the
// smallest one:
//   γ = argmin ‖f_k − Σ_j γ_j Δf_j‖,  p_{k+1} = G(p_k) − Σ_j γ_j ΔG_j,
// with Δf_j, ΔG_j the differences of consecutive residuals and images. On a linear map
// this is GMRES on (I − DG) with the iterates as its Krylov basis, so each iteration costs
// one sweep where Newton–Krylov pays a sweep and a Jacobian–vector product per Krylov step.
// The fit is on the real inner product Re tr(XᴴY) of the algebra (γ real, the backend's
// innerProduct), by the normal equations of m ≤ 4 unknowns with dependent differences left
// out; every operation on the iterates goes through the matrix backend
// (docs/design/matrix-backend.md), and no step allocates once the buffers are sized.
#pragma once

#include <ddb/core/matrix_backend.h>

#include <Eigen/Core>
#include <array>
#include <cmath>
#include <cstddef>

namespace ddb {

template <class Matrix>
class AndersonAcceleration {
 public:
  /// The most differences a mixing combines.
  static constexpr int kDepth = 4;

  /// Forgets the iterates (a new solve).
  void reset() { count_ = stored_ = 0; }

  /// The number of iterates remembered.
  int count() const { return count_; }

  /// Given the iterate p and its image g = G(p), replaces g by the mixed next iterate.
  void mix(const Matrix& p, Matrix& g) {
    allocate(p);
    B::sum(1.0, g, -1.0, p, residual_);
    if (count_ > 0) {
      const std::size_t slot = static_cast<std::size_t>(stored_ % kDepth);
      B::sum(1.0, residual_, -1.0, previous_residual_, dF_[slot]);
      B::sum(1.0, g, -1.0, previous_image_, dG_[slot]);
      ++stored_;
    }
    B::copy(residual_, previous_residual_);
    B::copy(g, previous_image_);
    ++count_;
    const int m = stored_ < kDepth ? stored_ : kDepth;
    if (m == 0) return;
    gram_.setZero(m, m);
    rhs_.setZero(m);
    for (int i = 0; i < m; ++i) {
      rhs_(i) = B::innerProduct(difference(i), residual_);
      for (int j = 0; j <= i; ++j) {
        gram_(i, j) = gram_(j, i) = B::innerProduct(difference(i), difference(j));
      }
    }
    if (!solveGram(m)) return;  // g stays the plain sweep
    for (int i = 0; i < m; ++i) B::axpy(-gamma_(i), image(i), g);
  }

 private:
  using B = MatrixBackend<Matrix>;
  using Small = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kDepth, kDepth>;
  using SmallVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kDepth, 1>;
  /// Pivots of the Gram matrix below this fraction of its largest diagonal entry count as
  /// zero: its condition is the square of the differences', so 1e-12 drops directions the
  /// residuals determine to fewer than six digits.
  static constexpr double kRankThreshold = 1e-12;

  // γ from gram γ = rhs by an LDLᵀ factorisation in place, a difference whose pivot is below
  // kRankThreshold (dependent on the others) left out with γ_i = 0. False when not finite.
  bool solveGram(int m) {
    gamma_.setZero(m);
    const double largest = gram_.diagonal().maxCoeff();
    if (!(largest > 0.0) || !std::isfinite(largest)) return false;
    for (int j = 0; j < m; ++j) {
      for (int k = 0; k < j; ++k) {
        if (gram_(k, k) == 0.0) continue;
        const double l = gram_(j, k) / gram_(k, k);
        for (int i = j; i < m; ++i) gram_(i, j) -= l * gram_(i, k);
        rhs_(j) -= l * rhs_(k);
        gram_(j, k) = l;
      }
      if (gram_(j, j) <= kRankThreshold * largest) gram_(j, j) = 0.0;
    }
    for (int j = m - 1; j >= 0; --j) {  // D Lᵀ γ = L⁻¹ rhs
      gamma_(j) = 0.0;
      if (gram_(j, j) == 0.0) continue;
      gamma_(j) = rhs_(j) / gram_(j, j);
      for (int i = j + 1; i < m; ++i) gamma_(j) -= gram_(i, j) * gamma_(i);
    }
    return gamma_.head(m).allFinite();
  }

  // The difference i of the m newest (any order: the fit is invariant under permutations).
  const Matrix& difference(int i) const { return dF_[static_cast<std::size_t>(i)]; }
  const Matrix& image(int i) const { return dG_[static_cast<std::size_t>(i)]; }

  void allocate(const Matrix& like) {
    if (B::sameShape(residual_, like)) return;
    for (Matrix* m : {&residual_, &previous_residual_, &previous_image_}) B::zeroLike(*m, like);
    for (int i = 0; i < kDepth; ++i) {
      B::zeroLike(dF_[static_cast<std::size_t>(i)], like);
      B::zeroLike(dG_[static_cast<std::size_t>(i)], like);
    }
    reset();
  }

  Matrix residual_, previous_residual_, previous_image_;
  std::array<Matrix, kDepth> dF_, dG_;
  Small gram_;
  SmallVector rhs_, gamma_;
  int count_ = 0, stored_ = 0;
};

}  // namespace ddb
