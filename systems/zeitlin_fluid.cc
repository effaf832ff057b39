// Zeitlin's fluid (systems/zeitlin_fluid.h): its Hamiltonian, diagnostics and constructor,
// compiled once into the library.
#include <ddb/systems/zeitlin_fluid.h>

namespace ddb {

template class ZeitlinHamiltonianOf<SUN, HoppeYauLaplacian>;

ZeitlinHamiltonian::ZeitlinHamiltonian(Eigen::Index n, const ZeitlinPhysics& physics)
    : ZeitlinHamiltonianOf(HoppeYauLaplacian(n, checked(physics).kappaSquared()), n,
                           zeitlinPlanetaryVorticity(n, physics.rotation)) {}

const ZeitlinPhysics& ZeitlinHamiltonian::checked(const ZeitlinPhysics& physics) {
  physics.validate();
  return physics;
}

ZeitlinHamiltonian::Matrix ZeitlinHamiltonian::streamMatrix(const Matrix& Q) const {
  Matrix P(Q.rows(), Q.cols());
  streamInto(Q, P);
  return P;
}

double ZeitlinDiagnostics::energy(const Matrix& Q) const {
  return h_.value(Q) * h_.hbar() / double(Q.rows());
}

double ZeitlinDiagnostics::enstrophy(const Matrix& Q) const {
  Matrix workspace;
  return h_.relativeVorticity(Q, workspace).squaredNorm() / (2.0 * Q.rows());
}

double ZeitlinDiagnostics::commutatorNorm(const Matrix& Q) const {
  const Matrix P = h_.streamMatrix(Q);
  return (P * Q - Q * P).norm();
}

std::shared_ptr<const LiePoissonSystem<SUN>> makeZeitlinFluid(Eigen::Index n, double alpha) {
  return makeZeitlinFluid(n, alpha, ZeitlinPhysics{});
}

std::shared_ptr<const LiePoissonSystem<SUN>> makeZeitlinFluid(Eigen::Index n, double alpha,
                                                              const ZeitlinPhysics& physics) {
  return makeLiePoissonSystem("zeitlin", std::make_shared<const ZeitlinHamiltonian>(n, physics),
                              std::make_shared<const ScaledIdentityMetric<SUN>>(alpha));
}

}  // namespace ddb
