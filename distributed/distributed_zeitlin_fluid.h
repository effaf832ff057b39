// Zeitlin's fluid (systems/zeitlin_fluid.h) on matrices distributed over MPI ranks: the
// fluid on the distributed backend (systems/zeitlin_fluid_on_backend.h) with
// DistributedPoissonSolver's Poisson solve, the system the distributed DDB Cayley step is
// instantiated with (docs/distributed.md, "One step formula").
#pragma once

#include <ddb/distributed/distributed_backend.h>
#include <ddb/distributed/distributed_poisson_solver.h>
#include <ddb/systems/zeitlin_fluid_on_backend.h>

namespace ddb {

class DistributedZeitlinFluid
    : public ZeitlinFluidOnBackend<DistributedMatrix, DistributedPoissonSolver> {
 public:
  /// The fluid of `layout`'s size with k♯ = α·Id; collective.
  DistributedZeitlinFluid(const BlockCyclicLayout& layout, double alpha)
      : ZeitlinFluidOnBackend(DistributedPoissonSolver(layout), layout.size(), alpha) {}
};

}  // namespace ddb
