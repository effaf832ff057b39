// f(−Δ) kept as an operator (systems/spherical_harmonic_degree_operator.h), compiled once: its
// Eigen expressions would otherwise be instantiated in every file that includes the header
// (docs/results/compile-costs.md).
#include <ddb/core/errors.h>
#include <ddb/systems/spherical_harmonic_degree_operator.h>

#include <cmath>
#include <complex>
#include <limits>
#include <string>
#include <vector>

namespace ddb {

void SphericalHarmonicDegreeOperator::addColumns(
    Eigen::Index size, const double* __restrict u, const double* __restrict v,
    const double* __restrict w, double* __restrict image0, double* __restrict image1,
    double* __restrict image2, double* __restrict image3) {
  const double a0 = w[0], a1 = w[1], a2 = w[2], a3 = w[3];
  const double b0 = w[4], b1 = w[5], b2 = w[6], b3 = w[7];
  for (Eigen::Index k = 0; k < size; ++k) {
    image0[k] += a0 * u[k] + b0 * v[k];
    image1[k] += a1 * u[k] + b1 * v[k];
    image2[k] += a2 * u[k] + b2 * v[k];
    image3[k] += a3 * u[k] + b3 * v[k];
  }
}

template <class Columns>
void SphericalHarmonicDegreeOperator::multiply(const Block& S, const Columns& x,
                                               Eigen::MatrixXd& images) {
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

template <class Entry>
void SphericalHarmonicDegreeOperator::applyBlock(Eigen::Index m, Eigen::Index columns,
                                                 const Entry& entry) {
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

void SphericalHarmonicDegreeOperator::requireKept(Eigen::Index m) const {
  if (!kept(m)) {
    throwInvalid("m", std::to_string(m), "is a block this operator does not keep");
  }
}

SphericalHarmonicDegreeOperator::SphericalHarmonicDegreeOperator(
    const SphericalHarmonicBasis& basis, const Eigen::VectorXd& factors,
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

void SphericalHarmonicDegreeOperator::setFactors(const SphericalHarmonicBasis& basis,
                                                 const Eigen::VectorXd& factors) {
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

void SphericalHarmonicDegreeOperator::apply(Eigen::MatrixXcd& W) {
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

void SphericalHarmonicDegreeOperator::applyToDiagonals(Eigen::Index m, std::complex<double>* first,
                                                       std::complex<double>* second) {
  requireKept(m);
  applyBlock(m, second != nullptr ? 4 : 2,
             [&](Eigen::Index column, Eigen::Index k) -> std::complex<double>& {
               return column < 2 ? first[k] : second[k];
             });
}

}  // namespace ddb
