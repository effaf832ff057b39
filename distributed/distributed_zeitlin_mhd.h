// Magnetohydrodynamics on the sphere (systems/zeitlin_mhd.h) on matrices distributed over MPI
// ranks: SU(N) ⋉ su(N)* on DualMatrix<DistributedMatrix> (two block-cyclic matrices, W and Θ, of
// one layout), with DistributedPoissonSolver's solve and apply. The method table's rows that run on
// the dense magnetic fluid (makeMethod; the exponential ones through DualEigenbasis on
// DistributedEigenbasis, core/dual_eigenbasis.h) and Relaxation run on it; every call is
// collective.
#pragma once

#include <ddb/core/dual_matrix.h>
#include <ddb/distributed/distributed_backend.h>
#include <ddb/distributed/distributed_method_table.h>
#include <ddb/distributed/distributed_poisson_solver.h>
#include <ddb/groups/dual_number_sun.h>
#include <ddb/systems/zeitlin_mhd.h>

#include <memory>

namespace ddb {

/// SU(N) ⋉ su(N)* with its states' parts distributed block-cyclically over MPI ranks.
using DistributedDualNumberSUN = DualNumberSUNOn<DistributedMatrix>;

/// The magnetic fluid of `layout`'s size with k♯ = α·swap; collective.
inline std::shared_ptr<const LiePoissonSystem<DistributedDualNumberSUN>> makeDistributedZeitlinMhd(
    const BlockCyclicLayout& layout, double alpha) {
  return makeZeitlinMhdOn<DistributedMatrix>(DistributedPoissonSolver(layout), layout.size(),
                                             alpha);
}

}  // namespace ddb
