// Zeitlin's fluid on one GPU: the fluid on any backend (systems/zeitlin_fluid_on_backend.h) with
// CudaPoissonSolver's Poisson solve, an ordinary LiePoissonSystem on SU(N) whose states are
// CudaMatrix (CudaSUN). The method table's methods for any backend (makeMethod) and Relaxation
// run on it (docs/guide/gpu.md).
#pragma once

#include <ddb/cuda/cuda_backend.h>
#include <ddb/cuda/cuda_device.h>
#include <ddb/cuda/cuda_method_table.h>
#include <ddb/cuda/cuda_poisson_solver.h>
#include <ddb/groups/sun.h>
#include <ddb/systems/zeitlin_fluid_on_backend.h>

#include <memory>

namespace ddb {

/// SU(N) with its states in one GPU's memory.
using CudaSUN = SUNOn<CudaMatrix>;

/// The fluid at resolution n with k♯ = α·Id, its Poisson factors on the device in `context`
/// (cuda/cuda_context.h), whose states it takes.
inline std::shared_ptr<const LiePoissonSystem<CudaSUN>> makeCudaZeitlinFluid(
    long n, double alpha, std::shared_ptr<CudaContext> context) {
  return makeZeitlinFluidOn<CudaMatrix>(CudaPoissonSolver(n, 0.0, std::move(context)), n, alpha);
}
/// ... in this thread's context (CudaContext::ofThisThread()).
inline std::shared_ptr<const LiePoissonSystem<CudaSUN>> makeCudaZeitlinFluid(long n, double alpha) {
  return makeCudaZeitlinFluid(n, alpha, nullptr);
}
/// ... on a rotating sphere and/or quasi-geostrophic (ZeitlinPhysics; InvalidArgument naming the
/// parameter): states are absolute vorticities.
inline std::shared_ptr<const LiePoissonSystem<CudaSUN>> makeCudaZeitlinFluid(
    long n, double alpha, const ZeitlinPhysics& physics, std::shared_ptr<CudaContext> context) {
  physics.validate();
  CudaPoissonSolver poisson(n, physics.kappaSquared(), std::move(context));
  CudaMatrix planetary =
      toDevice(zeitlinPlanetaryVorticity(n, physics.rotation), poisson.context());
  return makeZeitlinFluidOn<CudaMatrix>(std::move(poisson), n, alpha, std::move(planetary));
}
inline std::shared_ptr<const LiePoissonSystem<CudaSUN>> makeCudaZeitlinFluid(
    long n, double alpha, const ZeitlinPhysics& physics) {
  return makeCudaZeitlinFluid(n, alpha, physics, nullptr);
}

}  // namespace ddb
