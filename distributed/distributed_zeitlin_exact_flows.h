// The damping and forcing of Zeitlin's fluid on MPI ranks, in the order every placement splits
// them around a method (zeitlinExactFlowsBy, systems/zeitlin_exact_flows.h): fluid-relax-mpi's.
#pragma once

#include <ddb/distributed/distributed_zeitlin_forcing.h>
#include <ddb/distributed/distributed_zeitlin_viscous_flow.h>
#include <ddb/systems/zeitlin_exact_flows.h>

#include <memory>
#include <vector>

namespace ddb {

/// The flows of `d` on the block-cyclic states of `layout` of the fluid of `physics`
/// (makeDistributedZeitlinFluid), innermost first; the same arguments on every rank (Φ whole on
/// each). Throws InvalidArgument naming the parameter, as zeitlinExactFlows, on every rank alike.
inline std::vector<std::unique_ptr<ExactFlow<DistributedSUN>>> distributedZeitlinExactFlows(
    const BlockCyclicLayout& layout, const ZeitlinPhysics& physics,
    const ZeitlinDampingAndForcing& d) {
  struct Make {
    const BlockCyclicLayout& layout;
    const ZeitlinPhysics& physics;
    std::unique_ptr<ExactFlow<DistributedSUN>> viscous(const ZeitlinViscosity& viscosity) const {
      return std::make_unique<DistributedZeitlinViscousFlow>(layout, viscosity, physics.rotation);
    }
    std::unique_ptr<ExactFlow<DistributedSUN>> stochastic(
        const ZeitlinStochasticForcing& forcing) const {
      return std::make_unique<DistributedZeitlinStochasticForcingFlow>(layout, forcing,
                                                                       physics.kappaSquared());
    }
    std::unique_ptr<ExactFlow<DistributedSUN>> fixed(const Eigen::MatrixXcd& forcing) const {
      return std::make_unique<DistributedZeitlinFixedForcingFlow>(layout, forcing);
    }
  };
  return zeitlinExactFlowsBy(Make{layout, physics}, d);
}

}  // namespace ddb
