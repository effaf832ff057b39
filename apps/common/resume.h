// What a resume of a run folder (`--resume DIR`, docs/reference/command-lines-and-files.md,
// "Checkpoints") checks that both resumable apps share: the folder's lock taken only once its
// checkpoint is known to exist (bad input creates nothing), and the relaxation's record loaded
// with the resumed run's cap beyond it.
#pragma once

#include <ddb/core/binary_record.h>
#include <ddb/integrators/drivers/steady_state_search.h>

#include <functional>
#include <string>

#include "common/run_folder.h"

namespace ddb::app {

/// DIR's lock for `--resume DIR`, taken after refusing a folder another process holds and one
/// without `checkpoint_file` (UsageErrors naming --resume): nothing is created before.
RunFolderLock lockResumeFolder(const std::string& dir, const std::string& checkpoint_file);

/// Loads a checkpoint's relaxation record with `load`, which returns the loaded state
/// (Relaxation::load, or fluid-relax-mpi's reader of the same record), and checks that the
/// resumed run's cap (`caps`: max_steps, t_end) lies beyond it: a corrupt record or a cap
/// already reached is a UsageError naming --resume DIR.
void resumeRelaxation(BinaryRecordReader& relaxation, const RelaxOptions& caps,
                      const std::string& dir, const std::string& checkpoint_file,
                      const std::function<RelaxState(BinaryRecordReader&)>& load);

/// RelaxOptions' stopping rule and step control as a checkpoint records them (tolerance,
/// max_steps, t_end, control.adaptive, control.tolerance, in that order; not `newton`).
void putRelaxCaps(BinaryRecordWriter& out, const RelaxOptions& relax);
void getRelaxCaps(BinaryRecordReader& in, RelaxOptions& relax);

}  // namespace ddb::app
