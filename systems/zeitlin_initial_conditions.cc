// The fluid's seeded initial vorticities (systems/zeitlin_initial_conditions.h), compiled once
// into the library.
#include <ddb/systems/hoppe_yau_laplacian.h>
#include <ddb/systems/spherical_harmonic_basis.h>
#include <ddb/systems/zeitlin_initial_conditions.h>

#include <Eigen/QR>

namespace ddb {

Eigen::MatrixXcd detail::normalised(Eigen::MatrixXcd W) {
  W = SUN::vee(W);
  W.diagonal().array() -= W.trace() / double(W.rows());
  return W * (std::sqrt(double(W.rows())) / W.norm());
}

void detail::requireResolution(Eigen::Index n) {
  if (n < 2 || n > SUN::kMaxN) {
    throwInvalid("N", std::to_string(n), "must be in [2, " + std::to_string(SUN::kMaxN) + "]");
  }
}

Eigen::MatrixXcd zeitlinX3(Eigen::Index n) {
  Eigen::VectorXcd d(n);
  for (Eigen::Index j = 0; j < n; ++j) {
    d(j) = std::complex<double>(0.0, zeitlinHbar(n) * (double(j) - 0.5 * double(n - 1)));
  }
  return d.asDiagonal();
}

Eigen::MatrixXcd randomVorticity(Eigen::Index n, std::uint64_t seed) {
  detail::requireResolution(n);
  detail::NormalSource source(seed);
  return detail::normalised(source.complexMatrix(n));
}

Eigen::MatrixXcd randomUnitary(Eigen::Index n, std::uint64_t seed) {
  detail::NormalSource source(seed);
  const Eigen::HouseholderQR<Eigen::MatrixXcd> qr(source.complexMatrix(n));
  const Eigen::MatrixXcd Q = qr.householderQ();
  const Eigen::VectorXcd phases = qr.matrixQR().diagonal().unaryExpr(
      [](const std::complex<double>& r) { return r == 0.0 ? 1.0 : r / std::abs(r); });
  return Q * phases.asDiagonal();
}

Eigen::MatrixXcd l1Vorticity(Eigen::Index n, std::uint64_t seed) {
  detail::requireResolution(n);
  const Eigen::MatrixXcd U = randomUnitary(n, seed);
  return detail::normalised(U * zeitlinX3(n) * U.adjoint());
}

Eigen::MatrixXcd zonalVorticity(Eigen::Index n, std::uint64_t seed) {
  detail::requireResolution(n);
  detail::NormalSource source(seed);
  Eigen::VectorXcd d(n);
  for (Eigen::Index j = 0; j < n; ++j) d(j) = std::complex<double>(0.0, source.next());
  return detail::normalised(d.asDiagonal());
}

Eigen::MatrixXcd lowModeVorticity(Eigen::Index n, Eigen::Index l_max, std::uint64_t seed) {
  detail::requireResolution(n);
  if (l_max < 1 || l_max > n - 1) {
    throwInvalid("l_max", std::to_string(l_max),
                 "must be in [1, N - 1 = " + std::to_string(n - 1) + "]");
  }
  detail::NormalSource source(seed);
  Eigen::VectorXd omega = Eigen::VectorXd::Zero(n * n);
  for (Eigen::Index l = 1; l <= l_max; ++l) {
    for (Eigen::Index m = -l; m <= l; ++m) {
      omega(SphericalHarmonicBasis::index(l, m)) = source.next() / double(l);
    }
  }
  return detail::normalised(SphericalHarmonicBasis(HoppeYauLaplacian(n)).matrix(omega));
}

}  // namespace ddb
