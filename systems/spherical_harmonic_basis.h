// The real spherical-harmonic basis T_lm of su(N) ⊕ i·I (docs/reference/conventions.md §2): the
// eigenmatrices of the Hoppe–Yau Laplacian, ΔT_lm = −l(l+1) T_lm, orthonormal for
// Re tr(AᴴB)/N, so that ω_lm = Re tr(T_lmᴴ W)/N are the real spherical-harmonic
// coefficients of the vorticity W: ω(θ, φ) = √(4π) Σ ω_lm Y_lm(θ, φ), Y_lm orthonormal
// (systems/spherical_harmonic_grid.h, which evaluates it).
// For each m >= 0 the eigenvectors v_{l,m} (l = m..N−1) of the m-th diagonal block are
// scaled to ‖v‖ = √N with the sign of their last component (−1)^m, and
//   T_l0 = i diag(v_{l,0}),
//   m > 0: T_lm[k, k+m] = T_lm[k+m, k] = i (−1)^m v_{l,m}[k]/√2,
//   m < 0: T_lm[k, k+|m|] = (−1)^m v_{l,|m|}[k]/√2 = −T_lm[k+|m|, k].
// Coefficients are stored at index l² + l + m (l = 0..N−1, |m| <= l): N² of them.
// The eigenvectors are not stored (all blocks hold N³/3 numbers: 2.9 GB at N = 1024): each
// transform computes each block's in O((N − m)²) (twisted factorisations, eigenvectors())
// and applies them at once, so that a transform costs O(N³) and holds O(N²). A degree function
// applied at every step is kept instead (systems/spherical_harmonic_degree_operator.h).
#pragma once

#include <ddb/core/errors.h>
#include <ddb/systems/hoppe_yau_laplacian.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <string>
#include <vector>

namespace ddb {

class SphericalHarmonicBasis {
 public:
  explicit SphericalHarmonicBasis(const HoppeYauLaplacian& laplacian)
      : n_(laplacian.size()),
        diagonals_(static_cast<std::size_t>(n_)),
        subdiagonals_(static_cast<std::size_t>(n_)) {
    for (Eigen::Index m = 0; m < n_; ++m) {
      laplacian.block(m, diagonals_[std::size_t(m)], subdiagonals_[std::size_t(m)]);
    }
  }

  Eigen::Index size() const { return n_; }

  /// A block's eigenvectors in a workspace (blockVectors()).
  using BlockView = Eigen::Map<const Eigen::MatrixXd, 0, Eigen::OuterStride<>>;

  class Workspace {
   public:
    explicit Workspace(Eigen::Index n)
        : plus(n, n),
          minus(n, n),
          vectors(n, n),
          smallest(n),
          twist(n),
          gamma(n),
          lambda(n),
          scale(n),
          factors(n),
          parts(n, 4),
          projected(n, 4) {}
    Eigen::Index size() const { return vectors.rows(); }

   private:
    friend class SphericalHarmonicBasis;
    /// Block m's eigenvectors as the rows of a `length` × `length` matrix V (row l − m: v_{l,m}).
    BlockView block(Eigen::Index length) const {
      return BlockView(vectors.data(), length, length, Eigen::OuterStride<>(vectors.rows()));
    }
    // eigenvectors()'s pivots D₊, D₋ ((eigenvalue, row)), its vectors, the twist's search, the
    // eigenvalues and the vectors' scales; applyDegreeFunction's f_l/N of a block.
    Eigen::ArrayXXd plus, minus, vectors;
    Eigen::ArrayXd smallest, twist, gamma, lambda, scale, factors;
    // A diagonal's real columns (coefficients(): two; applyDegreeFunction(): the real and
    // imaginary parts of diagonals m and −m) and V times them.
    Eigen::MatrixXd parts, projected;
  };
  static Eigen::Index index(Eigen::Index l, Eigen::Index m) { return l * l + l + m; }
  /// The blocks m = 0..N − 1, each serving diagonals m and −m: what an operator on all of W keeps.
  static std::vector<Eigen::Index> allBlocks(Eigen::Index n) {
    std::vector<Eigen::Index> blocks(static_cast<std::size_t>(std::max<Eigen::Index>(n, 0)));
    for (std::size_t m = 0; m < blocks.size(); ++m) blocks[m] = Eigen::Index(m);
    return blocks;
  }

