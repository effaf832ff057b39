// The device table's cuda row (built where the CUDA backend is): the run with its states on one
// GPU (docs/guide/gpu.md), copied to this process's memory only for the history rows, the
// checkpoints and the final files; the spectrum drift of the rows' states (as on MPI ranks), so
// that no step waits for an eigensolver. Built as a module of its own, which fluid-relax loads
// when --device cuda is asked (fluid_relax/device.h).
#include <ddb/cuda/cuda_device.h>
#include <ddb/cuda/cuda_zeitlin_exact_flows.h>
#include <ddb/cuda/cuda_zeitlin_fluid.h>
#include <ddb/integrators/methods/strang_splitting.h>

#include "fluid_relax/device.h"
#include "fluid_relax/fluid_run.h"
#include "fluid_relax/one_process.h"

namespace ddb::fluid {

namespace {

class CudaPlacement : public OneProcess {
 public:
  using Group = CudaSUN;
  using State = CudaMatrix;
  static constexpr bool kSpectrumEveryState = false;

  CudaPlacement(Eigen::Index n, double alpha, const ZeitlinPhysics& physics)
      : OneProcess(n),
        fluid_(makeCudaZeitlinFluid(n, alpha, physics)),
        host_fluid_(makeZeitlinFluid(n, alpha, physics)) {}

  const std::shared_ptr<const LiePoissonSystem<CudaSUN>>& system() const { return fluid_; }
  const std::shared_ptr<const LiePoissonSystem<SUN>>& hostFluid() const { return host_fluid_; }
  CudaMatrix initialState(const Matrix& W0) const { return toDevice(W0); }
  const Matrix& onHost(const CudaMatrix& W, Matrix& buffer) const {
    toHost(W, buffer);
    return buffer;
  }
  /// ‖[P, W]‖ on the CPU only: on the GPU it would copy the state and take two products.
  std::string commutatorText(const CudaMatrix&) const { return ""; }
  std::string device() const { return "cuda: " + cudaDeviceName(); }
  /// The damping and forcing run on the host's copy of the state (cudaZeitlinExactFlows).
  std::unique_ptr<OneStepMethod<CudaSUN>> splitWith(std::unique_ptr<OneStepMethod<CudaSUN>> method,
                                                    const ZeitlinDampingAndForcing& flows) const {
    const auto& host = dynamic_cast<const ZeitlinHamiltonian&>(host_fluid_->hamiltonian());
    for (auto& flow : cudaZeitlinExactFlows(host, flows)) {
      method = std::make_unique<StrangSplitting<CudaSUN>>(std::move(method), std::move(flow));
    }
    return method;
  }

 private:
  std::shared_ptr<const LiePoissonSystem<CudaSUN>> fluid_;
  std::shared_ptr<const LiePoissonSystem<SUN>> host_fluid_;
};

int relaxOnCuda(const Options& o, const Settings& s, const GivenFlags& given, Checkpoint* resume,
                std::optional<app::RunFolderLock>& lock) {
  CudaPlacement where(s.W0.rows(), s.alpha, s.physics);
  return runFluidRelaxation(where, o, s, given, resume, lock);
}

}  // namespace

}  // namespace ddb::fluid

const ddb::fluid::CudaRun* ddbFluidRelaxCudaRun() {
  static const ddb::fluid::CudaRun run{ddb::cudaUnavailable, ddb::fluid::relaxOnCuda};
  return &run;
}
