// A function of the degree, W ← f(−Δ) W = Σ f_l ω_lm T_lm (SphericalHarmonicBasis::
// applyDegreeFunction), kept as an operator for factors f applied at every step: a step's viscous
// flow (systems/zeitlin_viscosity.h).
// On diagonal m (and −m) of W it is A_m = (1/N) Vᵀ diag(f) V, V's rows block m's eigenvectors
// v_{l,m}. Block m of the Hoppe–Yau Laplacian is persymmetric (its coefficients are unchanged by
// k → N − m − 1 − k, the sphere's reflection z → −z), so each v_{l,m} is even or odd under that
// reversal J and A_m is centrosymmetric. It is kept folded: for x = (x₁, [x_c], x₂) with
// y = x₁ + J x₂ (and x_c, for an odd length) and z = x₁ − J x₂,
//   A_m x = (P y + Q z, [(P y)_c], J (P y − Q z)),
// P = (1/N) Σ_even f_l a aᵀ and Q = (1/N) Σ_odd f_l b bᵀ over the vectors' first halves a, b
// (the middle entry in a). Both hold (N − m)²/2 numbers together, N³/6 over the blocks
// (bytes(N): 179 MB at N = 512), and an application reads each once: half the memory and work of
// applying A_m, and no eigenvector computed (the basis's transform computes them, about 30
// matrix products at N = 512; docs/results/benchmarks.md, "The viscous flow through a kept
// operator"). An operator may keep some blocks only, and apply to diagonals taken out of W one or
// two at a time: an MPI rank's share (DistributedZeitlinViscousFlow).
#pragma once

#include <ddb/core/errors.h>
#include <ddb/systems/spherical_harmonic_basis.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

namespace ddb {

class SphericalHarmonicDegreeOperator {
 public:
  /// f(−Δ) for the factors f_l = factors(l), l = 0..N−1 (N = basis.size()).
  SphericalHarmonicDegreeOperator(const SphericalHarmonicBasis& basis,
                                  const Eigen::VectorXd& factors)
      : SphericalHarmonicDegreeOperator(basis, factors,
                                        SphericalHarmonicBasis::allBlocks(basis.size())) {}

  /// ... on the diagonals ±m of the blocks m in `blocks` only (each 0 <= m < N; a rank's share
  /// of the diagonals, DistributedZeitlinViscousFlow): their memory and their setFactors' work.
  SphericalHarmonicDegreeOperator(const SphericalHarmonicBasis& basis,
                                  const Eigen::VectorXd& factors,
                                  const std::vector<Eigen::Index>& blocks);

  /// The bytes the operator holds at resolution N: 8 Σ_m ((N − m)²/2 rounded up), ≈ 8 N³/6.
  static double bytes(Eigen::Index n) {
    double total = 0;
    for (Eigen::Index m = 0; m < n; ++m) total += blockBytes(n, m);
    return total;
  }
  /// Block m's share of them: 8 ((N − m)²/2 rounded up).
  static double blockBytes(Eigen::Index n, Eigen::Index m) {
    const Eigen::Index length = n - m;
    return 8.0 * double(evenSize(length) * evenSize(length) + oddSize(length) * oddSize(length));
  }

  Eigen::Index size() const { return n_; }
  /// Whether block m (diagonals m and −m) is kept.
  bool kept(Eigen::Index m) const { return m >= 0 && m < n_ && kept_[std::size_t(m)]; }

  /// Replaces the factors: O(N⁴/8) in products (about 40 matrix products at N = 512).
  void setFactors(const SphericalHarmonicBasis& basis, const Eigen::VectorXd& factors);

  /// W ← f(−Δ) W. Allocates nothing. Every block must be kept.
  void apply(Eigen::MatrixXcd& W);

  /// Diagonals of block m (0 <= m < N) of a matrix W, each as its N − m entries in the order
  /// k = min(i, j): W's diagonal m (entries[k] = W(k, k + m)) or −m (W(k + m, k)), one of them
  /// (`second` null) or both; each replaced by that diagonal of f(−Δ) W, since the operator maps
  /// each diagonal to itself and acts alike on m and −m. Block m must be kept. Allocates nothing.
  void applyToDiagonals(Eigen::Index m, std::complex<double>* first,
                        std::complex<double>* second = nullptr);

 private:
  using Block = Eigen::Map<Eigen::MatrixXd>;

  void requireKept(Eigen::Index m) const;

  /// A_m applied to `columns` (2 or 4) real columns of block m's diagonals: entry(c, k) is entry k
  /// of column c's diagonal, whose real part is column c for even c and imaginary for odd c.
  template <class Entry>
  void applyBlock(Eigen::Index m, Eigen::Index columns, const Entry& entry);
  // Length L's even vectors' halves have ⌈L/2⌉ entries (the middle one included), its odd ones
  // ⌊L/2⌋; a block of length L has as many even (odd) vectors as that.
  static Eigen::Index evenSize(Eigen::Index length) { return length - length / 2; }
  static Eigen::Index oddSize(Eigen::Index length) { return length / 2; }

  /// P (index 2m) or Q (2m + 1) of block m, `size` × `size`.
  Block block(Eigen::Index index, Eigen::Index size) {
    return Block(operators_.data() + offsets_[std::size_t(index)], size, size);
  }

  /// images.col(c) = S · x.col(c), c = 0..3: a sum of S's columns (contiguous) weighted by x's
  /// rows, two columns of S read at a time for all four columns of x,
  /// so that S streams from memory once and the images stay in the first-level cache. Not
  /// through BLAS: OpenBLAS's dgemm allocates on shapes this narrow
  /// (SphericalHarmonicBasis::applyDegreeFunction).
  template <class Columns>
  static void multiply(const Block& S, const Columns& x, Eigen::MatrixXd& images);
  /// image_c += w_c u + w_{4+c} v, c = 0..3: restrict-qualified parameters, so that the compiler
  /// vectorises without checking for overlap.
  static void addColumns(Eigen::Index size, const double* __restrict u, const double* __restrict v,
                         const double* __restrict w, double* __restrict image0,
                         double* __restrict image1, double* __restrict image2,
                         double* __restrict image3);

  static void set(std::complex<double>& value, Eigen::Index column, double part) {
    if (column % 2 == 0) {
      value.real(part);
    } else {
      value.imag(part);
    }
  }

  Eigen::Index n_;
  std::vector<bool> kept_;  // per block m
  // P and Q of each block m (empty where not kept), column-major at offsets_[2m] and offsets_[2m +
  // 1].
  std::vector<std::size_t> offsets_;
  std::vector<double> operators_;
  // A block's folded columns (y over z, up to 4 of them) and their images P y and Q z.
  Eigen::MatrixXd folded_, even_images_, odd_images_;
};

}  // namespace ddb