  /// T_lm as an N×N complex matrix.
  Eigen::MatrixXcd element(Eigen::Index l, Eigen::Index m) const {
    if (!(l >= 0 && l < n_ && std::abs(m) <= l)) {
      throwInvalid("(l, m)", "(" + std::to_string(l) + ", " + std::to_string(m) + ")",
                   "must have 0 <= l < N and |m| <= l");
    }
    Workspace w(n_);
    const Eigen::Index a = std::abs(m);
    Eigen::VectorXd coefficients = Eigen::VectorXd::Zero(n_ - a);
    coefficients(l - a) = 1.0;
    Eigen::MatrixXcd T = Eigen::MatrixXcd::Zero(n_, n_);
    addBlock(a, blockVectors(a, w).transpose() * coefficients, m >= 0 ? 1.0 : 0.0,
             m >= 0 ? 0.0 : 1.0, T);
    return T;
  }

  /// Block m's eigenvectors v_{l,m}, l = m..N−1 (m = 0..N−1), as the rows of an (N − m) ×
  /// (N − m) matrix, row l − m of norm √N: computed into w, valid until w's next use.
  BlockView blockVectors(Eigen::Index m, Workspace& w) const {
    if (!(m >= 0 && m < n_)) {
      throwInvalid("m", std::to_string(m), "must be 0 <= m < N = " + std::to_string(n_));
    }
    if (w.size() != n_) {
      throwInvalid("workspace", "of N = " + std::to_string(w.size()),
                   "must be of this basis's N = " + std::to_string(n_));
    }
    computeBlockVectors(m, w);
    return w.block(n_ - m);
  }

  /// ω_lm = Re tr(T_lmᴴ W)/N for every (l, m), at index(l, m).
  Eigen::VectorXd coefficients(const Eigen::MatrixXcd& W) const {
    requireSize(W);
    Eigen::VectorXd omega = Eigen::VectorXd::Zero(n_ * n_);
    Workspace w(n_);
    for (Eigen::Index m = 0; m < n_; ++m) {
      const Eigen::Index length = n_ - m;
      const BlockView V = blockVectors(m, w);
      // m = 0: Re(conj(i v) w) = v Im w. m > 0: Re(conj(i s v/√2)(W[k,k+m] + W[k+m,k]));
      // m < 0: s v/√2 (W[k,k+m] − W[k+m,k]), s = (−1)^m. Column 0 of `parts` holds the former,
      // column 1 the latter.
      auto parts = w.parts.topLeftCorner(length, 2);
      auto projected = w.projected.topLeftCorner(length, 2);
      for (Eigen::Index k = 0; k < length; ++k) {
        parts(k, 0) = m == 0 ? W(k, k).imag() : (W(k, k + m) + W(k + m, k)).imag();
        parts(k, 1) = m == 0 ? 0.0 : (W(k, k + m) - W(k + m, k)).real();
      }
      const double scale = m == 0 ? 1.0 / double(n_) : sign(m) / (std::sqrt(2.0) * double(n_));
      projected.noalias() = V * parts;
      for (Eigen::Index l = m; l < n_; ++l) omega(index(l, m)) = scale * projected(l - m, 0);
      if (m == 0) continue;
      for (Eigen::Index l = m; l < n_; ++l) omega(index(l, -m)) = scale * projected(l - m, 1);
    }
    return omega;
  }

