// What the processes of a fluid run agree on after each step (fluid_relax/fluid_run.h): whether
// any received a stop signal, whether the writer failed to write a file and whether a checkpoint
// is due (the writer's clock decides). One process agrees with itself.
#pragma once

namespace ddb::fluid {

struct StepFlags {
  int signal = 0, write_failed = 0, checkpoint_due = 0;
};

}  // namespace ddb::fluid
