// fluid-relax --device (docs/guide/gpu.md): where the run's states live, a row of the device
// table: this process's memory (cpu) or one GPU's (cuda, the CUDA backend, cuda/cuda_backend.h).
// A new place is one more row (and its placement, fluid_relax/fluid_run.h), not a branch in main.
// The cuda row's run is a module of its own, loaded only when --device cuda is asked: linked into
// fluid-relax, CUDA's libraries would cost every run, on the CPU too, about 0.4 s and 260 MB at
// its start (docs/results/compile-costs.md, "fluid-relax's start").
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "common/run_folder.h"
#include "fluid_relax/checkpoint.h"
#include "fluid_relax/input.h"
#include "fluid_relax/options.h"

namespace ddb::fluid {

/// The run (fluid_relax/fluid_run.h) with its states on a device; returns the exit status.
using RelaxOn = int (*)(const Options& o, const Settings& s, const GivenFlags& given,
                        Checkpoint* resume, std::optional<app::RunFolderLock>& lock);

struct Device {
  const char* name;
  const char* place;  ///< as messages name it: "the CPU", "the GPU"
  /// The largest N here: fluid-relax's on the CPU (every state's spectrum is computed there),
  /// the group's on the GPU (the spectrum only at history rows).
  Eigen::Index max_n;
  /// Why no run can use this device here (not built, no usable GPU), or nothing.
  std::optional<std::string> (*unavailable)();
  RelaxOn relax;
};

/// What the cuda row's module (fluid_relax/cuda_run.cc) gives fluid-relax.
struct CudaRun {
  std::optional<std::string> (*unavailable)();  ///< no usable GPU, or nothing
  RelaxOn relax;
};

/// The row of --device's value (a UsageError naming --device and the choices otherwise).
const Device& deviceOf(const std::string& text);

/// Whether a run of size n can run on `device` here (every --method and --newton run on
/// any): a UsageError naming the flag and the reason if not.
void requireRunsOn(const Device& device, Eigen::Index n);

/// The cpu row's run (fluid_relax/cpu_run.cc).
int relaxOnCpu(const Options& o, const Settings& s, const GivenFlags& given, Checkpoint* resume,
               std::optional<app::RunFolderLock>& lock);

}  // namespace ddb::fluid

/// The cuda row's module's one entry point, looked up by this name (fluid_relax/device.cc).
extern "C" const ddb::fluid::CudaRun* ddbFluidRelaxCudaRun();