  /// W ← f(−Δ) W = Σ f_l ω_lm T_lm, f_l = factors(l), l = 0..N−1 (a function of the degree: the
  /// exact flow of a viscosity or a drag, a spectral filter). Each diagonal m of W (and −m) is
  /// taken to block m's eigenvector coordinates, scaled and taken back: (1/N) Vᵀ diag(f) V, with
  /// V's rows v_{l,m} of norm √N; O(N³) in all, the cost of coefficients() and matrix(). With a
  /// workspace of this N (Workspace(size())) it allocates nothing: a step's viscous flow.
  void applyDegreeFunction(const Eigen::VectorXd& factors, Eigen::MatrixXcd& W) const {
    Workspace w(n_);
    applyDegreeFunction(factors, W, w);
  }
  void applyDegreeFunction(const Eigen::VectorXd& factors, Eigen::MatrixXcd& W,
                           Workspace& w) const {
    requireSize(W);
    if (factors.size() != n_) {
      throwInvalid("factors", std::to_string(factors.size()) + " values",
                   "must be N = " + std::to_string(n_) + ", one per degree l");
    }
    // The workspace's N is checked by blockVectors(), before W is touched. The real and
    // imaginary parts of diagonal m's entries W(k, k + m), then of −m's W(k + m, k) (the main
    // diagonal once): one pass over V for both.
    for (Eigen::Index m = 0; m < n_; ++m) {
      applyDegreeFunctionToBlock(factors, m, m == 0 ? 2 : 4, w,
                                 [&](Eigen::Index column, Eigen::Index k) -> std::complex<double>& {
                                   return column < 2 ? W(k, k + m) : W(k + m, k);
                                 });
    }
  }

  /// The diagonals of block m (0 <= m < N) of a matrix W, each as its N − m entries in the order
  /// k = min(i, j), W's diagonal m or −m, one (`second` null) or both, replaced by those of
  /// f(−Δ) W (which maps each diagonal to itself, alike for m and −m): applyDegreeFunction on a
  /// share of the diagonals (DistributedZeitlinViscousFlow). Allocates nothing.
  void applyDegreeFunctionToDiagonals(const Eigen::VectorXd& factors, Eigen::Index m,
                                      std::complex<double>* first, std::complex<double>* second,
                                      Workspace& w) const {
    if (factors.size() != n_) {
      throwInvalid("factors", std::to_string(factors.size()) + " values",
                   "must be N = " + std::to_string(n_) + ", one per degree l");
    }
    applyDegreeFunctionToBlock(factors, m, second != nullptr ? 4 : 2, w,
                               [&](Eigen::Index column, Eigen::Index k) -> std::complex<double>& {
                                 return column < 2 ? first[k] : second[k];
                               });
  }

  /// W = Σ ω_lm T_lm.
  Eigen::MatrixXcd matrix(const Eigen::VectorXd& omega) const {
    if (omega.size() != n_ * n_) {
      throwInvalid("coefficients", std::to_string(omega.size()) + " values",
                   "must be N^2 = " + std::to_string(n_ * n_));
    }
    Eigen::MatrixXcd W = Eigen::MatrixXcd::Zero(n_, n_);
    Workspace w(n_);
    Eigen::VectorXd block;
    for (Eigen::Index m = 0; m < n_; ++m) {
      const BlockView V = blockVectors(m, w);
      block.resize(n_ - m);
      for (Eigen::Index l = m; l < n_; ++l) block(l - m) = omega(index(l, m));
      addBlock(m, V.transpose() * block, 1.0, 0.0, W);
      if (m == 0) continue;
      for (Eigen::Index l = m; l < n_; ++l) block(l - m) = omega(index(l, -m));
      addBlock(m, V.transpose() * block, 0.0, 1.0, W);
    }
    return W;
  }

