// Zeitlin's fluid (systems/zeitlin_fluid.h) on matrices distributed over MPI ranks: the fluid
// on any backend (systems/zeitlin_fluid_on_backend.h) with DistributedPoissonSolver's Poisson
// solve, an ordinary LiePoissonSystem on SU(N) with distributed states (DistributedSUN). The
// method table's methods for any backend (makeMethod) and Relaxation run on it; every call is
// collective (docs/design/distributed.md, "One step formula").
#pragma once

#include <ddb/distributed/distributed_backend.h>
#include <ddb/distributed/distributed_method_table.h>
#include <ddb/distributed/distributed_poisson_solver.h>
#include <ddb/systems/zeitlin_fluid_on_backend.h>

#include <memory>
#include <utility>

namespace ddb {

/// SU(N) with its states distributed block-cyclically over MPI ranks.
using DistributedSUN = SUNOn<DistributedMatrix>;

/// The fluid of `layout`'s size with k♯ = α·Id; collective.
inline std::shared_ptr<const LiePoissonSystem<DistributedSUN>> makeDistributedZeitlinFluid(
    const BlockCyclicLayout& layout, double alpha) {
  return makeZeitlinFluidOn<DistributedMatrix>(DistributedPoissonSolver(layout), layout.size(),
                                               alpha);
}

/// ... on a rotating sphere and/or quasi-geostrophic (ZeitlinPhysics; InvalidArgument naming the
/// parameter, on every rank): states are absolute vorticities. Collective.
inline std::shared_ptr<const LiePoissonSystem<DistributedSUN>> makeDistributedZeitlinFluid(
    const BlockCyclicLayout& layout, double alpha, const ZeitlinPhysics& physics) {
  physics.validate();
  DistributedMatrix planetary(layout);
  // F is the same formula on every rank; rank 0's copy is scattered.
  planetary.scatterFrom(zeitlinPlanetaryVorticity(layout.size(), physics.rotation));
  return makeZeitlinFluidOn<DistributedMatrix>(
      DistributedPoissonSolver(layout, physics.kappaSquared()), layout.size(), alpha,
      std::move(planetary));
}

}  // namespace ddb
