#include "fluid_relax/device.h"

#include <ddb/groups/sun.h>

#include "common/cli.h"
#include "common/exit_status.h"

#ifdef DDB_FLUID_RELAX_CUDA
#include <ddb/cuda/cuda_device.h>
#endif

namespace ddb::fluid {

Device deviceOf(const std::string& text) {
  app::requireChoice("--device", text, {"cpu", "cuda"});
  return text == "cuda" ? Device::kCuda : Device::kCpu;
}

Eigen::Index maxN(Device device) { return device == Device::kCuda ? SUN::kMaxN : kMaxN; }

void requireRunsOn(Device device, Eigen::Index n) {
  if (device == Device::kCpu) {
    if (n > kMaxN) {
      app::usageError("--device", "cpu",
                      "this run has N = " + std::to_string(n) +
                          "; on the CPU N <= " + std::to_string(kMaxN) + " (give --device cuda)");
    }
    return;
  }
#ifdef DDB_FLUID_RELAX_CUDA
  if (const auto why = cudaUnavailable()) app::usageError("--device", "cuda", *why);
#else
  app::usageError("--device", "cuda",
                  "this fluid-relax was built without the CUDA backend (configure ddb where "
                  "CUDA's toolkit is found: docs/guide/gpu.md)");
#endif
}

std::string deviceDescription(Device device) {
#ifdef DDB_FLUID_RELAX_CUDA
  if (device == Device::kCuda) return "cuda: " + cudaDeviceName();
#endif
  return device == Device::kCuda ? "cuda" : "cpu";
}

}  // namespace ddb::fluid