 private:
  /// The eigenvectors (unnormalised rows of w.vectors' n × n corner) of the symmetric tridiagonal
  /// matrix of `diagonal` (n) and `subdiagonal` (n − 1) for its eigenvalues w.lambda, in
  /// O(n) each: the twisted factorisation (Parlett and Dhillon, "Fernando's solution to
  /// Wilkinson's problem", Linear Algebra Appl. 1997). T − λI = L₊D₊L₊ᵀ from the top and
  /// U₋D₋U₋ᵀ from the bottom; at the twist r where γ_r = D₊(r) + D₋(r) − (d_r − λ) is
  /// smallest in modulus, z_r = 1 and z follows from the two bidiagonal factors, each step a
  /// product, so no recurrence runs against its growing solution. The pivots of all
  /// eigenvalues are computed together, a row at a time, so that the divisions are
  /// vectorised. The Laplacian's blocks have known eigenvalues, so none is computed:
  /// Eigen's QR iteration took O(n³) per block and made the basis O(N⁴)
  /// (docs/design/architecture.md, "The spherical-harmonic basis").
  static void eigenvectors(const Eigen::VectorXd& diagonal, const Eigen::VectorXd& subdiagonal,
                           Workspace& w) {
    // One eigenvalue per row of the block: the eigenvalues w.lambda's first n, the pivots and the
    // vectors the top-left n × n corners of w's arrays.
    const Eigen::Index n = diagonal.size();
    const auto lambda = w.lambda.head(n);
    auto plus = w.plus.topLeftCorner(n, n), minus = w.minus.topLeftCorner(n, n);
    auto twist = w.twist.head(n), smallest = w.smallest.head(n), gamma = w.gamma.head(n);
    auto z = w.vectors.topLeftCorner(n, n);
    // A zero pivot is replaced by a tiny one: its ratio is then huge, as the exact
    // eigenvector's is (the standard treatment, same paper).
    const double tiny = std::numeric_limits<double>::min() / std::numeric_limits<double>::epsilon();
    const auto pivot = [tiny](auto&& values) { return (values == 0.0).select(tiny, values); };
    plus.col(0) = pivot(diagonal(0) - lambda);
    for (Eigen::Index i = 1; i < n; ++i) {
      const double e2 = subdiagonal(i - 1) * subdiagonal(i - 1);
      plus.col(i) = pivot((diagonal(i) - lambda) - e2 / plus.col(i - 1));
    }
    minus.col(n - 1) = pivot(diagonal(n - 1) - lambda);
    for (Eigen::Index i = n - 2; i >= 0; --i) {
      const double e2 = subdiagonal(i) * subdiagonal(i);
      minus.col(i) = pivot((diagonal(i) - lambda) - e2 / minus.col(i + 1));
    }
    // The twist of each eigenvalue, as a double for the masks below.
    twist.setZero();
    smallest.setConstant(INFINITY);
    for (Eigen::Index k = 0; k < n; ++k) {
      gamma = (plus.col(k) + minus.col(k) - (diagonal(k) - lambda)).abs();
      for (Eigen::Index j = 0; j < n; ++j) {
        if (gamma(j) < smallest(j)) {
          smallest(j) = gamma(j);
          twist(j) = double(k);
        }
      }
    }
    // Row j of z is eigenvalue j's vector: z_r = 1, z_i = z_{i+1}·(−e_i/D₊(i)) above the
    // twist r, z_i = z_{i−1}·(−e_{i−1}/D₋(i)) below it; a column at a time for every
    // eigenvalue, with masks in place of branches: (r − i) clamped to [0, 1] is 1 above the
    // twist, 1 − |r − i| clamped at 0 is 1 at it. Masked ratios meet zeros of z, and the
    // ratios are finite (the pivots are not 0), so no 0·inf arises.
    const auto ratio = [&](double e, const auto& pivots) { return -e / pivots; };
    z.col(n - 1) = (1.0 - (twist - double(n - 1)).abs()).max(0.0);
    for (Eigen::Index i = n - 2; i >= 0; --i) {
      z.col(i) = (twist - double(i)).max(0.0).min(1.0) * ratio(subdiagonal(i), plus.col(i)) *
                     z.col(i + 1) +
                 (1.0 - (twist - double(i)).abs()).max(0.0);
    }
    for (Eigen::Index i = 1; i < n; ++i) {
      z.col(i) += (double(i) - twist).max(0.0).min(1.0) * ratio(subdiagonal(i - 1), minus.col(i)) *
                  z.col(i - 1);
    }
  }

  static double sign(Eigen::Index m) { return m % 2 == 0 ? 1.0 : -1.0; }

