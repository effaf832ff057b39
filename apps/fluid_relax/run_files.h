// The files of a fluid-relax run folder (docs/reference/command-lines-and-files.md, "Run folders"),
// shared by fluid-relax and fluid-relax-mpi: which names make a folder another run's (and go with
// --overwrite), and every check a --resume makes of the folder against its checkpoint before
// the resumed run touches anything (docs/reference/guarantees.md, "Nothing finished is lost").
#pragma once

#include <string>

#include "common/run_folder.h"
#include "fluid_relax/checkpoint.h"

namespace ddb::fluid {

/// Every output, the journal, the checkpoint, the figures and their temporaries.
const app::RunFiles& runFiles();

/// The checks of `--resume DIR`'s folder against its checkpoint `c`: history.csv (or the
/// .partial a killed or failed run left) is a regular file holding at least the recorded bytes,
/// whose hash is the recorded one, so that it is this run's history and not another's; with
/// --h5, fluid.hdf5 is a regular file of this run's N, alpha, h, method and initial vorticity
/// with at least the recorded frames; without, no fluid.hdf5 is there. A failure is a
/// UsageError naming --resume and the file. A checkpoint of layout 2, which has no hash, gets
/// the file's (c.files.history_digest), which the resumed run continues.
void checkResumeFolder(const std::string& dir, Checkpoint& c);

}  // namespace ddb::fluid
