// h = fraction · ħ/‖P‖₂, P = Δ⁻¹W the stream matrix (docs/reference/conventions.md §2): ξ = −P/ħ,
// so h‖ξ‖₂ = fraction, the scale on which the fluid's tests choose their steps (the
// Legendre fixed point contracts for small fractions; docs/design/architecture.md, "Large N:
// the step's stability bound", for the dissipative factor's bound).
#pragma once

#include <ddb/systems/zeitlin_fluid.h>

#include <Eigen/SVD>

namespace ddb::test {

inline double zeitlinStepFraction(const Eigen::MatrixXcd& W, double fraction) {
  const Eigen::Index n = W.rows();
  const ZeitlinHamiltonian hamiltonian(n);
  const Eigen::JacobiSVD<Eigen::MatrixXcd> svd(hamiltonian.streamMatrix(W));
  return fraction * zeitlinHbar(n) / svd.singularValues()(0);
}

}  // namespace ddb::test