  /// (1/N) Vᵀ diag(f) V applied to `columns` (2 or 4) real columns of block m's diagonals:
  /// entry(c, k) is entry k of column c's diagonal, its real part for even c, imaginary for odd.
  template <class Entry>
  void applyDegreeFunctionToBlock(const Eigen::VectorXd& factors, Eigen::Index m,
                                  Eigen::Index columns, Workspace& w, const Entry& entry) const {
    const Eigen::Index length = n_ - m;
    const BlockView V = blockVectors(m, w);
    // f_l/N in a vector of the workspace: an expression there would be evaluated into a
    // temporary by colwise() (Eigen's Replicate), an allocation per diagonal.
    auto f = w.factors.head(length);
    f = factors.tail(length).array() / double(n_);
    // Subnormal factors flushed to zero (each product with one costs a hundred normal ones;
    // SphericalHarmonicDegreeOperator::setFactors).
    f = (f.array().abs() < std::numeric_limits<double>::min()).select(0.0, f);
    auto parts = w.parts.topLeftCorner(length, columns);
    auto projected = w.projected.topLeftCorner(length, columns);
    for (Eigen::Index c = 0; c < columns; c += 2) {
      for (Eigen::Index k = 0; k < length; ++k) {
        parts(k, c) = entry(c, k).real();
        parts(k, c + 1) = entry(c, k).imag();
      }
    }
    // Not through BLAS: OpenBLAS's dgemm allocates on some of these shapes (an n × n block
    // times n × 2; measured, bench/zeitlin_bench.cc). V's columns are contiguous, so V·parts
    // is a sum of outer products and Vᵀ·projected a dot product per entry.
    projected.setZero();
    for (Eigen::Index k = 0; k < length; ++k) projected.noalias() += V.col(k) * parts.row(k);
    projected.array().colwise() *= f;
    parts.noalias() = V.transpose().lazyProduct(projected);
    for (Eigen::Index c = 0; c < columns; c += 2) {
      for (Eigen::Index k = 0; k < length; ++k) entry(c, k) = {parts(k, c), parts(k, c + 1)};
    }
  }

  void requireSize(const Eigen::MatrixXcd& W) const {
    if (W.rows() != n_ || W.cols() != n_) {
      throwInvalid("W", std::to_string(W.rows()) + "x" + std::to_string(W.cols()),
                   "must be N x N, N = " + std::to_string(n_));
    }
  }

  /// w.block(N − m) = v_{l,m}, l = m..N−1: block m's eigenvectors for −l(l+1)
  /// (docs/reference/conventions.md §2), scaled to ‖v‖ = √N with the sign of their last component
  /// (−1)^m.
  void computeBlockVectors(Eigen::Index m, Workspace& w) const {
    const Eigen::Index length = n_ - m;
    for (Eigen::Index l = m; l < n_; ++l) w.lambda(l - m) = -double(l) * double(l + 1);
    eigenvectors(diagonals_[std::size_t(m)], subdiagonals_[std::size_t(m)], w);
    // ‖v‖ = √N, last component of sign (−1)^m.
    auto vectors = w.vectors.topLeftCorner(length, length);
    auto scale = w.scale.head(length);
    scale = std::sqrt(double(n_)) / vectors.matrix().rowwise().norm().array();
    scale *= (vectors.col(length - 1) * sign(m) < 0.0).select(-1.0, Eigen::ArrayXd::Ones(length));
    vectors.colwise() *= scale;
  }

  /// W += Σ_l (c_plus T_{l,m} + c_minus T_{l,−m}) weighted by the block combination
  /// `values` = Σ_l ω_l v_{l,m} (m ≥ 0; c_minus is ignored for m = 0).
  void addBlock(Eigen::Index m, const Eigen::VectorXd& values, double c_plus, double c_minus,
                Eigen::MatrixXcd& W) const {
    const std::complex<double> i(0, 1);
    if (m == 0) {
      for (Eigen::Index k = 0; k < n_; ++k) W(k, k) += i * (c_plus * values(k));
      return;
    }
    const double scale = sign(m) / std::sqrt(2.0);
    for (Eigen::Index k = 0; k < n_ - m; ++k) {
      const std::complex<double> plus = i * (scale * c_plus * values(k));
      const double minus = scale * c_minus * values(k);
      W(k, k + m) += plus + minus;
      W(k + m, k) += plus - minus;
    }
  }

  Eigen::Index n_;
  std::vector<Eigen::VectorXd> diagonals_, subdiagonals_;  // of block m = 0..N−1
};

}  // namespace ddb
