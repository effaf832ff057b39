// Zeitlin's fluid (systems/zeitlin_fluid.h) on any matrix backend (docs/design/matrix-backend.md),
// given that backend's Poisson solve: the same system as makeZeitlinFluid's, a
// LiePoissonSystem on SUNOn<X> with k♯ = α·Id (ScaledIdentityMetric), whose Hamiltonian is the
// dense fluid's, evaluated through the backend (systems/zeitlin_hamiltonian.h). On MPI ranks it is
// the distributed fluid (distributed/distributed_zeitlin_fluid.h); every method of the method
// table's kBackendMatrixGroups family and Relaxation run on it.
#pragma once

#include <ddb/core/dissipation_metric.h>
#include <ddb/core/errors.h>
#include <ddb/core/lie_poisson_system.h>
#include <ddb/core/matrix_backend.h>
#include <ddb/groups/sun.h>
#include <ddb/systems/zeitlin_hamiltonian.h>

#include <memory>
#include <utility>

namespace ddb {

/// Zeitlin's Hamiltonian on matrices X (ZeitlinHamiltonianOf), with `Poisson::solve(const X& W,
/// X& out)` solving (Δ − κ²) out = W for a skew-Hermitian W. Every function is collective where
/// the backend's are; value() keeps the stream matrix in a workspace (one evaluation at a time).
template <class X, class Poisson>
using ZeitlinHamiltonianOn = ZeitlinHamiltonianOf<SUNOn<X>, Poisson>;

/// Zeitlin's fluid at resolution n on matrices X with k♯ = α·Id, given X's Poisson solve.
template <class X, class Poisson>
std::shared_ptr<const LiePoissonSystem<SUNOn<X>>> makeZeitlinFluidOn(Poisson poisson,
                                                                     Eigen::Index n, double alpha) {
  return makeLiePoissonSystem(
      "zeitlin", std::make_shared<const ZeitlinHamiltonianOn<X, Poisson>>(std::move(poisson), n),
      std::make_shared<const ScaledIdentityMetric<SUNOn<X>>>(alpha));
}

/// ... on a rotating sphere: `planetary` is F (zeitlinPlanetaryVorticity) in X's layout, and
/// `poisson` solves Δ − κ² for quasi-geostrophic flow; the states are absolute vorticities.
template <class X, class Poisson>
std::shared_ptr<const LiePoissonSystem<SUNOn<X>>> makeZeitlinFluidOn(Poisson poisson,
                                                                     Eigen::Index n, double alpha,
                                                                     X planetary) {
  return makeLiePoissonSystem("zeitlin",
                              std::make_shared<const ZeitlinHamiltonianOn<X, Poisson>>(
                                  std::move(poisson), n, std::move(planetary)),
                              std::make_shared<const ScaledIdentityMetric<SUNOn<X>>>(alpha));
}

}  // namespace ddb
