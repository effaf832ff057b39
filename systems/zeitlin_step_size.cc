// The fluid's default step size (systems/zeitlin_step_size.h), compiled once into the library.
#include <ddb/systems/zeitlin_step_size.h>

namespace ddb {

double zeitlinContractionStep(const Eigen::MatrixXcd& W0) {
  const ZeitlinHamiltonian hamiltonian(W0.rows());
  return kZeitlinContractionRate * hamiltonian.hbar() /
         SUN::spectralNorm(hamiltonian.streamMatrix(W0));
}

double zeitlinDefaultStep(const Eigen::MatrixXcd& W0, double alpha) {
  const double norm = SUN::spectralNorm(W0);
  return std::min(zeitlinContractionStep(W0),
                  kZeitlinStiffness * zeitlinHbar(W0.rows()) / (std::abs(alpha) * norm * norm));
}

}  // namespace ddb
