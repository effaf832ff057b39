#include "fluid_relax/device.h"

#include <ddb/groups/sun.h>

#include <array>

#include "common/cli.h"
#include "common/exit_status.h"

#ifdef DDB_FLUID_RELAX_CUDA
#include <ddb/cuda/cuda_device.h>
#endif

namespace ddb::fluid {

namespace {

std::optional<std::string> cpuUnavailable() { return std::nullopt; }
std::string cpuDescription() { return "cpu"; }

// The CUDA row: its run where the CUDA backend was built (the one place that asks).
#ifdef DDB_FLUID_RELAX_CUDA
std::optional<std::string> cudaRowUnavailable() { return cudaUnavailable(); }
std::string cudaDescription() { return "cuda: " + cudaDeviceName(); }
constexpr auto kCudaRelax = &relaxOnCuda;
#else
std::optional<std::string> cudaRowUnavailable() {
  return "this fluid-relax was built without the CUDA backend (configure ddb where CUDA's "
         "toolkit is found: docs/guide/gpu.md)";
}
std::string cudaDescription() { return "cuda"; }
constexpr decltype(&relaxOnCuda) kCudaRelax = nullptr;  // never run: unavailable says why
#endif

const std::array<Device, 2> kDevices{{
    {"cpu", "the CPU", kMaxN, cpuUnavailable, relaxOnCpu, cpuDescription},
    {"cuda", "the GPU", SUN::kMaxN, cudaRowUnavailable, kCudaRelax, cudaDescription},
}};

}  // namespace

const Device& deviceOf(const std::string& text) {
  std::vector<std::string> names;
  for (const Device& device : kDevices) names.emplace_back(device.name);
  app::requireChoice("--device", text, names);
  for (const Device& device : kDevices) {
    if (text == device.name) return device;
  }
  throw std::logic_error("device table: no row " + text);
}

void requireRunsOn(const Device& device, Eigen::Index n) {
  if (const auto why = device.unavailable()) app::usageError("--device", device.name, *why);
  if (n > device.max_n) {
    app::usageError("--device", device.name,
                    "this run has N = " + std::to_string(n) + "; on " + device.place +
                        " N <= " + std::to_string(device.max_n) +
                        (device.max_n < SUN::kMaxN ? " (give --device cuda)" : ""));
  }
}

}  // namespace ddb::fluid
