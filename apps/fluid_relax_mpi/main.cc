// fluid-relax-mpi: fluid-relax's relaxation with every N×N matrix distributed block-cyclically
// over the ranks of an MPI job (docs/design/distributed.md, "fluid-relax-mpi"). The run is
// fluid-relax's (fluid_relax/fluid_run.h) on the distributed fluid (makeDistributedZeitlinFluid,
// a LiePoissonSystem on DistributedSUN; fluid_relax_mpi/distributed_placement.h): the method of
// --method built by makeMethod (the method table's methods for any backend) and Relaxation
// (fixed steps, --adaptive's energy step control, --until-steady); this file is MPI's set-up
// around that call. The command line, its checks and the files are fluid-relax's
// (docs/reference/command-lines-and-files.md), written by rank 0 from the states gathered there for
// the history rows and at the end; summary.json adds mpi_ranks, process_grid and block_size. Exit
// statuses as fluid-relax's, agreed by every rank: 2 bad input on any rank (nothing written),
// 1 a failed step or a file rank 0 could not write, 130/143 a SIGINT/SIGTERM on any rank
// (outputs and a checkpoint written); anything unexpected on one rank ends the job
// (MPI_Abort). Checkpoints are Relaxation's record (docs/design/distributed.md, "Checkpoints"), so
// either app resumes the other's; with --h5, rank 0 appends fluid.hdf5's frames as fluid-relax
// does.
#include <ddb/distributed/process_grid.h>
#include <mpi.h>
#include <spdlog/spdlog.h>

#include <cstdio>
#include <exception>
#include <optional>

#include "common/cli.h"
#include "common/exit_status.h"
#include "common/logging.h"
#include "fluid_relax/fluid_run.h"
#include "fluid_relax/outputs.h"
#include "fluid_relax_mpi/distributed_placement.h"
#include "fluid_relax_mpi/mpi_input.h"

namespace {

using namespace ddb;
using namespace ddb::fluid;
using namespace ddb::fluid_mpi;

// fluid-relax's run (fluid_relax/fluid_run.h) on distributed states. A resumed run starts from
// W₀ too (rank 0's, from the checkpoint), which the checkpoint's state replaces: the Newton
// search takes its direction from W₀'s energy rate, as fluid-relax's resumed search does.
int relax(MpiRun& run, const ProcessGrid& grid) {
  DistributedPlacement where(run, grid);
  return runFluidRelaxation(where, run.options, run.settings, run.given,
                            run.resume ? &*run.resume : nullptr, run.lock);
}

int run(int argc, char** argv, const ProcessGrid& grid) {
  CLI::App cli{
      "Relax Zeitlin's SU(N) fluid on the sphere with double-bracket dissipation, "
      "distributed over MPI ranks",
      fluid_mpi::kApp};
  MpiOptions o;
  addMpiOptions(cli, o);
  std::optional<int> status;
  try {
    status = app::parseCommandLine(cli, argc, argv);
  } catch (const app::UsageError& e) {
    // Every rank parsed the same command line: rank 0 speaks for all.
    if (grid.rank() == 0) std::fprintf(stderr, "%s: %s\n", fluid_mpi::kApp, e.what());
    return app::kExitBadInput;
  }
  if (status) return *status;
  app::setupLogging(o.relax.log);
  if (grid.rank() != 0) spdlog::set_level(spdlog::level::off);
  MpiRun run = mpiRun(cli, o, grid);
  // --grid-rows: a grid of the same ranks in the shape asked for (every rank agreed on it).
  std::optional<ProcessGrid> shaped;
  if (run.grid_rows != grid.rows()) shaped.emplace(grid.comm(), run.grid_rows);
  const int result = relax(run, shaped ? *shaped : grid);
  // Rank 0 makes the figures; every rank exits with its status.
  int exit_status = grid.rank() == 0 ? makeFigures(run.options, run.settings.out, result,
                                                   DDB_PLOT_SCRIPT, DDB_ANIMATE_SCRIPT)
                                     : result;
  MPI_Bcast(&exit_status, 1, MPI_INT, 0, grid.comm());
  return exit_status;
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int status = ddb::app::kExitFailed;
  {
    const ddb::ProcessGrid grid;
    // --help and --version are printed once.
    if (grid.rank() != 0 && std::freopen("/dev/null", "w", stdout) == nullptr) {
      MPI_Abort(MPI_COMM_WORLD, ddb::app::kExitFailed);
    }
    try {
      status = run(argc, argv, grid);
    } catch (const Reported& reported) {
      status = reported.status;
    } catch (const std::exception& e) {
      // Not an outcome every rank shares: the others may wait in a collective call.
      std::fprintf(stderr, "%s: rank %d: %s\n", fluid_mpi::kApp, grid.rank(), e.what());
      MPI_Abort(MPI_COMM_WORLD, ddb::app::kExitFailed);
    }
  }
  MPI_Finalize();
  return status;
}
