// fluid-relax --device (docs/guide/gpu.md): where the run's states live, a row of the device
// table: this process's memory (cpu) or one GPU's (cuda, the CUDA backend, cuda/cuda_backend.h).
// A new place is one more row (and its placement, fluid_relax/fluid_run.h), not a branch in main.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "common/run_folder.h"
#include "fluid_relax/checkpoint.h"
#include "fluid_relax/input.h"
#include "fluid_relax/options.h"

namespace ddb::fluid {

struct Device {
  const char* name;
  const char* place;  ///< as messages name it: "the CPU", "the GPU"
  /// The largest N here: fluid-relax's on the CPU (every state's spectrum is computed there),
  /// the group's on the GPU (the spectrum only at history rows).
  Eigen::Index max_n;
  /// Why no run can use this device here (not built, no usable GPU), or nothing.
  std::optional<std::string> (*unavailable)();
  /// The run (fluid_relax/fluid_run.h) with its states here; returns the exit status.
  int (*relax)(const Options& o, const Settings& s, const GivenFlags& given, Checkpoint* resume,
               std::optional<app::RunFolderLock>& lock);
  /// What summary.json records, once the device is known to be available.
  std::string (*description)();
};

/// The row of --device's value (a UsageError naming --device and the choices otherwise).
const Device& deviceOf(const std::string& text);

/// Whether a run of size n can run on `device` here (every --method and --newton run on
/// any): a UsageError naming the flag and the reason if not.
void requireRunsOn(const Device& device, Eigen::Index n);

/// The runs of the table's rows (fluid_relax/cpu_run.cc, fluid_relax/cuda_run.cc).
int relaxOnCpu(const Options& o, const Settings& s, const GivenFlags& given, Checkpoint* resume,
               std::optional<app::RunFolderLock>& lock);
int relaxOnCuda(const Options& o, const Settings& s, const GivenFlags& given, Checkpoint* resume,
                std::optional<app::RunFolderLock>& lock);

}  // namespace ddb::fluid
