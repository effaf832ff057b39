// The rounding of an energy difference, shared by the step-size control of the time loop
// (integrators/drivers/energy_step_control.h) and the Newton search's energy guard
// (integrators/solvers/orbit_newton.h), which sits a layer below it.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

namespace ddb {

/// The rounding of an energy difference H(μ') − H(μ): the energy is a sum of a few rounded
/// products, each good to ε relative, so honest round-off stays within kRoundOffUlps·ε of
/// the larger of the two values.
inline double energyRoundOff(double e0, double e1) {
  constexpr double kRoundOffUlps = 8.0;
  return kRoundOffUlps * std::numeric_limits<double>::epsilon() *
         std::max(std::abs(e0), std::abs(e1));
}

}  // namespace ddb
