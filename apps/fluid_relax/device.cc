#include "fluid_relax/device.h"

#include <ddb/groups/sun.h>
#include <dlfcn.h>

#include <array>

#include "common/cli.h"

namespace ddb::fluid {

namespace {

std::optional<std::string> cpuUnavailable() { return std::nullopt; }

// The cuda row: its module, loaded once, where the CUDA backend was built (the one place that
// asks), and kept for the life of the process.
struct CudaModule {
  const CudaRun* run = nullptr;
  std::string why;  ///< why it is not there, if not
};

const CudaModule& cudaModule() {
  static const CudaModule module = [] {
    CudaModule m;
#ifdef DDB_FLUID_RELAX_CUDA_MODULE
    void* handle = ::dlopen(DDB_FLUID_RELAX_CUDA_MODULE, RTLD_NOW | RTLD_LOCAL);
    void* entry = handle == nullptr ? nullptr : ::dlsym(handle, "ddbFluidRelaxCudaRun");
    if (entry == nullptr) {
      const char* error = ::dlerror();
      m.why = std::string(
                  "fluid-relax's CUDA part cannot be loaded (rebuild the target "
                  "fluid-relax: docs/guide/gpu.md): ") +
              (error != nullptr ? error : "no entry point");
    } else {
      m.run = reinterpret_cast<decltype(&ddbFluidRelaxCudaRun)>(entry)();
    }
#else
    m.why =
        "this fluid-relax was built without the CUDA backend (configure ddb where CUDA's "
        "toolkit is found: docs/guide/gpu.md)";
#endif
    return m;
  }();
  return module;
}

std::optional<std::string> cudaRowUnavailable() {
  const CudaModule& module = cudaModule();
  if (module.run == nullptr) return module.why;
  return module.run->unavailable();
}

int relaxOnCuda(const Options& o, const Settings& s, const GivenFlags& given, Checkpoint* resume,
                std::optional<app::RunFolderLock>& lock) {
  return cudaModule().run->relax(o, s, given, resume, lock);  // after cudaRowUnavailable()
}

const std::array<Device, 2> kDevices{{
    {"cpu", "the CPU", kMaxN, cpuUnavailable, relaxOnCpu},
    {"cuda", "the GPU", SUN::kMaxN, cudaRowUnavailable, relaxOnCuda},
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
