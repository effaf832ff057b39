// The Hoppe–Yau Laplacian Δ_N on N×N matrices, the quantised Laplace–Beltrami operator
// of Zeitlin's fluid on the sphere (docs/reference/conventions.md §2), indices 0-based:
//   (Δ P)_ij = −((N−1)(i+j+1) − 2ij) P_ij + √(i(N−i) j(N−j)) P_{i−1,j−1}
//              + √((i+1)(N−i−1)(j+1)(N−j−1)) P_{i+1,j+1}.
// Each diagonal m = j − i is an invariant tridiagonal block (the same coefficients for
// −m), with eigenvalues −l(l+1), l = |m|..N−1; the kernel on gl(N) is the identity.
// apply and solve cost O(N²): the solve is one Thomas (LDLᵀ) sweep per diagonal on
// factors computed once here; the blocks are negative definite except m = 0, which is
// solved on the traceless part with one unknown pinned and the mean removed afterwards.
// Constructed with κ² > 0 the operator is Δ_N − κ², quasi-geostrophy's Helmholtz operator
// (κ = 1/deformation radius; docs/reference/conventions.md §2): every block is shifted by −κ²
// and so negative definite, m = 0 included (nothing pinned); the trace is still removed, so the
// solution of a traceless W is the traceless one.
// Entry (i, j) follows (i−1, j−1) on its diagonal, so the factors are stored as N×N
// matrices laid out like P and all diagonals are swept at once, column after column:
// contiguous memory instead of a stride of N + 1 (the solve runs in every sweep of the
// fluid's Legendre solver; docs/design/architecture.md, "Measured, and what it decided").
#pragma once

#include <ddb/core/errors.h>
#include <ddb/core/parallel_passes.h>
#include <ddb/core/thread_pool.h>
#include <ddb/systems/hoppe_yau_coefficients.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace ddb {

class HoppeYauLaplacian {
  // A diagonal of an N×N matrix as a vector (onDiagonal).
  using DiagonalView = Eigen::Map<Eigen::VectorXd, 0, Eigen::InnerStride<>>;
  using ConstDiagonalView = Eigen::Map<const Eigen::VectorXd, 0, Eigen::InnerStride<>>;

 public:
  /// Δ_N − κ² on N×N matrices (κ² = 0: the Laplacian).
  explicit HoppeYauLaplacian(Eigen::Index n, double kappa_squared = 0.0)
      : n_(n), kappa_squared_(kappa_squared), blocks_(static_cast<std::size_t>(n)) {
    if (n < 2) throwInvalid("N", std::to_string(n), "must be >= 2");
    requireShift(kappa_squared);
    lower_.setZero(n, n);
    inverse_pivot_.setZero(n, n);
    for (Eigen::Index m = 0; m < n; ++m) {
      Block& b = blocks_[static_cast<std::size_t>(m)];
      blockCoefficients(n, m, b.diagonal, b.off);
      // Entry k of diagonal m at (k, k + m) and of −m at (k + m, k): strides of N + 1.
      DiagonalView lower = onDiagonal(lower_, m), inverse_pivot = onDiagonal(inverse_pivot_, m);
      factorDiagonal(n, m, kappa_squared, lower, inverse_pivot);
      onDiagonal(lower_, -m) = lower;
      onDiagonal(inverse_pivot_, -m) = inverse_pivot;
    }
  }

  /// Throws InvalidArgument unless κ² is finite and >= 0 (the parameter the user gave is the
  /// deformation radius L_d, κ² = 1/L_d²).
  static void requireShift(double kappa_squared) {
    if (!(kappa_squared >= 0 && std::isfinite(kappa_squared))) {
      throwInvalid("deformation_radius", "1/sqrt(" + formatValue(kappa_squared) + ")",
                   "must be > 0 (infinite: no quasi-geostrophic shift)");
    }
  }

  /// The LDLᵀ factors (factorBlock) of diagonal m's block of Δ_N − κ², sized N − |m|: the
  /// one place the shift and the pinning are decided, for every backend's solver. The m = 0
  /// block is singular only at κ² = 0, where its first unknown is pinned.
  template <class Lower, class InversePivot>
  static void factorDiagonal(Eigen::Index n, Eigen::Index m, double kappa_squared, Lower& lower,
                             InversePivot& inverse_pivot) {
    Eigen::VectorXd diagonal, off;
    blockCoefficients(n, m, diagonal, off);
    diagonal.array() -= kappa_squared;
    factorBlock(diagonal, off, m == 0 && kappa_squared == 0.0, lower, inverse_pivot);
  }

  /// Diagonal m's tridiagonal block (the same for m and −m): its diagonal d_k and the
  /// couplings off(k) of entries k − 1 and k (off(0) = 0), k = 0 … N − |m| − 1.
  static void blockCoefficients(Eigen::Index n, Eigen::Index m, Eigen::VectorXd& diagonal,
                                Eigen::VectorXd& off) {
    const Eigen::Index offset = std::abs(m), length = n - offset;
    diagonal.resize(length);
    off.resize(length);
    for (Eigen::Index k = 0; k < length; ++k) {
      diagonal(k) = hoppe_yau::diagonalCoefficient(n, k, offset);
      off(k) = hoppe_yau::coupling(n, k, offset);
    }
  }

