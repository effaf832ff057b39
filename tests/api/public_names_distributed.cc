// The distributed layer's (ddb::distributed) public C++ names and headers that README.md and
// docs/guide/*.md show, each used so that removing or renaming one fails the build
// (tests/checks/check_public_names.py keeps the list complete). No main(): the compile is the test.

#include <ddb/core/matrix_backend.h>
#include <ddb/distributed/block_cyclic_layout.h>
#include <ddb/distributed/distributed_backend.h>
#include <ddb/distributed/distributed_matrix.h>
#include <ddb/distributed/distributed_zeitlin_exact_flows.h>
#include <ddb/distributed/distributed_zeitlin_fluid.h>
#include <ddb/distributed/distributed_zeitlin_mhd.h>
#include <ddb/distributed/process_grid.h>
#include <ddb/groups/sun.h>
#include <ddb/integrators/drivers/relax.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/integrators/solvers/orbit_preconditioner.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <ddb/systems/zeitlin_step_size.h>
#include <mpi.h>

#include <Eigen/Core>
#include <memory>
#include <string_view>
#include <type_traits>

namespace {

// Marks its arguments used: functions' addresses, member pointers, values.
template <class... T>
void use(const T&...) {}

using SystemPtr = std::shared_ptr<const ddb::LiePoissonSystem<ddb::DistributedSUN>>;
using MethodPtr = std::unique_ptr<ddb::OneStepMethod<ddb::DistributedSUN>>;

// docs/guide/defining-a-system.md: SUNOn<X>, here DistributedSUN, is SU(N) with Algebra and Dual
// the backend's matrix type.
static_assert(std::is_same_v<ddb::DistributedSUN, ddb::SUNOn<ddb::DistributedMatrix>>);
static_assert(std::is_same_v<ddb::DistributedSUN::Dual<double>, ddb::DistributedMatrix>);
static_assert(std::is_same_v<ddb::DistributedSUN::Algebra<double>, ddb::DistributedMatrix>);
// The Newton search's preconditioner weighs the entries of the backend's eigenbasis
// (docs/guide/steady-states.md, "Newton on the orbit"), not the shift's alone.
static_assert(std::is_same_v<ddb::OrbitPreconditionerFor<ddb::DistributedSUN>,
                             ddb::OrbitPreconditioner<ddb::DistributedMatrix>>);

// docs/guide/cluster.md: a process grid over MPI_COMM_WORLD, a seeded random vorticity scattered
// over it, makeMethod<ddb::DistributedSUN> on makeDistributedZeitlinFluid, the gathered W; the
// same Relaxation as fluid-relax (core/matrix_backend.h: MatrixBackend<DistributedMatrix>).
[[maybe_unused]] void clusterOwnMpiProgram() {
  const int n = 64, block = 16;
  const double alpha = 0.5;
  const ddb::ProcessGrid grid(MPI_COMM_WORLD);
  const Eigen::MatrixXcd W0 = ddb::randomVorticity(n, 1);
  const double h = ddb::zeitlinDefaultStep(W0, alpha);
  ddb::DistributedMatrix W(grid, n, block);
  W.scatterFrom(W0);
  const auto fluid = ddb::makeDistributedZeitlinFluid(W.layout(), alpha);
  const auto step = ddb::makeMethod<ddb::DistributedSUN>("ddb-cay", fluid);
  try {
    for (int k = 0; k < 3; ++k) step->advance(W, k * h, h);
  } catch (const ddb::SolveFailure& failure) {
    use(failure.step());
  }
  const Eigen::MatrixXcd gathered = W.gather();

  ddb::RelaxOptions options;
  options.max_steps = 10;
  ddb::Relaxation<ddb::DistributedSUN> run(*step, *fluid, W, h, options);
  while (run.advance()) {
  }
  const Eigen::MatrixXcd final_state = run.current().gather();
  use(gathered, final_state, grid.rank(),
      ddb::MatrixBackend<ddb::DistributedMatrix>::frobeniusNorm(W));
}

// docs/guide/matrix-groups-and-the-fluid.md: magnetohydrodynamics on MPI ranks.
[[maybe_unused]] void magnetohydrodynamicsOnRanks(const ddb::ProcessGrid& grid) {
  ddb::DualMatrix<ddb::DistributedMatrix> mu{ddb::DistributedMatrix(grid, 16, 4),
                                             ddb::DistributedMatrix(grid, 16, 4)};
  const auto mhd = ddb::makeDistributedZeitlinMhd(mu.real.layout(), 0.5);
  const auto step = ddb::makeMethod<ddb::DistributedDualNumberSUN>("ddb-cay", mhd);
  step->advance(mu, 0.0, 0.01);
  use(mhd->energy(mu));
}

// docs/guide/matrix-groups-and-the-fluid.md: the damping and forcing on MPI ranks.
[[maybe_unused]] void dampingAndForcingOnRanks(const ddb::BlockCyclicLayout& layout) {
  ddb::ZeitlinDampingAndForcing d;
  d.viscosity.viscosity = 1e-3;
  const auto flows = ddb::distributedZeitlinExactFlows(layout, ddb::ZeitlinPhysics{}, d);
  ddb::DistributedZeitlinViscousFlow viscous(layout, d.viscosity, 2.0);
  use(flows.size(), viscous.name());
}

[[maybe_unused]] void clusterNames() {
  use(static_cast<SystemPtr (*)(const ddb::BlockCyclicLayout&, double)>(
          &ddb::makeDistributedZeitlinFluid),
      static_cast<MethodPtr (*)(std::string_view, SystemPtr)>(
          &ddb::makeMethod<ddb::DistributedSUN>),
      static_cast<MethodPtr (*)(const ddb::MethodInfo&, SystemPtr)>(
          &ddb::makeMethod<ddb::DistributedSUN>),
      &ddb::DistributedMatrix::scatterFrom, &ddb::DistributedMatrix::gather,
      &ddb::DistributedMatrix::layout, &ddb::ProcessGrid::rank,
      &ddb::Relaxation<ddb::DistributedSUN>::advance,
      &ddb::Relaxation<ddb::DistributedSUN>::current);
  static_assert(std::is_constructible_v<ddb::ProcessGrid, MPI_Comm, int>);
  static_assert(std::is_constructible_v<ddb::DistributedMatrix, const ddb::ProcessGrid&, int, int>);
  static_assert(
      std::is_constructible_v<ddb::Relaxation<ddb::DistributedSUN>,
                              ddb::OneStepMethod<ddb::DistributedSUN>&,
                              const ddb::LiePoissonSystem<ddb::DistributedSUN>&,
                              const ddb::DistributedMatrix&, double, const ddb::RelaxOptions&>);
}

}  // namespace
