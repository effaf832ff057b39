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

#include <ddb/systems/hoppe_yau_laplacian.h>

#include <Eigen/Core>
#include <complex>
#include <vector>

namespace ddb {

class SphericalHarmonicBasis {
 public:
  explicit SphericalHarmonicBasis(const HoppeYauLaplacian& laplacian);

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
  static std::vector<Eigen::Index> allBlocks(Eigen::Index n);

  /// T_lm as an N×N complex matrix.
  Eigen::MatrixXcd element(Eigen::Index l, Eigen::Index m) const;

  /// Block m's eigenvectors v_{l,m}, l = m..N−1 (m = 0..N−1), as the rows of an (N − m) ×
  /// (N − m) matrix, row l − m of norm √N: computed into w, valid until w's next use.
  BlockView blockVectors(Eigen::Index m, Workspace& w) const;

  /// ω_lm = Re tr(T_lmᴴ W)/N for every (l, m), at index(l, m).
  Eigen::VectorXd coefficients(const Eigen::MatrixXcd& W) const;

  /// W ← f(−Δ) W = Σ f_l ω_lm T_lm, f_l = factors(l), l = 0..N−1 (a function of the degree: the
  /// exact flow of a viscosity or a drag, a spectral filter). Each diagonal m of W (and −m) is
  /// taken to block m's eigenvector coordinates, scaled and taken back: (1/N) Vᵀ diag(f) V, with
  /// V's rows v_{l,m} of norm √N; O(N³) in all, the cost of coefficients() and matrix(). With a
  /// workspace of this N (Workspace(size())) it allocates nothing: a step's viscous flow.
  void applyDegreeFunction(const Eigen::VectorXd& factors, Eigen::MatrixXcd& W) const;
  void applyDegreeFunction(const Eigen::VectorXd& factors, Eigen::MatrixXcd& W, Workspace& w) const;

  /// The diagonals of block m (0 <= m < N) of a matrix W, each as its N − m entries in the order
  /// k = min(i, j), W's diagonal m or −m, one (`second` null) or both, replaced by those of
  /// f(−Δ) W (which maps each diagonal to itself, alike for m and −m): applyDegreeFunction on a
  /// share of the diagonals (DistributedZeitlinViscousFlow). Allocates nothing.
  void applyDegreeFunctionToDiagonals(const Eigen::VectorXd& factors, Eigen::Index m,
                                      std::complex<double>* first, std::complex<double>* second,
                                      Workspace& w) const;

  /// W = Σ ω_lm T_lm.
  Eigen::MatrixXcd matrix(const Eigen::VectorXd& omega) const;

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
                           Workspace& w);

  static double sign(Eigen::Index m) { return m % 2 == 0 ? 1.0 : -1.0; }

  /// (1/N) Vᵀ diag(f) V applied to `columns` (2 or 4) real columns of block m's diagonals:
  /// entry(c, k) is entry k of column c's diagonal, its real part for even c, imaginary for odd.
  template <class Entry>
  void applyDegreeFunctionToBlock(const Eigen::VectorXd& factors, Eigen::Index m,
                                  Eigen::Index columns, Workspace& w, const Entry& entry) const;

  void requireSize(const Eigen::MatrixXcd& W) const;

  /// w.block(N − m) = v_{l,m}, l = m..N−1: block m's eigenvectors for −l(l+1)
  /// (docs/reference/conventions.md §2), scaled to ‖v‖ = √N with the sign of their last component
  /// (−1)^m.
  void computeBlockVectors(Eigen::Index m, Workspace& w) const;

  /// W += Σ_l (c_plus T_{l,m} + c_minus T_{l,−m}) weighted by the block combination
  /// `values` = Σ_l ω_l v_{l,m} (m ≥ 0; c_minus is ignored for m = 0).
  void addBlock(Eigen::Index m, const Eigen::VectorXd& values, double c_plus, double c_minus,
                Eigen::MatrixXcd& W) const;

  Eigen::Index n_;
  std::vector<Eigen::VectorXd> diagonals_, subdiagonals_;  // of block m = 0..N−1
};

}  // namespace ddb
