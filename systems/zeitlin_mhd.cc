// Zeitlin's magnetic fluid (systems/zeitlin_mhd.h): its constructor and diagnostics, compiled
// once into the library.
#include <ddb/systems/zeitlin_mhd.h>

#include <cmath>
#include <string>

namespace ddb {

template class ZeitlinMhdHamiltonianOf<Eigen::MatrixXcd, HoppeYauLaplacian>;

std::shared_ptr<const LiePoissonSystem<DualNumberSUN>> makeZeitlinMhd(Eigen::Index n,
                                                                      double alpha) {
  if (n < 2 || n > DualNumberSUN::kMaxN) {
    throwInvalid("N", std::to_string(n),
                 "must be >= 2 and <= " + std::to_string(DualNumberSUN::kMaxN));
  }
  return makeZeitlinMhdOn<Eigen::MatrixXcd>(HoppeYauLaplacian(n), n, alpha);
}

double ZeitlinMhdDiagnostics::kineticEnergy(const State& mu) const {
  return h_.kineticValue(mu.eps) * h_.hbar() / double(mu.eps.rows());
}

double ZeitlinMhdDiagnostics::magneticEnergy(const State& mu) const {
  return h_.magneticValue(mu.real) * h_.hbar() / double(mu.real.rows());
}

double ZeitlinMhdDiagnostics::crossHelicity(const State& mu) const {
  return MatrixBackend<Matrix>::innerProduct(mu.eps, mu.real) / (2.0 * double(mu.real.rows()));
}

double ZeitlinMhdDiagnostics::equilibriumResidual(const State& mu) const {
  const Matrix& W = mu.eps;
  const Matrix& Theta = mu.real;
  Matrix P(W.rows(), W.cols()), B(W.rows(), W.cols());
  h_.poisson().solve(W, P);
  h_.poisson().apply(Theta, B);
  const Matrix magnetic = P * Theta - Theta * P;
  const Matrix momentum = P * W - W * P + B * Theta - Theta * B;
  return std::hypot(magnetic.norm(), momentum.norm());
}

}  // namespace ddb
