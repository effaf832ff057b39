// fluid-relax --device (docs/guide/gpu.md): where the run's states live, this process's memory
// (cpu) or one GPU's (cuda, the CUDA backend, cuda/cuda_backend.h), checked before anything is
// written.
#pragma once

#include <Eigen/Core>
#include <string>

#include "fluid_relax/options.h"

namespace ddb::fluid {

enum class Device { kCpu, kCuda };

/// --device's value, cpu or cuda (a UsageError naming --device otherwise).
Device deviceOf(const std::string& text);

/// The largest N on `device`: fluid-relax's on the CPU (every state's spectrum is computed
/// there), the group's on the GPU (the spectrum only at history rows).
Eigen::Index maxN(Device device);

/// Whether a run of size n can run on `device` here (every --method and --newton run on
/// either): a UsageError naming the flag and the reason if not (N too large for the CPU, no
/// CUDA backend in this build, no usable GPU).
void requireRunsOn(Device device, Eigen::Index n);

/// What summary.json records: "cpu", or "cuda: " and the GPU's name.
std::string deviceDescription(Device device);

}  // namespace ddb::fluid