  /// The LDLᵀ factors of a block, restricted to entries first … length − 1 (first = 1 for
  /// `pinned`: the singular m = 0 block of Δ_N, else 0): lower(k) = off(k)/w_{k−1} and
  /// inverse_pivot(k) = 1/w_k, w_k = d_k − lower(k) off(k); entries before `first` get 0.
  template <class Lower, class InversePivot>
  static void factorBlock(const Eigen::VectorXd& diagonal, const Eigen::VectorXd& off, bool pinned,
                          Lower& lower, InversePivot& inverse_pivot) {
    const Eigen::Index length = diagonal.size(), first = pinned ? 1 : 0;
    double w = 0.0;
    for (Eigen::Index k = 0; k < length; ++k) {
      if (k < first) {
        lower(k) = inverse_pivot(k) = 0.0;
        continue;
      }
      lower(k) = k > first ? off(k) / w : 0.0;
      w = diagonal(k) - lower(k) * off(k);
      inverse_pivot(k) = 1.0 / w;
    }
  }

  /// values ← the block's solve given its factors (factorBlock): the forward sweep, then
  /// back substitution; the zeroth diagonal removes the mean before and after, as solve does
  /// with the trace.
  template <class Lower, class InversePivot>
  static void sweepDiagonal(bool zeroth, const Lower& lower, const InversePivot& inverse_pivot,
                            Eigen::Ref<Eigen::VectorXcd> values) {
    const Eigen::Index length = values.size();
    if (zeroth) values.array() -= values.mean();
    for (Eigen::Index k = 1; k < length; ++k) values(k) -= lower(k) * values(k - 1);
    values(length - 1) *= inverse_pivot(length - 1);
    for (Eigen::Index k = length - 2; k >= 0; --k) {
      values(k) = values(k) * inverse_pivot(k) - lower(k + 1) * values(k + 1);
    }
    if (zeroth) values.array() -= values.mean();
  }

  Eigen::Index size() const { return n_; }
  /// κ², the shift of Δ_N − κ² (0: the Laplacian).
  double kappaSquared() const { return kappa_squared_; }

  /// The tridiagonal block of Δ_N's diagonal m (and −m), unshifted: its diagonal and its
  /// sub-diagonal (entry k couples k and k+1), for eigen-decompositions (spherical harmonics,
  /// Δ_N's eigenvectors and so Δ_N − κ²'s).
  void block(Eigen::Index m, Eigen::VectorXd& diagonal, Eigen::VectorXd& subdiagonal) const {
    const Block& b = block(m);
    diagonal = b.diagonal;
    subdiagonal = b.off.tail(b.off.size() - 1);
  }

  /// out = (Δ − κ²) P (out must not alias P).
  template <class X>
  void apply(const X& P, X& out) const {
    requireSize(P);
    out.resize(n_, n_);
    for (Eigen::Index m = -(n_ - 1); m < n_; ++m) {
      const Block& b = block(m);
      applyBlock(
          b.diagonal, b.off, kappa_squared_, [&](Eigen::Index k) { return at(P, m, k); },
          [&](Eigen::Index k, const auto& value) { at(out, m, k) = value; });
    }
  }

  /// One diagonal's block of Δ − κ² (blockCoefficients' diagonal and off) applied to the entries
  /// in(k), k < diagonal.size(), into out(k, value): value = (d_k − κ²) in(k) + off(k) in(k − 1)
  /// + off(k + 1) in(k + 1), in that order (apply's, and the distributed apply's,
  /// DistributedPoissonSolver: the same bits).
  template <class Diagonal, class Off, class In, class Out>
  static void applyBlock(const Diagonal& diagonal, const Off& off, double kappa_squared,
                         const In& in, const Out& out) {
    const Eigen::Index length = diagonal.size();
    for (Eigen::Index k = 0; k < length; ++k) {
      auto value = (diagonal(k) - kappa_squared) * in(k);
      if (k > 0) value += off(k) * in(k - 1);
      if (k + 1 < length) value += off(k + 1) * in(k + 1);
      out(k, value);
    }
  }

  /// out = (Δ − κ²)⁻¹ (W − tr(W)/N · I), the traceless solution (Poisson solve, O(N²)).
  /// out may alias W. Bands of diagonals, each swept alone, on the library's threads
  /// (core/thread_pool.h): the same operations on every entry whatever their number.
  template <class X>
  void solve(const X& W, X& out) const {
    requireSize(W);
    const auto mean = W.trace() / typename X::Scalar(double(n_));
    if (&out != &W) {
      out.resize(n_, n_);
      assignInParallel(out, W);
    }
    out.diagonal().array() -= mean;
    ThreadPool& pool = ThreadPool::instance();
    const int tasks = pool.tasksFor(n_ * n_);
    pool.run(tasks,
             [&](int task) { solveBand(bandStart(task, tasks), bandStart(task + 1, tasks), out); });
    out.diagonal().array() -= out.diagonal().mean();
  }

