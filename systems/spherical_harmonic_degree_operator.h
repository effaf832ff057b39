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
                                  const std::vector<Eigen::Index>& blocks)
      : n_(basis.size()),
        kept_(static_cast<std::size_t>(n_), false),
        offsets_(2 * static_cast<std::size_t>(n_) + 1, 0),
        folded_(n_, 4),
        even_images_(n_, 4),
        odd_images_(n_, 4) {
    for (const Eigen::Index m : blocks) {
      if (!(m >= 0 && m < n_)) {
        throwInvalid("blocks", std::to_string(m), "must be 0 <= m < N = " + std::to_string(n_));
      }
      kept_[std::size_t(m)] = true;
    }
    for (Eigen::Index m = 0; m < n_; ++m) {
      const std::size_t even = kept(m) ? std::size_t(evenSize(n_ - m)) : 0,
                        odd = kept(m) ? std::size_t(oddSize(n_ - m)) : 0;
      offsets_[2 * std::size_t(m) + 1] = offsets_[2 * std::size_t(m)] + even * even;
      offsets_[2 * std::size_t(m) + 2] = offsets_[2 * std::size_t(m) + 1] + odd * odd;
    }
    operators_.resize(offsets_.back());
    setFactors(basis, factors);
  }

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
  void setFactors(const SphericalHarmonicBasis& basis, const Eigen::VectorXd& factors) {
    if (basis.size() != n_) {
      throwInvalid("basis", "of N = " + std::to_string(basis.size()),
                   "must be of this operator's N = " + std::to_string(n_));
    }
    if (factors.size() != n_) {
      throwInvalid("factors", std::to_string(factors.size()) + " values",
                   "must be N = " + std::to_string(n_) + ", one per degree l");
    }
    SphericalHarmonicBasis::Workspace w(n_);
    Eigen::MatrixXd even_halves, odd_halves;
    Eigen::VectorXd even_factors, odd_factors;
    for (Eigen::Index m = 0; m < n_; ++m) {
      if (!kept(m)) continue;
      const Eigen::Index length = n_ - m, even = evenSize(length), odd = oddSize(length);
      const SphericalHarmonicBasis::BlockView V = basis.blockVectors(m, w);
      even_halves.resize(even, even);
      odd_halves.resize(odd, odd);
      even_factors.resize(even);
      odd_factors.resize(odd);
      Eigen::Index evens = 0, odds = 0;
      for (Eigen::Index row = 0; row < length; ++row) {
        const auto v = V.row(row);
        const bool is_even = (v - v.reverse()).norm() < (v + v.reverse()).norm();
        if (is_even ? evens == even : odds == odd) {
          throwInvalid("block " + std::to_string(m), "eigenvectors of mixed parity",
                       "must be even or odd under reversal (a persymmetric block)");
        }
        if (is_even) {
          even_halves.col(evens) = v.head(even).transpose();
          even_factors(evens++) = factors(m + row);
        } else {
          odd_halves.col(odds) = v.head(odd).transpose();
          odd_factors(odds++) = factors(m + row);
        }
      }
      // P = (1/N) Σ f a aᵀ: the halves' columns scaled by f/N, times the halves' transpose.
      block(2 * m, even).noalias() =
          (even_halves * (even_factors / double(n_)).asDiagonal()) * even_halves.transpose();
      block(2 * m + 1, odd).noalias() =
          (odd_halves * (odd_factors / double(n_)).asDiagonal()) * odd_halves.transpose();
    }
    // Subnormal entries flushed to zero (an absolute change below 2.3e-308): a strong damping
    // makes whole blocks of them (f_l = e^{−rate h} below 1e-308 for every l of a block of large
    // m), and each product with one costs a hundred normal ones: at N = 512 with ν = 1e-4, p = 2,
    // h = 0.01 an application took 0.9 s instead of 0.06 s.
    for (double& entry : operators_) {
      if (std::abs(entry) < std::numeric_limits<double>::min()) entry = 0.0;
    }
  }

  /// W ← f(−Δ) W. Allocates nothing. Every block must be kept.
  void apply(Eigen::MatrixXcd& W) {
    if (W.rows() != n_ || W.cols() != n_) {
      throwInvalid("W", std::to_string(W.rows()) + "x" + std::to_string(W.cols()),
                   "must be N x N, N = " + std::to_string(n_));
    }
    for (Eigen::Index m = 0; m < n_; ++m) {
      requireKept(m);
      // Columns: diagonal m's real and imaginary parts, then −m's (the main diagonal once).
      applyBlock(m, m == 0 ? 2 : 4,
                 [&](Eigen::Index column, Eigen::Index k) -> std::complex<double>& {
                   return column < 2 ? W(k, k + m) : W(k + m, k);
                 });
    }
  }

  /// Diagonals of block m (0 <= m < N) of a matrix W, each as its N − m entries in the order
  /// k = min(i, j): W's diagonal m (entries[k] = W(k, k + m)) or −m (W(k + m, k)), one of them
  /// (`second` null) or both; each replaced by that diagonal of f(−Δ) W, since the operator maps
  /// each diagonal to itself and acts alike on m and −m. Block m must be kept. Allocates nothing.
  void applyToDiagonals(Eigen::Index m, std::complex<double>* first,
                        std::complex<double>* second = nullptr) {
    requireKept(m);
    applyBlock(m, second != nullptr ? 4 : 2,
               [&](Eigen::Index column, Eigen::Index k) -> std::complex<double>& {
                 return column < 2 ? first[k] : second[k];
               });
  }

 private:
  using Block = Eigen::Map<Eigen::MatrixXd>;

  void requireKept(Eigen::Index m) const {
    if (!kept(m)) {
      throwInvalid("m", std::to_string(m), "is a block this operator does not keep");
    }
  }

  /// A_m applied to `columns` (2 or 4) real columns of block m's diagonals: entry(c, k) is entry k
  /// of column c's diagonal, whose real part is column c for even c and imaginary for odd c.
  template <class Entry>
  void applyBlock(Eigen::Index m, Eigen::Index columns, const Entry& entry) {
    const Eigen::Index length = n_ - m, even = evenSize(length), odd = oddSize(length);
    const auto part = [](const std::complex<double>& value, Eigen::Index column) {
      return column % 2 == 0 ? value.real() : value.imag();
    };
    if (columns == 2) folded_.rightCols(2).setZero();
    // y (rows 0..even−1) and z (rows even..even+odd−1) of each column.
    for (Eigen::Index c = 0; c < columns; ++c) {
      for (Eigen::Index k = 0; k < odd; ++k) {
        const double top = part(entry(c, k), c), bottom = part(entry(c, length - 1 - k), c);
        folded_(k, c) = top + bottom;
        folded_(even + k, c) = top - bottom;
      }
      if (even > odd) folded_(odd, c) = part(entry(c, odd), c);
    }
    multiply(block(2 * m, even), folded_.topRows(even), even_images_);
    multiply(block(2 * m + 1, odd), folded_.middleRows(even, odd), odd_images_);
    for (Eigen::Index c = 0; c < columns; ++c) {
      for (Eigen::Index k = 0; k < odd; ++k) {
        set(entry(c, k), c, even_images_(k, c) + odd_images_(k, c));
        set(entry(c, length - 1 - k), c, even_images_(k, c) - odd_images_(k, c));
      }
      if (even > odd) set(entry(c, odd), c, even_images_(odd, c));
    }
  }
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
  static void multiply(const Block& S, const Columns& x, Eigen::MatrixXd& images) {
    const Eigen::Index size = S.rows();
    images.topRows(size).setZero();
    for (Eigen::Index j = 0; j < size; j += 2) {
      // An odd size's last column pairs with a zero weight on itself.
      const bool pair = j + 1 < size;
      const double* first = S.data() + j * size;
      const double weights[8] = {x(j, 0),
                                 x(j, 1),
                                 x(j, 2),
                                 x(j, 3),
                                 pair ? x(j + 1, 0) : 0.0,
                                 pair ? x(j + 1, 1) : 0.0,
                                 pair ? x(j + 1, 2) : 0.0,
                                 pair ? x(j + 1, 3) : 0.0};
      addColumns(size, first, pair ? first + size : first, weights, images.col(0).data(),
                 images.col(1).data(), images.col(2).data(), images.col(3).data());
    }
  }
  /// image_c += w_c u + w_{4+c} v, c = 0..3: restrict-qualified parameters, so that the compiler
  /// vectorises without checking for overlap.
  static void addColumns(Eigen::Index size, const double* __restrict u, const double* __restrict v,
                         const double* __restrict w, double* __restrict image0,
                         double* __restrict image1, double* __restrict image2,
                         double* __restrict image3) {
    const double a0 = w[0], a1 = w[1], a2 = w[2], a3 = w[3];
    const double b0 = w[4], b1 = w[5], b2 = w[6], b3 = w[7];
    for (Eigen::Index k = 0; k < size; ++k) {
      image0[k] += a0 * u[k] + b0 * v[k];
      image1[k] += a1 * u[k] + b1 * v[k];
      image2[k] += a2 * u[k] + b2 * v[k];
      image3[k] += a3 * u[k] + b3 * v[k];
    }
  }

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
