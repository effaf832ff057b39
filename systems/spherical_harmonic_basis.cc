// The spherical-harmonic basis of Zeitlin's fluid (systems/spherical_harmonic_basis.h), compiled
// once: its Eigen expressions would otherwise be instantiated in every file that includes the
// header (docs/results/compile-costs.md).
#include <ddb/core/errors.h>
#include <ddb/systems/spherical_harmonic_basis.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <string>
#include <vector>

namespace ddb {

template <class Entry>
void SphericalHarmonicBasis::applyDegreeFunctionToBlock(const Eigen::VectorXd& factors,
                                                        Eigen::Index m, Eigen::Index columns,
                                                        Workspace& w, const Entry& entry) const {
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

SphericalHarmonicBasis::SphericalHarmonicBasis(const HoppeYauLaplacian& laplacian)
    : n_(laplacian.size()),
      diagonals_(static_cast<std::size_t>(n_)),
      subdiagonals_(static_cast<std::size_t>(n_)) {
  for (Eigen::Index m = 0; m < n_; ++m) {
    laplacian.block(m, diagonals_[std::size_t(m)], subdiagonals_[std::size_t(m)]);
  }
}

std::vector<Eigen::Index> SphericalHarmonicBasis::allBlocks(Eigen::Index n) {
  std::vector<Eigen::Index> blocks(static_cast<std::size_t>(std::max<Eigen::Index>(n, 0)));
  for (std::size_t m = 0; m < blocks.size(); ++m) blocks[m] = Eigen::Index(m);
  return blocks;
}

Eigen::MatrixXcd SphericalHarmonicBasis::element(Eigen::Index l, Eigen::Index m) const {
  if (!(l >= 0 && l < n_ && std::abs(m) <= l)) {
    throwInvalid("(l, m)", "(" + std::to_string(l) + ", " + std::to_string(m) + ")",
                 "must have 0 <= l < N and |m| <= l");
  }
  Workspace w(n_);
  const Eigen::Index a = std::abs(m);
  Eigen::VectorXd coefficients = Eigen::VectorXd::Zero(n_ - a);
  coefficients(l - a) = 1.0;
  Eigen::MatrixXcd T = Eigen::MatrixXcd::Zero(n_, n_);
  addBlock(a, blockVectors(a, w).transpose() * coefficients, m >= 0 ? 1.0 : 0.0, m >= 0 ? 0.0 : 1.0,
           T);
  return T;
}

SphericalHarmonicBasis::BlockView SphericalHarmonicBasis::blockVectors(Eigen::Index m,
                                                                       Workspace& w) const {
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

Eigen::VectorXd SphericalHarmonicBasis::coefficients(const Eigen::MatrixXcd& W) const {
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

void SphericalHarmonicBasis::applyDegreeFunction(const Eigen::VectorXd& factors,
                                                 Eigen::MatrixXcd& W) const {
  Workspace w(n_);
  applyDegreeFunction(factors, W, w);
}

void SphericalHarmonicBasis::applyDegreeFunction(const Eigen::VectorXd& factors,
                                                 Eigen::MatrixXcd& W, Workspace& w) const {
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

void SphericalHarmonicBasis::applyDegreeFunctionToDiagonals(const Eigen::VectorXd& factors,
                                                            Eigen::Index m,
                                                            std::complex<double>* first,
                                                            std::complex<double>* second,
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

Eigen::MatrixXcd SphericalHarmonicBasis::matrix(const Eigen::VectorXd& omega) const {
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

void SphericalHarmonicBasis::eigenvectors(const Eigen::VectorXd& diagonal,
                                          const Eigen::VectorXd& subdiagonal, Workspace& w) {
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
    z.col(i) =
        (twist - double(i)).max(0.0).min(1.0) * ratio(subdiagonal(i), plus.col(i)) * z.col(i + 1) +
        (1.0 - (twist - double(i)).abs()).max(0.0);
  }
  for (Eigen::Index i = 1; i < n; ++i) {
    z.col(i) += (double(i) - twist).max(0.0).min(1.0) * ratio(subdiagonal(i - 1), minus.col(i)) *
                z.col(i - 1);
  }
}

void SphericalHarmonicBasis::requireSize(const Eigen::MatrixXcd& W) const {
  if (W.rows() != n_ || W.cols() != n_) {
    throwInvalid("W", std::to_string(W.rows()) + "x" + std::to_string(W.cols()),
                 "must be N x N, N = " + std::to_string(n_));
  }
}

void SphericalHarmonicBasis::computeBlockVectors(Eigen::Index m, Workspace& w) const {
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

void SphericalHarmonicBasis::addBlock(Eigen::Index m, const Eigen::VectorXd& values, double c_plus,
                                      double c_minus, Eigen::MatrixXcd& W) const {
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

}  // namespace ddb
