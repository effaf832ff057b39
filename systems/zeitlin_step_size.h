// The fluid's default step size (docs/design/architecture.md, "Large N: the step's stability
// bound"): the smaller of two limits, each a dimensionless number of the step kept below a bound.
//  * The Legendre fixed point's contraction rate h‖P‖₂/ħ (docs/reference/conventions.md §2), so
//  that
//    a solve takes a few sweeps.
//  * The dissipation's stiffness s = h|α|‖W‖₂²/ħ, past which DDB's explicit dissipative
//    factor has a growing period-2 mode and the energy moves against α's sign. ‖W‖₂ is a
//    Casimir, so a bound on s at W₀ holds along the whole run.
#pragma once

#include <ddb/groups/sun.h>
#include <ddb/systems/zeitlin_fluid.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

namespace ddb {

/// The contraction rate h‖P₀‖₂/ħ the default step keeps.
constexpr double kZeitlinContractionRate = 0.02;
/// The stiffness h|α|‖W₀‖₂²/ħ the default step keeps, below the threshold
/// docs/design/architecture.md measures.
constexpr double kZeitlinStiffness = 4.0;

/// h = kZeitlinContractionRate·ħ/‖P₀‖₂, P₀ = Δ⁻¹W₀.
double zeitlinContractionStep(const Eigen::MatrixXcd& W0);

/// h = min(kZeitlinContractionRate·ħ/‖P₀‖₂, kZeitlinStiffness·ħ/(|α|‖W₀‖₂²)); the second
/// is no limit for α = 0.
double zeitlinDefaultStep(const Eigen::MatrixXcd& W0, double alpha);

}  // namespace ddb
