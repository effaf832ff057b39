// fluid-relax-mpi's input (docs/design/distributed.md, "fluid-relax-mpi"): fluid-relax's command
// line and checks (fluid_relax/input.h, and fluid_relax/checkpoint.h for --resume) with
// --block and --grid-rows, less the flags it refuses, and the agreement of all ranks on the
// outcome: rank 0 alone makes W₀ or reads the checkpoint and checks what depends on them, every
// rank checks the rest, and a rank that refuses the input refuses it for all.
#pragma once

#include <ddb/distributed/process_grid.h>
#include <ddb/groups/sun.h>

#include <CLI/CLI.hpp>
#include <functional>
#include <optional>
#include <string>

#include "common/run_folder.h"
#include "fluid_relax/checkpoint.h"
#include "fluid_relax/input.h"
#include "fluid_relax/options.h"

namespace ddb::fluid_mpi {

constexpr const char* kApp = "fluid-relax-mpi";
/// The largest N: the group's (SUN::kMaxN), not fluid-relax's, since the sizes one machine
/// cannot step in time are this app's purpose. W₀ is still made whole on rank 0 and each
/// history row's state gathered whole there.
constexpr Eigen::Index kMaxN = SUN::kMaxN;
/// The default block size is this, or less where N is small: max(1, ⌊N / max(grid rows,
/// cols)⌋), so that every rank holds entries when N ≥ max(grid rows, cols). The grid is the
/// ProcessGrid's default shape unless --grid-rows asks for another.
constexpr int kDefaultBlock = 64;

/// An outcome every rank agreed on and one rank has printed: the app exits with `status`.
struct Reported {
  int status;
};

struct MpiOptions {
  fluid::Options relax;
  std::string block;      // as given ("" for the default)
  std::string grid_rows;  // likewise
};

/// fluid-relax's options with --block, --grid-rows and this app's --help footer.
void addMpiOptions(CLI::App& cli, MpiOptions& o);

/// The run a command line asks for, the same on every rank but for the whole matrices,
/// which only rank 0 holds (docs/design/distributed.md, "Memory per rank"): a new run's options and
/// settings, or (--resume DIR) the resumed run's recorded ones with its checkpoint, as
/// fluid-relax makes them (fluid::resumeSettings).
struct MpiRun {
  fluid::Options options;
  fluid::GivenFlags given;
  /// W₀ on rank 0 only (empty on the others).
  fluid::Settings settings;
  Eigen::Index n = 0;
  /// With --resume: on rank 0 the checkpoint read (its settings moved to `settings`), whose
  /// relaxation record every rank reads through a RankZeroRecordReader; on the others one
  /// with an empty record.
  std::optional<fluid::Checkpoint> resume;
  int block = 0;
  /// The process grid's rows (--grid-rows, or the default shape's), a divisor of the ranks.
  int grid_rows = 0;
  /// Rank 0's lock of the run folder (docs/reference/command-lines-and-files.md, "Run folders"),
  /// held to the end: taken before the checkpoint is read (--resume) or once the input is checked
  /// (a new run).
  std::optional<app::RunFolderLock> lock;
};

/// fluid::settings() (a new run: W₀, the default h and every check that reads W₀) or
/// fluid-relax's reading of the checkpoint (--resume), on rank 0, whose run definition is
/// then broadcast; the refused flags, the resume's checks against the command line and
/// --block and --grid-rows on every rank. Bad input on any rank is Reported{2} on every rank
/// (printed by the lowest such rank), so that no rank goes on alone.
MpiRun mpiRun(const CLI::App& cli, const MpiOptions& o, const ProcessGrid& grid);

/// Runs `job` on rank 0 and agrees on its outcome: a UsageError (status 2) or any other
/// exception (status 1) there is printed by rank 0 and returned on every rank; 0 if it ran.
int onRankZero(const ProcessGrid& grid, const std::function<void()>& job);

/// Runs `job` on every rank and agrees on the outcomes likewise (printed by the lowest rank
/// of the worst one).
int onEveryRank(const ProcessGrid& grid, const std::function<void()>& job);

}  // namespace ddb::fluid_mpi
