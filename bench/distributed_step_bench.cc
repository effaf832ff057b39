// The DDB Cayley step on distributed matrices (Ddb<Cayley<DistributedSUN>> of the distributed
// fluid, distributed/distributed_zeitlin_fluid.h) timed against one
// distributed complex N×N product (pzgemm_) in the same run, on the ranks it is started
// with (docs/results/distributed.md, "Measured"): products per step = step time / product time;
// strong scaling = the step time on 1 rank over that on P. On one rank it also times the
// dense step (Ddb<Cayley<SUN>>), the serial engine, as the peer. State: the seeded random
// vorticity (seed 1, ‖W‖_F = √N), h = min(0.02 ħ/‖P₀‖₂, 4ħ/(|α| ‖W₀‖₂²)) (fluid-relax's
// default, systems/zeitlin_step_size.h), α as given,
// Legendre tolerance 1e-12 relative as the Zeitlin benchmarks; 10 untimed steps fill the
// predictor. Times are the largest over the ranks (MPI_Wtime between barriers). Prints one
// JSON object from rank 0, with the bytes sent to other ranks per product and per step
// (summed over the ranks; counted at the MPI calls, mpi_byte_counter.cc). The BLAS thread
// count is the environment's. grid_rows picks the process grid's shape (0, the default: the
// ProcessGrid's own, rows ≥ cols).
//
//   mpiexec -n P distributed-step-bench N [steps] [alpha] [block] [grid_rows]
#include <ddb/distributed/distributed_zeitlin_fluid.h>
#include <ddb/distributed/process_grid.h>
#include <ddb/integrators/methods/ddb.h>
#include <ddb/systems/zeitlin_fluid.h>
#include <ddb/systems/zeitlin_initial_conditions.h>
#include <ddb/systems/zeitlin_step_size.h>
#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>

#include "mpi_byte_counter.h"

namespace {

using namespace ddb;

struct PerCall {
  double seconds;  // the largest over the ranks
  double bytes;    // sent to other ranks, summed over the ranks
};

// Time and bytes per call of f over `count` calls.
PerCall perCall(const ProcessGrid& grid, long count, const std::function<void()>& f) {
  MPI_Barrier(grid.comm());
  const std::int64_t sent = bench::mpiBytesSent();
  const double begin = MPI_Wtime();
  for (long i = 0; i < count; ++i) f();
  const double local = (MPI_Wtime() - begin) / static_cast<double>(count);
  const double bytes = static_cast<double>(bench::mpiBytesSent() - sent) / count;
  MPI_Barrier(grid.comm());
  return {grid.max(local), grid.sum(bytes)};
}

int runBench(int argc, char** argv, const ProcessGrid& grid) {
  if (argc < 2) {
    if (grid.rank() == 0)
      std::fprintf(stderr, "usage: distributed-step-bench N [steps] [alpha] [block] [grid_rows]\n");
    return 2;
  }
  const int n = std::atoi(argv[1]);
  const long steps = argc > 2 ? std::atol(argv[2]) : 20;
  const double alpha = argc > 3 ? std::atof(argv[3]) : 0.5;
  const int block = argc > 4 ? std::atoi(argv[4]) : 64;
  constexpr long kWarmUp = 10;
  SolverOptions options;
  options.relative_tolerance = 1e-12;

  const Eigen::MatrixXcd W0 = randomVorticity(n, 1);
  const double h = zeitlinDefaultStep(W0, alpha);

  DistributedMatrix W(grid, n, block), a(W.layout()), b(W.layout()), c(W.layout());
  W.scatterFrom(W0);
  a.scatterFrom(W0);
  b.scatterFrom(W0);
  multiply(a, b, c);  // untimed: BLACS sets up its buffers on the first call
  const PerCall product = perCall(grid, 10, [&] { multiply(a, b, c); });

  Ddb<Cayley<DistributedSUN>> ddb(makeDistributedZeitlinFluid(W.layout(), alpha),
                                  Cayley<DistributedSUN>(), LegendreForm::kHamiltonian, options);
  long k = 0, sweeps = 0, refinements = 0, newton = 0;
  for (; k < kWarmUp; ++k) ddb.advance(W, k * h, h);
  const PerCall step = perCall(grid, steps, [&] {
    ddb.advance(W, k * h, h);
    ++k;
    const LegendreStats& stats = ddb.legendreSolver().stats();
    sweeps += stats.fixed_point;
    refinements += stats.refinements;
    newton += stats.newton;
  });

  double dense_step = 0.0;
  if (grid.size() == 1) {
    Ddb<Cayley<SUN>> dense(makeZeitlinFluid(n, alpha), Cayley<SUN>(), LegendreForm::kHamiltonian,
                           options);
    Eigen::MatrixXcd Wd = W0;
    long j = 0;
    for (; j < kWarmUp; ++j) dense.advance(Wd, j * h, h);
    dense_step = perCall(grid, steps, [&] {
                   dense.advance(Wd, j * h, h);
                   ++j;
                 }).seconds;
  }
  if (grid.rank() == 0) {
    std::printf(
        "{\"n\": %d, \"ranks\": %d, \"grid\": [%d, %d], \"block\": %d, \"alpha\": %g, \"steps\": "
        "%ld, \"product_s\": %.6g, \"step_s\": %.6g, \"products_per_step\": %.4g, "
        "\"sweeps_per_step\": %.4g, \"refinements_per_step\": %.4g, \"newton_per_step\": %.4g, "
        "\"bytes_per_product\": %.4g, \"bytes_per_step\": %.4g, \"dense_step_s\": %s}\n",
        n, grid.size(), grid.rows(), grid.cols(), block, alpha, steps, product.seconds,
        step.seconds, step.seconds / product.seconds, double(sweeps) / steps,
        double(refinements) / steps, double(newton) / steps, product.bytes, step.bytes,
        grid.size() == 1 ? std::to_string(dense_step).c_str() : "null");
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int status = 0;
  try {
    // grid_rows: a whole number (ProcessGrid refuses one that does not divide P).
    int rows = 0;
    if (argc > 5) {
      char* end = nullptr;
      const long value = std::strtol(argv[5], &end, 10);
      if (end == argv[5] || *end != '\0' || value < 1 || value > 1 << 20) {
        ddb::throwInvalid("grid rows", argv[5], "must be a positive integer");
      }
      rows = static_cast<int>(value);
    }
    const ddb::ProcessGrid grid(MPI_COMM_WORLD, rows);
    status = runBench(argc, argv, grid);
  } catch (const ddb::InvalidArgument& e) {
    int rank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (rank == 0) std::fprintf(stderr, "distributed-step-bench: %s\n", e.what());
    status = 2;
  }
  MPI_Finalize();
  return status;
}
