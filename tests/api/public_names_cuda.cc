// The CUDA backend's (ddb::cuda) public C++ names and headers that README.md and docs/guide/*.md
// show, each used so that removing or renaming one fails the build
// (tests/checks/check_public_names.py keeps the list complete). No main(): the compile is the test.

// docs/guide/gpu.md, "In your own program": its includes.
#include <ddb/cuda/cuda_device.h>
#include <ddb/cuda/cuda_zeitlin_fluid.h>
#include <ddb/integrators/drivers/relax.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/integrators/solvers/orbit_preconditioner.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
// CudaError's own header, and CudaMatrix's.
#include <ddb/cuda/cuda_context.h>
#include <ddb/cuda/cuda_error.h>
#include <ddb/cuda/cuda_matrix.h>
// docs/guide/gpu.md, "Run": the damping and forcing for the device's states.
#include <ddb/cuda/cuda_zeitlin_exact_flows.h>
// docs/guide/gpu.md, "The magnetic fluid": its header, the GPU's Laplacian and the host's.
#include <ddb/cuda/cuda_poisson_solver.h>
#include <ddb/cuda/cuda_zeitlin_mhd.h>
#include <ddb/systems/hoppe_yau_laplacian.h>

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace {

// Marks its arguments used: functions' addresses, member pointers, values.
template <class... T>
void use(const T&...) {}

using SystemPtr = std::shared_ptr<const ddb::LiePoissonSystem<ddb::CudaSUN>>;
using MethodPtr = std::unique_ptr<ddb::OneStepMethod<ddb::CudaSUN>>;

// docs/guide/defining-a-system.md: SUNOn<X>, here CudaSUN, is SU(N) with Algebra and Dual the
// backend's matrix type.
static_assert(std::is_same_v<ddb::CudaSUN, ddb::SUNOn<ddb::CudaMatrix>>);
static_assert(std::is_same_v<ddb::CudaSUN::Dual<double>, ddb::CudaMatrix>);
static_assert(std::is_same_v<ddb::CudaSUN::Algebra<double>, ddb::CudaMatrix>);
// The Newton search's preconditioner weighs the entries of the backend's eigenbasis
// (docs/guide/steady-states.md, "Newton on the orbit"), not the shift's alone.
static_assert(std::is_same_v<ddb::OrbitPreconditionerFor<ddb::CudaSUN>,
                             ddb::OrbitPreconditioner<ddb::CudaMatrix>>);

// The magnetic fluid's Newton search takes the shift's preconditioner on the GPU as on the host
// (docs/guide/steady-states.md).
static_assert(std::is_same_v<ddb::CudaDualNumberSUN, ddb::DualNumberSUNOn<ddb::CudaMatrix>>);
static_assert(std::is_same_v<ddb::OrbitPreconditionerFor<ddb::CudaDualNumberSUN>,
                             ddb::ShiftOrbitPreconditioner<ddb::DualMatrix<ddb::CudaMatrix>>>);

// docs/guide/gpu.md, "The magnetic fluid" (the method table's calls are the fluid's, below).
[[maybe_unused]] void gpuMagneticFluid() {
  const auto mhd = ddb::makeCudaZeitlinMhd(64, 0.5);
  const ddb::DualMatrix<ddb::CudaMatrix> mu =
      ddb::toDevice(ddb::zeitlinMhdState(ddb::randomVorticity(64, 1), ddb::randomVorticity(64, 2)));
  const ddb::DualMatrix<Eigen::MatrixXcd> back = ddb::toHost(mu);
  use(mhd->energy(mu), back);
  ddb::CudaPoissonSolver laplacian(64);
  ddb::CudaMatrix current;
  laplacian.apply(mu.real, current);
  Eigen::MatrixXcd host_current;
  ddb::HoppeYauLaplacian(64).apply(back.real, host_current);
  use(ddb::makeCudaZeitlinMhd(64, 0.5, ddb::CudaContext::ofThisThread()),
      ddb::toDevice(back, ddb::CudaContext::ofThisThread()));
  // The Newton search, with the shift's preconditioner (docs/guide/gpu.md, "The magnetic fluid").
  ddb::RelaxOptions options;
  options.newton = true;
  ddb::Relaxation<ddb::CudaDualNumberSUN> search(*mhd, mu, options);
  while (search.advance()) {
  }
}

// docs/guide/gpu.md
[[maybe_unused]] void gpuOwnProgram() {
  if (const std::optional<std::string> why = ddb::cudaUnavailable()) {
    use(*why);
    return;
  }
  try {
    const Eigen::MatrixXcd W0 = ddb::randomVorticity(1024, 1);
    const auto fluid = ddb::makeCudaZeitlinFluid(1024, 0.5);
    const auto method = ddb::makeMethod<ddb::CudaSUN>("sddb-cay", fluid);
    ddb::RelaxOptions options;
    options.max_steps = 1000;
    ddb::Relaxation<ddb::CudaSUN> run(*method, *fluid, ddb::toDevice(W0), 0.01, options);
    while (run.advance()) {
    }
    const Eigen::MatrixXcd W = ddb::toHost(run.current());
    Eigen::MatrixXcd again;
    ddb::toHost(run.current(), again);
    use(W, again);
  } catch (const ddb::CudaError& failed) {
    use(failed.what());
  }
}

[[maybe_unused]] void gpuNames() {
  use(static_cast<SystemPtr (*)(long, double)>(&ddb::makeCudaZeitlinFluid),
      static_cast<MethodPtr (*)(std::string_view, SystemPtr)>(&ddb::makeMethod<ddb::CudaSUN>),
      static_cast<MethodPtr (*)(const ddb::MethodInfo&, SystemPtr)>(&ddb::makeMethod<ddb::CudaSUN>),
      static_cast<std::optional<std::string> (*)()>(&ddb::cudaUnavailable),
      static_cast<ddb::CudaMatrix (*)(const Eigen::MatrixXcd&)>(&ddb::toDevice),
      static_cast<Eigen::MatrixXcd (*)(const ddb::CudaMatrix&)>(&ddb::toHost),
      static_cast<void (*)(const ddb::CudaMatrix&, Eigen::MatrixXcd&)>(&ddb::toHost),
      static_cast<void (*)(const Eigen::MatrixXcd&, ddb::CudaMatrix&)>(&ddb::toDevice),
      static_cast<ddb::CudaMatrix (*)(const Eigen::MatrixXcd&,
                                      const std::shared_ptr<ddb::CudaContext>&)>(&ddb::toDevice),
      static_cast<SystemPtr (*)(long, double, std::shared_ptr<ddb::CudaContext>)>(
          &ddb::makeCudaZeitlinFluid),
      &ddb::CudaContext::create, &ddb::CudaContext::ofThisThread, &ddb::CudaContext::synchronize,
      &ddb::CudaMatrix::context,
      static_cast<std::vector<std::unique_ptr<ddb::ExactFlow<ddb::CudaSUN>>> (*)(
          const ddb::ZeitlinHamiltonian&, const ddb::ZeitlinDampingAndForcing&)>(
          &ddb::cudaZeitlinExactFlows),
      &ddb::Relaxation<ddb::CudaSUN>::advance, &ddb::Relaxation<ddb::CudaSUN>::current);
  static_assert(
      std::is_constructible_v<ddb::Relaxation<ddb::CudaSUN>, ddb::OneStepMethod<ddb::CudaSUN>&,
                              const ddb::LiePoissonSystem<ddb::CudaSUN>&, const ddb::CudaMatrix&,
                              double, const ddb::RelaxOptions&>);
}

}  // namespace
