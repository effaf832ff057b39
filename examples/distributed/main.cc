// Zeitlin's fluid on SU(N) over the ranks of an MPI job (docs/design/distributed.md): a seeded
// random vorticity W₀ is scattered block-cyclically over a process grid of MPI_COMM_WORLD,
// a few DDB Cayley steps (α = 0.5) are taken on the distributed matrices, and the gathered
// W is checked on rank 0 against the dense step of the same library from the same W₀ (to
// 1e-12 relative) and against W₀'s spectrum, which the step keeps (Eigen's eigensolver,
// to 1e-12 relative). Every rank exits with status 1 if a check fails.
//   mpiexec -n 2 ./app
#include <ddb/distributed/distributed_zeitlin_fluid.h>
#include <ddb/distributed/process_grid.h>
#include <ddb/groups/sun.h>
#include <ddb/integrators/methods/ddb.h>
#include <ddb/integrators/methods/method_table.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <ddb/systems/zeitlin_step_size.h>
#include <mpi.h>

#include <cstdio>
#include <exception>

namespace {

constexpr int kN = 24;     // resolution
constexpr int kBlock = 5;  // ScaLAPACK block size (any b ≥ 1; it need not divide N)
constexpr int kSteps = 10;
constexpr double kAlpha = 0.5;
constexpr double kTolerance = 1e-12;

double relativeDistance(const Eigen::MatrixXcd& a, const Eigen::MatrixXcd& b) {
  return (a - b).norm() / b.norm();
}

// The distributed run and, on rank 0, its checks; true on every rank when they pass.
bool run() {
  const ddb::ProcessGrid grid(MPI_COMM_WORLD);
  // Every rank draws the same W₀ (only rank 0's is read by the scatter) and so computes
  // the same step size, fluid-relax's default.
  const Eigen::MatrixXcd W0 = ddb::randomVorticity(kN, 1);
  const double h = ddb::zeitlinDefaultStep(W0, kAlpha);

  ddb::DistributedMatrix W(grid, kN, kBlock);
  W.scatterFrom(W0);
  // The library's fluid and method, on distributed states (ddb::DistributedSUN).
  const auto fluid = ddb::makeDistributedZeitlinFluid(W.layout(), kAlpha);
  const auto step = ddb::makeMethod<ddb::DistributedSUN>("ddb-cay", fluid);
  // Every call is collective: a failed solve throws ddb::SolveFailure on every rank.
  for (int k = 0; k < kSteps; ++k) step->advance(W, k * h, h);
  const Eigen::MatrixXcd W_distributed = W.gather();  // whole on rank 0, empty elsewhere

  int passed = 1;
  if (grid.rank() == 0) {
    ddb::Ddb<ddb::Cayley<ddb::SUN>> dense(ddb::makeZeitlinFluid(kN, kAlpha),
                                          ddb::Cayley<ddb::SUN>(), ddb::LegendreForm::kHamiltonian);
    Eigen::MatrixXcd W_dense = W0;
    for (int k = 0; k < kSteps; ++k) dense.advance(W_dense, k * h, h);

    const double against_dense = relativeDistance(W_distributed, W_dense);
    const double moved = relativeDistance(W_distributed, W0);
    const Eigen::VectorXd initial = ddb::SUN::casimirs(W0);
    const double spectrum_drift =
        (ddb::SUN::casimirs(W_distributed) - initial).norm() / initial.norm();
    // The step must have moved W, or agreeing with the dense step would prove nothing.
    passed = against_dense < kTolerance && spectrum_drift < kTolerance && moved > kTolerance;
    std::printf(
        "N = %d, alpha = %g, %d steps of h = %.6g on %d ranks (%dx%d grid, block %d): "
        "|W - W_dense|/|W_dense| = %.2e, spectrum drift %.2e, |W - W0|/|W0| = %.2e: %s\n",
        kN, kAlpha, kSteps, h, grid.size(), grid.rows(), grid.cols(), kBlock, against_dense,
        spectrum_drift, moved, passed ? "passed" : "FAILED");
  }
  MPI_Bcast(&passed, 1, MPI_INT, 0, grid.comm());
  return passed == 1;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  bool passed = false;
  try {
    passed = run();
  } catch (const std::exception& error) {
    // A failure thrown on some ranks only would leave the others waiting in a collective,
    // so the whole job is stopped.
    std::fprintf(stderr, "%s\n", error.what());
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  MPI_Finalize();
  return passed ? 0 : 1;
}
