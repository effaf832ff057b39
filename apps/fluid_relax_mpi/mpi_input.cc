#include "fluid_relax_mpi/mpi_input.h"

#include <mpi.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <vector>

#include "common/cli.h"
#include "common/exit_status.h"
#include "common/initial_vorticity.h"

namespace ddb::fluid_mpi {

namespace {

// What fluid-relax has and this app does not yet (docs/distributed.md, "Not done yet").
void refuseUnsupported(const CLI::App& cli, const fluid::Options& o) {
  if (o.method != "ddb-cay") {
    app::usageError("--method", o.method, "fluid-relax-mpi runs ddb-cay only");
  }
  for (const char* flag :
       {"--adaptive", "--newton", "--checkpoint-every", "--resume", "--h5", "--animate"}) {
    if (cli.count(flag) > 0) {
      throw app::UsageError(std::string(flag) +
                            ": not available in fluid-relax-mpi (docs/distributed.md); run "
                            "fluid-relax for it");
    }
  }
}

int readBlock(const MpiOptions& o, const ProcessGrid& grid, long n) {
  if (o.block.empty()) {
    // ⌊N/q⌋ gives every process row and column at least one block (⌈N/q⌉ may not: N = 6
    // on a 1×5 grid would give 3 blocks of 2).
    const long per_process = n / std::max(grid.rows(), grid.cols());
    return static_cast<int>(std::clamp<long>(per_process, 1, kDefaultBlock));
  }
  const double block = app::parseNumber("--block", o.block, o.block);
  if (!(block >= 1 && block <= static_cast<double>(n) && block == static_cast<int>(block))) {
    app::usageError("--block", o.block,
                    "must be an integer in [1, N] (N = " + std::to_string(n) + ")");
  }
  return static_cast<int>(block);
}

// Every rank's outcome (0 ok, 2 usage error, 1 other) made everyone's: the largest status,
// the message of the lowest rank with it, printed by that rank.
int agree(const ProcessGrid& grid, int status, const std::string& message) {
  int worst = status;
  MPI_Allreduce(MPI_IN_PLACE, &worst, 1, MPI_INT, MPI_MAX, grid.comm());
  if (worst == 0) return 0;
  int speaker = status == worst ? grid.rank() : grid.size();
  MPI_Allreduce(MPI_IN_PLACE, &speaker, 1, MPI_INT, MPI_MIN, grid.comm());
  if (speaker == grid.rank()) {
    const std::string where = grid.rank() == 0 ? "" : "rank " + std::to_string(grid.rank()) + ": ";
    std::fprintf(stderr, "%s: %s%s\n", kApp, where.c_str(), message.c_str());
  }
  return worst;
}

// Runs `job` where `here`, then agree() on its outcome: a UsageError is status 2, any other
// exception 1.
int runAndAgree(const ProcessGrid& grid, bool here, const std::function<void()>& job) {
  int status = 0;
  std::string message;
  if (here) {
    try {
      job();
    } catch (const app::UsageError& e) {
      status = app::kExitBadInput;
      message = e.what();
    } catch (const std::exception& e) {
      status = app::kExitFailed;
      message = e.what();
    }
  }
  return agree(grid, status, message);
}

}  // namespace

void addMpiOptions(CLI::App& cli, MpiOptions& o) {
  fluid::addOptions(cli, o.relax, kMaxN);
  cli.add_option(
      "--block", o.block,
      "block size of the block-cyclic layout (default: " + std::to_string(kDefaultBlock) +
          ", or N / max(grid rows, grid cols) rounded down if smaller)");
  cli.footer(
      "\nfluid-relax-mpi is fluid-relax's ddb-cay relaxation with every N x N matrix "
      "distributed over the MPI ranks\n(docs/distributed.md): start it with mpirun -np P. "
      "Not available here: --method other than ddb-cay,\n--adaptive, --newton, "
      "--checkpoint-every, --resume, --h5, --animate.\n\nInitial vorticities (--init; all "
      "scaled to ||W||_F = sqrt(N), seeded by --seed):\n" +
      app::describeChoices(app::initDescriptions()) +
      "\nFiles in --out (written by rank 0): history.csv, W_final.csv, omega_initial.csv, "
      "omega_final.csv, summary.json\n(docs/file-formats.md). Exit status: 0 ok, 1 a step "
      "failed or a file could not be written, 2 bad input\n(nothing written), 130/143 "
      "stopped by SIGINT/SIGTERM (outputs written).\n");
}

fluid::Settings mpiSettings(const CLI::App& cli, const MpiOptions& o, const ProcessGrid& grid,
                            int& block) {
  fluid::Settings s;
  const int agreed = runAndAgree(grid, true, [&] {
    refuseUnsupported(cli, o.relax);
    s = fluid::settings(cli, o.relax, kMaxN);
    block = readBlock(o, grid, s.W0.rows());
  });
  if (agreed != 0) throw Reported{agreed};
  return s;
}

int onRankZero(const ProcessGrid& grid, const std::function<void()>& job) {
  return runAndAgree(grid, grid.rank() == 0, job);
}

}  // namespace ddb::fluid_mpi
