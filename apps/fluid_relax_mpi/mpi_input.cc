#include "fluid_relax_mpi/mpi_input.h"

#include <ddb/core/binary_record.h>
#include <ddb/distributed/rank_zero_record_reader.h>
#include <ddb/integrators/methods/method_table.h>
#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <vector>

#include "common/cli.h"
#include "common/exit_status.h"
#include "common/initial_vorticity.h"
#include "common/resume.h"
#include "fluid_relax/run_files.h"

namespace ddb::fluid_mpi {

namespace {

// The run's definition (options, given flags, settings but W₀) and N, made on rank 0, on
// every rank: written and read as the checkpoint writes and reads them, each value broadcast
// by a RankZeroRecordReader. The other ranks never hold W₀ whole.
void shareDefinition(const ProcessGrid& grid, fluid::Options& o, fluid::GivenFlags& given,
                     fluid::Settings& s, Eigen::Index& n) {
  BinaryRecordWriter record;
  if (grid.rank() == 0) {
    fluid::putRunDefinition(record, o, given, s);
    record.put(s.out.string());
    record.put(static_cast<std::int64_t>(s.W0.rows()));
  }
  RankZeroRecordReader in(grid, BinaryRecordReader(record.bytes()));
  fluid::getRunDefinition(in, o, given, s);
  s.out = in.get<std::string>();
  n = static_cast<Eigen::Index>(in.get<std::int64_t>());
}

// --grid-rows: a divisor of the number of ranks, or the ProcessGrid's default shape.
int readGridRows(const MpiOptions& o, int ranks) {
  if (o.grid_rows.empty()) return ProcessGrid::defaultRows(ranks);
  const double rows = app::parseNumber("--grid-rows", o.grid_rows, o.grid_rows);
  if (!(rows >= 1 && rows <= ranks && rows == static_cast<int>(rows) &&
        ranks % static_cast<int>(rows) == 0)) {
    app::usageError("--grid-rows", o.grid_rows,
                    "must be a divisor of the number of ranks, " + std::to_string(ranks));
  }
  return static_cast<int>(rows);
}

int readBlock(const MpiOptions& o, int ranks, int grid_rows, long n) {
  if (o.block.empty()) {
    // ⌊N/q⌋ gives every process row and column at least one block (⌈N/q⌉ may not: N = 6
    // on a 5×1 grid would give 3 blocks of 2).
    const long per_process = n / std::max(grid_rows, ranks / grid_rows);
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
  cli.add_option("--grid-rows", o.grid_rows,
                 "rows of the process grid, a divisor of the number of ranks (default: the most "
                 "square grid with rows >= columns)");
  cli.footer(
      "\nfluid-relax-mpi is fluid-relax's relaxation with every N x N matrix "
      "distributed over the MPI ranks\n(docs/design/distributed.md): start it with mpirun -np P. "
      "Methods (--method), and --newton: fluid-relax's, " +
      methodList(kBackendMatrixGroups) +
      ".\n\nInitial "
      "vorticities (--init; all scaled to ||W||_F = sqrt(N), seeded by --seed):\n" +
      app::describeChoices(app::initDescriptions()) +
      "\nFiles in --out (written by rank 0): history.csv, W_final.csv, omega_initial.csv, "
      "omega_final.csv, summary.json,\ncheckpoint.ddb (fluid-relax's: either app resumes "
      "it), fluid.hdf5 with --h5 or --animate\n(docs/reference/command-lines-and-files.md). "
      "Exit status: 0 ok, 1 a step failed or a file could not be written, 2 bad input\n(nothing "
      "written), 130/143 "
      "stopped by SIGINT/SIGTERM (outputs and a checkpoint written).\n");
}

MpiRun mpiRun(const CLI::App& cli, const MpiOptions& o, const ProcessGrid& grid) {
  MpiRun run;
  if (const int status = onEveryRank(grid, [&] { run.grid_rows = readGridRows(o, grid.size()); })) {
    throw Reported{status};
  }
  if (!o.relax.resume.empty()) {
    const std::string& dir = o.relax.resume;
    run.resume.emplace();
    fluid::Checkpoint& c = *run.resume;
    if (const int status = onRankZero(grid, [&] {
          // The lock first: the checkpoint and the files are read as their one writer left them.
          run.lock.emplace(app::lockResumeFolder(dir, fluid::kCheckpointFile));
          c = fluid::readCheckpoint(dir);
        })) {
      throw Reported{status};
    }
    shareDefinition(grid, c.options, c.given, c.settings, run.n);
    const int status = onEveryRank(grid, [&] {
      fluid::resumeSettings(cli, o.relax, c);
      run.block = readBlock(o, grid.size(), run.grid_rows, run.n);
    });
    if (status != 0) throw Reported{status};
    // The folder against the checkpoint, on rank 0, which holds both.
    if (const int checked = onRankZero(grid, [&] { fluid::checkResumeFolder(dir, c); })) {
      throw Reported{checked};
    }
    run.options = c.options;
    run.given = c.given;
    run.settings = std::move(c.settings);
    return run;
  }
  run.options = o.relax;
  run.given = fluid::givenFlags(cli);
  if (const int status =
          onRankZero(grid, [&] { run.settings = fluid::settings(cli, o.relax, kMaxN); })) {
    throw Reported{status};
  }
  shareDefinition(grid, run.options, run.given, run.settings, run.n);
  if (const int status =
          onEveryRank(grid, [&] { run.block = readBlock(o, grid.size(), run.grid_rows, run.n); })) {
    throw Reported{status};
  }
  return run;
}

int onRankZero(const ProcessGrid& grid, const std::function<void()>& job) {
  return runAndAgree(grid, grid.rank() == 0, job);
}

int onEveryRank(const ProcessGrid& grid, const std::function<void()>& job) {
  return runAndAgree(grid, true, job);
}

}  // namespace ddb::fluid_mpi
