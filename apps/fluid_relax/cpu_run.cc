// The device table's cpu row: the run with its states in this process's memory.
#include "fluid_relax/device.h"
#include "fluid_relax/fluid_run.h"
#include "fluid_relax/one_process.h"

namespace ddb::fluid {

int relaxOnCpu(const Options& o, const Settings& s, const GivenFlags& given, Checkpoint* resume,
               std::optional<app::RunFolderLock>& lock) {
  CpuPlacement where(s.W0.rows(), s.alpha, s.physics);
  return runFluidRelaxation(where, o, s, given, resume, lock);
}

}  // namespace ddb::fluid
