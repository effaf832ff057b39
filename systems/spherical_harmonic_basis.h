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
// and applies them at once, so that a transform costs O(N³) and holds O(N²).
#pragma once

#include <ddb/core/errors.h>
#include <ddb/systems/hoppe_yau_laplacian.h>

#include <Eigen/Core>
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
  static Eigen::Index index(Eigen::Index l, Eigen::Index m) { return l * l + l + m; }

  /// T_lm as an N×N complex matrix.
  Eigen::MatrixXcd element(Eigen::Index l, Eigen::Index m) const {
    if (!(l >= 0 && l < n_ && std::abs(m) <= l)) {
      throwInvalid("(l, m)", "(" + std::to_string(l) + ", " + std::to_string(m) + ")",
                   "must have 0 <= l < N and |m| <= l");
    }
    Workspace w;
    const Eigen::Index a = std::abs(m);
    blockVectors(a, w);
    Eigen::VectorXd coefficients = Eigen::VectorXd::Zero(n_ - a);
    coefficients(l - a) = 1.0;
    Eigen::MatrixXcd T = Eigen::MatrixXcd::Zero(n_, n_);
    addBlock(a, w.vectors.matrix().transpose() * coefficients, m >= 0 ? 1.0 : 0.0,
             m >= 0 ? 0.0 : 1.0, T);
    return T;
  }

  /// ω_lm = Re tr(T_lmᴴ W)/N for every (l, m), at index(l, m).
  Eigen::VectorXd coefficients(const Eigen::MatrixXcd& W) const {
    requireSize(W);
    Eigen::VectorXd omega = Eigen::VectorXd::Zero(n_ * n_);
    Workspace w;
    for (Eigen::Index m = 0; m < n_; ++m) {
      const Eigen::Index length = n_ - m;
      blockVectors(m, w);
      // m = 0: Re(conj(i v) w) = v Im w. m > 0: Re(conj(i s v/√2)(W[k,k+m] + W[k+m,k]));
      // m < 0: s v/√2 (W[k,k+m] − W[k+m,k]), s = (−1)^m.
      w.plus.resize(length);
      w.minus.resize(length);
      for (Eigen::Index k = 0; k < length; ++k) {
        w.plus(k) = m == 0 ? W(k, k).imag() : (W(k, k + m) + W(k + m, k)).imag();
        w.minus(k) = m == 0 ? 0.0 : (W(k, k + m) - W(k + m, k)).real();
      }
      const double scale = m == 0 ? 1.0 / double(n_) : sign(m) / (std::sqrt(2.0) * double(n_));
      w.projected.noalias() = w.vectors.matrix() * w.plus;
      for (Eigen::Index l = m; l < n_; ++l) omega(index(l, m)) = scale * w.projected(l - m);
      if (m == 0) continue;
      w.projected.noalias() = w.vectors.matrix() * w.minus;
      for (Eigen::Index l = m; l < n_; ++l) omega(index(l, -m)) = scale * w.projected(l - m);
    }
    return omega;
  }

  /// W ← f(−Δ) W = Σ f_l ω_lm T_lm, f_l = factors(l), l = 0..N−1 (a function of the degree: the
  /// exact flow of a viscosity or a drag, a spectral filter). Each diagonal m of W (and −m) is
  /// taken to block m's eigenvector coordinates, scaled and taken back: (1/N) Vᵀ diag(f) V, with
  /// V's rows v_{l,m} of norm √N; O(N³) in all, the cost of coefficients() and matrix().
  void applyDegreeFunction(const Eigen::VectorXd& factors, Eigen::MatrixXcd& W) const {
    requireSize(W);
    if (factors.size() != n_) {
      throwInvalid("factors", std::to_string(factors.size()) + " values",
                   "must be N = " + std::to_string(n_) + ", one per degree l");
    }
    Workspace w;
    // The real and imaginary parts of a diagonal's entries, in V's real arithmetic.
    Eigen::MatrixXd parts, projected;
    for (Eigen::Index m = 0; m < n_; ++m) {
      const Eigen::Index length = n_ - m;
      blockVectors(m, w);
      const auto V = w.vectors.matrix();
      const auto f = factors.tail(length).array() / double(n_);
      // Diagonal m, then −m (the main diagonal once).
      for (Eigen::Index side = 0; side < (m == 0 ? 1 : 2); ++side) {
        const Eigen::Index d = side == 0 ? m : -m;
        const auto entry = [&](Eigen::Index k) -> std::complex<double>& {
          return d >= 0 ? W(k, k + d) : W(k - d, k);
        };
        parts.resize(length, 2);
        for (Eigen::Index k = 0; k < length; ++k) parts.row(k) << entry(k).real(), entry(k).imag();
        projected.noalias() = V * parts;
        projected.array().colwise() *= f;
        parts.noalias() = V.transpose() * projected;
        for (Eigen::Index k = 0; k < length; ++k) entry(k) = {parts(k, 0), parts(k, 1)};
      }
    }
  }

  /// W = Σ ω_lm T_lm.
  Eigen::MatrixXcd matrix(const Eigen::VectorXd& omega) const {
    if (omega.size() != n_ * n_) {
      throwInvalid("coefficients", std::to_string(omega.size()) + " values",
                   "must be N^2 = " + std::to_string(n_ * n_));
    }
    Eigen::MatrixXcd W = Eigen::MatrixXcd::Zero(n_, n_);
    Workspace w;
    Eigen::VectorXd block;
    for (Eigen::Index m = 0; m < n_; ++m) {
      blockVectors(m, w);
      block.resize(n_ - m);
      for (Eigen::Index l = m; l < n_; ++l) block(l - m) = omega(index(l, m));
      addBlock(m, w.vectors.matrix().transpose() * block, 1.0, 0.0, W);
      if (m == 0) continue;
      for (Eigen::Index l = m; l < n_; ++l) block(l - m) = omega(index(l, -m));
      addBlock(m, w.vectors.matrix().transpose() * block, 0.0, 1.0, W);
    }
    return W;
  }

 private:
  /// Workspaces of eigenvectors(), reused from block to block.
  struct TwistedFactors {
    Eigen::ArrayXXd plus, minus;  // (eigenvalue, row): the pivots D₊, D₋
    Eigen::ArrayXd smallest, twist, gamma;
  };

  /// The eigenvectors (unnormalised rows of `z`) of the symmetric tridiagonal
  /// matrix of `diagonal` (n) and `subdiagonal` (n − 1) for its eigenvalues `lambda`, in
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
                           const Eigen::ArrayXd& lambda, TwistedFactors& f, Eigen::ArrayXXd& z) {
    const Eigen::Index n = diagonal.size(), count = lambda.size();
    // A zero pivot is replaced by a tiny one: its ratio is then huge, as the exact
    // eigenvector's is (the standard treatment, same paper).
    const double tiny = std::numeric_limits<double>::min() / std::numeric_limits<double>::epsilon();
    const auto pivot = [tiny](auto&& values) { return (values == 0.0).select(tiny, values); };
    f.plus.resize(count, n);
    f.minus.resize(count, n);
    f.plus.col(0) = pivot(diagonal(0) - lambda);
    for (Eigen::Index i = 1; i < n; ++i) {
      const double e2 = subdiagonal(i - 1) * subdiagonal(i - 1);
      f.plus.col(i) = pivot((diagonal(i) - lambda) - e2 / f.plus.col(i - 1));
    }
    f.minus.col(n - 1) = pivot(diagonal(n - 1) - lambda);
    for (Eigen::Index i = n - 2; i >= 0; --i) {
      const double e2 = subdiagonal(i) * subdiagonal(i);
      f.minus.col(i) = pivot((diagonal(i) - lambda) - e2 / f.minus.col(i + 1));
    }
    // The twist of each eigenvalue, as a double for the masks below.
    f.twist.setZero(count);
    f.smallest.setConstant(count, INFINITY);
    for (Eigen::Index k = 0; k < n; ++k) {
      f.gamma = (f.plus.col(k) + f.minus.col(k) - (diagonal(k) - lambda)).abs();
      for (Eigen::Index j = 0; j < count; ++j) {
        if (f.gamma(j) < f.smallest(j)) {
          f.smallest(j) = f.gamma(j);
          f.twist(j) = double(k);
        }
      }
    }
    // Row j of z is eigenvalue j's vector: z_r = 1, z_i = z_{i+1}·(−e_i/D₊(i)) above the
    // twist r, z_i = z_{i−1}·(−e_{i−1}/D₋(i)) below it; a column at a time for every
    // eigenvalue, with masks in place of branches: (r − i) clamped to [0, 1] is 1 above the
    // twist, 1 − |r − i| clamped at 0 is 1 at it. Masked ratios meet zeros of z, and the
    // ratios are finite (the pivots are not 0), so no 0·inf arises.
    z.resize(count, n);
    const auto ratio = [&](double e, const auto& pivots) { return -e / pivots; };
    z.col(n - 1) = (1.0 - (f.twist - double(n - 1)).abs()).max(0.0);
    for (Eigen::Index i = n - 2; i >= 0; --i) {
      z.col(i) = (f.twist - double(i)).max(0.0).min(1.0) * ratio(subdiagonal(i), f.plus.col(i)) *
                     z.col(i + 1) +
                 (1.0 - (f.twist - double(i)).abs()).max(0.0);
    }
    for (Eigen::Index i = 1; i < n; ++i) {
      z.col(i) += (double(i) - f.twist).max(0.0).min(1.0) *
                  ratio(subdiagonal(i - 1), f.minus.col(i)) * z.col(i - 1);
    }
  }

  struct Workspace {
    TwistedFactors factors;
    Eigen::ArrayXd lambda;
    Eigen::ArrayXXd vectors;  // row l − m: v_{l,m}
    Eigen::ArrayXd scale;
    Eigen::VectorXd plus, minus, projected;
  };

  static double sign(Eigen::Index m) { return m % 2 == 0 ? 1.0 : -1.0; }

  void requireSize(const Eigen::MatrixXcd& W) const {
    if (W.rows() != n_ || W.cols() != n_) {
      throwInvalid("W", std::to_string(W.rows()) + "x" + std::to_string(W.cols()),
                   "must be N x N, N = " + std::to_string(n_));
    }
  }

  /// w.vectors = v_{l,m}, l = m..N−1: block m's eigenvectors for −l(l+1)
  /// (docs/reference/conventions.md §2), scaled to ‖v‖ = √N with the sign of their last component
  /// (−1)^m.
  void blockVectors(Eigen::Index m, Workspace& w) const {
    const Eigen::Index length = n_ - m;
    w.lambda.resize(length);
    for (Eigen::Index l = m; l < n_; ++l) w.lambda(l - m) = -double(l) * double(l + 1);
    eigenvectors(diagonals_[std::size_t(m)], subdiagonals_[std::size_t(m)], w.lambda, w.factors,
                 w.vectors);
    // ‖v‖ = √N, last component of sign (−1)^m.
    w.scale = std::sqrt(double(n_)) / w.vectors.matrix().rowwise().norm().array();
    w.scale *=
        (w.vectors.col(length - 1) * sign(m) < 0.0).select(-1.0, Eigen::ArrayXd::Ones(length));
    w.vectors.colwise() *= w.scale;
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
