// The fluid benchmarks' step sizes (docs/design.md, "Large N: the step's stability bound"),
// shared by ddb-bench's Zeitlin benchmarks and distributed-step-bench.
#pragma once

#include <ddb/groups/sun.h>
#include <ddb/systems/zeitlin_fluid.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

namespace ddb::bench {

/// h = 0.02 ħ/‖P₀‖₂, fluid-relax's default: the Legendre fixed point's rate kept small.
inline double benchmarkStep(const Eigen::MatrixXcd& W) {
  const ZeitlinHamiltonian hamiltonian(W.rows());
  return 0.02 * hamiltonian.hbar() / SUN::spectralNorm(hamiltonian.streamMatrix(W));
}

/// The benchmark's step within the double bracket's period-2 stability bound,
/// h |α| ‖W‖₂²/ħ ≤ 4 (‖W‖₂ is a Casimir: the bound holds along the whole trajectory).
inline double resolvedStep(const Eigen::MatrixXcd& W, double alpha) {
  constexpr double kStiffness = 4.0;
  const double norm = SUN::spectralNorm(W);
  return std::min(benchmarkStep(W),
                  kStiffness * zeitlinHbar(W.rows()) / (std::abs(alpha) * norm * norm));
}

}  // namespace ddb::bench
