// The field's diagnostics of Zeitlin's fluid (systems/zeitlin_spectra.h), compiled once: the
// scale decomposition's eigensolver would otherwise be instantiated in every file that includes
// the header (docs/results/compile-costs.md).
#include <ddb/core/errors.h>
#include <ddb/systems/zeitlin_spectra.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <string>

namespace ddb {

ZeitlinSpectra zeitlinSpectra(const Eigen::VectorXd& omega, double kappa_squared) {
  const auto n = static_cast<Eigen::Index>(std::lround(std::sqrt(double(omega.size()))));
  if (n * n != omega.size() || n < 1) {
    throwInvalid("omega", std::to_string(omega.size()) + " coefficients", "must be N^2 of them");
  }
  ZeitlinSpectra s{Eigen::VectorXd::Zero(n), Eigen::VectorXd::Zero(n)};
  for (Eigen::Index l = 0; l < n; ++l) {
    const double squares =
        omega.segment(SphericalHarmonicBasis::index(l, -l), 2 * l + 1).squaredNorm();
    s.enstrophy(l) = 0.5 * squares;
    if (l > 0) s.energy(l) = 0.5 * squares / (double(l) * double(l + 1) + kappa_squared);
  }
  return s;
}

double zeitlinGamma(const Eigen::VectorXd& omega) {
  if (omega.size() < 4) throwInvalid("omega", std::to_string(omega.size()), "must hold l = 1");
  const double all = omega.norm();
  return all > 0 ? omega.segment(SphericalHarmonicBasis::index(1, -1), 3).norm() / all : 0.0;
}

ZeitlinGammaFromMatrix::ZeitlinGammaFromMatrix(const SphericalHarmonicBasis& basis)
    : n_(basis.size()),
      harmonics_{basis.element(1, -1), basis.element(1, 0), basis.element(1, 1)} {}

double ZeitlinGammaFromMatrix::operator()(const Eigen::MatrixXcd& W) const {
  double l1 = 0.0;
  for (const Eigen::MatrixXcd& T : harmonics_) {
    const double omega = T.cwiseProduct(W.conjugate()).sum().real() / double(n_);
    l1 += omega * omega;
  }
  const double all = W.norm() / std::sqrt(double(n_));
  return all > 0 ? std::sqrt(l1) / all : 0.0;
}

ScaleDecomposition zeitlinScaleDecomposition(const Eigen::MatrixXcd& W,
                                             const Eigen::MatrixXcd& psi) {
  if (W.rows() != W.cols() || psi.rows() != W.rows() || psi.cols() != W.cols()) {
    throwInvalid("psi", std::to_string(psi.rows()) + "x" + std::to_string(psi.cols()),
                 "must be square and of W's size");
  }
  const Eigen::MatrixXcd hermitian = std::complex<double>(0.0, -1.0) * psi;
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd> eigen(hermitian);
  const Eigen::MatrixXcd& U = eigen.eigenvectors();
  const Eigen::VectorXcd diagonal = (U.adjoint() * W * U).diagonal();
  ScaleDecomposition d;
  d.steady = U * diagonal.asDiagonal() * U.adjoint();
  d.remainder = W - d.steady;
  return d;
}

}  // namespace ddb