  /// Solves diagonal m alone, in place: `values` holds the N − |m| entries of diagonal m of
  /// W, (k, k + m) or (k − m, k) for k = 0, 1, …, and becomes those of solve(W). The same
  /// sweeps on the same factors as solve, one diagonal at a time, for a caller that holds
  /// whole diagonals rather than the matrix (docs/design/distributed.md); m = 0 removes the mean
  /// before and after, as solve does with the trace.
  void solveDiagonal(Eigen::Index m, Eigen::Ref<Eigen::VectorXcd> values) const {
    const Eigen::Index offset = std::abs(m), length = n_ - offset;
    if (offset >= n_ || values.size() != length) {
      throwInvalid("diagonal",
                   std::to_string(m) + " with " + std::to_string(values.size()) + " entries",
                   "must be within ±" + std::to_string(n_ - 1) + " and have N − |m| entries");
    }
    sweepDiagonal(m == 0, onDiagonal(lower_, m), onDiagonal(inverse_pivot_, m), values);
  }

 private:
  // The first diagonal m of band `task` of `tasks`: bands of about equal numbers of entries,
  // from m = −(N − 1) up (diagonal m has N − |m|).
  Eigen::Index bandStart(int task, int tasks) const {
    if (task == 0) return -(n_ - 1);
    if (task == tasks) return n_;
    const long target = n_ * n_ * task / tasks;
    long below = 0;
    Eigen::Index m = -(n_ - 1);
    while (m < n_ && below + (n_ - std::abs(m)) <= target) below += n_ - std::abs(m++);
    return m;
  }

  // The sweeps of solve on diagonals first <= m < end: entry (i, j) lies on m = j − i and
  // follows (i − 1, j − 1), so in column j the band holds rows j − end < i <= j − first.
  template <class X>
  void solveBand(Eigen::Index first, Eigen::Index end, X& out) const {
    const Eigen::Index n = n_;
    const auto rowsOf = [&](Eigen::Index j, Eigen::Index lowest) {
      return std::pair{std::max(lowest, j - end + 1), std::min(n - 1, j - first)};
    };
    // Forward sweep L y = b on every diagonal: y(i, j) −= lower(i, j) y(i − 1, j − 1).
    for (Eigen::Index j = 1; j < n; ++j) {
      auto* y = &out(0, j);
      const auto* previous = &out(0, j - 1);
      const double* lower = &lower_(0, j);
      const auto [top, bottom] = rowsOf(j, 1);
      for (Eigen::Index i = top; i <= bottom; ++i) y[i] -= lower[i] * previous[i - 1];
    }
    // Back substitution D Lᵀ x = y: x(i, j) = y(i, j)/w(i, j) − lower(i + 1, j + 1) x(i + 1, j +
    // 1). The pinned unknown of m = 0 (κ² = 0) has 1/w = 0 and lower(1, 1) = 0, so it comes out 0.
    for (Eigen::Index j = n - 1; j >= 0; --j) {
      auto* x = &out(0, j);
      const double* inverse_pivot = &inverse_pivot_(0, j);
      const auto [top, bottom] = rowsOf(j, 0);
      if (j + 1 == n) {
        for (Eigen::Index i = top; i <= bottom; ++i) x[i] *= inverse_pivot[i];
        continue;
      }
      const auto* next = &out(0, j + 1);
      const double* lower = &lower_(0, j + 1);
      for (Eigen::Index i = top; i <= std::min(bottom, n - 2); ++i) {
        x[i] = x[i] * inverse_pivot[i] - lower[i + 1] * next[i + 1];
      }
      if (top <= bottom && bottom == n - 1) x[n - 1] *= inverse_pivot[n - 1];
    }
  }

  struct Block {
    Eigen::VectorXd diagonal, off;
  };

  // Diagonal m of an N×N matrix as a vector, entry k at (k, k + m) (m ≥ 0) or (k − m, k).
  static DiagonalView onDiagonal(Eigen::MatrixXd& matrix, Eigen::Index m) {
    const Eigen::Index n = matrix.rows();
    return DiagonalView(matrix.data() + (m >= 0 ? m * n : -m), n - std::abs(m),
                        Eigen::InnerStride<>(n + 1));
  }
  static ConstDiagonalView onDiagonal(const Eigen::MatrixXd& matrix, Eigen::Index m) {
    const Eigen::Index n = matrix.rows();
    return ConstDiagonalView(matrix.data() + (m >= 0 ? m * n : -m), n - std::abs(m),
                             Eigen::InnerStride<>(n + 1));
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
  double kappa_squared_;
  std::vector<Block> blocks_;  // Δ_N's, unshifted
  // lower(k) and 1/w_k of entry k of diagonal m, stored at that entry's (i, j).
  Eigen::MatrixXd lower_, inverse_pivot_;
};

}  // namespace ddb
